#!/bin/sh
# gamg-threshold.sh -- CG iterations of the contact solve against GAMG's
#                      threshold on its finest level       [chapter 13]
#
#   sh bench/gamg-threshold.sh [BUILD_DIR] [N] [THRESHOLDS...]
#
# The 3D Taylor patch test with hex8 (chapters/08-experiments/
# taylor3d.scene, --set mesh.numbers=n=N, default 36: 295,602 dofs, about
# 15 s a run) through `mpirun -n 2 lac run --strategy petsc --no-output`
# for each threshold T (default: -1 0.05 0.07 0.08 0.1 0.12 0.2; -1
# keeps every coupling), two ways:
#   every coupling   --petsc-options "-elast_pc_type gamg
#                    -elast_pc_gamg_threshold T,0": PETSc's GAMG alone,
#                    its threshold on the whole finest level;
#   contact nodes    --petsc-options "-lac_contact_threshold T": lac's
#                    finest level, the couplings with a contact node at
#                    one end only (src/linalg/lac_petsc_mg.h; lac's
#                    default, T = 0.1), GAMG below;
# with PETSC_OPTIONS="-info :pc" for the operator complexity of the
# multigrid (lac's: 1 + nnz(A_1) / nnz(K) times GAMG's on A_1).  Prints the table of bench/README.md (section "Why the patch
# test took three times the cube's iterations"): a Markdown table, one
# column per threshold, the rows the projected CG's iterations and the
# complexity, each way.  On two processes the iterations vary by one or
# two from run to run.  Nothing is written but to stdout.
set -u
B=${1:-build}
N=${2:-36}
[ $# -ge 2 ] && shift 2 || shift $#
TS=${*:--1 0.05 0.07 0.08 0.1 0.12 0.2}
LAC="$B/lac"
command -v mpirun > /dev/null 2>&1 || { echo "gamg-threshold: mpirun not found (openmpi-bin)" >&2; exit 1; }
[ -x "$LAC" ] || { echo "gamg-threshold: $LAC not built (make)" >&2; exit 1; }
MPIRUN="mpirun"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
T=$(mktemp -d) || exit 1
trap 'rm -rf "$T"' EXIT
head="| threshold on the finest level |" rule="|---|"
its1="| CG iterations, every coupling |" cx1="| operator complexity, every coupling |"
its2="| CG iterations, contact nodes only |" cx2="| operator complexity, contact nodes only |"
# run WAY T: one run into $T/out, 1 if it failed
run () {
  if [ "$1" = every ]; then opt="-elast_pc_type gamg -elast_pc_gamg_threshold $2,0"; else opt="-lac_contact_threshold $2"; fi
  if ! PETSC_OPTIONS="-info :pc" $MPIRUN -n 2 "$LAC" run chapters/08-experiments/taylor3d.scene \
       --set mesh.numbers=n="$N" --strategy petsc --no-output \
       --petsc-options "$opt" > "$T/out" 2> "$T/err"; then
    echo "gamg-threshold: $opt failed: $(tail -1 "$T/err")" >&2
    return 1
  fi
}
iterations () { sed -n 's/^solver_iterations = //p' "$T/out"; }
complexity () {
  r=$(grep -o 'nnz(A_1) / nnz(K) [0-9.e+-]*' "$T/out" | head -1 | awk '{ print $NF }')
  grep -o 'operator complexity = [0-9.]*' "$T/out" | head -1 \
    | awk -v r="$r" '{ printf "%.2f", r == "" ? $4 : 1 + r * $4 }'
}
for t in $TS; do
  [ "$t" = -1 ] && name="none (-1)" || name=$t
  head="$head $name |" rule="$rule---:|"
  run every "$t" || exit 1
  its1="$its1 $(iterations) |" cx1="$cx1 $(complexity) |"
  run contact "$t" || exit 1
  its2="$its2 $(iterations) |" cx2="$cx2 $(complexity) |"
done
printf '%s\n%s\n%s\n%s\n%s\n%s\n' "$head" "$rule" "$its1" "$cx1" "$its2" "$cx2"
