#!/bin/sh
# bench_taylor.sh -- where the time goes in one 3D patch-test solve
#                                              [LAC §5.1; issue: contact core]
# The Taylor patch test in 3D (chapters/08-experiments/taylor3d.scene) at
# increasing levels, up to more than 100k dofs, with --timings: the time of
# every stage and, inside them, of the refinement, the pairing, the
# factorization of K (cholmod's Schur path) and the active-set iterations.
# The upper block is held by contact alone, so K is singular and the run
# solves the saddle-point system with umfpack (the note on stderr says so).
#   sh bench/bench_taylor.sh [build-dir] [element] [levels...]
B=${1:-build}
E=${2:-hex8}
shift 2 2>/dev/null
LEVELS=${*:-"2 4 6 8 9"}
printf '%-6s %5s %8s %7s %8s %8s %9s %8s %9s %8s %6s\n' element level dofs mult \
  mesh refine pairing assemble factor_K active_set iters
for L in $LEVELS; do
  echo "taylor3d $E level $L ..." >&2
  "$B/lac" run chapters/08-experiments/taylor3d.scene --set element="$E" \
      --set level="$L" --timings --quiet --no-output |
    awk -v e="$E" -v L="$L" -F' = ' '
      { v[$1] = $2 }
      END { printf "%-6s %5s %8s %7s %8s %8s %9s %8s %9s %8s %6s\n", e, L,
            v["dofs"], v["multipliers"], v["time_mesh"], v["time_refine"],
            v["time_pairing"], v["time_assemble"], v["time_factor_K"],
            v["time_solve"], v["newton_iterations"] }'
done
echo "(seconds; active_set = the solve stage: the saddle-point factorizations" \
     "and solves of all iterations)"
