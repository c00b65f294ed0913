#!/bin/sh
# ring-runs.sh -- the ring on block on its six meshes, as Markdown tables
#
#   sh chapters/14-results/ring-runs.sh [BUILD]
#
# Runs chapters/10-large-deformation/ring.scene for each run of RUNS
# (ELEMENT:LEVEL[:STEPS]; default "hex8:0 hex20:0 hex27:0 hex8:1 hex20:1
# hex27:1:20", STEPS the load steps after the approach, 60 unless given)
# with [steps] tangent = $TANGENT (consistent unless given), one after the
# other, and prints two tables (section 4 of this chapter): the meshes
# (nodes and cells after lac's cut of the contact layer) against those of
# the paper's Table 7 (quoted here), then the runs: dofs, load steps, wall
# time (it depends on the machine and its load), Newton iterations (all,
# most in a step), the final u_z of ring_mid and the extreme u_z.  The six
# runs take hours on 2 cores (the fine hex20 about 30 minutes, the fine
# hex27 longer); their summaries go to BUILD/ring-runs.
B=${1:-build}
RUNS=${RUNS:-"hex8:0 hex20:0 hex27:0 hex8:1 hex20:1 hex27:1:20"}
TANGENT=${TANGENT:-consistent}
W=$B/ring-runs
mkdir -p "$W" || exit 1
for r in $RUNS; do
  el=${r%%:*}; rest=${r#*:}; lv=${rest%%:*}; n=60
  [ "$rest" = "$lv" ] || n=${rest#*:}
  t0=$(date +%s)
  "$B/lac" run chapters/10-large-deformation/ring.scene --set element="$el" \
    --set level="$lv" --set steps.n="$n" --set steps.tangent="$TANGENT" \
    --no-output --quiet > "$W/$r.sum" 2> "$W/$r.err" ||
    { echo "ring-runs.sh: $r: $(tail -1 "$W/$r.err")" >&2; exit 1; }
  echo "wall = $(( $(date +%s) - t0 ))" >> "$W/$r.sum"
done
# name RUN: "hex8 coarse"; table7 RUN: the paper's nodes and elements
name () { l=${1#*:}; l=${l%%:*}; [ "$l" = 0 ] && echo "${1%%:*} coarse" || echo "${1%%:*} fine"; }
table7 () {
  case $1 in
    hex8:0*) echo "3085 | 4162" ;;  hex20:0*) echo "11133 | 4162" ;;
    hex27:0*) echo "13998 | 3037" ;; hex8:1*) echo "17998 | 21784" ;;
    hex20:1*) echo "67454 | 21784" ;; hex27:1*) echo "102114 | 17284" ;;
    *) echo "– | –" ;;
  esac
}
# value RUN KEY
value () { awk -F' = ' -v k="$2" '$1 == k { print $2 }' "$W/$1.sum"; }
echo '| mesh | nodes | cells | Table 7 nodes | Table 7 elements |'
echo '|---|---:|---:|---:|---:|'
for r in $RUNS; do
  echo "| $(name "$r") | $(value "$r" nodes) | $(value "$r" cells) | $(table7 "$r") |"
done
echo
echo '| run | dofs | load steps | wall time | Newton iterations (most in a step) | final u_z of ring_mid (mm) | extreme u_z (mm) |'
echo '|---|---:|---:|---|---:|---:|---:|'
for r in $RUNS; do
  awk -F' = ' -v nm="$(name "$r")" '{ v[$1] = $2 }
    function th(n,   s) { s = ""; while (n >= 1000) { s = sprintf (",%03d", n % 1000) s; n = int (n / 1000) } return n s }
    function mm(x,   s) { s = sprintf ("%.3f", x); sub (/^-/, "−", s); return s }
    END { printf "| %s | %s | %d | %.1f min | %d (%d) | %s | %s |\n", nm, th(v["dofs"]), v["load_steps"],
            v["wall"] / 60, v["newton_iterations"], v["max_iterations_per_step"], mm(v["monitor_uz"]),
            mm(v["monitor_extreme"]) }' "$W/$r.sum"
done
