#!/bin/sh
# cattaneo.sh -- Cattaneo-Mindlin in 2D: the stick zone and the tangential
#                traction at three refinement levels and three loads
#
#   sh chapters/15-friction/cattaneo.sh [BUILD] [LEVELS] [RATIOS] [P]
#
# Runs cattaneo2d.scene (quad8; P = 7 N/mm or the P given, the mesh's
# fine zone scaled as Hertz's a, then Q = ratio mu P) at each
# level (default "1 2 3") for each ratio Q / (mu P) (default "0.3 0.6
# 0.9") and prints, per run (chapters/15-friction/cattaneo.py): the
# macro-elements in contact, c/a measured and Cattaneo's, the error of c in
# %, the relative L2 error of the tangential traction, the most Newton
# iterations of a load step.  Several minutes on two cores (level 3 has
# 62k dofs).  FIG=file.png: the finest level at Q / (mu P) = 0.6 (the
# first ratio if 0.6 is not among them), FIG=fig-%s.png one picture per
# ratio: `lac render --contact` of the run, zoomed on the contact zone,
# with Cattaneo's tangential traction for comparison.
B=${1:-build}
LEVELS=${2:-"1 2 3"}
RATIOS=${3:-"0.3 0.6 0.9"}
P=${4:-7}
A0=$(awk -v p="$P" 'BEGIN { printf "%.10g", 0.03 * sqrt(p / 7) }')
here=$(dirname "$0")
OUT=$B/cattaneo
mkdir -p "$OUT" || exit 1
rundir () { if [ "$P" = 7 ]; then echo "$OUT/L$1-$2"; else echo "$OUT/L$1-$2-P$P"; fi; }
printf '%5s %5s %6s %10s %10s %9s %11s %6s\n' level Q/muP macros c/a \
  exact "error %" "L2(q) rel" iters
for L in $LEVELS; do
  for r in $RATIOS; do
    Q=$(awk -v r="$r" -v p="$P" 'BEGIN { printf "%.10g", r * 0.3 * p }')
    d=$(rundir "$L" "$r")
    if "$B/lac" run "$here/cattaneo2d.scene" --set level="$L" \
         --set "load.press.total_force=0 -$P" --set "mesh.numbers=a0=$A0" \
         --set "load.pull.point_force=$Q 0" --quiet --out "$d" \
         > /dev/null 2> "$d.err"; then
      printf '%5d %5s ' "$L" "$r"
      python3 "$here/cattaneo.py" "$d" "$r" "$P"
    else
      printf '%5d %5s failed: %s\n' "$L" "$r" "$(tail -1 "$d.err")"
    fi
  done
done

# FIG: the finest level drawn by `lac render --contact`: lambda, the mean
# gap and the tangential traction per macro-element, zoomed on the contact
# zone, against Cattaneo's q written in render's abscissa s.  s runs over
# the admissible macro-elements of the block's flat face from its end of
# lower x, so s = x - x0 with x0 the lower end of the first of them (from
# contact.csv); q takes the sign of lambda_t (the block's traction, against
# the pull).  The picture is drawn in the run's directory, where render
# leaves its data and script (traction.dat, traction.gp), and copied to FIG.
draw_fig () {  # draw_fig RATIO PNG
  d=$(rundir "$Lmax" "$1")
  [ -f "$d/contact.csv" ] || { echo "cattaneo.sh: no run $d for FIG" >&2; return 1; }
  awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
    $(c["admissible"]) == 1 { x = $(c["x"]) - $(c["measure"]) / 2
                              if (!n++ || x < x0) x0 = x
                              f += $(c["lambda_t"]) * $(c["covered"]) }
    END { printf "%.12g %d\n", x0, f < 0 ? -1 : 1 }' "$d/contact.csv" \
    > "$d/origin.txt"
  read x0 sign < "$d/origin.txt"
  # Hertz: E* = E / (2 (1 - nu^2)), a = sqrt(4 P R / (pi E*)), p0 = 2 P /
  # (pi a); Cattaneo: c = a sqrt(1 - Q / (mu P)), q = mu p0 sqrt(1 - x^2 /
  # a^2) - mu p0 (c / a) sqrt(1 - x^2 / c^2) (the second term for |x| < c);
  # 1201 points over |x| < 1.3 a, the range of s drawn
  awk -v r="$1" -v P="$P" -v x0="$x0" -v sg="$sign" -v range="$d/srange.txt" 'BEGIN {
    pi = 3.14159265358979; Es = 200000 / (2 * (1 - 0.09)); mu = 0.3
    a = sqrt(4 * P * 10 / (pi * Es)); p0 = 2 * P / (pi * a)
    c = a * sqrt(1 - r)
    printf "# Cattaneo q(x), c / a = %.4f\n", c / a
    for (i = 0; i <= 1200; i++) {
      x = -1.3 * a + 2.6 * a * i / 1200; q = 0
      if (x * x < a * a) q = mu * p0 * sqrt(1 - x * x / (a * a))
      if (x * x < c * c) q -= mu * p0 * (c / a) * sqrt(1 - x * x / (c * c))
      printf "%.10e %.10e\n", x - x0, q == 0 ? 0 : sg * q }
    printf "%.10g:%.10g\n", -1.3 * a - x0, 1.3 * a - x0 > range }' \
    > "$d/cattaneo-q.txt"
  "$B/lac" render "$d" --contact --compare "$d/cattaneo-q.txt" \
    --srange "$(cat "$d/srange.txt")" --units MPa --width 900 --height 1000 \
    --title "Cattaneo-Mindlin, quad8 level $Lmax, Q / (mu P) = $1" \
    --out "$d/traction.png" > /dev/null && cp "$d/traction.png" "$2"
}

if [ -n "$FIG" ]; then
  Lmax=$(echo $LEVELS | awk '{ print $NF }')
  case $FIG in
    *%s*) for r in $RATIOS; do
            draw_fig "$r" "$(printf "$FIG" "$r")" || exit 1
          done ;;
    *) r=$(echo $RATIOS | awk '{ for (k = 1; k <= NF; k++) if ($k == 0.6) { print $k; exit }
                                 print $1 }')
       draw_fig "$r" "$FIG" || exit 1 ;;
  esac
fi
