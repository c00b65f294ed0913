#!/bin/sh
# gamg-threshold.sh -- CG iterations of the contact solve against GAMG's
#                      threshold on its finest level       [chapter 13]
#
#   sh bench/gamg-threshold.sh [BUILD_DIR] [N] [THRESHOLDS...]
#
# The 3D Taylor patch test with hex8 (chapters/08-experiments/
# taylor3d.scene, --set mesh.numbers=n=N, default 36: 295,602 dofs, about
# 15 s a run) through `mpirun -n 2 lac run --strategy petsc --no-output
# --petsc-options "-elast_pc_gamg_threshold T,0"` for each threshold T
# (default: -1 0.07 0.08 0.1 0.11 0.12; -1 keeps every coupling), with
# PETSC_OPTIONS="-info :pc" for the operator complexity of the multigrid.
# Prints the table of bench/README.md (section "Why the patch test took
# three times the cube's iterations"): a Markdown table, one column per
# threshold, the rows the projected CG's iterations and the complexity.
# On two processes the iterations vary by one or two from run to run.
# Nothing is written but to stdout.
set -u
B=${1:-build}
N=${2:-36}
[ $# -ge 2 ] && shift 2 || shift $#
TS=${*:--1 0.07 0.08 0.1 0.11 0.12}
LAC="$B/lac"
command -v mpirun > /dev/null 2>&1 || { echo "gamg-threshold: mpirun not found (openmpi-bin)" >&2; exit 1; }
[ -x "$LAC" ] || { echo "gamg-threshold: $LAC not built (make)" >&2; exit 1; }
MPIRUN="mpirun"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
T=$(mktemp -d) || exit 1
trap 'rm -rf "$T"' EXIT
head="| threshold on the finest level |" rule="|---|" its="| CG iterations |"
cx="| operator complexity of the multigrid |"
for t in $TS; do
  if ! PETSC_OPTIONS="-info :pc" $MPIRUN -n 2 "$LAC" run chapters/08-experiments/taylor3d.scene \
       --set mesh.numbers=n="$N" --strategy petsc --no-output \
       --petsc-options "-elast_pc_gamg_threshold $t,0" > "$T/out" 2> "$T/err"; then
    echo "gamg-threshold: threshold $t failed: $(tail -1 "$T/err")" >&2
    exit 1
  fi
  [ "$t" = -1 ] && name="none (-1)" || name=$t
  head="$head $name |" rule="$rule---:|"
  its="$its $(sed -n 's/^solver_iterations = //p' "$T/out") |"
  cx="$cx $(grep -o 'operator complexity = [0-9.]*' "$T/out" | head -1 | awk '{ printf "%.2f", $4 }') |"
done
printf '%s\n%s\n%s\n%s\n' "$head" "$rule" "$its" "$cx"
