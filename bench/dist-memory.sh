#!/bin/sh
# dist-memory.sh -- the peak memory of each MPI process of the petsc
#                   strategy: process 0 against the others  [chapter 13]
#
#   sh bench/dist-memory.sh [BUILD_DIR] [N] [NP...]
#   PROBLEM=cube sh bench/dist-memory.sh [BUILD_DIR] [N] [NP...]
#
# The 3D Taylor patch test with hex8 (chapters/08-experiments/
# taylor3d.scene, --set mesh.numbers=n=N: 3 ((N+1)^3 + N^3) dofs; N = 55:
# 1,034,721 dofs, the default, about a minute and 5 GB summed on two
# processes; N = 25: 101,331 dofs, seconds) through `mpirun -n NP lac run
# --strategy petsc --no-output` for each NP (default: 2 and 4,
# oversubscribed), each process under /usr/bin/time.  Prints per run the
# dofs, lambda, the wall time, each process's peak resident memory (MB)
# and the ratio of process 0's to the mean of the others' (issue 26 asks
# for at most 1.5 at a million dofs, with the summed memory not above
# that of the root's assembly).  PROBLEM=cube: the clamped cube of
# bench/cube.scene instead (no contact, --solver petsc, 3 (N+1)^3 dofs;
# N = 69: 1,029,000), default N 69.  Processes 0 .. NP-1 in order;
# nothing is written but to stdout.
set -u
B=${1:-build}
case ${PROBLEM:-taylor} in
  taylor) SCENE=chapters/08-experiments/taylor3d.scene; HOW="--strategy petsc"; N=${2:-55} ;;
  cube) SCENE=bench/cube.scene; HOW="--solver petsc"; N=${2:-69} ;;
  *) echo "dist-memory: PROBLEM=$PROBLEM: expected taylor or cube" >&2; exit 1 ;;
esac
[ $# -ge 2 ] && shift 2 || shift $#
NPS=${*:-2 4}
LAC="$B/lac"
command -v mpirun > /dev/null 2>&1 || { echo "dist-memory: mpirun not found (openmpi-bin)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "dist-memory: /usr/bin/time not found (apt-get install time)" >&2; exit 1; }
[ -x "$LAC" ] || { echo "dist-memory: $LAC not built (make)" >&2; exit 1; }
MPIRUN="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
T=$(mktemp -d) || exit 1
trap 'rm -rf "$T"' EXIT
for np in $NPS; do
  t0=$(date +%s.%N)
  # shellcheck disable=SC2086
  if ! $MPIRUN -n "$np" sh -c '/usr/bin/time -f "%M" -o "$0/rss.$OMPI_COMM_WORLD_RANK" "$@"' "$T" \
       "$LAC" run "$SCENE" --set mesh.numbers=n="$N" \
       $HOW --quiet --no-output > "$T/out" 2> "$T/err"; then
    echo "dist-memory: -n $np failed: $(tail -1 "$T/err")" >&2
    exit 1
  fi
  wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  awk -v np="$np" -v dir="$T" -v wall="$wall" '
    /^dofs = / { dofs = $3 } /^lambda_min = / { lmin = $3 }
    END {
      printf "n = %s processes, %s dofs, lambda_min = %s, wall %s s; peak MB:", np, dofs, lmin, wall
      for (p = 0; p < np; p++) {
        f = dir "/rss." p; if ((getline kb < f) <= 0) { print " (no memory of process " p ")"; exit 1 }
        mb[p] = kb / 1024; printf " %.0f", mb[p]; if (p > 0) others += mb[p]; total += mb[p]
      }
      printf "; summed %.0f; process 0 / mean of the others = %.2f\n", total, mb[0] / (others / (np - 1))
    }' "$T/out" || exit 1
  rm -f "$T"/rss.*
done
