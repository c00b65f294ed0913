# tests/cases-loads.sh -- total forces, rigid plates, point forces
# (sourced by tests/run.sh; same conventions as tests/cases.sh)
#
#   point_force: the cantilever of tests/loads/beam.scene, P = (0, -1) at
#     the tip: the work of the loads is -P u_y(tip) to 1e-10 (the force
#     acts at that node alone), and u_y(tip) is within 3 % of beam theory
#     with shear (P L^3 / (3 E' I) + P L / (kappa G A), plane strain);
#   total_force: the Taylor patch test loaded by total_force = (0, -1250)
#     on its top instead of pressure = 25: the same exact solution
#     (max_rel_err_lambda <= 1e-12), contact_force = -1250 to 1e-10;
#   plate = yes: the same force through a rigid plate: contact_force =
#     -1250 to 1e-10, every top node moves by the same u (to 1e-12), the
#     plate's u_x = 0 (the symmetry plane at its left end holds the whole
#     plate), lambda no longer uniform (the plate holds the top's lateral
#     expansion);
#   bad input: one line naming the file, the line and the group.

B=${B:-build}
C="$B/cases-loads"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"
loads_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
loads_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
loads_value () { sed -n "s/^$2 = //p" "$1"; }

# 1. point force at the tip of the cantilever
if "$LAC" run tests/loads/beam.scene --out "$C/beam" --quiet > "$C/beam.out" 2> "$C/beam.err"; then
  w=$(loads_value "$C/beam.out" load_work)
  uy=$(awk -F, 'NR > 1 && $2 > 9.99999 && $3 > 0.99999 { print $6 }' "$C/beam/nodes.csv")
  if awk -v w="$w" -v u="$uy" 'BEGIN { E = 1000 / (1 - 0.09); I = 1 / 12; G = 1000 / 2.6
       d = 1000 / (3 * E * I) + 10 / (5 / 6 * G)
       exit !(u != "" && (w + u) ^ 2 <= (1e-10 * w) ^ 2 && (-u - d) ^ 2 <= (0.03 * d) ^ 2) }'; then
    loads_ok point-force
  else
    loads_fail point-force "load_work = $w, u_y(tip) = $uy (want -load_work, and beam theory within 3 %)"
  fi
else
  loads_fail point-force "lac run failed: $(tail -1 "$C/beam.err")"
fi

# 2. and 3. the Taylor patch test under a total force, spread or by a plate
T=chapters/08-experiments
sed "s|^file = taylor2d.geo|file = $PWD/$T/taylor2d.geo|; s|^pressure = 25|total_force = 0 -1250|" \
  "$T/taylor2d.scene" > "$C/total.scene"
sed "s|^file = taylor2d.geo|file = $PWD/$T/taylor2d.geo|; s|^pressure = 25|total_force = 0 -1250\nplate = yes|" \
  "$T/taylor2d.scene" > "$C/plate.scene"
for e in quad8 tri6; do
  if "$LAC" run "$C/total.scene" --set element=$e --quiet --no-output > "$C/total-$e.out" 2> "$C/total-$e.err"; then
    el=$(loads_value "$C/total-$e.out" max_rel_err_lambda); f=$(loads_value "$C/total-$e.out" contact_force)
    if awk -v a="$el" -v f="$f" 'BEGIN { exit !(a != "" && a <= 1e-12 && (f + 1250) ^ 2 <= (1.25e-7) ^ 2) }'; then
      loads_ok "total-force-$e"
    else
      loads_fail "total-force-$e" "max_rel_err_lambda = $el (want <= 1e-12), contact_force = $f (want -1250)"
    fi
  else
    loads_fail "total-force-$e" "lac run failed: $(tail -1 "$C/total-$e.err")"
  fi
  if "$LAC" run "$C/plate.scene" --set element=$e --out "$C/plate-$e" > "$C/plate-$e.out" 2> "$C/plate-$e.err"; then
    el=$(loads_value "$C/plate-$e.out" max_rel_err_lambda); f=$(loads_value "$C/plate-$e.out" contact_force)
    spread=$(awk -F, 'NR > 1 && $3 > 99.99999 { n++; if (n == 1) { x = $5; y = $6 }
             d = ($5 - x) ^ 2 + ($6 - y) ^ 2 + x * x; if (d > m) m = d; s = y }
             END { printf "%.3g %d %.17g", sqrt(m) / (s < 0 ? -s : s), n, s }' "$C/plate-$e/nodes.csv")
    if awk -v a="$el" -v f="$f" -v s="$spread" 'BEGIN { split(s, v, " ")
         exit !(a > 1e-3 && (f + 1250) ^ 2 <= (1.25e-7) ^ 2 && v[1] <= 1e-12 && v[2] >= 5 && v[3] < 0) }' \
       && grep -q 'tied to 1 rigid plates' "$C/plate-$e.err"; then
      loads_ok "plate-$e"
    else
      loads_fail "plate-$e" "contact_force = $f (want -1250), top nodes: spread, count, u_y = $spread, max_rel_err_lambda = $el (want > 1e-3)"
    fi
  else
    loads_fail "plate-$e" "lac run failed: $(tail -1 "$C/plate-$e.err")"
  fi
done

# 4. bad input: exit status 1, one line on stderr with every word
loads_bad () {
  name=$1; words=$2; scene=$3; shift 3
  "$LAC" run "$scene" --no-output --quiet "$@" > "$C/bad-$name.out" 2> "$C/bad-$name.err"
  rc=$?; nl=$(wc -l < "$C/bad-$name.err"); msg=""
  if [ "$rc" -ne 1 ]; then msg="exit status $rc"; elif [ "$nl" -ne 1 ]; then msg="$nl lines"; fi
  old_ifs=$IFS; IFS='|'
  for w in $words; do
    [ -z "$msg" ] && ! grep -qF -- "$w" "$C/bad-$name.err" && msg="message lacks '$w'"
  done
  IFS=$old_ifs
  if [ -z "$msg" ]; then loads_ok "bad-$name"; else loads_fail "bad-$name" "$msg: $(head -2 "$C/bad-$name.err")"; fi
}
BEAM=tests/loads/beam.scene
sed "s|^file = beam.geo|file = $PWD/tests/loads/beam.geo|; s|^group = tip|group = nope|" $BEAM > "$C/beam-nope.scene"
loads_bad unknown-group "beam-nope.scene:21:|[load tip] group = 'nope'|no physical group|tip" "$C/beam-nope.scene"
loads_bad point-on-curve "--set|group = 'right'|dimension 1|point_force (a point group)|dimension 0" $BEAM --set load.tip.group=right
loads_bad point-two-nodes "--set|group = 'ends'|a point group of 2 nodes|one point" $BEAM --set load.tip.group=ends
loads_bad point-3-numbers "--set|point_force|expected 2 numbers" $BEAM --set "load.tip.point_force=0 -1 0"
sed "s|^file = beam.geo|file = $PWD/tests/loads/beam.geo|; s|^point_force = 0 -1|total_force = 0 -1|" \
  $BEAM > "$C/beam-total.scene"
loads_bad total-on-volume "--set|group = 'body'|dimension 2|total_force (a boundary group|dimension 1" \
  "$C/beam-total.scene" --set load.tip.group=body
loads_bad total-on-point "beam-total.scene:21:|group = 'tip'|dimension 0|total_force (a boundary group" \
  "$C/beam-total.scene"
loads_bad two-kinds "beam.scene:20:|[load tip]|exactly one of|total_force, point_force" $BEAM --set "load.tip.total_force=0 -1"
loads_bad plate-alone "--set|[load tip] plate|give total_force" $BEAM --set load.tip.plate=yes
sed "s|^file = taylor2d.geo|file = $PWD/$T/taylor2d.geo|; s|^pressure = 25|total_force = 0 -1250\nplate = yes|; s|^group = upper_top|group = upper_bottom|" \
  "$T/taylor2d.scene" > "$C/plate-contact.scene"
loads_bad plate-on-contact "plate-contact.scene|[load top] group = 'upper_bottom'|rigid plate on a contact surface" "$C/plate-contact.scene"

# 5. several mesh files, one per body: tests/meshes/taylor-two-files.scene
# (the Taylor patch test, each square from its own .geo) is as exact as the
# one-file scene and has its nodes and cells; a group defined by two files,
# a file that does not open and a broken second file are one-line errors
# naming the files.
for e in quad4 tri6 quad8; do
  if "$LAC" run tests/meshes/taylor-two-files.scene --set element=$e --quiet --no-output \
       > "$C/two-$e.out" 2> "$C/two-$e.err" \
     && "$LAC" run chapters/08-experiments/taylor2d.scene --set element=$e --quiet --no-output \
       > "$C/one-$e.out" 2> "$C/one-$e.err"; then
    el=$(loads_value "$C/two-$e.out" max_rel_err_lambda)
    if awk -v a="$el" 'BEGIN { exit !(a != "" && a <= 1e-12) }' \
       && [ "$(loads_value "$C/two-$e.out" nodes)" = "$(loads_value "$C/one-$e.out" nodes)" ] \
       && [ "$(loads_value "$C/two-$e.out" cells)" = "$(loads_value "$C/one-$e.out" cells)" ]; then
      loads_ok "two-files-$e"
    else
      loads_fail "two-files-$e" "max_rel_err_lambda = $el; nodes/cells differ from taylor2d.scene's"
    fi
  else
    loads_fail "two-files-$e" "lac run failed: $(tail -1 "$C/two-$e.err" "$C/one-$e.err")"
  fi
done
TWO=tests/meshes/taylor-two-files.scene
loads_bad same-group "--set|group 'upper_bottom'|defined in 'taylor-upper.geo' and in '$PWD/chapters/08-experiments/taylor2d.geo'|distinct group names" \
  $TWO --set "mesh.file=taylor-upper.geo $PWD/chapters/08-experiments/taylor2d.geo"
loads_bad second-missing "--set|[mesh] file|tests/meshes/nothere.geo: cannot open" $TWO --set "mesh.file=taylor-upper.geo nothere.geo"
loads_bad second-broken "--set|[mesh] file|garbage.msh: " $TWO --set "mesh.file=taylor-upper.geo garbage.msh"

# 6. rollers whose face is not one flat face (tests/meshes/turned-*,
# ring-rollers.*, quarter-ring.*).  A roller group over a corner gets a
# condition per side there: the turned square and the turned cube (edges,
# a vertex) are exact, u at every node and von Mises to 1e-10, in one
# section and in one per side; the quarter ring's cuts and outer arc in
# one group give Lame's ring, as three sections do.  A roller on an arc
# leaves the rotation about its centre free: refused, naming it, on a
# quarter of the circle, on the whole circle, on the circle in four
# sections; four sections with two values where they meet: refused.
#
# loads_exact NAME SCENE ARGS...: u at every node of SCENE's run is the
# exact one (ex: the strains along the turned axes; R: the turning), and
# von Mises at every node is vm, to 1e-10
loads_exact () {
  name=$1 scene=$2
  shift 2
  if ! "$LAC" run "$scene" --quiet --out "$C/$name" "$@" > "$C/$name.out" 2> "$C/$name.err"; then
    loads_fail "$name" "lac run failed: $(tail -1 "$C/$name.err")"
    return
  fi
  if msg=$(awk -F, -v vm="$vm" -v ex="$ex" '
    BEGIN { split(ex, e, " "); pi = atan2(0, -1)
            c = cos(pi / 6); s = sin(pi / 6); c2 = cos(pi / 9); s2 = sin(pi / 9)
            if (length(e) == 2) {                 # 30 degrees about z
              R[1,1] = c; R[1,2] = -s; R[2,1] = s; R[2,2] = c; d = 2
            } else {                              # then 20 degrees about x
              R[1,1] = c; R[1,2] = -s; R[1,3] = 0
              R[2,1] = c2 * s; R[2,2] = c2 * c; R[2,3] = -s2
              R[3,1] = s2 * s; R[3,2] = s2 * c; R[3,3] = c2; d = 3 } }
    FNR == 1 { next }
    { n++; for (i = 1; i <= d; i++) { x[i] = $(1 + i); u[i] = $(4 + i) }
      for (i = 1; i <= d; i++) { xi[i] = 0; for (j = 1; j <= d; j++) xi[i] += R[j,i] * x[j] }
      for (i = 1; i <= d; i++) { w = 0; for (j = 1; j <= d; j++) w += R[i,j] * e[j] * xi[j]
        err = u[i] - w; if (err < 0) err = -err; if (err > eu) eu = err
        if (w < 0) w = -w; if (w > um) um = w }
      err = $NF - vm; if (err < 0) err = -err; if (err > ev) ev = err }
    END { if (n < 20 || eu > 1e-10 * um || ev > 1e-10 * vm) {
            printf "%d nodes, max |u - exact| = %.3g (max |u| %.3g), max |von Mises - %.6g| = %.3g", n, eu, um, vm, ev
            exit 1 } }' "$C/$name/nodes.csv" 2>&1); then
    loads_ok "$name"
  else
    loads_fail "$name" "$msg"
  fi
}
SQ=tests/meshes/turned-square.scene
sed "s|^file = turned-square.geo|file = $PWD/tests/meshes/turned-square.geo|; s|^\[dirichlet held\]|[dirichlet left]|; s|^group = held|group = left\nnormal = 0\n\n[dirichlet bottom]\ngroup = bottom|" \
  $SQ > "$C/square-two.scene"
vm=10.535653752852738 ex="-1.3e-3 -1.43e-2"          # sqrt(111); plane strain
for e in quad4 tri6 quad8; do
  loads_exact "roller-corner-$e" $SQ --set element=$e
  loads_exact "roller-corner-two-$e" "$C/square-two.scene" --set element=$e
done
CU=tests/meshes/turned-cube.scene
sed "s|^file = turned-cube.geo|file = $PWD/tests/meshes/turned-cube.geo|; s|^\[dirichlet held\]|[dirichlet x0]|; s|^group = held|group = x0\nnormal = 0\n\n[dirichlet y0]\ngroup = y0\nnormal = 0\n\n[dirichlet z0]\ngroup = z0|" \
  $CU > "$C/cube-three.scene"
vm=17.320508075688775 ex="5e-3 -8e-3 -2.1e-2"         # sqrt(300)
for e in hex8 tet4 hex20; do
  loads_exact "roller-vertex-$e" $CU --set element=$e
done
loads_exact "roller-vertex-three-hex8" "$C/cube-three.scene"

# the quarter ring: one section over a curve with corners = three sections
# = Lame's ring (u_r(a) = 6e-3; level 1: 4.8e-6 from it)
QR=tests/meshes/quarter-ring.scene
sed "s|^file = quarter-ring.geo|file = $PWD/tests/meshes/quarter-ring.geo|; s|^\[dirichlet held\]|[dirichlet cut0]|; s|^group = held|group = cut0\nnormal = 0\n\n[dirichlet outer]\ngroup = outer\nnormal = 0\n\n[dirichlet cut1]\ngroup = cut1|" \
  $QR > "$C/quarter-three.scene"
if "$LAC" run $QR --set mesh.level=1 --quiet --out "$C/quarter-one" > "$C/quarter-one.out" 2> "$C/quarter-one.err" \
   && "$LAC" run "$C/quarter-three.scene" --set mesh.level=1 --quiet --out "$C/quarter-three" > "$C/quarter-three.out" 2> "$C/quarter-three.err"; then
  if msg=$(awk -F, -v u1="$(loads_value "$C/quarter-one.out" max_u)" '
      FNR == 1 { next }
      FILENAME ~ /one/ { a[FNR] = $5; b[FNR] = $6; n++; next }
      { d = $5 - a[FNR]; if (d < 0) d = -d; if (d > e) e = d
        d = $6 - b[FNR]; if (d < 0) d = -d; if (d > e) e = d }
      END { r = (u1 - 6e-3) / 6e-3; if (r < 0) r = -r
            if (n < 20 || e > 1e-10 * u1 || r > 1e-5) {
              printf "max_u = %s (Lame 6e-3, relative %.3g), one section against three: %.3g", u1, r, e; exit 1 } }' \
      "$C/quarter-one/nodes.csv" "$C/quarter-three/nodes.csv" 2>&1); then
    loads_ok roller-arc-corners
  else
    loads_fail roller-arc-corners "$msg"
  fi
else
  loads_fail roller-arc-corners "lac run failed: $(tail -1 "$C/quarter-one.err" "$C/quarter-three.err")"
fi

# a roller on arcs of the ring: the rotation about the centre is free
RR=tests/meshes/ring-rollers.scene
{ sed "s|^file = ring-rollers.geo|file = $PWD/tests/meshes/ring-rollers.geo|; /^\[dirichlet roller\]/,\$d" $RR
  for k in 1 2 3 4; do printf '[dirichlet q%d]\ngroup = outer%d\nnormal = 0\n\n' $k $k; done
  printf '[load twist]\ngroup = inner1\ntraction = -1 1\n'; } > "$C/ring-four.scene"
FREE="body 'ring' is not fixed against rigid motion|free: rotation about (0, 0)|a roller lets a curved face slide along itself"
for e in quad4 quad8; do
  for l in 0 1; do
    loads_bad "roller-quarter-arc-$e-$l" "ring-rollers.scene|$FREE" $RR --set element=$e --set mesh.level=$l
    loads_bad "roller-four-arcs-$e-$l" "ring-four.scene|$FREE" "$C/ring-four.scene" --set element=$e --set mesh.level=$l
  done
  loads_bad "roller-circle-$e" "ring-rollers.scene|$FREE" $RR --set element=$e --set dirichlet.roller.group=outer
done
loads_bad roller-two-values "ring-four.scene:29:|[dirichlet q2] group = 'outer2'|u.n = 0.01|[dirichlet q1] (line 24) imposes 0 on the same face|corner rule" \
  "$C/ring-four.scene" --set dirichlet.q2.normal=0.01
