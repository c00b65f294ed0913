#!/bin/sh
# ring.sh -- the ring on block, coarse and fine, timed      [LAC §5.4]
#
#   sh bench/ring.sh [BUILD_DIR] [ELEMENT] [LEVELS]      (make bench-ring)
#
# Runs chapters/10-large-deformation/ring.scene (ELEMENT: hex20; 61 load steps)
# on each of LEVELS ("0 1": the coarse mesh, 34k dofs, and the fine one,
# 209k dofs) alone, one after the other, and prints per run: dofs, wall
# time of the run and of its solve stage, Newton iterations (all, most in
# a load step), load steps cut, the final vertical displacement of the
# ring's inner bottom point against the value before the consistent
# tangent (the runs of chapter 14's table of the ring: hex20 coarse -19.0528000050,
# fine -19.060 mm), and the histogram of Newton iterations per load step
# after the first contact step.  The runs go to $OUT/ring-ELEMENT-LEVEL/
# (OUT = BUILD_DIR/bench-ring), with their progress lines in .err.  The
# fine hex20 run takes about 10 minutes on 2 cores (the estimate that
# guards a .geo mesh, io/lac_mesh_gmsh_estimate.c, counts its 55,610
# hex20 nodes from the transfinite and extruded curves: 5.8e4, 6.2 GB).
B=${1:-build}
EL=${2:-hex20}
LEVELS=${3:-"0 1"}
LAC=$B/lac
OUT=$B/bench-ring
[ -x "$LAC" ] || ${MAKE:-make} -s B="$B" "$LAC" >&2 || exit 1
mkdir -p "$OUT" || exit 1

# u_z of ring_mid before the consistent tangent (chapter 14's table of the ring)
reference () {
  case "$EL:$1" in
    hex20:0) echo -19.0528000050 ;;
    hex20:1) echo -19.060 ;;
    hex8:0) echo -19.446 ;;
    hex8:1) echo -19.156 ;;
    hex27:0) echo -19.055 ;;
    hex27:1) echo -19.060 ;;
    *) echo nan ;;
  esac
}

printf "run          dofs   wall s  solve s  newton  max/step  cut   u_z (mm)        before    diff %%\n"
for L in $LEVELS; do
  D=$OUT/ring-$EL-$L
  t0=$(date +%s.%N)
  if ! "$LAC" run chapters/10-large-deformation/ring.scene --set element="$EL" \
       --set level="$L" --out "$D" --timings \
       > "$D.sum" 2> "$D.err"; then
    echo "ring.sh: the run $EL level $L failed: $(tail -1 "$D.err")" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  v () { sed -n "s/^$1 = //p" "$D.sum"; }
  ref=$(reference "$L")
  awk -v n="$EL level $L" -v dofs="$(v dofs)" -v t0="$t0" -v t1="$t1" \
      -v solve="$(v time_solve)" -v it="$(v newton_iterations)" \
      -v mx="$(v max_iterations_per_step)" -v cut="$(v cut_steps)" \
      -v uz="$(v monitor_uz)" -v ref="$ref" 'BEGIN {
    d = ref == "nan" ? 0 : 100 * (uz - ref) / ref; if (d < 0) d = -d
    wall = t1 - t0
    printf "%-11s %6d %8.1f %8.1f %7d %9d %4d   %.10f  %s  %.4f\n", n, dofs,
           wall, solve, it, mx, cut, uz, ref, d }'
  # iterations per load step after the first contact step (ring_curve.csv:
  # 7 iterations, 11 active)
  awk -F, 'NR > 2 { if (seen) h[$7]++; if ($11 > 0) seen = 1 }
    END { printf "            iterations per step after the first contact:";
          for (k = 0; k <= 40; k++) if (h[k]) printf " %dx%d", h[k], k;
          printf "\n" }' "$D/ring_curve.csv"
done
