# tests/cases-petsc.sh -- the petsc strategy and MPI (sourced by tests/run.sh)
#
# [LAC (17), Alg. 1; chapter 13]  lac run with --strategy petsc (Krylov
# methods and algebraic multigrid, solve/lac_petsc.h) against the direct
# path on the same scenes, small sizes:
#   petsc-vs-direct  the Taylor patch tests (2D quad4, 3D hex8 and tet4;
#                    the 2D one turned by 30 degrees on rollers, quad8),
#                    the spheres (axisymmetric quad8, 3D hex20) and the
#                    plain elasticity of a cube and of a sphere (no
#                    contact, --solver petsc against cholmod): lambda_min,
#                    lambda_max, max_u equal to 1e-8 relative, and the
#                    Taylor lambda = 25 to 1e-8; the summary reports the
#                    solver's iterations and true residual (<= 1e-9);
#   mpi              mpirun -n 1, -n 2 and -n 4 give the same U and von
#                    Mises stress (nodes.csv) and lambda (contact.csv) to
#                    1e-8 of their largest (patch tests, spheres, Hertz),
#                    only process 0 prints the summary and writes the
#                    files, processes = N; mpi-post: on 2 and 4 processes
#                    the 3D patch test's and spheres' stresses and errors
#                    come from the processes' cells (the progress line),
#                    the spheres' L2 and H1 errors those of -n 1 to 1e-8;
#   mpi-mg           the unit test t512 (the contact multigrid's finest
#                    level) on 2 and 3 processes: the graphs and
#                    aggregates of each process's own nodes;
#   mpi-fail         a failure injected on process 1 (or 3 of 4) in the
#                    assembly (build/tests/lac_faults, LAC_TEST_FAIL_RANK),
#                    or on process 1 of 2 after its part of a command of
#                    the root (LAC_TEST_FAIL_AFTER=1:solve, 1:post), ends
#                    every process (a hang meets `timeout 60`: status
#                    124, a failure; the wall clock is not asserted, it
#                    grows with the load and under AddressSanitizer),
#                    exit status 1, with the line "lac: ... process 1:
#                    failure injected ...";
#   assembly check   PETSc's K made different from its cells' (one
#                    cell's matrix times 1.01, LAC_TEST_SCALE_CELL) on 1
#                    and 2 processes: exit status 1 and one line that
#                    says so, not an answer;
#   auto             the strategy auto (no --strategy): under mpirun -n 2
#                    petsc on 2 processes, with the direct lambda; on one
#                    process, with a --max-memory the Cholesky factor is
#                    estimated not to fit in (the 3D patch test, n = 14),
#                    petsc instead of the refusal, which stays when petsc
#                    does not fit either; in 3D above the crossover in
#                    time (n = 26) petsc, the solve line saying why, with
#                    the direct lambda;
#   contact pc       the 3D patch test (n = 20) within 1.5 times the CG
#                    iterations of the cube of the same size, and fewer
#                    than two thirds of those without the contact nodes'
#                    weak couplings left out (-lac_contact_threshold -1);
#                    the oblique projection P_Z (one Jacobi step) fewer
#                    than the l2 one (-lac_projection_steps 0), lambda to
#                    1e-9;
#   options          --petsc-options and PETSC_OPTIONS reach PETSc; an
#                    option nothing read is named in a warning
#                    (BoomerAMG instead of GAMG, the fieldsplit solver)
#                    with the same answers; a bad option is one line
#                    "lac: ..." and exit status 1; the user's options win
#                    over lac's: -pc_type none (the projected CG without
#                    multigrid: more iterations, the same lambda),
#                    -ksp_rtol 0.5 (inexact solves: a last residual above
#                    1e-9, the loop still converges to lambda), -ksp_max_it
#                    2 (exit status 1 "after 2 iterations"); -pc_type
#                    jacobi, -lac_contact_threshold nan, -lac_omega inf,
#                    an option of lac's without its value, a
#                    -lac_projection_steps beyond 100 or not an integer, a
#                    -lac_omega above 1e6 are one line "lac: ..." and
#                    exit status 1;
#   large-deformation  the large-deformation loop through petsc: the 3D
#                    patch test (hex8, a body held by contact alone) and the
#                    Hertz cylinder (2D, an obstacle), two load steps each,
#                    on 1 process and on mpirun -n 2: every number of the
#                    summary equal to the direct run's to 1e-8 relative;
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

# petsc_field NAME FILE1 FILE2 COLUMNS...: the columns (by their header
# names, csv) equal to 1e-8 of their largest absolute value.
petsc_field () {
  pf_name=$1 pf_f1=$2 pf_f2=$3 pf_diff="$C/$(echo "$1" | tr ' ' _).diff"
  shift 3
  if awk -F, -v cols="$*" '
    FNR == 1 { n = split(cols, want, " "); for (c = 1; c <= NF; c++) for (w = 1; w <= n; w++)
                 if ($c == want[w]) use[FILENAME, c] = 1; next }
    { for (c = 1; c <= NF; c++) if (use[FILENAME, c]) {
        k = FILENAME == ARGV[1] ? "a" : "b"; v[k, FNR, c] = $c; rows[FNR, c] = 1
        if ((($c < 0) ? -$c : $c) > big) big = ($c < 0) ? -$c : $c } }
    END { if (big == 0) exit 1
          for (rc in rows) { split(rc, q, SUBSEP); d = v["a", q[1], q[2]] - v["b", q[1], q[2]]
            if (d < 0) d = -d; if (d > worst) worst = d }
          printf "%.3g\n", worst / big > "/dev/stderr"; exit !(worst <= 1e-8 * big) }' \
      "$pf_f1" "$pf_f2" 2> "$pf_diff"; then
    petsc_ok "$pf_name"
  else
    petsc_fail "$pf_name" "$* differ by $(cat "$pf_diff") of the largest (want <= 1e-8): $pf_f1 $pf_f2"
  fi
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
  petsc_vs taylor2d-rotated-quad8 "$D8/taylor2d-rotated.scene" "--strategy saddle" "$CONTACT_KEYS" -- --set element=quad8
  petsc_vs spheres-axi-quad8 chapters/09-spheres-rates/spheres-axi.scene "--strategy saddle" "$CONTACT_KEYS" -- --set element=quad8 --set level=1
  petsc_vs spheres3d-hex20 chapters/09-spheres-rates/spheres3d.scene "--strategy saddle" "$CONTACT_KEYS" -- --set element=hex20
  petsc_vs cube-hex8 bench/cube.scene "--solver cholmod" "max_u load_work" -- --set mesh.numbers=n=6
  petsc_vs sphere-axi chapters/01-problem/sphere-axi.scene "--solver cholmod" "max_u load_work" -- --set level=1
  for e in taylor2d-quad4 taylor3d-hex8 taylor3d-tet4 taylor2d-rotated-quad8; do
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
    # petsc_mpi NAME SCENE ARGS...: -n 1, -n 2 and -n 4 agree.
    petsc_mpi () {
      name=$1 scene=$2
      shift 2
      for np in 1 2 4; do
        # shellcheck disable=SC2086
        if ! env "$PETSC_ENV" $MPIRUN -n $np "$LAC" run "$scene" "$@" --strategy petsc \
             --out "$C/$name.np$np" > "$C/$name.np$np.out" 2> "$C/$name.np$np.err"; then
          petsc_fail "mpi $name" "mpirun -n $np failed: $(tail -1 "$C/$name.np$np.err")"
          return
        fi
      done
      petsc_same "mpi $name" "$C/$name.np2.out" "$C/$name.np1.out" lambda_min lambda_max max_u max_von_mises
      u="u_x u_y"
      head -1 "$C/$name.np1/nodes.csv" | grep -q u_z && u="$u u_z"
      for np in 2 4; do
        petsc_field "mpi-u $name -n $np" "$C/$name.np$np/nodes.csv" "$C/$name.np1/nodes.csv" $u von_mises
        petsc_field "mpi-lambda $name -n $np" "$C/$name.np$np/contact.csv" "$C/$name.np1/contact.csv" lambda
      done
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
    petsc_mpi spheres3d-hex20 chapters/09-spheres-rates/spheres3d.scene --set element=hex20
    petsc_mpi hertz-cylinder chapters/10-large-deformation/hertz-cylinder.scene
    for name in taylor3d-hex8 spheres3d-hex20; do
      for np in 2 4; do
        if grep -q "post .*(on the $np processes' cells)" "$C/$name.np$np.err"; then
          petsc_ok "mpi-post $name -n $np"
        else
          petsc_fail "mpi-post $name -n $np" "the stresses were not computed on the processes: $(grep 'post ' "$C/$name.np$np.err")"
        fi
      done
    done
    petsc_same "mpi-post errors" "$C/spheres3d-hex20.np4.out" "$C/spheres3d-hex20.np1.out" l2_err_u h1_err_u

    # ---- mpi-mg: the contact multigrid on each process (t512 on 2 and 3)
    for np in 2 3; do
      # shellcheck disable=SC2086
      if env "$PETSC_ENV" $MPIRUN -n $np "$B/tests/t512-petsc-mg" \
           > "$C/mg.np$np.out" 2>&1; then
        petsc_ok "mpi-mg -n $np"
      else
        petsc_fail "mpi-mg -n $np" "$(grep FAIL "$C/mg.np$np.out" | head -2)"
      fi
    done

    # ---- mpi-fail: a failure on one process ends them all -------------
    # petsc_fault NP RANK [VAR=VALUE WANT]: the failure injected on
    # process RANK of NP, in the assembly (or as VAR=VALUE says); WANT:
    # what the line names after "process RANK: ".
    petsc_fault () {
      fname="mpi-fail -n $1 on $2${3:+ ($3)}"
      fvar=${3:-LAC_TEST_FAIL_RANK=$2}
      fwant=${4:-failure injected by LAC_TEST_FAIL_RANK in the assembly}
      if [ ! -x "$B/tests/lac_faults" ]; then
        petsc_fail "$fname" "$B/tests/lac_faults not built (make $B/tests/lac_faults)"
        return
      fi
      t0=$(date +%s)
      # shellcheck disable=SC2086
      env "$PETSC_ENV" "$fvar" timeout 60 $MPIRUN -n "$1" "$B/tests/lac_faults" run \
        "$D8/taylor3d.scene" --set element=hex8 --set level=1 --strategy petsc --quiet --no-output \
        > "$C/fault$1.out" 2> "$C/fault$1.err"
      rc=$? t=$(( $(date +%s) - t0 ))
      want="^lac: .*process $2: $fwant"
      if [ "$rc" != 0 ] && [ "$rc" != 124 ] \
         && [ "$(grep -c '^lac: ' "$C/fault$1.err")" = 1 ] && grep -q "$want" "$C/fault$1.err"; then
        petsc_ok "$fname"
      else
        petsc_fail "$fname" "want one line '$want' and an end before the timeout, got status $rc after $t s: $(grep -m 2 . "$C/fault$1.err")"
      fi
    }
    petsc_fault 2 1
    petsc_fault 4 3
    # after the last collective call of a command: only the agreement that
    # ends the command carries it to the root (before: exit 0, an answer)
    for step in solve post; do
      petsc_fault 2 1 "LAC_TEST_FAIL_AFTER=1:$step" \
        "failure injected by LAC_TEST_FAIL_AFTER after the $step"
    done

    # ---- assembly check: PETSc's K against its cells -------------------
    # one cell's matrix in PETSc's K times 1.01 (LAC_TEST_SCALE_CELL, not
    # in the cells' own products): the run stops with one line, not with
    # the answer of another stiffness (before: exit 0, lambda 7e-5 off)
    for np in 1 2; do
      # shellcheck disable=SC2086
      env "$PETSC_ENV" LAC_TEST_SCALE_CELL=1.01 timeout 60 $MPIRUN -n $np "$B/tests/lac_faults" run \
        "$D8/taylor3d.scene" --set element=hex8 --set level=1 --strategy petsc --quiet --no-output \
        > "$C/scaled$np.out" 2> "$C/scaled$np.err"
      rc=$?
      if [ "$rc" = 1 ] && [ "$(grep -c '^lac: ' "$C/scaled$np.err")" = 1 ] \
         && grep -q "^lac: .*the stiffness PETSc assembled on $np process.* is not its cells'" "$C/scaled$np.err"; then
        petsc_ok "assembly check -n $np"
      else
        petsc_fail "assembly check -n $np" "want exit 1 and one line 'the stiffness ... is not its cells', got $rc: $(grep -m 2 . "$C/scaled$np.err") $(grep max_u "$C/scaled$np.out")"
      fi
    done

    # ---- auto on 2 processes: petsc, with the direct answer ------------
    # shellcheck disable=SC2086
    if env "$PETSC_ENV" $MPIRUN -n 2 "$LAC" run "$D8/taylor3d.scene" --set element=hex8 --set level=1 \
         --no-output > "$C/auto-mpi.out" 2> "$C/auto-mpi.err" \
       && [ "$(petsc_value "$C/auto-mpi.out" processes)" = 2 ] \
       && grep -q "solve .*projected cg + lac-sa + gamg on K_W, 2 processes (auto: more than one MPI process)" "$C/auto-mpi.err"; then
      petsc_ok "auto-mpi petsc"
      [ -f "$C/taylor3d-hex8.direct.out" ] && petsc_same "auto-mpi vs direct" \
        "$C/auto-mpi.out" "$C/taylor3d-hex8.direct.out" lambda_min lambda_max max_u
    else
      petsc_fail "auto-mpi petsc" "want processes = 2 and the projected CG: $(grep -E 'solve|^lac: [^[]' "$C/auto-mpi.err" | tail -2)"
    fi
  else
    petsc_fail "mpi" "mpirun not found (Debian: openmpi-bin)"
  fi

  # ---- the contact solve against plain elasticity (chapter 13, section 1):
  # the patch test at n = 20 (52,866 dofs) within 1.5 times the CG
  # iterations of the cube at n = 25 (52,728 dofs): 58 against 20 when the
  # contact multigrid keeps every coupling, 27 when it leaves out the
  # contact nodes' weak ones, 25 with the oblique projection too.
  if petsc_run pc-taylor "$D8/taylor3d.scene" --set mesh.numbers=n=20 --strategy petsc \
     && petsc_run pc-cube bench/cube.scene --set mesh.numbers=n=25 --strategy petsc; then
    a=$(petsc_value "$C/pc-taylor.out" solver_iterations) b=$(petsc_value "$C/pc-cube.out" solver_iterations)
    if awk -v a="$a" -v b="$b" 'BEGIN { exit !(a > 0 && b > 0 && a <= 1.5 * b) }'; then
      petsc_ok "contact solve within 1.5 x the iterations of plain elasticity"
    else
      petsc_fail "contact solve within 1.5 x the iterations of plain elasticity" \
        "patch test $a CG iterations, cube $b (want <= 1.5 x)"
    fi
    if petsc_run pc-taylor-all "$D8/taylor3d.scene" --set mesh.numbers=n=20 --strategy petsc \
         --petsc-options "-lac_contact_threshold -1"; then
      a1=$(petsc_value "$C/pc-taylor-all.out" solver_iterations)
      if awk -v a="$a" -v a1="$a1" 'BEGIN { exit !(a > 0 && 3 * a < 2 * a1) }'; then
        petsc_ok "the contact nodes' weak couplings left out"
      else
        petsc_fail "the contact nodes' weak couplings left out" \
          "$a CG iterations, $a1 with every coupling kept (want fewer than two thirds)"
      fi
    fi
    if petsc_run pc-taylor-l2 "$D8/taylor3d.scene" --set mesh.numbers=n=20 --strategy petsc \
         --petsc-options "-lac_projection_steps 0"; then
      a0=$(petsc_value "$C/pc-taylor-l2.out" solver_iterations)
      e=$(petsc_value "$C/pc-taylor.out" max_rel_err_lambda)
      if awk -v a="$a" -v a0="$a0" -v e="$e" 'BEGIN { exit !(a > 0 && a < a0 && e <= 1e-9) }'; then
        petsc_ok "the oblique projection saves iterations"
      else
        petsc_fail "the oblique projection saves iterations" \
          "P_Z: $a CG iterations (max_rel_err_lambda $e), l2 P: $a0 (want fewer, lambda to 1e-9)"
      fi
    fi
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

  # the user's options win over lac's: -pc_type none leaves the multigrid
  # out (more iterations, the same lambda), -ksp_rtol 0.5 makes every
  # solve inexact (the loop's own residual still converges: lambda to
  # 1e-8, the last solve's residual above 1e-9), -ksp_max_it 2 stops the
  # CG (before: all three overridden without a word)
  petsc_run opt-default "$D8/taylor3d.scene" --strategy petsc
  if petsc_run opt-pcnone "$D8/taylor3d.scene" --strategy petsc --petsc-options "-pc_type none"; then
    a=$(petsc_value "$C/opt-pcnone.out" solver_iterations) b=$(petsc_value "$C/opt-default.out" solver_iterations)
    if awk -v a="$a" -v b="$b" 'BEGIN { exit !(a > 2 * b && b > 0) }' \
       && ! grep -q "never read" "$C/opt-pcnone.err"; then
      petsc_ok "options -pc_type none honoured"
    else
      petsc_fail "options -pc_type none honoured" "$a iterations without the multigrid, $b with it (want more than twice): $(cat "$C/opt-pcnone.err")"
    fi
    petsc_same "options -pc_type none lambda" "$C/opt-pcnone.out" "$C/opt-ref.out" lambda_min lambda_max max_u
  fi
  if petsc_run opt-rtol "$D8/taylor3d.scene" --strategy petsc --petsc-options "-ksp_rtol 0.5"; then
    r=$(petsc_value "$C/opt-rtol.out" solver_residual)
    if awk -v r="$r" 'BEGIN { exit !(r > 1e-9) }'; then
      petsc_ok "options -ksp_rtol honoured"
    else
      petsc_fail "options -ksp_rtol honoured" "the last solve's residual $r (want above 1e-9: -ksp_rtol 0.5)"
    fi
    petsc_same "options -ksp_rtol lambda" "$C/opt-rtol.out" "$C/opt-ref.out" lambda_min lambda_max
  fi
  # petsc_refused NAME OPTIONS WANT: exit 1, one line "lac: ...WANT"
  petsc_refused () {
    env "$PETSC_ENV" timeout 300 "$LAC" run "$D8/taylor3d.scene" --strategy petsc --petsc-options "$2" \
      --quiet --no-output > "$C/$1.out" 2> "$C/$1.err"
    rc=$?
    if [ "$rc" = 1 ] && [ "$(wc -l < "$C/$1.err")" -eq 1 ] && grep -q "^lac: .*$3" "$C/$1.err"; then
      petsc_ok "options $2"
    else
      petsc_fail "options $2" "want exit 1 and one line 'lac: ...$3', got $rc: $(cat "$C/$1.err")"
    fi
  }
  petsc_refused opt-maxit "-ksp_max_it 2" "after 2 iterations"
  petsc_refused opt-pcjacobi "-pc_type jacobi" "-pc_type jacobi: .*-elast_pc_type"
  petsc_refused opt-nan "-lac_contact_threshold nan" "-lac_contact_threshold nan: expected a finite number"
  petsc_refused opt-inf "-lac_omega inf" "-lac_omega inf: expected a finite number"
  # lac's own options read as lac reads a number (base/lac_number.h):
  # given without a value (PETSc kept lac's value, exit 0), an integer
  # beyond 32 bits (PETSc wrapped it to 1215752191 Jacobi steps a solve:
  # the run hung), an omega whose C W C^T swamps K (the loop stalled, or
  # the CG met an indefinite preconditioner, without naming -lac_omega)
  petsc_refused opt-novalue "-lac_contact_threshold" "-lac_contact_threshold: expected a finite number .*got no value"
  petsc_refused opt-steps-huge "-lac_projection_steps 99999999999" "-lac_projection_steps 99999999999: expected an integer from 0 to 100; above the largest allowed value 100"
  petsc_refused opt-steps-frac "-lac_projection_steps 2.5" "-lac_projection_steps 2.5: expected an integer .*not an integer"
  petsc_refused opt-omega-huge "-lac_omega 1e8" "-lac_omega 1e8: expected a finite number > 0 and at most 1e6.*above the largest allowed value"

  # ---- large deformation: the same loop through petsc -----------------
  # petsc_ld NAME SCENE ARGS...: the scene's own strategy, --strategy petsc
  # on 1 process and on mpirun -n 2 (when there): every number of the
  # summary equal to 1e-8 relative (a vector: of its largest component),
  # and the petsc runs report their processes.
  petsc_ld () {
    ld_name=$1 ld_scene=$2
    shift 2
    petsc_run "$ld_name.direct" "$ld_scene" "$@" || return
    petsc_run "$ld_name.petsc" "$ld_scene" "$@" --strategy petsc || return
    ld_runs="petsc"
    if [ -n "${MPIRUN:-}" ]; then    # set by the mpi cases when mpirun is there
      # shellcheck disable=SC2086
      if env "$PETSC_ENV" $MPIRUN -n 2 "$LAC" run "$ld_scene" "$@" --strategy petsc --quiet \
           --no-output > "$C/$ld_name.np2.out" 2> "$C/$ld_name.np2.err"; then
        ld_runs="petsc np2"
      else
        petsc_fail "large-deformation $ld_name -n 2" "mpirun -n 2 failed: $(tail -1 "$C/$ld_name.np2.err")"
      fi
    fi
    for r in $ld_runs; do
      np=1
      [ "$r" = np2 ] && np=2
      if awk -v np="$np" '
        function num(v) { return v ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ }
        FNR == 1 { f++ }
        { k = $1; sub(/^[^=]* = /, ""); val[f, k] = $0 }
        f == 1 && k != "" { keys[k] = 1 }
        END {
          bad = ""; n = 0
          for (k in keys) {
            m = split(val[1, k], b, " "); split(val[2, k], a, " ")
            if (!num(b[1])) continue
            big = 0
            for (i = 1; i <= m; i++) { x = b[i] < 0 ? -b[i] : b[i]; if (x > big) big = x }
            for (i = 1; i <= m; i++) { d = a[i] - b[i]; if (d < 0) d = -d
              if (!(a[i] != "" && d <= 1e-8 * big)) { bad = bad " " k ": " val[2, k] " against " val[1, k] ";"; break } }
            n++
          }
          if (val[2, "processes"] != np) bad = bad " processes = " val[2, "processes"] " (want " np ")"
          if (bad != "" || n < 10) { print n " values;" bad > "/dev/stderr"; exit 1 } }' \
          "$C/$ld_name.direct.out" "$C/$ld_name.$r.out" 2> "$C/$ld_name.$r.diff"; then
        petsc_ok "large-deformation $ld_name $r"
      else
        petsc_fail "large-deformation $ld_name $r" "against the direct run: $(cat "$C/$ld_name.$r.diff")"
      fi
    done
  }
  # the 3D patch test in large deformation (a body held by contact alone),
  # two load steps; the Hertz cylinder on a rigid flat (2D, an obstacle)
  sed '/^\[exact\]/,$d' "$D8/taylor3d.scene" > "$C/taylor3d-ld.scene"
  cp "$D8/taylor3d.geo" "$C/"
  petsc_ld taylor3d-ld "$C/taylor3d-ld.scene" --set element=hex8 --set level=1 \
    --set scene.large_deformation=yes --set steps.n=2
  petsc_ld hertz-cylinder-ld chapters/10-large-deformation/hertz-cylinder.scene \
    --set scene.large_deformation=yes --set steps.n=2
  # ---- auto when the factor does not fit: petsc, not a refusal ----------
  # 18,864 dofs: about 0.27 GB with a Cholesky factor, 0.19 GB with
  # petsc (src/io/lac_mesh_gmsh_estimate.c); --max-memory 230M between.
  NOFIT="--set element=hex8 --set mesh.numbers=n=14"
  # shellcheck disable=SC2086
  if petsc_run auto-nofit "$D8/taylor3d.scene" $NOFIT --max-memory 230M \
     && petsc_run auto-fit "$D8/taylor3d.scene" $NOFIT; then
    if [ "$(petsc_value "$C/auto-nofit.out" processes)" = 1 ] \
       && [ -n "$(petsc_value "$C/auto-nofit.out" solver_iterations)" ] \
       && [ -z "$(petsc_value "$C/auto-fit.out" solver_iterations)" ]; then
      petsc_ok "auto-nofit petsc"
    else
      petsc_fail "auto-nofit petsc" "want the petsc lines with --max-memory 230M only: $(grep -c solver_ "$C/auto-nofit.out") and $(grep -c solver_ "$C/auto-fit.out")"
    fi
    petsc_same "auto-nofit vs direct" "$C/auto-nofit.out" "$C/auto-fit.out" lambda_min lambda_max max_u
  fi
  # ---- auto in 3D above its trade of time for memory: petsc, 1 process ----
  # n = 26: 110,130 dofs, a run with a Cholesky factor estimated above
  # LAC_STRATEGY_ITERATIVE_BYTES (n = 14 above: below it, a factor); the
  # solve line says why, and the answer is the factor's to 1e-8.
  BIG="--set element=hex8 --set mesh.numbers=n=26"
  # shellcheck disable=SC2086
  if env "$PETSC_ENV" "$LAC" run "$D8/taylor3d.scene" $BIG --no-output \
       > "$C/auto-time.out" 2> "$C/auto-time.err" \
     && petsc_run auto-time-direct "$D8/taylor3d.scene" $BIG --strategy split; then
    if [ "$(petsc_value "$C/auto-time.out" processes)" = 1 ] \
       && grep -q "solve .*projected cg + lac-sa + gamg on K_W, 1 process (auto: in 3D a Cholesky factor this large costs far more memory than it saves time)" "$C/auto-time.err"; then
      petsc_ok "auto-time petsc"
    else
      petsc_fail "auto-time petsc" "want the projected CG, 1 process, and why: $(grep 'solve ' "$C/auto-time.err" | tail -1)"
    fi
    petsc_same "auto-time vs direct" "$C/auto-time.out" "$C/auto-time-direct.out" lambda_min lambda_max max_u
  else
    petsc_fail "auto-time petsc" "lac run failed: $(tail -1 "$C/auto-time.err")"
  fi
  # shellcheck disable=SC2086
  env "$PETSC_ENV" "$LAC" run "$D8/taylor3d.scene" $NOFIT --max-memory 150M --quiet --no-output \
    > "$C/auto-none.out" 2> "$C/auto-none.err"
  rc=$?
  if [ "$rc" = 1 ] && grep -q "^lac: .*0.193 GB of memory with an iterative solve, more than the limit of 0.15 GB" "$C/auto-none.err"; then
    petsc_ok "auto-nofit refused when petsc does not fit either"
  else
    petsc_fail "auto-nofit refused when petsc does not fit either" "got $rc: $(cat "$C/auto-none.err")"
  fi
fi
