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
# 62k dofs).  FIG=file.png: the tangential traction of the finest level
# at each ratio against Cattaneo's, with mu times the pressure and the
# stick zone (gnuplot, pngcairo).
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

if [ -n "$FIG" ]; then
  Lmax=$(echo $LEVELS | awk '{ print $NF }')
  n=$(echo $RATIOS | wc -w)
  {
    echo "set terminal pngcairo size $((520 * n)),560 font \"DejaVu Sans,12\" enhanced"
    echo "set output '$FIG'"
    echo "set multiplot layout 1,$n"
    echo 'set xlabel "x (mm)"; set ylabel "traction (MPa)"; set key top center font ",10"; set offsets 0, 0, 170, 0'
    echo 'Es = 200000 / (2 * (1 - 0.09)); a = sqrt(4 * 700 * 10 / (pi * Es)); p0 = 2 * 700 / (pi * a); mu = 0.3'
    echo 'set xrange [-1.3 * a:1.3 * a]; set samples 600'
    echo 'p(x) = abs(x) < a ? p0 * sqrt(1 - x * x / (a * a)) : 0'
    for r in $RATIOS; do
      d="$OUT/L$Lmax-$r"
      awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
        $(c["multiplier"]) != "" && $(c["status"]) != "inactive" {
          w = $(c["covered"]) / 2; t = $(c["lambda_t"]); t = t < 0 ? -t : t
          n = $(c["lambda"]); n = n < 0 ? -n : n
          print $2 - w, $2 + w, t, 0.3 * n }' "$d/contact.csv" | sort -g |
        awk '{ print $1, $3, $4; print $2, $3, $4; print "" }' \
        > "$d/traction.dat"      # one segment per macro-element
      echo "c = a * sqrt(1 - $r)"
      echo "q(x) = abs(x) < c ? mu * p(x) - mu * p0 * (c / a) * sqrt(1 - x * x / (c * c)) : mu * p(x)"
      echo "set title \"Q / ({/Symbol m} P) = $r, quad8 level $Lmax\""
      echo "set object 1 rect from -c, graph 0 to c, graph 1 behind fc rgb '#e8f0ff' fs solid noborder"
      echo "plot '$d/traction.dat' using 1:3 with lines lc rgb '#999999' lw 1.5 title '{/Symbol m} |{/Symbol l}_n|', '' using 1:2 with lines lc rgb '#d03030' lw 2 title '|{/Symbol l}_t|, LAC (shaded: Cattaneo stick zone)', q(x) with lines lc rgb 'black' dt 2 lw 2 title 'Cattaneo q(x)'"
    done
    echo 'unset multiplot'
  } > "$OUT/cattaneo.gp"
  gnuplot "$OUT/cattaneo.gp"
fi
