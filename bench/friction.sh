#!/bin/sh
# friction.sh -- what Coulomb friction costs                 [chapter 15]
#
#   sh bench/friction.sh [BUILD_DIR] [LEVEL] [REPEATS]
#
# Cattaneo-Mindlin at LEVEL (default 3, the finest level of chapter 15,
# 72k dofs), every body held by its Dirichlet conditions
# (bench/cattaneo-disp.scene): the frictional run (mu = 0.3) and the same
# scene frictionless (mu = 0, the cylinder slides), alternately REPEATS
# times (default 5).  Prints each pair's seconds (the whole run, wall
# clock, and its solve stage, --timings), the medians and their ratios,
# and the active-set iterations of
# each load step; then one run of the force-controlled scene of chapter 15
# (the cylinder held by contact alone), whose frictionless twin has no
# static solution, for its time and strategy.  Alone on the machine.
B=${1:-build}
L=${2:-3}
R=${3:-5}
here=$(dirname "$0")
OUT=$B/bench-friction
mkdir -p "$OUT" || exit 1
run() {   # run MU DIR: "wall solve" seconds of one run on stdout
  t0=$(date +%s.%N)
  "$B/lac" run "$here/cattaneo-disp.scene" --set level="$L" \
    --set contact.interface.friction="$1" --timings --quiet --out "$2" \
    > "$2.log" 2>&1 || { echo "failed: $(tail -1 "$2.log")" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" '/^time_solve =/ { s = $3 }
    END { printf "%.3f %.3f\n", b - a, s }' "$2/summary.txt"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "Cattaneo-Mindlin, quad8 level $L, imposed displacements: seconds of"
echo "the whole run (wall) and of its solve stage (time_solve of --timings)"
printf '%6s %18s %18s\n' run "mu = 0.3" "mu = 0"
printf '%6s %9s %8s %9s %8s\n' "" wall solve wall solve
: > "$OUT/f.txt"; : > "$OUT/n.txt"
i=1
while [ "$i" -le "$R" ]; do
  f=$(run 0.3 "$OUT/fric") || exit 1
  n=$(run 0 "$OUT/none") || exit 1
  echo "$f" >> "$OUT/f.txt"; echo "$n" >> "$OUT/n.txt"
  printf '%6d %9s %8s %9s %8s\n' "$i" $f $n
  i=$((i + 1))
done
mfw=$(cut -d' ' -f1 "$OUT/f.txt" | median); mfs=$(cut -d' ' -f2 "$OUT/f.txt" | median)
mnw=$(cut -d' ' -f1 "$OUT/n.txt" | median); mns=$(cut -d' ' -f2 "$OUT/n.txt" | median)
printf '%6s %9s %8s %9s %8s\n' median "$mfw" "$mfs" "$mnw" "$mns"
awk -v a="$mfw" -v b="$mnw" -v c="$mfs" -v d="$mns" \
  'BEGIN { printf "ratio friction / frictionless: whole run %.2f, solve stage %.2f\n", a / b, c / d }'
for d in fric none; do
  printf '%s: %s, %s\n' "$d" \
    "$(grep '^dofs =' "$OUT/$d/summary.txt")" \
    "$(grep '^newton_iterations\|^max_iterations_per_step\|^factorizations' "$OUT/$d/summary.txt" | tr '\n' ' ')"
done
echo "force-controlled (chapters/15-friction/cattaneo2d.scene, Q = 0.6 mu P):"
t0=$(date +%s.%N)
"$B/lac" run "$here/../chapters/15-friction/cattaneo2d.scene" --set level="$L" \
  --set "load.pull.point_force=1.26 0" --out "$OUT/force" \
  > "$OUT/force.log" 2>&1 || { echo "failed: $(tail -1 "$OUT/force.log")"; exit 1; }
t1=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" 'BEGIN { printf "  %.3f s wall, ", b - a }'
grep '^newton_iterations\|^max_iterations_per_step\|^factorizations' "$OUT/force/summary.txt" | tr '\n' ' '; echo
grep -o 't = 2.0000, [a-z]* ([^)]*)' "$OUT/force.log" | sed 's/^/  /'
