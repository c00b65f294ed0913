#!/bin/sh
# ring-newton.sh -- the convergence of the Newton loop on the ring on block,
# with the frozen-geometry tangent (before) and the consistent one (after)
#                                                  [LAC §4.5, Alg. 1; §5.4]
#
#   sh figures/ring-newton.sh [BUILD_DIR] [--quick] [--out DIR] [--table]
#
# Runs chapters/10-large-deformation/ring.scene (hex20, coarse mesh, 61 load
# steps; --quick: hex8, 7 steps) twice, with [steps] tangent = frozen and
# tangent = consistent, keeps the progress lines (one per Newton iteration:
# the residual at its start; the step line: the final residual), and draws
# OUT/fig08-ring-newton-residual.png (OUT = figures):
#   left   the residual against the iteration, for four load steps spread
#          over the loading, both tangents (frozen dashed);
#   right  the Newton iterations of every load step, both tangents.
# The data: BUILD_DIR/figures-work/ring-newton/{frozen,consistent}.csv
# (step, iteration, residual; iteration 0 is the residual the step ended
# with, written last) and .sum (the runs' summaries); the table
# iterations-per-step is printed, or with --table the Markdown table of
# chapter 10 (tangent, Newton iterations, most in a step, final u_z of
# ring_mid; make doc-snapshots compares it with the book).  The coarse
# hex20 runs take about 6 and 2 minutes on 2 cores.
B=build
QUICK=0
TABLE=0
OUT=figures
while [ $# -gt 0 ]; do
  case $1 in
    --quick) QUICK=1 ;;
    --table) TABLE=1 ;;
    --out) shift; OUT=${1:?--out needs a directory} ;;
    -*) echo "ring-newton.sh: unknown option '$1'" >&2; exit 2 ;;
    *) B=$1 ;;
  esac
  shift
done
LAC=$B/lac
W=$B/figures-work/ring-newton
[ $QUICK = 1 ] && W=$B/figures-work-quick/ring-newton
SET="--set element=hex20"
[ $QUICK = 1 ] && SET="--set element=hex8 --set steps.n=6"
[ -x "$LAC" ] || ${MAKE:-make} -s B="$B" "$LAC" >&2 || exit 1
command -v gnuplot > /dev/null || { echo "ring-newton.sh: gnuplot not found (Debian: gnuplot-nox)" >&2; exit 1; }
mkdir -p "$W" "$OUT" || exit 1
rm -f "$W"/*.dat "$W"/*.csv
OUTABS=$(cd "$OUT" && pwd)

# the runs, then per run a CSV "step,iteration,residual" from the progress
for tg in frozen consistent; do
  if ! "$LAC" run chapters/10-large-deformation/ring.scene $SET \
       --set steps.tangent=$tg --out "$W/$tg" > "$W/$tg.sum" 2> "$W/$tg.err"
  then
    echo "ring-newton.sh: the $tg run failed: $(tail -1 "$W/$tg.err")" >&2
    exit 1
  fi
  awk '
    / iteration [0-9]+: residual / {
      split ($0, a, "step "); split (a[2], b, "/"); s = b[1] + 0
      match ($0, / iteration [0-9]+:/); it = substr ($0, RSTART + 11, RLENGTH - 12) + 0
      match ($0, /residual [0-9.e+-]+/); r = substr ($0, RSTART + 9, RLENGTH - 9)
      print s "," it "," r; next }
    / step [0-9]+\/[0-9]+: t = .* Newton iteration/ {
      split ($0, a, "step "); split (a[2], b, "/"); s = b[1] + 0
      match ($0, /residual [0-9.e+-]+/); r = substr ($0, RSTART + 9, RLENGTH - 9)
      print s ",0," r }' "$W/$tg.err" > "$W/$tg.csv"
done

# iterations per step, both tangents
N=$(awk -F, '$2 == 0' "$W/consistent.csv" | wc -l)
awk -F, 'FNR == 1 { f++ } $2 > 0 { n[f, $1]++; if ($1 > s) s = $1 }
  END { print "step  frozen  consistent"
        for (k = 1; k <= s; k++) printf "%4d %7d %11d\n", k, n[1, k], n[2, k] }' \
  "$W/frozen.csv" "$W/consistent.csv" > "$W/iterations.txt"
if [ $TABLE = 1 ]; then
  echo '| tangent | Newton iterations | most in a step | final $u_z$ of ring_mid |'
  echo '|---|---:|---:|---:|'
  for tg in frozen consistent; do
    awk -F' = ' -v tg=$tg '{ v[$1] = $2 }
      END { u = sprintf ("%.10f", v["monitor_uz"]); sub (/^-/, "−", u)
            printf "| %s | %d | %d | %s |\n", tg, v["newton_iterations"], v["max_iterations_per_step"], u }' "$W/$tg.sum"
  done
else
  cat "$W/iterations.txt"
fi

# four load steps spread over the loading (the last one among them)
S1=$((N / 4 + 1)); S2=$((N / 2 + 1)); S3=$((3 * N / 4 + 1)); S4=$N
for tg in frozen consistent; do
  for s in $S1 $S2 $S3 $S4; do
    # iterations 1..n, then the final residual as iteration n + 1
    awk -F, -v s=$s '$1 == s && $2 > 0 { print $2 "," $3; n = $2 }
      $1 == s && $2 == 0 { f = $3 } END { print n + 1 "," f }' \
      "$W/$tg.csv" > "$W/$tg-$s.dat"
  done
done
awk -F, '$2 == 0 { print $1 "," n[$1] + 0 } $2 > 0 { n[$1]++ }' "$W/frozen.csv" > "$W/frozen-its.dat"
awk -F, '$2 == 0 { print $1 "," n[$1] + 0 } $2 > 0 { n[$1]++ }' "$W/consistent.csv" > "$W/consistent-its.dat"
el=$(sed -n 's/^element = //p' "$W/consistent.sum")
dofs=$(sed -n 's/^dofs = //p' "$W/consistent.sum")
itf=$(sed -n 's/^newton_iterations = //p' "$W/frozen.sum")
itc=$(sed -n 's/^newton_iterations = //p' "$W/consistent.sum")
{
  echo 'set terminal pngcairo size 1500,620 font "DejaVu Sans,13" enhanced'
  echo "set output '$OUTABS/fig08-ring-newton-residual.png'"
  echo 'set datafile separator ","'
  echo "set multiplot layout 1,2 title \"ring on block, $el ($dofs dofs): Newton iterations with the frozen-geometry tangent (dashed) and the consistent one (solid)\" font \",14\""
  echo 'set logscale y; set format y "10^{%L}"; set grid'
  echo 'set xlabel "Newton iteration in the load step"; set ylabel "relative residual at its start"'
  echo 'set key top right'
  printf 'plot '
  c=1
  for s in $S1 $S2 $S3 $S4; do
    col=$(echo "#1f77b4 #d62728 #2ca02c #9467bd" | cut -d' ' -f$c)
    printf "'frozen-%s.dat' using 1:2 with linespoints dt 2 lw 2 pt 6 lc rgb \"%s\" notitle, " "$s" "$col"
    printf "'consistent-%s.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb \"%s\" title \"step %s\"" "$s" "$col" "$s"
    [ $c -lt 4 ] && printf ', '
    c=$((c + 1))
  done
  echo
  echo 'unset logscale y; set format y "%g"'
  echo 'set xlabel "load step"; set ylabel "Newton iterations"'
  echo 'set key top left'
  echo "plot 'frozen-its.dat' using 1:2 with steps lw 2 dt 2 lc rgb \"#d62728\" title \"frozen geometry ($itf in all)\", 'consistent-its.dat' using 1:2 with steps lw 2 lc rgb \"#1f77b4\" title \"consistent ($itc in all)\""
  echo 'unset multiplot'
} > "$W/ring-newton.gp"
(cd "$W" && gnuplot ring-newton.gp) || exit 1
echo "ring-newton.sh: $OUTABS/fig08-ring-newton-residual.png" >&2
