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
