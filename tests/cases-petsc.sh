# tests/cases-petsc.sh -- the petsc strategy and MPI (sourced by tests/run.sh)
#
# [LAC (17), Alg. 1; chapter 13]  lac run with --strategy petsc (Krylov
# methods and algebraic multigrid, solve/lac_petsc.h) against the direct
# path on the same scenes, small sizes:
#   petsc-vs-direct  the Taylor patch tests (2D quad4, 3D hex8 and tet4),
#                    the spheres (axisymmetric quad8, 3D hex20) and the
#                    plain elasticity of a cube and of a sphere (no
#                    contact, --solver petsc against cholmod): lambda_min,
#                    lambda_max, max_u equal to 1e-8 relative, and the
#                    Taylor lambda = 25 to 1e-8; the summary reports the
#                    solver's iterations and true residual (<= 1e-9);
#   mpi              mpirun -n 1 and -n 2 give the same lambda and max_u
#                    to 1e-8 (patch test, spheres), only process 0 prints
#                    the summary and writes the files, processes = 2;
#   options          --petsc-options and PETSC_OPTIONS reach PETSc; an
#                    option nothing read is named in a warning
#                    (BoomerAMG instead of GAMG, the fieldsplit solver)
#                    with the same answers; a bad option is one line
#                    "lac: ..." and exit status 1;
#   no-petsc         a build without PETSc: --strategy petsc and --solver
#                    petsc fail with the apt-get line (the other cases are
#                    then skipped).
# Open MPI refuses to start as root without --allow-run-as-root: added
# when the tests run as root.  Under make test-asan, lac's runs here
# unwind in full (LAC_MPI_ASAN, see the Makefile).  Same conventions as tests/cases.sh ($B,
# pass, fail).  About 15 s.

B=${B:-build}
C="$B/cases-petsc"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

petsc_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
petsc_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
petsc_value () { sed -n "s/^$2 = //p" "$1"; }
D8=chapters/08-experiments
PETSC_LINE="apt-get install -y --no-install-recommends libpetsc-real-dev"
PETSC_ENV="ASAN_OPTIONS=${ASAN_OPTIONS:-}${LAC_MPI_ASAN:-}"

# petsc_same NAME FILE1 FILE2 KEYS...: every key equal to 1e-8 relative.
# (sh functions share their variables: each function has its own names)
petsc_same () {
  ps_name=$1 ps_f1=$2 ps_f2=$3
  shift 3
  ps_msg=""
  for key in "$@"; do
    a=$(petsc_value "$ps_f1" "$key") b=$(petsc_value "$ps_f2" "$key")
    awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b
      exit !(a != "" && b != "" && d <= 1e-8 * m + 1e-300) }' ||
      ps_msg="$ps_msg $key: $a against $b;"
  done
  if [ -z "$ps_msg" ]; then petsc_ok "$ps_name"; else petsc_fail "$ps_name" "$ps_msg"; fi
}

# petsc_run NAME ARGS...: lac run into $C/NAME.out; 0 or a FAIL line.
petsc_run () {
  pr_name=$1
  shift
  if env "$PETSC_ENV" "$LAC" run "$@" --quiet --no-output > "$C/$pr_name.out" 2> "$C/$pr_name.err"; then
    return 0
  fi
  petsc_fail "$pr_name" "lac run $* failed: $(tail -1 "$C/$pr_name.err")"
  return 1
}

# ---- no-petsc: the install line --------------------------------------
have_petsc=1
for opt in "--strategy petsc" "--solver petsc"; do
  # shellcheck disable=SC2086
  env "$PETSC_ENV" "$LAC" run "$D8/taylor2d.scene" $opt --quiet --no-output > "$C/avail.out" 2> "$C/avail.err"
  rc=$?
  if grep -q "built without PETSc" "$C/avail.err"; then
    have_petsc=0
    if [ "$rc" = 1 ] && grep -q "$PETSC_LINE" "$C/avail.err" \
       && [ "$(wc -l < "$C/avail.err")" -eq 1 ]; then
      petsc_ok "no-petsc $opt"
    else
      petsc_fail "no-petsc $opt" "want exit 1 and one line with '$PETSC_LINE', got $rc: $(cat "$C/avail.err")"
    fi
  fi
done

if [ "$have_petsc" = 1 ]; then
  # ---- petsc-vs-direct -------------------------------------------------
  # petsc_vs NAME SCENE REF KEYS -- ARGS...: --strategy petsc against REF.
  petsc_vs () {
    name=$1 scene=$2 ref=$3 keys=$4
    shift 5
    petsc_run "$name.direct" "$scene" "$@" $ref || return
    petsc_run "$name.petsc" "$scene" "$@" --strategy petsc || return
    # shellcheck disable=SC2086
    petsc_same "petsc-vs-direct $name" "$C/$name.petsc.out" "$C/$name.direct.out" $keys
    it=$(petsc_value "$C/$name.petsc.out" solver_iterations)
    res=$(petsc_value "$C/$name.petsc.out" solver_residual)
    if awk -v i="$it" -v r="$res" 'BEGIN { exit !(i > 0 && r != "" && r <= 1e-9) }'; then
      petsc_ok "petsc-report $name"
    else
      petsc_fail "petsc-report $name" "solver_iterations = $it, solver_residual = $res (want > 0, <= 1e-9)"
    fi
  }
  CONTACT_KEYS="lambda_min lambda_max max_u"
  petsc_vs taylor2d-quad4 "$D8/taylor2d.scene" "--strategy saddle" "$CONTACT_KEYS" -- --set element=quad4 --set level=1
  petsc_vs taylor3d-hex8 "$D8/taylor3d.scene" "--strategy saddle" "$CONTACT_KEYS" -- --set element=hex8 --set level=1
  petsc_vs taylor3d-tet4 "$D8/taylor3d.scene" "--strategy saddle" "$CONTACT_KEYS" -- --set element=tet4
  petsc_vs spheres-axi-quad8 chapters/09-spheres-rates/spheres-axi.scene "--strategy saddle" "$CONTACT_KEYS" -- --set element=quad8 --set level=1
  petsc_vs spheres3d-hex20 chapters/09-spheres-rates/spheres3d.scene "--strategy saddle" "$CONTACT_KEYS" -- --set element=hex20
  petsc_vs cube-hex8 bench/cube.scene "--solver cholmod" "max_u load_work" -- --set mesh.numbers=n=6
  petsc_vs sphere-axi chapters/01-problem/sphere-axi.scene "--solver cholmod" "max_u load_work" -- --set level=1
  for e in taylor2d-quad4 taylor3d-hex8 taylor3d-tet4; do
    f="$C/$e.petsc.out"
    [ -f "$f" ] || continue
    lmin=$(petsc_value "$f" lambda_min) lmax=$(petsc_value "$f" lambda_max)
    if awk -v a="$lmin" -v b="$lmax" 'BEGIN { exit !(a != "" && (a + 25 < 0 ? -(a + 25) : a + 25) <= 25e-8 && (b + 25 < 0 ? -(b + 25) : b + 25) <= 25e-8) }'; then
      petsc_ok "petsc-exact $e"
    else
      petsc_fail "petsc-exact $e" "lambda in [$lmin, $lmax], want -25 to 1e-8"
    fi
  done

  # ---- mpi: 1 and 2 processes -------------------------------------------
  if command -v mpirun > /dev/null 2>&1; then
    MPIRUN="mpirun"
    if mpirun --version 2>&1 | grep -q "Open MPI"; then
      MPIRUN="$MPIRUN --oversubscribe"
      [ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
    fi
    # petsc_mpi NAME SCENE ARGS...: -n 1 and -n 2 agree.
    petsc_mpi () {
      name=$1 scene=$2
      shift 2
      for np in 1 2; do
        # shellcheck disable=SC2086
        if ! env "$PETSC_ENV" $MPIRUN -n $np "$LAC" run "$scene" "$@" --strategy petsc \
             --out "$C/$name.np$np" > "$C/$name.np$np.out" 2> "$C/$name.np$np.err"; then
          petsc_fail "mpi $name" "mpirun -n $np failed: $(tail -1 "$C/$name.np$np.err")"
          return
        fi
      done
      petsc_same "mpi $name" "$C/$name.np2.out" "$C/$name.np1.out" lambda_min lambda_max max_u
      n=$(grep -c '^dofs = ' "$C/$name.np2.out")
      p=$(petsc_value "$C/$name.np2.out" processes)
      if [ "$n" = 1 ] && [ "$p" = 2 ] && [ -f "$C/$name.np2/summary.txt" ] \
         && cmp -s "$C/$name.np2/summary.txt" "$C/$name.np2.out"; then
        petsc_ok "mpi-root $name"
      else
        petsc_fail "mpi-root $name" "summaries printed: $n (want 1), processes = $p (want 2), summary.txt: $(ls "$C/$name.np2" 2>&1 | tr '\n' ' ')"
      fi
    }
    petsc_mpi taylor3d-hex8 "$D8/taylor3d.scene" --set element=hex8 --set level=1
    petsc_mpi taylor2d-quad4 "$D8/taylor2d.scene" --set element=quad4 --set level=1
    petsc_mpi spheres-axi-quad8 chapters/09-spheres-rates/spheres-axi.scene --set element=quad8 --set level=1
  else
    petsc_fail "mpi" "mpirun not found (Debian: openmpi-bin)"
  fi

  # ---- options ---------------------------------------------------------
  petsc_run opt-ref "$D8/taylor3d.scene" --strategy saddle
  env "$PETSC_ENV" "$LAC" run "$D8/taylor3d.scene" --strategy petsc --no-output \
    --petsc-options "-elast_pc_type hypre" > "$C/opt-hypre.out" 2> "$C/opt-hypre.err"
  env "$PETSC_ENV" PETSC_OPTIONS="-lac_contact fieldsplit" "$LAC" run "$D8/taylor3d.scene" \
    --strategy petsc --no-output > "$C/opt-env.out" 2> "$C/opt-env.err"
  petsc_same "options hypre" "$C/opt-hypre.out" "$C/opt-ref.out" lambda_min lambda_max max_u
  petsc_same "options env" "$C/opt-env.out" "$C/opt-ref.out" lambda_min lambda_max max_u
  if grep -q "cg + hypre on K_W" "$C/opt-hypre.err" && grep -q "fieldsplit(gamg" "$C/opt-env.err"; then
    petsc_ok "options reach PETSc"
  else
    petsc_fail "options reach PETSc" "$(grep 'solve ' "$C/opt-hypre.err" "$C/opt-env.err")"
  fi
  env "$PETSC_ENV" "$LAC" run "$D8/taylor3d.scene" --strategy petsc --petsc-options "-elast_pc_type nonsense" \
    --quiet --no-output > "$C/opt-bad.out" 2> "$C/opt-bad.err"
  rc=$?
  if [ "$rc" = 1 ] && [ "$(wc -l < "$C/opt-bad.err")" -eq 1 ] && grep -q "^lac: .*nonsense" "$C/opt-bad.err"; then
    petsc_ok "options bad"
  else
    petsc_fail "options bad" "want exit 1 and one line 'lac: ... nonsense', got $rc: $(cat "$C/opt-bad.err")"
  fi

  # an option nothing read is named (a run without PETSc's solver; a typo)
  env "$PETSC_ENV" "$LAC" run "$D8/taylor2d.scene" --petsc-options "-ksp_type bogus" \
    --quiet --no-output > "$C/opt-unused.out" 2> "$C/opt-unused.err"
  rc=$?
  env "$PETSC_ENV" "$LAC" run "$D8/taylor3d.scene" --strategy petsc --petsc-options "-elast_pc_type jacobi -kps_monitor" \
    --quiet --no-output > "$C/opt-typo.out" 2> "$C/opt-typo.err"
  rc2=$?
  if [ "$rc" = 0 ] && [ "$rc2" = 0 ] && [ "$(wc -l < "$C/opt-unused.err")" -eq 1 ] \
     && grep -q "^lac: warning: 1 PETSc option was never read: -ksp_type " "$C/opt-unused.err" \
     && grep -q "never read: -kps_monitor " "$C/opt-typo.err" && ! grep -q elast_pc "$C/opt-typo.err"; then
    petsc_ok "options unused"
  else
    petsc_fail "options unused" "want exit 0 and the warnings, got $rc $rc2: $(cat "$C/opt-unused.err" "$C/opt-typo.err")"
  fi

  # ---- large deformation: refused, not solved by CHOLMOD ---------------
  env "$PETSC_ENV" "$LAC" run chapters/10-large-deformation/ring.scene --strategy petsc --quiet --no-output \
    > "$C/large.out" 2> "$C/large.err"
  rc=$?
  if [ "$rc" = 1 ] && [ "$(wc -l < "$C/large.err")" -eq 1 ] \
     && grep -q "^lac: .*--strategy petsc: the large-deformation loop .*dense, schur or saddle" "$C/large.err"; then
    petsc_ok "large deformation refused"
  else
    petsc_fail "large deformation refused" "want exit 1 and one line naming the strategies, got $rc: $(head -3 "$C/large.err")"
  fi
fi
