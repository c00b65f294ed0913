# tests/cases-steps.sh -- load steps and load curves in small strain
#                         (sourced by tests/run.sh)  [LAC §4.5, Alg. 1]
#
# Checked through `lac run` (chapter 16, section 6):
#   - frictionless small strain has no memory: chapter 07's cylinder on a
#     flat pressed in 10 steps, the 3D patch test of chapter 08 and the
#     manufactured solution of chapter 09 (non-zero Dirichlet values on
#     the contact surface: its mean gaps change with them) in 5, end with
#     every summary number of one step to 1e-10 (relative, or absolute for
#     the errors at the level of rounding); a scene without [steps] writes
#     no curve and says nothing of steps;
#   - a load curve up and down (0 -> 1 -> 0) on the cylinder ends with
#     u = 0 and no active multiplier, after the contact zone grew to two
#     macro-elements; curve.csv's imposed column is f(t) times the value
#     at the steps (t = 0.5 and 1.5: half of it); contact_steps.csv has
#     every multiplier at every step; vtu_every writes the step files
#     and steps.pvd;
#   - two curves at once (the stacked blocks on rollers: the bottom
#     roller's u.n on one curve, the top pressure on another) end where
#     one step with the values at the end ends; a plate (total_force,
#     plate = yes) in 7 steps ends where one step ends;
#   - K stays factorized across the steps: with schur the whole run makes
#     one factorization, for 1 step and for 20; with petsc (K assembled
#     from the cells, none on this process) the right-hand sides of the
#     curves come from the cells, the same answer to 1e-8;
#   - bad input: a curve of an odd count of numbers, decreasing or equal
#     times, a non-number, an infinite number, end <= 0, start >= end, a
#     curve without [steps], a curve or end != 1 with large_deformation,
#     a Newton key of large deformation, [steps] without [contact], ramp
#     and curve together, two curves at a node with a frame: exit status
#     1, one line naming the section, key (and line), the earlier files
#     of the output directory byte-identical.
# Same conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
C="$B/cases-steps"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

steps_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
steps_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
steps_value () { sed -n "s/^$2 = //p" "$1"; }
# the summary without the lines that count steps and iterations (and the
# Krylov iterations and residual of petsc)
steps_numbers () {
  grep -v -e '^effects' -e '^newton_iterations' -e '^load_steps' \
    -e '^max_iterations_per_step' -e '^factorizations' -e '^monitor_' \
    -e '^solver_iterations' -e '^solver_residual' "$1"
}

CYL=chapters/07-newton/cylinder-flat.scene
sed "s|^file = cylinder-flat.geo|file = $PWD/chapters/07-newton/cylinder-flat.geo|" \
  "$CYL" > "$C/cylinder.scene"

# steps_same NAME SCENE ARGS_A ARGS_B N: the two runs' summaries agree to
# 1e-10 (STEPS_TOL), the second in N load steps
steps_same () {
  name=$1; scene=$2; a=$3; b=$4; tol=${STEPS_TOL:-1e-10}
  # shellcheck disable=SC2086
  if env "ASAN_OPTIONS=${ASAN_OPTIONS:-}${STEPS_ASAN:-}" "$LAC" run "$scene" $a \
       --no-output > "$C/$name-a.out" 2> "$C/$name-a.err" \
     && env "ASAN_OPTIONS=${ASAN_OPTIONS:-}${STEPS_ASAN:-}" "$LAC" run "$scene" $b \
       --no-output > "$C/$name-b.out" 2> "$C/$name-b.err"; then
    steps_numbers "$C/$name-a.out" > "$C/$name-a.num"
    steps_numbers "$C/$name-b.out" > "$C/$name-b.num"
    n=$(steps_value "$C/$name-b.out" load_steps)
    if [ "$n" = "$5" ] && "$B/tests/numcmp" --rtol "$tol" --atol "$tol" \
         "$C/$name-a.num" "$C/$name-b.num" > "$C/$name.cmp" 2>&1; then
      steps_ok "$name"
    else
      steps_fail "$name" "load_steps = $n (want $5); $(head -3 "$C/$name.cmp")"
    fi
  else
    steps_fail "$name" "lac run failed: $(tail -1 "$C/$name-a.err") $(tail -1 "$C/$name-b.err")"
  fi
}

# ---- no memory: one step or many ---------------------------------------------
steps_same cylinder-1-10 "$C/cylinder.scene" "" "--set steps.n=10" 10
steps_same cylinder-steps-1-10 "$C/cylinder.scene" "--set steps.n=1" "--set steps.n=10" 10
steps_same taylor3d-1-5 chapters/08-experiments/taylor3d.scene "--set steps.n=1" "--set steps.n=5" 5
# the manufactured solution of chapter 09: Dirichlet values (exact = yes)
# at the ends of the contact surface, moved into its mean gaps each step
steps_same manufactured2d-5 chapters/09-spheres-rates/manufactured2d.scene "" "--set steps.n=5" 5

# without [steps]: no steps, no curve
if "$LAC" run "$C/cylinder.scene" --quiet --out "$C/plain" > "$C/plain.out" 2> "$C/plain.err" \
   && [ ! -e "$C/plain/curve.csv" ] && ! grep -q -e 'load_steps' -e 'load steps' "$C/plain.out"; then
  steps_ok plain-no-steps
else
  steps_fail plain-no-steps "a scene without [steps] wrote curve.csv or a line about steps"
fi

# ---- up and down --------------------------------------------------------------
if "$LAC" run "$C/cylinder.scene" --set steps.n=20 --set steps.end=2 \
     --set "dirichlet.top.curve=0 0 1 1 2 0" --set steps.vtu_every=5 \
     --out "$C/updown" > "$C/updown.out" 2> "$C/updown.err"; then
  u=$(steps_value "$C/updown.out" max_u); a=$(steps_value "$C/updown.out" active)
  peak=$(awk -F, 'NR > 2 && $10 > m { m = $10 } END { print m + 0 }' "$C/updown/curve.csv")
  rows=$(awk 'END { print NR }' "$C/updown/curve.csv")
  imp=$(awk -F, '$1 == 5 || $1 == 10 || $1 == 15 || $1 == 20 { printf "%s ", $3 }' "$C/updown/curve.csv")
  ms=$(awk -F, 'NR > 1 { n[$1]++ } END { m = 99; for (s in n) if (n[s] < m) m = n[s]; print length(n), m }' \
       "$C/updown/contact_steps.csv")
  files=$(ls "$C/updown" | grep -c '^step_0[0-9][0-9]\.vtu$')
  if awk -v u="$u" -v a="$a" -v p="$peak" -v r="$rows" -v i="$imp" -v m="$ms" -v f="$files" 'BEGIN {
       split(i, v, " "); split(m, w, " ")
       exit !(u != "" && u <= 1e-12 * 0.2 && a == 0 && p == 2 && r == 22 \
              && (v[1] + 0.1) ^ 2 < 1e-24 && (v[2] + 0.2) ^ 2 < 1e-24 \
              && (v[3] + 0.1) ^ 2 < 1e-24 && v[4] == 0 \
              && w[1] == 20 && w[2] == 8 && f == 4) }' \
     && grep -c 'file="step_0' "$C/updown/steps.pvd" | grep -qx 4; then
    steps_ok updown
  else
    steps_fail updown "max_u = $u, active = $a (want 0, 0), peak active $peak (want 2), $rows rows, imposed at t = 0.5 1 1.5 2: $imp, contact_steps: $ms, $files step files"
  fi
else
  steps_fail updown "lac run failed: $(tail -1 "$C/updown.err")"
fi

# ---- two curves; a rigid plate -----------------------------------------------
ROT="$C/rotated.scene"
sed "s|^file = stacked2d-rotated.geo|file = $PWD/tests/meshes/stacked2d-rotated.geo|" \
  tests/meshes/stacked2d-rotated.scene > "$ROT"
steps_same two-curves "$ROT" "--set dirichlet.bottom.normal=0.02" \
  "--set steps.n=4 --set steps.end=2 --set dirichlet.bottom.normal=0.01 --set dirichlet.bottom.curve=0,0,1,2 --set load.top.curve=0,0,1,0,2,1" 4
T=chapters/08-experiments
sed "s|^file = taylor2d.geo|file = $PWD/$T/taylor2d.geo|; s|^pressure = 25|total_force = 0 -1250\nplate = yes|" \
  "$T/taylor2d.scene" > "$C/plate.scene"
steps_same plate "$C/plate.scene" "" "--set steps.n=7" 7

# ---- K assembled from the cells (petsc): b of each curve without K ----------
"$LAC" run "$C/cylinder.scene" --strategy petsc --quiet --no-output > /dev/null 2> "$C/petsc.err"
if ! grep -q "built without PETSc" "$C/petsc.err"; then
  STEPS_TOL=1e-8 STEPS_ASAN="${LAC_MPI_ASAN:-}" steps_same petsc-cells "$C/cylinder.scene" \
    "--strategy petsc" "--strategy petsc --set steps.n=5 --set dirichlet.top.curve=0,0,1,0.5,2,1 --set steps.end=2" 5
  grep -q "the solver assembles it from the cells" "$C/petsc-cells-b.err" \
    || steps_fail petsc-cells-digest "stage 4 made K: $(grep assemble "$C/petsc-cells-b.err")"
fi

# ---- the factorization of K is kept ------------------------------------------
f1=$("$LAC" run "$C/cylinder.scene" --set level=1 --set contact.flat.strategy=schur \
      --set steps.n=1 --quiet --no-output 2> "$C/schur1.err" | sed -n 's/^factorizations = //p')
f20=$("$LAC" run "$C/cylinder.scene" --set level=1 --set contact.flat.strategy=schur \
       --set steps.n=20 --quiet --no-output 2> "$C/schur20.err" | sed -n 's/^factorizations = //p')
if [ "$f1" = 1 ] && [ "$f20" = 1 ]; then
  steps_ok schur-one-factorization
else
  steps_fail schur-one-factorization "factorizations: ${f1:-none} for 1 step, ${f20:-none} for 20 (want 1 and 1)"
fi

# ---- bad input -----------------------------------------------------------------
# an earlier run's files, which a failed run must leave as they are
"$LAC" run "$C/cylinder.scene" --quiet --out "$C/keep" > /dev/null 2>&1
cksum "$C"/keep/* > "$C/keep.sum" 2>&1
steps_bad () {
  name=$1; words=$2; scene=$3; shift 3
  "$LAC" run "$scene" --out "$C/keep" --quiet "$@" > "$C/bad-$name.out" 2> "$C/bad-$name.err"
  rc=$?; nl=$(wc -l < "$C/bad-$name.err"); msg=""
  if [ "$rc" -ne 1 ]; then msg="exit status $rc"; elif [ "$nl" -ne 1 ]; then msg="$nl lines"; fi
  old_ifs=$IFS; IFS='|'
  for w in $words; do
    [ -z "$msg" ] && ! grep -qF -- "$w" "$C/bad-$name.err" && msg="message lacks '$w'"
  done
  IFS=$old_ifs
  cksum "$C"/keep/* 2>&1 | cmp -s - "$C/keep.sum" || msg="${msg:-the earlier files changed}"
  if [ -z "$msg" ]; then steps_ok "bad-$name"; else steps_fail "bad-$name" "$msg: $(head -2 "$C/bad-$name.err")"; fi
}
S="$C/cylinder.scene"
steps_bad odd-count "--set|[dirichlet top] curve = '0 0 1'|pairs t f: 3 numbers" "$S" --set steps.n=2 --set "dirichlet.top.curve=0 0 1"
steps_bad decreasing "[dirichlet top] curve|must increase: t = 0.5 (pair 3) after t = 1" "$S" --set steps.n=2 --set "dirichlet.top.curve=0 0 1 1 0.5 2"
steps_bad equal-times "[dirichlet top] curve|must increase: t = 1 (pair 2) after t = 1" "$S" --set steps.n=2 --set "dirichlet.top.curve=1 0 1 1"
steps_bad not-a-number "[load top] curve = '0 0 1 one'|number 4, 'one'|not a decimal number" "$C/plate.scene" --set steps.n=2 --set "load.top.curve=0 0 1 one"
steps_bad infinite "[dirichlet top] curve|magnitude at most" "$S" --set steps.n=2 --set "dirichlet.top.curve=0 0 1 1e999"
steps_bad end-zero "[steps] end = '0'|a number > 0" "$S" --set steps.end=0
steps_bad end-negative "[steps] end = '-2'|a number > 0" "$S" --set steps.end=-2
steps_bad start-end "[steps] start = '3'|below end = 2" "$S" --set steps.end=2 --set steps.start=3
steps_bad no-steps "[dirichlet top] curve|give [steps]" "$S" --set "dirichlet.top.curve=0 0 1 1"
steps_bad newton-key "[steps] maxit = '5'|[contact] max_iterations" "$S" --set steps.maxit=5
steps_bad ramp-and-curve "[dirichlet top] ramp|either ramp or curve" "$S" --set steps.n=2 --set dirichlet.top.ramp=no --set "dirichlet.top.curve=0 0 1 1"
sed '/^\[contact/,$d' "$S" > "$C/no-contact.scene"
printf '[steps]\nn = 2\n' >> "$C/no-contact.scene"
steps_bad no-contact "no-contact.scene:|[steps]|need [contact]" "$C/no-contact.scene"
steps_bad frame-curves "[dirichlet bottom]|[dirichlet lower_left]|different load curves|a node with a frame" \
  "$ROT" --set steps.n=2 --set dirichlet.bottom.normal=0.01 --set dirichlet.lower_left.normal=0.001 --set "dirichlet.bottom.curve=0 0 1 2"
RING=chapters/10-large-deformation/ring.scene
steps_bad ld-curve "[dirichlet block_x0] curve|with large_deformation|small-strain scenes" "$RING" --set "dirichlet.block_x0.curve=0 0 1 1"
steps_bad ld-end "[steps] end = '2'|ends at 1" "$RING" --set steps.end=2
