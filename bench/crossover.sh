#!/bin/sh
# crossover.sh -- a Cholesky factor against the petsc strategy on one
#                 process: where auto changes sides          [chapter 13]
#
#   sh bench/crossover.sh [BUILD_DIR] [REPEATS] [CASES]
#
# The Taylor patch tests of chapter 08 (the upper body held by contact
# alone) at growing sizes, each case run with a Cholesky factor
# (--strategy split) and with the petsc strategy (projected CG and GAMG,
# one process), alternately REPEATS times (default 3).  Prints per case:
# the dofs, the memory lac estimates for the run with a Cholesky factor
# (what auto compares with LAC_STRATEGY_ITERATIVE_BYTES in 3D), the median
# wall seconds of each run, their ratio (above 1: petsc is faster), the
# median peak memory of each (GB, the summary's peak_rss_total_mb), and
# the strategy auto takes; then per element where the ratio crosses 1,
# and what petsc costs and saves from LAC_STRATEGY_ITERATIVE_BYTES on
# (the ranges of its time and its memory as multiples of the factor's,
# auto's trade in 3D, chapter 13).  CASES: a list of SCENE:ELEMENT:SET, SET the
# size (n=N, the geometries' [mesh] numbers, or level=L); default
# hex8, tet4 and hex20 in 3D, quad4 and quad8 in 2D, from about 12k to
# 1M dofs.  About 20 minutes on two cores.  Alone on the machine.
B=${1:-build}
R=${2:-3}
T3=chapters/08-experiments/taylor3d.scene
T2=chapters/08-experiments/taylor2d.scene
CASES=${3:-"$T3:hex8:n=14 $T3:hex8:n=17 $T3:hex8:n=20 $T3:hex8:n=22
$T3:hex8:n=24 $T3:hex8:n=28 $T3:tet4:n=14 $T3:tet4:n=20 $T3:tet4:n=24
$T3:hex20:n=7 $T3:hex20:n=9 $T3:hex20:n=11 $T3:hex20:n=13
$T2:quad4:n=160 $T2:quad4:n=320 $T2:quad4:n=500
$T2:quad8:n=90 $T2:quad8:n=180 $T2:quad8:n=290"}
OUT=$B/bench-crossover
mkdir -p "$OUT" || exit 1
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
sets () {   # sets SET: the --set of a case's size
  case $1 in n=*) echo "mesh.numbers=$1" ;; *) echo "$1" ;; esac
}
run () {    # run SCENE ELEMENT SET STRATEGY DIR: wall seconds and peak GB
  t0=$(date +%s.%N)
  "$B/lac" run "$1" --set scene.element="$2" --set "$(sets "$3")" \
    --strategy "$4" --quiet --timings --out "$5" > "$5.log" 2>&1 \
    || { echo "failed: $(tail -1 "$5.log")" >&2; return 1; }
  t1=$(date +%s.%N)
  mb=$(sed -n 's/^peak_rss_total_mb = //p' "$5/summary.txt")
  awk -v a="$t0" -v b="$t1" -v m="$mb" 'BEGIN { printf "%.3f %.3f\n", b - a, m / 1000 }'
}
col () { cut -d' ' -f"$1" "$2" | median; }   # col K FILE: median of column K
: > "$OUT/rows.txt"
printf '%-8s %-6s %-10s %9s %9s %9s %9s %6s %9s %9s  %s\n' scene element size dofs \
  "GB chol" "direct s" "petsc s" ratio "direct GB" "petsc GB" "auto takes"
for c in $CASES; do
  scene=${c%%:*}; r=${c#*:}; el=${r%%:*}; size=${r#*:}
  name=$(basename "$scene" .scene); d="$OUT/$name-$el-$size"
  # lac's estimate of the run with a Cholesky factor: its refusal under
  # the smallest --max-memory says it
  gb=$("$B/lac" run "$scene" --set scene.element="$el" --set "$(sets "$size")" \
         --strategy split --max-memory 100M --no-output 2>&1 \
       | sed -n 's/.*need about \([0-9.e+-]*\) GB.*/\1/p')
  : > "$d.direct"; : > "$d.petsc"; i=1
  while [ "$i" -le "$R" ]; do
    run "$scene" "$el" "$size" split "$d-direct" >> "$d.direct" || exit 1
    run "$scene" "$el" "$size" petsc "$d-petsc" >> "$d.petsc" || exit 1
    i=$((i + 1))
  done
  md=$(col 1 "$d.direct"); mp=$(col 1 "$d.petsc")
  gd=$(col 2 "$d.direct"); gp=$(col 2 "$d.petsc")
  dofs=$(sed -n 's/^dofs = //p' "$d-direct/summary.txt")
  auto=$("$B/lac" run "$scene" --set scene.element="$el" --set "$(sets "$size")" \
           --no-output 2>&1 | sed -n 's/.*\[5\/7\] solve     \([a-z]*\).*/\1/p' | tail -1)
  printf '%-8s %-6s %-10s %9s %9s %9s %9s %6.2f %9s %9s  %s\n' "$name" "$el" "$size" \
    "$dofs" "${gb:-?}" "$md" "$mp" "$(awk -v a="$md" -v b="$mp" 'BEGIN { print a / b }')" \
    "$gd" "$gp" "$auto" | tee -a "$OUT/rows.txt"
done
# per element, in the order of the cases: the last estimate where the
# factor was faster and the first where petsc was (the crossover lies
# between), or the largest estimate measured if petsc never was
echo
echo "crossover, in lac's estimate of the run with a Cholesky factor:"
awk '{ e = $2; if (!(e in seen)) { seen[e] = 1; order[++n] = e }
       if ($8 < 1) { below[e] = $5; bd[e] = $4 }
       else if (!(e in above)) { above[e] = $5; ad[e] = $4 } }
     END { for (i = 1; i <= n; i++) { e = order[i]
             if (e in above)
               printf "%-6s petsc faster from between %s GB (%s dofs) and %s GB (%s dofs)\n",
                      e, below[e], bd[e], above[e], ad[e]
             else
               printf "%-6s the factor faster up to %s GB (%s dofs)\n", e, below[e], bd[e] } }' \
  "$OUT/rows.txt"
# what auto's petsc costs and saves where it takes it: from the
# constant's estimate on, petsc's wall time and peak memory as multiples
# of the factor's (ranges over the sizes), per element
BYTES=$(sed -n 's/^#define LAC_STRATEGY_ITERATIVE_BYTES \([0-9.e+]*\).*/\1/p' \
          src/solve/lac_strategy.h)
echo
echo "from LAC_STRATEGY_ITERATIVE_BYTES ($BYTES bytes), petsc against the factor:"
awk -v c="$BYTES" '$5 != "?" && $5 * 1e9 >= c {
       e = $2; t = $7 / $6; m = $10 / $9
       if (!(e in n)) { order[++k] = e; tl[e] = th[e] = t; ml[e] = mh[e] = m }
       n[e]++
       if (t < tl[e]) tl[e] = t; if (t > th[e]) th[e] = t
       if (m < ml[e]) ml[e] = m; if (m > mh[e]) mh[e] = m }
     END { for (i = 1; i <= k; i++) { e = order[i]
             printf "%-6s %d sizes: %.2f to %.2f times the time, %.2f to %.2f times the memory\n",
                    e, n[e], tl[e], th[e], ml[e], mh[e] }
           if (!k) print "(no case measured there)" }' "$OUT/rows.txt"
