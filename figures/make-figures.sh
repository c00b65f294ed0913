#!/bin/sh
# make-figures.sh -- regenerate figures/: the counterparts of the paper's
# Figure 2 (the refinement of the first layer, chapter 03) and Figures
# 3-11 [LAC §5], several contact pairs (Figure 13, chapter 06), a compound
# ring (Figure 16, chapter 16) and the accuracy-cost study (chapter 12).
#
#   sh figures/make-figures.sh [BUILD_DIR] [--quick] [--out DIR] [--no-bench]
#
#   BUILD_DIR   where lac and the figures/ programs are built (build);
#               missing programs are built with `make B=BUILD_DIR`
#   --quick     coarse meshes, no accuracy-cost study (CI: a few seconds)
#   --out DIR   write the PNGs there instead of figures/ (tests use a
#               temporary directory so that the committed figures stay)
#   --no-bench  skip bench/accuracy-cost.sh (it is skipped with --quick)
#   --only LIST only these figures, e.g. --only 01,05 (10 draws 10 and 11;
#               no accuracy-cost study)
#
# Every picture is drawn without a display: meshes and fields by OSMesa
# (`lac render`, and figures/figrun.c for what only a live run has: the
# slave sub-facets of the macro-elements coloured by lambda), curves by
# gnuplot (pngcairo).  Scenes are those of chapters/08-10; the
# runs go to BUILD_DIR/figures-work (kept, for inspection: solution.vtu,
# contact.csv, the gnuplot scripts and data).  figures/README.md lists the
# figures.  Exit status: 0 if every figure was drawn (figures 10-11 may be
# skipped, with a message, while the ring scene is not in the tree), 1
# otherwise.
B=build
QUICK=0
OUT=figures
BENCH=1
ONLY=
while [ $# -gt 0 ]; do
  case $1 in
    --quick) QUICK=1 ;;
    --out) shift; OUT=${1:?--out needs a directory} ;;
    --no-bench) BENCH=0 ;;
    --only) shift; ONLY=${1:?--only needs figure numbers}; BENCH=0 ;;
    -*) echo "make-figures.sh: unknown option '$1'" >&2; exit 2 ;;
    *) B=$1 ;;
  esac
  shift
done
[ $QUICK = 1 ] && BENCH=0

LAC=$B/lac
FIGRUN=$B/figures/figrun
FIG02=$B/figures/fig02-refine
D=chapters/08-experiments
D9=chapters/09-spheres-rates
D10=chapters/10-large-deformation
W=$B/figures-work
[ $QUICK = 1 ] && W=$B/figures-work-quick

if [ ! -x "$LAC" ] || [ ! -x "$FIGRUN" ] || [ ! -x "$FIG02" ]; then
  ${MAKE:-make} -s B="$B" "$LAC" "$FIGRUN" "$FIG02" >&2 || exit 1
fi
command -v gnuplot > /dev/null || { echo "make-figures.sh: gnuplot not found (Debian: gnuplot-nox)" >&2; exit 1; }
mkdir -p "$OUT" || exit 1
OUTABS=$(cd "$OUT" && pwd)
[ -z "$ONLY" ] && rm -rf "$W"
mkdir -p "$W" || exit 1

failed=0
T0=$(date +%s)
say () { echo "make-figures: $*" >&2; }
# want NN: figure NN is asked for (all of them without --only)
want () { [ -z "$ONLY" ] || case ",$ONLY," in *",$1,"*) true ;; *) false ;; esac; }
fail () { say "FAILED: $*"; failed=1; }
# the seconds since a start time
since () { echo $(( $(date +%s) - $1 )); }
# run NAME ARGS...: `lac run` into $W/NAME, the summary in $W/NAME.sum
run () {
  name=$1; shift
  if ! "$LAC" run "$@" --out "$W/$name" --quiet > "$W/$name.sum" 2> "$W/$name.err"; then
    fail "lac run $* : $(tail -1 "$W/$name.err")"
    return 1
  fi
}
# frun NAME ARGS...: figrun (run + contact pictures) into $W/NAME
frun () {
  name=$1; shift
  if ! "$FIGRUN" "$@" --out "$W/$name" --quiet > "$W/$name.sum" 2> "$W/$name.err"; then
    fail "figrun $* : $(tail -1 "$W/$name.err")"
    return 1
  fi
}
# render RESULT OUT.png ARGS...: `lac render`
render () {
  res=$1 png=$2; shift 2
  "$LAC" render "$W/$res" --out "$OUT/$png" "$@" > /dev/null 2> "$W/render.err" \
    || fail "lac render $res $*: $(tail -1 "$W/render.err")"
}
val () { sed -n "s/^$2 = //p" "$W/$1.sum"; }
# gp NAME: run gnuplot on $W/NAME.gp (in $W, data files there)
gp () {
  (cd "$W" && gnuplot "$1.gp" 2> "$1.gp.err") || fail "gnuplot $W/$1.gp: $(tail -3 "$W/$1.gp.err")"
}
GPTERM='set terminal pngcairo size 900,620 font "DejaVu Sans,13" enhanced'
GPWIDE='set terminal pngcairo size 1500,620 font "DejaVu Sans,13" enhanced'

# ---- the ring on block runs first, in the background: they are the long
# part (large deformation, 60 load steps; hex20 coarse about 5 minutes).
# RING_MESHES lists ELEMENT:LEVEL[:STEPS] (level 0 coarse, 1 fine: hex8
# about 10 minutes, hex20 about an hour, hex27 more; STEPS replaces the 60
# equal steps of ring.scene, e.g. hex27:1:20 for every third point).
RING=$D10/ring.scene
ring_pids=
if [ -f $RING ] && want 10; then
  if [ $QUICK = 1 ]; then
    # touch, then 10 mm of crushing in 4 steps (the pipeline, not the curve)
    RING_MESHES=${RING_MESHES:-"hex8:0"}
    RING_SET="--set dirichlet.ends.uz=-30 --set steps.start=0.6666666666666666 --set steps.n=4 --set steps.vtu_every=2 --set output.vtu_format=ascii"
  else
    RING_MESHES=${RING_MESHES:-"hex8:0 hex20:0 hex8:1"}
    RING_SET="--set steps.vtu_every=15 --set output.vtu_format=ascii"
  fi
  # steps.vtu_every: step_NNN.vtu every K-th load step and the last (61
  # steps: 15, 30, 45, 60, 61; --quick, 5 steps: 2, 4, 5) for Figure 11,
  # in ASCII for vtu_extent below
  specs=$RING_MESHES
  RING_MESHES=
  for spec in $specs; do
    e=${spec%%:*}; rest=${spec#*:}; l=${rest%%:*}
    nsteps=
    [ "$rest" != "$l" ] && nsteps="--set steps.n=${rest#*:}"
    m=$e:$l
    RING_MESHES="$RING_MESHES $m"
    n=ring-$e-$l
    # RING_REUSE=DIR: a run kept from an earlier make figures (the fine
    # hex20 and hex27 ones take an hour or more) is copied, not redone
    if [ -n "$RING_REUSE" ] && [ "$(cat "$RING_REUSE/$n.rc" 2> /dev/null)" = 0 ] \
       && [ -f "$RING_REUSE/$n/ring_curve.csv" ]; then
      cp -r "$RING_REUSE/$n" "$RING_REUSE/$n.rc" "$RING_REUSE/$n.sum" "$W/" \
        && say "ring $m: the run in $RING_REUSE/$n reused (RING_REUSE)" && continue
    fi
    # shellcheck disable=SC2086
    ( "$LAC" run $RING --set element="$e" --set level="$l" $RING_SET $nsteps --timings \
        --set output.csv=no --out "$W/$n" --quiet > "$W/$n.sum" 2> "$W/$n.err"
      echo $? > "$W/$n.rc" ) &
    ring_pids="$ring_pids $!"
  done
fi

# ---- levels: the paper-like meshes, or coarse ones with --quick ---------
if [ $QUICK = 1 ]; then
  LS1=0 LT2=0 LT3=0 LSA=0 LS3=0 LM2=1 LM3=0 LB=0
else
  LS1=1 LT2=4 LT3=1 LSA=2 LS3=1 LM2=3 LM3=2 LB=1
fi

# ---- Figure 1 (chapter 01): one thick sphere, no contact -----------------
# The problem of chapter 01 (chapters/01-problem/sphere-axi.scene): u_R on
# the mesh, and u_R, sigma_RR at every node against the radius with the
# exact Lame solution.
if want 01; then
t=$(date +%s)
if frun sphere1 chapters/01-problem/sphere-axi.scene --set level=$LS1 --edges \
     --title "thick sphere (chapter 01), tri6: radial displacement u_R" \
     --label u_R --units mm --draw u_R "$OUT/fig01-sphere-axi-u-r.png"; then
  # nodes.csv (axisymmetric): x = r, y = z, u_x = u_r, u_y = u_z, s_xx =
  # sigma_rr, s_yy = sigma_zz, s_xy = sigma_rz: spherical R, u_R, sigma_RR
  awk -F, 'NR > 1 { R = sqrt($2*$2 + $3*$3); nr = $2 / R; nz = $3 / R
             print R, nr * $5 + nz * $6, nr*nr*$7 + nz*nz*$8 + 2*nr*nz*$10 }' \
    "$W/sphere1/nodes.csv" > "$W/sphere1-prof.dat"
  cat > "$W/sphere1-prof.gp" <<EOF
$GPWIDE
set output '$OUTABS/fig01-sphere-axi-profiles.png'
set multiplot layout 1,2 title "thick sphere a = 20, b = 40 mm, p = 25 MPa, E = 2000 MPa, {/Symbol n} = 0.3: every node of the tri6 mesh ($(val sphere1 dofs) dofs) against the exact solution"
a = 20.; b = 40.; p = 25.; E = 2000.; nu = 0.3
c = p * a**3 / (b**3 - a**3)
uR(R) = c / E * ((1 - 2*nu) * R + (1 + nu) * b**3 / (2 * R**2))
sRR(R) = -c * (b**3 / R**3 - 1)
set grid; set xrange [20:40]; set key top right
set xlabel "R (mm)"
set ylabel "u_R (mm)"
plot uR(x) with lines lw 2 lc rgb "#5ec962" title "exact", 'sphere1-prof.dat' using 1:2 with points pt 7 ps 0.5 lc rgb "#3b528b" title "nodes"
set ylabel "{/Symbol s}_{RR} (MPa)"
set key bottom right
plot sRR(x) with lines lw 2 lc rgb "#5ec962" title "exact", 'sphere1-prof.dat' using 1:3 with points pt 7 ps 0.5 lc rgb "#3b528b" title "nodes (averaged nodal stresses)"
unset multiplot
EOF
  gp sphere1-prof
fi
say "fig01 ($(since "$t") s)"
fi

# ---- Figure 2: refinement of the first layer [LAC §4.4, Hyp. 1] ----------
# figures/fig02-refine.c refines a small box per element type with
# lac_macromesh_build and writes the edges, the slave sub-facets (coloured
# by macro-element), the designated interior nodes and the new nodes; the
# same in --quick (the meshes are tiny).
if want 02; then
t=$(date +%s)
mkdir -p "$W/fig02"
if "$FIG02" "$W/fig02" > "$W/fig02.txt" 2> "$W/fig02.err"; then
  # ttl NAME TEXT: a panel title with the macro-elements, the cells and
  # the mean of the designated basis function of T^0 from fig02-refine's report (92:
  # a backslash, so that gnuplot gets the two characters \n)
  ttl () { awk -v n="$1" -v t="$2" '$1 == n { printf "%s%cn%d T^m, cells %s -> %s, mean %.4f", t, 92, $9, $3, $5, $13 }' "$W/fig02.txt"; }
  # panel NAME TITLE 2|3: the plot or splot commands of one case
  panel () {
    printf 'set title "%s"\n' "$(ttl "$1" "$2")"   # (dash's echo would expand \n)
    if [ "$3" = 2 ]; then
      echo "plot 'fig02/$1.edges' using 1:2 with lines lw 1 lc rgb '#909090' notitle, \\"
      echo "     'fig02/$1.slave' using 1:2:(int(\$4) % 4 + 1) with lines lw 6 lc variable notitle, \\"
      echo "     'fig02/$1.new' using 1:2 with points pt 6 ps 1.6 lw 2 lc rgb '#c00000' notitle, \\"
      echo "     'fig02/$1.inode' using 1:2 with points pt 7 ps 1.8 lc rgb '#000000' notitle"
    else
      echo "splot 'fig02/$1.edges' using 1:2:3 with lines lw 1 lc rgb '#909090' notitle, \\"
      echo "      'fig02/$1.slave' using 1:2:3:(int(\$4) % 4 + 1) with lines lw 5 lc variable notitle, \\"
      echo "      'fig02/$1.new' using 1:2:3 with points pt 6 ps 1.0 lw 2 lc rgb '#c00000' notitle, \\"
      echo "      'fig02/$1.inode' using 1:2:3 with points pt 7 ps 1.8 lc rgb '#000000' notitle"
    fi
  }
  colours="set linetype 1 lc rgb '#3b528b'; set linetype 2 lc rgb '#e08000'; set linetype 3 lc rgb '#21918c'; set linetype 4 lc rgb '#b03a8c'"
  {
    # two panels a row, so that the labels stay readable at a page's width
    echo 'set terminal pngcairo size 1100,1000 font "DejaVu Sans,15" enhanced'
    echo "set output '$OUTABS/fig02-refinement-2d.png'"
    echo "$colours"
    echo 'set multiplot layout 3,2 title "Figure 2, 2D: macro-elements of the slave side y = 2 (colours),\\ndesignated interior nodes (black), new nodes (red circles)" font ",16"'
    echo 'set size ratio -1; unset key; set xrange [-0.2:5.2]; set yrange [-0.2:2.3]; set xtics 1; set ytics 1'
    panel tri3 "tri3: seg2 gathered in pairs, a triple at the end" 2
    panel tri3-cut "tri3, option cut-2d: each first-layer cell cut" 2
    panel quad4 "quad4: seg2 gathered in pairs, a triple at the end" 2
    panel quad4-cut "quad4, option cut-2d: each first-layer cell cut" 2
    panel tri6 "tri6: each seg3 alone (its mid-node)" 2
    panel quad8 "quad8: each seg3 alone (its mid-node)" 2
    echo 'unset multiplot'
  } > "$W/fig02-2d.gp"
  gp fig02-2d
  # 3D: each type twice, the cut cell in perspective and its slave face
  # from above (z = 1: the sub-facets, the designated and the new nodes)
  top () {
    printf 'set title "%s"\n' "$2"
    echo "plot 'fig02/$1.slave' using 1:2:(int(\$4) % 4 + 1) with lines lw 4 lc variable notitle, \\"
    echo "     'fig02/$1.new' using 1:(\$3 > 0.999 ? \$2 : NaN) with points pt 6 ps 1.4 lw 2 lc rgb '#c00000' notitle, \\"
    echo "     'fig02/$1.inode' using 1:2 with points pt 7 ps 1.6 lc rgb '#000000' notitle"
  }
  {
    # one element a row: the cut cell and its face, two panels side by side
    echo 'set terminal pngcairo size 1100,2900 font "DejaVu Sans,15" enhanced'
    echo "set output '$OUTABS/fig02-refinement-3d.png'"
    echo "$colours"
    echo 'set multiplot layout 6,2 title "Figure 2, 3D: a unit cube cut below its slave face z = 1, and the face seen from above\\nmacro-elements (colours), designated interior nodes (black), new nodes (red circles)" font ",16"'
    echo 'unset key; unset tics; unset border'
    for c in "tet4|tet4: 3 tet4 cones from the face centre" "hex8|hex8: 5 pyramids from the face centre" \
             "hex8-six|hex8, option six: six hexahedra" "tet10|tet10: 3 tet10 cones" \
             "hex20|hex20: six hexahedra" "hex27|hex27: nothing cut"; do
      n=${c%%|*}
      echo 'set view 55,25; set view equal xyz; set xrange [0:1]; set yrange [0:1]; set zrange [0:1]; set size noratio'
      panel "$n" "${c#*|}" 3
      echo 'set size ratio -1; set xrange [-0.05:1.05]; set yrange [-0.05:1.05]'
      top "$n" "the slave face of $n"
    done
    echo 'unset multiplot'
  } > "$W/fig02-3d.gp"
  gp fig02-3d
else
  fail "fig02-refine: $(tail -1 "$W/fig02.err")"
fi
say "fig02 ($(since "$t") s)"
fi

# ---- Figure 3: Taylor patch test 2D, quad4 [LAC §5.1] --------------------
if want 03; then
t=$(date +%s)
if run taylor2d $D/taylor2d.scene --set element=quad4 --set level=$LT2; then
  dofs=$(val taylor2d dofs); el=$(val taylor2d max_rel_err_lambda)
  render taylor2d fig03-taylor2d-quad4-sigma-yy.png --field stress_yy --edges \
    --units MPa --title "Taylor patch test 2D, quad4: sigma_yy ($dofs dofs)"
  # lambda and mean gap per macro-element along Gamma_C (y = 50): one
  # horizontal segment over each macro-element [x - |T|/2, x + |T|/2] and
  # its ends marked
  awk -F, 'NR > 1 && $8 == 1 { print $2 - $5 / 2, $2 + $5 / 2, $10, $11, $12 }' \
    "$W/taylor2d/contact.csv" | sort -g > "$W/taylor2d-c.dat"
  awk '{ print $1, $3, $4, $5; print $2, $3, $4, $5; print "" }' "$W/taylor2d-c.dat" > "$W/taylor2d-seg.dat"
  nm=$(wc -l < "$W/taylor2d-c.dat")
  cat > "$W/taylor2d-c.gp" <<EOF
$GPTERM
set output '$OUTABS/fig03-taylor2d-quad4-lambda-gap.png'
set multiplot layout 2,1 title "Taylor patch test 2D, quad4, $dofs dofs: {/Symbol l} and mean gap on {/Symbol G}_C\\n($nm macro-elements, max relative error of {/Symbol l}: $el)"
set grid
set xrange [-1:51]
set key bottom right
set ylabel "{/Symbol l} (MPa)"
set yrange [-30:-20]
plot 'taylor2d-seg.dat' using 1:2 with linespoints lw 3 pt 6 ps 1.2 lc rgb "#3b528b" title "{/Symbol l}^h, one value per macro-element (o: its ends)", \\
     -25 with lines dt 2 lw 2 lc rgb "#5ec962" title "exact {/Symbol l} = -p = -25 MPa"
set xlabel "x along {/Symbol G}_C (mm)"
set ylabel "mean gap (mm)"
set yrange [-1e-6:1e-6]
set format y "%.0e"
plot 'taylor2d-seg.dat' using 1:4 with linespoints lw 3 pt 6 ps 1.2 lc rgb "#21918c" title "mean gap d_m / |T^m| (closed: 0)"
unset multiplot
EOF
  gp taylor2d-c
fi
say "fig03 ($(since "$t") s)"
fi

# ---- Figure 4: Taylor patch test 3D, hex8 [LAC §5.1] ---------------------
if want 04; then
t=$(date +%s)
if frun taylor3d $D/taylor3d.scene --set element=hex8 --set level=$LT3 \
     --edges --el 40 --title "Taylor 3D, hex8: lambda on the slave sub-facets" \
     --label lambda --units MPa --draw lambda "$OUT/fig04-taylor3d-hex8-lambda.png" \
     --range -1e-6:1e-6 --title "Taylor 3D, hex8: mean gap per macro-element" \
     --label "mean gap" --units mm --draw gap "$OUT/fig04-taylor3d-hex8-gap.png"; then
  dofs=$(val taylor3d dofs)
  render taylor3d fig04-taylor3d-hex8-sigma-zz.png --field stress_zz --scale 10 \
    --edges --units MPa --title "Taylor 3D, hex8: sigma_zz, deformed x10 ($dofs dofs)"
fi
say "fig04 ($(since "$t") s)"
fi

# ---- Figures 5 and 6: self-included spheres [LAC §5.2] -------------------
# spheres NAME SCENE ELEMENT LEVEL FIG "FIELD VIEW" "LAMBDA VIEW": u_R, von
# Mises, sigma_RR, lambda on the slave surface, and lambda against the
# polar angle (gnuplot).
spheres () {
  name=$1 scene=$2 e=$3 l=$4 fig=$5 fview=$6 lview=$7
  # shellcheck disable=SC2086
  frun "$name" $D9/$scene.scene --set element="$e" --set level="$l" --edges $fview \
    --title "self-included spheres, $e: radial displacement u_R" \
    --label u_R --units mm --draw u_R "$OUT/$fig-u-r.png" $lview \
    --title "spheres, $e: lambda on the slave R = 30 (exact +-5%)" \
    --range -5.139:-4.649 --label lambda --units MPa --draw lambda "$OUT/$fig-lambda.png" || return 1
  dofs=$(val "$name" dofs)
  # shellcheck disable=SC2086
  render "$name" "$fig-von-mises.png" --field von_mises --edges --units MPa $fview \
    --title "self-included spheres, $e: von Mises ($dofs dofs)"
  # shellcheck disable=SC2086
  render "$name" "$fig-sigma-rr.png" --field radial_stress --edges --units MPa $fview \
    --title "self-included spheres, $e: sigma_RR ($dofs dofs)"
  # lambda per macro-element against the polar angle from the z axis
  zc=3; [ "$scene" = spheres3d ] && zc=4     # the column of z (axisymmetric: y)
  awk -F, -v zc=$zc 'NR > 1 && $8 == 1 { r = sqrt($2*$2 + $3*$3 + $4*$4); z = $zc;
             print atan2(sqrt(r*r - z*z), z) * 180 / 3.14159265358979, $10, $11 }' \
    "$W/$name/contact.csv" | sort -g > "$W/$name-lam.dat"
  # y range: [-5.5, -4.3] MPa, widened to every value
  yr=$(awk 'BEGIN { lo = -5.5; hi = -4.3 } { if ($2 < lo) lo = $2; if ($2 > hi) hi = $2 }
            END { d = 0.05 * (hi - lo); printf "%g:%g", lo - d, hi + d }' "$W/$name-lam.dat")
  el=$(val "$name" max_rel_err_lambda)
  nm=$(wc -l < "$W/$name-lam.dat")
  printf '0 -4.894179894\n90 -4.894179894\n' > "$W/lac-exact"
  cat > "$W/$name-lam.gp" <<EOF
$GPTERM
set output '$OUTABS/$fig-lambda-curve.png'
set title "self-included spheres, $e, $dofs dofs: {/Symbol l} on $nm macro-elements\\n(max relative error $el)"
set grid
set key bottom left
set xlabel "polar angle of the macro-element's centroid from the z axis (degrees)"
set ylabel "{/Symbol l} (MPa)"
set xrange [0:90]
set yrange [$yr]
plot 'lac-exact' using 1:2 with lines dt 2 lw 2 lc rgb "#5ec962" title "exact {/Symbol l} = {/Symbol s}_{RR}(30) = -4.894 MPa", \\
     '$name-lam.dat' using 1:2 with points pt 7 ps 1.1 lc rgb "#3b528b" title "{/Symbol l}^h (one point per macro-element)"
EOF
  gp "$name-lam"
}
if want 05; then
t=$(date +%s)
spheres spheres-axi spheres-axi tri6 $LSA fig05-spheres-axi-tri6 "" ""
say "fig05 ($(since "$t") s)"
fi
if want 06; then
t=$(date +%s)
spheres spheres3d spheres3d tet10 $LS3 fig06-spheres3d-tet10 "--az -45 --el 25" "--az 135 --el 30"
say "fig06 ($(since "$t") s)"
fi

# ---- Figures 7 and 8: manufactured solutions [LAC §5.3] ------------------
if want 07; then
t=$(date +%s)
if run man2d $D9/manufactured2d.scene --set element=quad8 --set level=$LM2; then
  dofs=$(val man2d dofs)
  render man2d fig07-manufactured2d-quad8-u.png --field u --scale 1 --edges \
    --title "manufactured 2D, quad8: |u|, deformed x1 ($dofs dofs)"
  # lambda per macro-element against the exact -0.05 (x - 1/2)^2 - 0.01
  awk -F, 'NR > 1 && $8 == 1 { print $2 - $5 / 2, $2 + $5 / 2, $10, $11 }' \
    "$W/man2d/contact.csv" | sort -g \
    | awk '{ print $1, $3, $4; print $2, $3, $4; print "" }' > "$W/man2d-seg.dat"
  cat > "$W/man2d-lam.gp" <<EOF
$GPTERM
set output '$OUTABS/fig07-manufactured2d-quad8-lambda.png'
set title "manufactured 2D, quad8, $dofs dofs: contact pressure on the bottom side\\n(L^2 error of {/Symbol l}: $(val man2d l2_err_lambda))"
set grid
set key bottom center
set xlabel "x (unit square, E = 1)"
set ylabel "{/Symbol l} (same units as E)"
set xrange [0:1]
plot -0.05 * (x - 0.5)**2 - 0.01 with lines dt 2 lw 2 lc rgb "#5ec962" title "exact {/Symbol l} = -0.05 (x - 1/2)^2 - 0.01", \\
     'man2d-seg.dat' using 1:2 with lines lw 3 lc rgb "#3b528b" title "{/Symbol l}^h, one value per macro-element"
EOF
  gp man2d-lam
fi
say "fig07 ($(since "$t") s)"
fi
if want 08; then
t=$(date +%s)
if frun man3d $D9/manufactured3d.scene --set element=hex20 --set level=$LM3 \
     --edges --el 30 --az 35 --scale 1 --title "manufactured 3D, hex20: lambda on the bottom" \
     --label lambda --draw lambda "$OUT/fig08-manufactured3d-hex20-lambda.png"; then
  render man3d fig08-manufactured3d-hex20-u.png --field u --scale 1 --edges --el 30 --az 35 \
    --title "manufactured 3D, hex20: |u|, deformed x1 ($(val man3d dofs) dofs)"
fi
say "fig08 ($(since "$t") s)"
fi

# ---- Figures 10 and 11: ring on block [LAC §5.4] -------------------------
# vtu_extent FILE...: "UMAX X0:X1:Y0:Y1:Z0:Z1", the largest |u| and the
# bounding box of the deformed configurations x + u of VTU files, in one
# pass (one point per line, as lac writes them with output.vtu_format =
# ascii)
vtu_extent () {
  awk '/<DataArray/ { c = /Name="coordinates"/; d = /Name="displacement"/
                      if (FNR == 1 || c) n = 0; m = 0; next }
       /<\/DataArray>/ { c = d = 0 }
       c { x[++n] = $1; y[n] = $2; z[n] = $3 }
       d { m++; X = x[m] + $1; Y = y[m] + $2; Z = z[m] + $3
           u = $1 * $1 + $2 * $2 + $3 * $3; if (u > U) U = u
           if (!seen++) { a = b = X; e = f = Y; g = h = Z }
           if (X < a) a = X; if (X > b) b = X; if (Y < e) e = Y; if (Y > f) f = Y
           if (Z < g) g = Z; if (Z > h) h = Z }
       END { printf "%.6g %.6g:%.6g:%.6g:%.6g:%.6g:%.6g\n", sqrt(U), a, b, e, f, g, h }' "$@"
}
# ring_steps_figure RUN ELEMENT: fig11-ring-ELEMENT-u-steps.png, |u| on the
# deformed shape at the step files of $W/RUN/steps.pvd ([steps] vtu_every),
# one picture each in $W/RUN (step_NNN-u.png), same colour range, a montage
ring_steps_figure () {
  rs=$1 re=$2
  [ -f "$W/$rs/steps.pvd" ] || { fail "no $W/$rs/steps.pvd (steps.vtu_every)"; return; }
  sel=$(sed -n 's/.*file="step_0*\([0-9][0-9]*\)\.vtu".*/\1/p' "$W/$rs/steps.pvd" \
        | awk '{ s[++m] = $1 } END { for (i = 1; i <= m; i++)
                 if (i == m || s[m] - s[i] >= s[1] / 2) printf "%d ", s[i] }')
  [ -n "$sel" ] || { fail "no step file in $W/$rs/steps.pvd"; return; }
  files=$(for s in $sel; do printf '%s/%s/step_%03d.vtu ' "$W" "$rs" "$s"; done)
  # shellcheck disable=SC2086
  ext=$(vtu_extent $files)
  umax=${ext% *} box=${ext#* }
  last=$(($(wc -l < "$W/$rs/ring_curve.csv") - 2))
  np=0
  for s in $sel; do
    f=$(printf "step_%03d" "$s")
    imp=$(awk -F, -v s="$s" '$1 == s { printf "%.1f", -$3 }' "$W/$rs/ring_curve.csv")
    "$LAC" render "$W/$rs" --vtu "$f.vtu" --out "$W/$rs/$f-u.png" --field u --scale 1 \
      --edges --az 30 --el 20 --units mm --range "0:$umax" --box "$box" \
      --title "step $s/$last: ends moved down by $imp mm" > /dev/null 2> "$W/render.err" \
      || { fail "lac render $rs --vtu $f.vtu: $(tail -1 "$W/render.err")"; return; }
    np=$((np + 1))
  done
  cols=$(( np <= 2 ? np : np <= 4 ? 2 : 3 ))
  rows=$(( (np + cols - 1) / cols ))
  {
    echo "set terminal pngcairo size $((800 * cols)),$((600 * rows + 60)) font \"DejaVu Sans,16\" enhanced"
    echo "set output '$OUTABS/fig11-ring-$re-u-steps.png'"
    echo "set multiplot layout $rows,$cols title \"ring on block, $re: |u| (mm) on the deformed shape (x1) at $np load steps, one colour range ($(val "$rs" dofs) dofs)\" margins 0,1,0,$(awk -v h=$((600 * rows + 60)) 'BEGIN { printf "%.4f", 1 - 60 / h }') spacing 0,0"
    echo 'unset border; unset tics; unset key; set size ratio -1'
    echo 'set xrange [0:799]; set yrange [0:599]'
    for s in $sel; do
      printf "plot '%s/step_%03d-u.png' binary filetype=png with rgbimage\n" "$rs" "$s"
    done
    echo 'unset multiplot'
  } > "$W/ring-u-steps.gp"
  gp ring-u-steps
}
if want 10; then
t=$(date +%s)
if [ ! -f $RING ]; then
  say "ring scene not available: fig10/fig11 not regenerated"
else
  # shellcheck disable=SC2086
  [ -n "$ring_pids" ] && wait $ring_pids
  ok=
  for m in $RING_MESHES; do
    n=ring-${m%:*}-${m#*:}
    if [ "$(cat "$W/$n.rc" 2> /dev/null)" = 0 ] && [ -f "$W/$n/ring_curve.csv" ]; then
      ok="$ok $m"
    else
      say "ring $m failed: $(tail -1 "$W/$n.err")"
    fi
  done
  if [ -z "$ok" ]; then
    fail "ring scene failed: fig10/fig11 not regenerated"
  else
    # Figure 10: u_z of ring_mid against the imposed displacement, one
    # panel per level (coarse, fine) present
    levels=$(for m in $ok; do echo "${m#*:}"; done | sort -u)
    nl=$(echo "$levels" | wc -l)
    {
      echo "$GPTERM" | sed "s/size 900,620/size $((700 * nl + 200)),620/"
      echo "set output '$OUTABS/fig10-ring-center-displacement.png'"
      echo "set multiplot layout 1,$nl title \"ring on block: vertical displacement of the middle of the half-ring (inner bottom point)\" font \",14\""
      echo 'set grid; set key bottom left; set yrange [-30:0]'
      echo 'set xlabel "imposed displacement of the ring'"'"'s ends (mm, downwards)"'
      echo 'set ylabel "displacement of the middle of the ring, u_z (mm)"'
      for l in $levels; do
        [ "$l" = 0 ] && echo 'set title "coarse meshes"' || echo "set title \"fine meshes (level $l)\""
        printf 'plot '
        sep=
        for m in $ok; do
          [ "${m#*:}" = "$l" ] || continue
          e=${m%:*}
          st=$(($(wc -l < "$W/ring-$e-$l/ring_curve.csv") - 2))
          printf "%s'ring-%s-%s/ring_curve.csv' using (-\$3):6 every ::1 with linespoints lw 2 pt %s ps 0.8 lc rgb \"%s\" title \"%s (%s dofs, %s steps)\"" \
            "$sep" "$e" "$l" "$(case $e in hex8) echo 5 ;; hex20) echo 7 ;; *) echo 9 ;; esac)" \
            "$(case $e in hex8) echo '#3b528b' ;; hex20) echo '#21918c' ;; *) echo '#e08000' ;; esac)" \
            "$e" "$(val "ring-$e-$l" dofs)" "$st"
          sep=', '
        done
        echo
      done
      echo 'set datafile separator ","'
      echo 'unset multiplot'
    } > "$W/ring-curve.gp"
    # the CSV files: comma separated, read with the separator set first
    sed -i '1a set datafile separator ","' "$W/ring-curve.gp"
    gp ring-curve
    # the 2 % criterion [experiments issue]: coarse against the finest
    # level of the same element, at the imposed displacements both have
    for e in $(for m in $ok; do echo "${m%:*}"; done | sort -u); do
      fine=$(for m in $ok; do [ "${m%:*}" = "$e" ] && echo "${m#*:}"; done | sort -n | tail -1)
      [ "$fine" != 0 ] && echo "$ok " | grep -q " $e:0 " || continue
      awk -F, -v e="$e" -v l="$fine" '
        FNR == 1 { next }
        FILENAME == ARGV[1] { c[sprintf ("%.6f", $3)] = $6; next }
        { k = sprintf ("%.6f", $3); if (!(k in c) || $3 == 0) next
          d = 100 * ($6 - c[k]) / ($3 < 0 ? -$3 : $3); if (d < 0) d = -d
          if (d > w) { w = d; at = -$3 }; n++ }
        END { printf "%s level 0 / level %d: %d common load steps, largest difference %.3f %% of the imposed displacement (at %.2f mm; criterion < 2 %%)\n", e, l, n, w, at }' \
        "$W/ring-$e-0/ring_curve.csv" "$W/ring-$e-$fine/ring_curve.csv"
    done > "$W/ring-coarse-fine.txt"
    while read -r line; do say "fig10: $line"; done < "$W/ring-coarse-fine.txt"

    # Figure 11: hex20 if it ran, else the first mesh: the deformed shape
    # at the last step and the contact pressure at four load steps
    m=$(for x in $ok; do echo "$x"; done | grep '^hex20:0$' || true)
    [ -n "$m" ] || m=$(for x in $ok; do echo "$x"; break; done)
    e=${m%:*}; l=${m#*:}; n=ring-$e-$l
    render "$n" "fig11-ring-$e-u.png" --field u --scale 1 --edges --az 30 --el 20 --units mm \
      --title "ring on block, $e: |u| at the last step (x1, $(val "$n" dofs) dofs)"
    # |u| at several load steps: the step files of steps.pvd (a step
    # closer than K/2 to the last is left out: 15, 30, 45, 61), drawn with
    # one colour range, assembled by gnuplot (2 x 2)
    ring_steps_figure "$n" "$e"
    # four steps spread over the crushing (from the first with contact)
    steps=$(awk -F, 'NR > 2 && $11 > 0 { s[++n] = $1 }
                     END { if (n == 0) exit; for (k = 1; k <= 4; k++) { i = int(1 + (n - 1) * k / 4 + 0.5); if (i < 1) i = 1; printf "%d ", s[i] } }' \
            "$W/$n/ring_curve.csv" | tr ' ' '\n' | sort -nu | tr '\n' ' ')
    pmax=$(awk -F, 'NR > 1 && $8 == 1 && -$6 > p { p = -$6 } END { print (p > 0 ? p : 1) }' "$W/$n/contact_steps.csv")
    {
      echo "$GPTERM" | sed 's/size 900,620/size 1400,900/'
      echo "set output '$OUTABS/fig11-ring-$e-pressure.png'"
      echo "set multiplot layout 2,2 title \"ring on block, $e: contact pressure -{/Symbol l} per macro-element on the block, at four load steps\" font \",14\""
      echo 'set datafile separator ","'
      echo 'set palette viridis' | sed 's/.*/set palette defined (0 "#440154", 0.25 "#3b528b", 0.5 "#21918c", 0.75 "#5ec962", 1 "#fde725")/'
      echo "set cbrange [0:$pmax]; set cblabel \"-{/Symbol l} (MPa)\""
      echo 'set xlabel "x along the block (mm)"; set ylabel "y, depth (mm)"'
      echo 'set xrange [0:*]; set yrange [0:25]; set grid'
      for s in $steps; do
        imp=$(awk -F, -v s="$s" '$1 == s { printf "%.1f", -$3 }' "$W/$n/ring_curve.csv")
        echo "set title \"step $s: imposed displacement $imp mm\""
        echo "plot '$n/contact_steps.csv' using 3:(\$1 == $s && \$8 == 1 ? \$4 : 1/0):(-\$6) with points pt 5 ps 2.2 palette notitle"
      done
      echo 'unset multiplot'
    } > "$W/ring-pressure.gp"
    gp ring-pressure
    {
      echo "$GPTERM"
      echo "set output '$OUTABS/fig11-ring-$e-pressure-x.png'"
      echo "set title \"ring on block, $e: contact pressure against x (every macro-element, all depths)\""
      echo 'set datafile separator ","'
      echo 'set grid; set key top left'
      echo 'set xlabel "x along the block (mm)"; set ylabel "contact pressure -{/Symbol l} (MPa)"'
      printf 'plot '
      sep=
      k=0
      for s in $steps; do
        k=$((k + 1))
        imp=$(awk -F, -v s="$s" '$1 == s { printf "%.1f", -$3 }' "$W/$n/ring_curve.csv")
        c=$(echo '#440154 #3b528b #21918c #5ec962' | cut -d' ' -f$k)
        printf "%s'%s/contact_steps.csv' using (\$1 == %s && \$8 == 1 ? \$3 : 1/0):(-\$6) with points pt 7 ps 0.9 lc rgb \"%s\" title \"step %s (%s mm)\"" "$sep" "$n" "$s" "$c" "$s" "$imp"
        sep=', '
      done
      echo
    } > "$W/ring-pressure-x.gp"
    gp ring-pressure-x
  fi
fi
say "fig10-11 ($(since "$t") s)"
fi

# ---- Figure 13 (chapter 06): five bodies, six contact pairs -------------
if want 13; then
t=$(date +%s)
B6=chapters/06-assembly/blocks.scene
if frun blocks $B6 --set level=$LB --edges \
     --title "five blocks, six pairs: lambda on the slave sub-facets" \
     --label lambda --units MPa --draw lambda "$OUT/fig13-blocks-quad4-lambda.png" \
   && run blocks-run $B6 --set level=$LB; then
  render blocks-run fig13-blocks-quad4-von-mises.png --field von_mises --edges \
    --units MPa --scale 5 \
    --title "five blocks, six contact pairs (quad4): von Mises, deformed x5"
fi
say "fig13 ($(since "$t") s)"
fi

# ---- Figure 15 (chapter 15): Cattaneo-Mindlin, partial slip -------------
# (the table of the three ratios in cattaneo.txt; the picture at 0.6, drawn
# by lac render --contact --compare --srange)
if want 15; then
t=$(date +%s)
LC=3; [ $QUICK = 1 ] && LC=0
FIG="$OUT/fig15-cattaneo-traction.png" \
  sh chapters/15-friction/cattaneo.sh "$B" "$LC" "0.3 0.6 0.9" \
  > "$W/cattaneo.txt" 2> "$W/cattaneo.err" \
  || fail "chapters/15-friction/cattaneo.sh: $(tail -1 "$W/cattaneo.err")"
say "fig15 ($(since "$t") s)"
fi

# ---- Figure 16 (chapter 16): a compound ring, two pairs, a roller -------
if want 16; then
t=$(date +%s)
C16=chapters/16-setups/compound.scene
LR=1; [ $QUICK = 1 ] && LR=0
if frun compound $C16 --set level=$LR --edges \
     --title "compound ring, two pairs: lambda on the slave sub-facets" \
     --label lambda --units MPa --draw lambda "$OUT/fig16-compound-lambda.png" \
   && run compound-run $C16 --set level=$LR; then
  render compound-run fig16-compound-von-mises.png --field von_mises --edges \
    --units MPa --scale 200 \
    --title "compound ring (quad8): von Mises, deformed x200"
fi
say "fig16 ($(since "$t") s)"
fi

# ---- the accuracy-cost study (chapter 12) ----------------------------------
if [ $BENCH = 1 ]; then
  t=$(date +%s)
  sh bench/accuracy-cost.sh "$B" --out "$OUT" || fail "bench/accuracy-cost.sh"
  say "accuracy-cost ($(since "$t") s)"
fi

say "done in $(since "$T0") s, PNGs in $OUT/ (work files in $W/)"
exit $failed
