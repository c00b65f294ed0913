# tests/cases-ring.sh -- the large-deformation run (sourced by tests/run.sh)
#
# The ring on block [LAC §5.4] at CI size: coarse hex8 mesh (ring.geo
# level 0, 2309 nodes after the macro-mesh cut) and 7 load steps instead
# of 61 ([steps] n = 6: the rigid first step to -20 mm, then 6 steps of
# 11.67 mm; the hyperelastic, frictionless solution does not depend on
# the path, and the final state agrees with the 61-step run to 1e-4 mm).
# About a minute on 2 cores.  Checked:
#   - the summary against tests/golden/ring-hex8-ci.out and the curve
#     (load factor, imposed displacement, ring_mid u_z, contact force) of
#     ring_curve.csv against tests/golden/ring-hex8-ci-curve.out (numcmp;
#     the iteration counts are left out of both and only bounded);
#   - the effects line lists large deformation, neo-Hookean material,
#     re-pairing every iteration and load steps, and a linear contact
#     scene still reports small strain and one active-set solve;
#   - bad large-deformation input: one line naming the scene line.
# LAC_GOLDEN_UPDATE=1 rewrites the golden files (check the diff).  Same
# conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
C="$B/cases-ring"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

ring_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
ring_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

# ring_golden GOLDEN ACTUAL NAME TOLERANCE-LINE
ring_golden () {
  if [ -n "$LAC_GOLDEN_UPDATE" ]; then
    { echo "$4"; cat "$2"; } > "$1"
  fi
  if [ ! -f "$1" ]; then
    ring_fail "$3" "no $1"
  elif "$B/tests/numcmp" "$1" "$2" > "$2.cmp" 2>&1; then
    ring_ok "$3"
  else
    ring_fail "$3" "differs from $1: $(head -1 "$2.cmp")"
  fi
}

# 1. the CI run
if "$LAC" run chapters/08-experiments/ring.scene --set element=hex8 \
     --set steps.n=6 --out "$C/run" --quiet > "$C/run.out" 2> "$C/run.err"; then
  ring_ok ring-run
  grep -v -e '^newton_iterations' -e '^max_iterations_per_step' "$C/run.out" \
    > "$C/summary.out"
  ring_golden tests/golden/ring-hex8-ci.out "$C/summary.out" ring-summary \
    "# numcmp: rtol=1e-5 atol=1e-8 int=3"
  awk -F, 'NR > 1 { printf "%s %s %s %s %s\n", $1, $2, $3, $6, $12 }' \
    "$C/run/ring_curve.csv" > "$C/curve.out"
  ring_golden tests/golden/ring-hex8-ci-curve.out "$C/curve.out" ring-curve \
    "# numcmp: rtol=1e-5 atol=1e-6 int=exact"
  it=$(sed -n 's/^max_iterations_per_step = //p' "$C/run.out")
  if [ -n "$it" ] && [ "$it" -le 25 ]; then ring_ok ring-iterations
  else ring_fail ring-iterations "max_iterations_per_step = $it (want <= 25)"; fi
  if grep -q '^effects = .*large deformation, neo-Hookean material, re-pairing every iteration, load steps' "$C/run.out"
  then ring_ok ring-effects
  else ring_fail ring-effects "$(grep '^effects' "$C/run.out")"; fi
  for f in solution.vtu nodes.csv ring_curve.csv contact.csv contact_steps.csv summary.txt; do
    [ -s "$C/run/$f" ] || { ring_fail ring-files "no $f"; f=; break; }
  done
  [ -n "$f" ] && ring_ok ring-files
else
  ring_fail ring-run "lac run failed: $(tail -1 "$C/run.err")"
fi

# 2. a linear contact scene: no Newton loop, one pairing, as before
if "$LAC" run chapters/08-experiments/taylor3d.scene --set element=hex8 \
     --quiet --no-output > "$C/linear.out" 2> "$C/linear.err" \
   && grep -q '^effects = 3D solid, frictionless contact (LAC), small strain, linear elastic material$' "$C/linear.out" \
   && [ "$(sed -n 's/^newton_iterations = //p' "$C/linear.out")" = 1 ]; then
  ring_ok ring-linear-unchanged
else
  ring_fail ring-linear-unchanged "$(tail -1 "$C/linear.err") $(grep '^effects' "$C/linear.out")"
fi

# 3. bad input: exit 1 and one line "lac: FILE:LINE: [section] key ..."
# ring_bad NAME 'EXPECTED TEXT' --set ...
ring_bad () {
  n="$1"; want="$2"; shift 2
  if "$LAC" run chapters/08-experiments/ring.scene "$@" --quiet --no-output \
       > "$C/$n.out" 2> "$C/$n.err"; then
    ring_fail "$n" "accepted"
  elif [ "$(wc -l < "$C/$n.err")" -eq 1 ] && grep -q -- "$want" "$C/$n.err"; then
    ring_ok "$n"
  else
    ring_fail "$n" "want one line with '$want', got: $(cat "$C/$n.err")"
  fi
}
ring_bad ring-bad-law "law = 'neo_hookean': needs \[scene\] large_deformation = yes" \
  --set scene.large_deformation=no --set steps.n=1
ring_bad ring-bad-lawname "law" --set material.inner.law=mooney
ring_bad ring-bad-start "\[steps\] start = '1'" --set steps.start=1
ring_bad ring-bad-monitor "monitor = 'nowhere'" --set steps.monitor=nowhere --set steps.n=1 --set element=hex8
