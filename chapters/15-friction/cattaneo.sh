#!/bin/sh
# cattaneo.sh -- Cattaneo-Mindlin in 2D: the stick zone and the tangential
#                traction at three refinement levels and three loads
#
#   sh chapters/15-friction/cattaneo.sh [BUILD] [LEVELS] [RATIOS]
#
# Runs cattaneo2d.scene (quad8; P = 700 N/mm, then Q = ratio mu P) at each
# level (default "1 2 3") for each ratio Q / (mu P) (default "0.3 0.6
# 0.9") and prints, per run (chapters/15-friction/cattaneo.py): the
# macro-elements in contact, c/a measured and Cattaneo's, the error of c in
# %, the relative L2 error of the tangential traction, the most Newton
# iterations of a load step.  Several minutes on two cores (level 3 has
# 62k dofs).
B=${1:-build}
LEVELS=${2:-"1 2 3"}
RATIOS=${3:-"0.3 0.6 0.9"}
here=$(dirname "$0")
OUT=$B/cattaneo
mkdir -p "$OUT" || exit 1
printf '%5s %5s %6s %10s %10s %9s %11s %6s\n' level Q/muP macros c/a \
  exact "error %" "L2(q) rel" iters
for L in $LEVELS; do
  for r in $RATIOS; do
    Q=$(awk -v r="$r" 'BEGIN { printf "%.10g", r * 0.3 * 700 }')
    d="$OUT/L$L-$r"
    if "$B/lac" run "$here/cattaneo2d.scene" --set level="$L" \
         --set "load.pull.point_force=$Q 0" --quiet --out "$d" \
         > /dev/null 2> "$d.err"; then
      printf '%5d %5s ' "$L" "$r"
      python3 "$here/cattaneo.py" "$d" "$r"
    else
      printf '%5d %5s failed: %s\n' "$L" "$r" "$(tail -1 "$d.err")"
    fi
  done
done
