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
#   - the progress: one line per Newton iteration (as many as the summary's
#     newton_iterations, each with its residual, active count and time)
#     and one per load step with its labelled times;
#   - the effects line lists large deformation, neo-Hookean material,
#     re-pairing every iteration and load steps, and a linear contact
#     scene still reports small strain and one active-set solve;
#   - [steps] vtu_every = 2 (the same run): step_002, 004, 006 and 007.vtu
#     and no other, steps.pvd lists them with the curve's load factors
#     (increasing, the last 1), each file holds its step's displacement
#     (the monitor node's u against the curve), the last one solution.vtu's;
#     lac render --vtu draws a step file;
#   - bad large-deformation input: exit status 1 and one line naming the
#     scene line (vtu_every = -1, abc among them).
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
if "$LAC" run chapters/10-large-deformation/ring.scene --set element=hex8 \
     --set steps.n=6 --set steps.vtu_every=2 --set output.vtu_format=ascii --out "$C/run" \
     > "$C/run.out" 2> "$C/run.err"; then
  ring_ok ring-run
  nit=$(sed -n 's/^newton_iterations = //p' "$C/run.out")
  nline=$(grep -c '^lac: \[5/7\] solve  *step [0-9]*/7 iteration [0-9]*: residual [0-9.e+-]*, [0-9]* status\(es\)\{0,1\} changed, [0-9]*/[0-9]* active.*, [0-9.]* s' "$C/run.err")
  nstep=$(grep -c '^lac: \[5/7\] solve  *step [0-9]*/7: t = .*; assembly [0-9.]* s, pairing [0-9.]* s, factorization [0-9.]* s, solves [0-9.]* s, step [0-9.]* s' "$C/run.err")
  if [ -n "$nit" ] && [ "$nline" = "$nit" ] && [ "$nstep" = 7 ]; then
    ring_ok ring-progress
  else
    ring_fail ring-progress "$nline iteration lines for $nit iterations, $nstep step lines for 7 steps"
  fi
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

# 1b. the step files of vtu_every = 2 (7 steps: 2, 4, 6 and the last, 7)
# vtu_u FILE: the displacement array of a VTU (ASCII: the run above asks
# output.vtu_format = ascii for this reading), "ux uy uz" per node
vtu_u () {
  awk '/<DataArray/ { on = /Name="displacement"/; next } /<\/DataArray>/ { on = 0 } on' "$1"
}
# u_same A B: the two "ux uy uz" lists agree to 1e-9 (same length)
u_same () {
  awk 'NR == FNR { a[FNR] = $0; n = FNR; next }
       { split(a[FNR], v); m = FNR
         for (k = 1; k <= 3; k++) { d = v[k] - $k; if (d < -1e-9 || d > 1e-9) bad = 1 } }
       END { exit (bad || m != n || n == 0) }' "$1" "$2"
}
R="$C/run"
if [ -f "$R/summary.txt" ]; then
  got=$(cd "$R" && ls step_*.vtu 2> /dev/null | tr '\n' ' ')
  if [ "$got" = "step_002.vtu step_004.vtu step_006.vtu step_007.vtu " ]; then ring_ok ring-step-files
  else ring_fail ring-step-files "step files: '$got' (want step_002, 004, 006, 007)"; fi
  # steps.pvd: the same files in order, timestep = the curve's load factor
  sed -n 's/.*timestep="\([^"]*\)".*file="step_0*\([0-9]*\)\.vtu".*/\2 \1/p' \
    "$R/steps.pvd" > "$C/pvd.txt" 2> /dev/null
  if [ "$(cut -d' ' -f1 "$C/pvd.txt" | tr '\n' ' ')" = "2 4 6 7 " ] \
     && awk -F, 'NR == FNR { t[$1] = $2; next }
                 { d = $2 - t[$1]; if (d < -1e-9 || d > 1e-9 || (FNR > 1 && $2 <= p)) bad = 1; p = $2 }
                 END { exit (bad || p != 1) }' "$R/ring_curve.csv" FS=' ' "$C/pvd.txt"; then
    ring_ok ring-step-pvd
  else
    ring_fail ring-step-pvd "steps.pvd: $(tr '\n' ';' < "$C/pvd.txt") (want steps 2 4 6 7, t of ring_curve.csv, increasing to 1)"
  fi
  # the last step file's displacement is solution.vtu's
  vtu_u "$R/solution.vtu" > "$C/u-solution.txt"
  vtu_u "$R/step_007.vtu" > "$C/u-step7.txt"
  if u_same "$C/u-solution.txt" "$C/u-step7.txt"; then ring_ok ring-step-last
  else ring_fail ring-step-last "step_007.vtu's displacement differs from solution.vtu's"; fi
  # each step file holds its own step: the monitor node (found in the
  # last step by its u) has the curve's monitor u at every step
  mon=$(awk -F, '$1 == 7 { print $4, $5, $6 }' "$R/ring_curve.csv" \
        | awk 'NR == FNR { x = $1; y = $2; z = $3; next }
               { if (($1 - x) ^ 2 + ($2 - y) ^ 2 + ($3 - z) ^ 2 < 1e-18) { print FNR; exit } }' \
          - "$C/u-solution.txt")
  bad=
  for s in 2 4 6 7; do
    f=$(printf "%s/step_%03d.vtu" "$R" "$s")
    awk -F, -v s="$s" '$1 == s { print $4, $5, $6 }' "$R/ring_curve.csv" > "$C/mon-$s.txt"
    vtu_u "$f" | sed -n "${mon:-0}p" > "$C/u-mon-$s.txt" 2> /dev/null
    u_same "$C/mon-$s.txt" "$C/u-mon-$s.txt" || bad="$bad $s"
  done
  if [ -n "$mon" ] && [ -z "$bad" ]; then ring_ok ring-step-monitor
  else ring_fail ring-step-monitor "monitor node '${mon}': u differs from ring_curve.csv at steps$bad"; fi
  # lac render --vtu: a picture of a step file, default name STEM-FIELD.png
  if "$LAC" render "$R" --vtu step_004.vtu --field u --scale 1 --range 0:100 \
       > "$C/render.out" 2> "$C/render.err" \
     && [ "$(cat "$C/render.out")" = "$R/step_004-u.png" ] && [ -s "$R/step_004-u.png" ]; then
    ring_ok ring-step-render
  else
    ring_fail ring-step-render "lac render --vtu step_004.vtu: $(cat "$C/render.out" "$C/render.err")"
  fi
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
  "$LAC" run chapters/10-large-deformation/ring.scene "$@" --quiet --no-output \
    > "$C/$n.out" 2> "$C/$n.err"
  rc=$?
  if [ "$rc" -eq 0 ]; then
    ring_fail "$n" "accepted"
  elif [ "$rc" -eq 1 ] && [ "$(wc -l < "$C/$n.err")" -eq 1 ] && grep -q -- "$want" "$C/$n.err"; then
    ring_ok "$n"
  else
    ring_fail "$n" "want exit 1 and one line with '$want', got $rc: $(cat "$C/$n.err")"
  fi
}
ring_bad ring-bad-law "law = 'neo_hookean': needs \[scene\] large_deformation = yes" \
  --set scene.large_deformation=no --set steps.n=1
ring_bad ring-bad-lawname "law" --set material.inner.law=mooney
ring_bad ring-bad-start "\[steps\] start = '1'" --set steps.start=1
ring_bad ring-bad-monitor "monitor = 'nowhere'" --set steps.monitor=nowhere --set steps.n=1 --set element=hex8
ring_bad ring-bad-vtu-every-neg "\[steps\] vtu_every = '-1': expected an integer" --set steps.vtu_every=-1
ring_bad ring-bad-vtu-every-abc "\[steps\] vtu_every = 'abc': expected an integer" --set steps.vtu_every=abc
