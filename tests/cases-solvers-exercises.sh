# tests/cases-solvers-exercises.sh -- the answers of
# chapters/13-solvers-mpi/exercises.md (sourced by tests/run.sh; same
# conventions as tests/cases.sh: $B, pass, fail)   [LAC (17); chapter 13]
#
# At the small sizes of each exercise (the larger ones are for
# bench/solvers.sh), with --strategy / --solver petsc:
#   ex1  the clamped cube without contact, n = 10 and 14 (3993 and 10,125
#        dofs): CG + GAMG takes 17 and 18 iterations (within 2: PETSc's
#        version), true residual <= 1e-10, the same max_u as CHOLMOD to
#        1e-8, and the iterations grow by at most 2 while the dofs grow
#        2.5 times;
#   ex2  the 3D Taylor patch test at n = 10 (7236 dofs), -lac_omega 0.1,
#        1, 10, 100, 1000: 30, 23, 52, 92, 231 iterations (within 15 %),
#        fewest at omega = 1, increasing from 1 on; lambda = -25 to 1e-9
#        for every omega;
#   ex3  the same with BoomerAMG (14) fewer iterations than lac's
#        multigrid (23);
#        fieldsplit 40 (GAMG) and 30 (BoomerAMG) within 15 %; lambda to
#        1e-9.
# Skipped (nothing counted) in a build without PETSc: cases-petsc.sh
# checks that message.  About 15 s.

B=${B:-build}
C="$B/cases-solvers-exercises"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

sx_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
sx_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
sx_value () { sed -n "s/^$2 = //p" "$C/$1.out"; }
SX_ENV="ASAN_OPTIONS=${ASAN_OPTIONS:-}${LAC_MPI_ASAN:-}"

# sx_run NAME ARGS...: lac run into $C/NAME.out; 0 or a FAIL line.
sx_run () {
  sr_name=$1
  shift
  if env "$SX_ENV" "$LAC" run "$@" --quiet --no-output > "$C/$sr_name.out" 2> "$C/$sr_name.err"; then
    return 0
  fi
  sx_fail "$sr_name" "lac run $* failed: $(tail -1 "$C/$sr_name.err")"
  return 1
}

# sx_check NAME CONDITION MESSAGE -v VAR=VALUE...: awk decides; near(x, y)
# is x within 15 % of y.
sx_check () {
  sc_name=$1 sc_cond=$2 sc_msg=$3
  shift 3
  if awk "$@" "function near(x, y) { return x >= 0.85 * y && x <= 1.15 * y }
               BEGIN { exit !($sc_cond) }"; then sx_ok "$sc_name"
  else sx_fail "$sc_name" "$sc_msg"; fi
}

env "$SX_ENV" "$LAC" run chapters/08-experiments/taylor2d.scene --strategy petsc \
  --quiet --no-output > "$C/avail.out" 2> "$C/avail.err"
if ! grep -q "built without PETSc" "$C/avail.err"; then
  # ---- exercise 1: iterations against size ------------------------------
  for n in 10 14; do
    sx_run "ex1-cholmod-$n" bench/cube.scene --set mesh.numbers=n=$n --solver cholmod || continue
    sx_run "ex1-petsc-$n" bench/cube.scene --set mesh.numbers=n=$n --solver petsc || continue
    it=$(sx_value "ex1-petsc-$n" solver_iterations)
    want=$([ $n = 10 ] && echo 17 || echo 18)
    sx_check "ex1 n=$n iterations" "it >= want - 2 && it <= want + 2 && r <= 1e-10 && d <= 1e-8 * m" \
      "n = $n: $it iterations (want $want +- 2), residual $(sx_value "ex1-petsc-$n" solver_residual), max_u $(sx_value "ex1-petsc-$n" max_u) against $(sx_value "ex1-cholmod-$n" max_u)" \
      -v it="$it" -v want="$want" -v r="$(sx_value "ex1-petsc-$n" solver_residual)" \
      -v m="$(sx_value "ex1-cholmod-$n" max_u)" \
      -v d="$(awk -v a="$(sx_value "ex1-petsc-$n" max_u)" -v b="$(sx_value "ex1-cholmod-$n" max_u)" 'BEGIN { d = a - b; print d < 0 ? -d : d }')"
  done
  if [ -f "$C/ex1-petsc-10.out" ] && [ -f "$C/ex1-petsc-14.out" ]; then
    sx_check "ex1 iterations hardly grow" "i2 - i1 <= 2 && d2 / d1 > 2.5" \
      "$(sx_value ex1-petsc-10 solver_iterations) -> $(sx_value ex1-petsc-14 solver_iterations) iterations for $(sx_value ex1-petsc-10 dofs) -> $(sx_value ex1-petsc-14 dofs) dofs" \
      -v i1="$(sx_value ex1-petsc-10 solver_iterations)" -v i2="$(sx_value ex1-petsc-14 solver_iterations)" \
      -v d1="$(sx_value ex1-petsc-10 dofs)" -v d2="$(sx_value ex1-petsc-14 dofs)"
  fi

  # ---- exercise 2: the weight omega --------------------------------------
  T3="chapters/08-experiments/taylor3d.scene --set mesh.numbers=n=10 --strategy petsc"
  its=
  for w in 0.1 1 10 100 1000; do
    # shellcheck disable=SC2086
    if sx_run "ex2-omega-$w" $T3 --petsc-options "-lac_omega $w"; then
      its="$its $(sx_value "ex2-omega-$w" solver_iterations)"
      sx_check "ex2 omega=$w lambda" "l >= -25 * (1 + 1e-9) && u <= -25 * (1 - 1e-9) && e <= 1e-9" \
        "omega $w: lambda in [$(sx_value "ex2-omega-$w" lambda_min), $(sx_value "ex2-omega-$w" lambda_max)]" \
        -v l="$(sx_value "ex2-omega-$w" lambda_min)" -v u="$(sx_value "ex2-omega-$w" lambda_max)" \
        -v e="$(sx_value "ex2-omega-$w" max_rel_err_lambda)"
    else
      its="$its x"
    fi
  done
  # shellcheck disable=SC2086
  set -- $its
  sx_check "ex2 iterations against omega" \
    "n == 5 && near(a, 30) && near(b, 23) && near(c, 52) && near(d, 92) && near(e, 231) && b < a && b < c && c < d && d < e" \
    "iterations for omega 0.1 1 10 100 1000:$its (want 30 23 52 92 231 within 15 %, fewest at 1)" \
    -v n="$#" -v a="${1:-0}" -v b="${2:-0}" -v c="${3:-0}" -v d="${4:-0}" -v e="${5:-0}"

  # ---- exercise 3: GAMG, BoomerAMG, fieldsplit ---------------------------
  i=0
  for o in "-elast_pc_type hypre" "-lac_contact fieldsplit" "-lac_contact fieldsplit -fieldsplit_u_pc_type hypre"; do
    i=$((i+1))
    want=$(echo "14 40 30" | cut -d' ' -f$i)
    # shellcheck disable=SC2086
    sx_run "ex3-$i" $T3 --petsc-options "$o" || continue
    it=$(sx_value "ex3-$i" solver_iterations)
    sx_check "ex3 $o" "near(it, want) && e <= 1e-9" \
      "$o: $it iterations (want $want within 15 %), max_rel_err_lambda $(sx_value "ex3-$i" max_rel_err_lambda)" \
      -v it="$it" -v want="$want" -v e="$(sx_value "ex3-$i" max_rel_err_lambda)"
  done
  if [ -f "$C/ex3-1.out" ] && [ -f "$C/ex2-omega-1.out" ]; then
    sx_check "ex3 BoomerAMG needs fewer iterations than the default multigrid" "h < g" \
      "BoomerAMG $(sx_value ex3-1 solver_iterations), lac-sa + gamg $(sx_value ex2-omega-1 solver_iterations)" \
      -v h="$(sx_value ex3-1 solver_iterations)" -v g="$(sx_value ex2-omega-1 solver_iterations)"
  fi
fi
