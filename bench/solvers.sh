#!/bin/sh
# solvers.sh -- direct against iterative solvers, on 1 and 2 MPI processes
#                                                 [LAC (17), Alg. 1; ch. 13]
#
#   sh bench/solvers.sh [BUILD_DIR] [--quick] [--out DIR]
#   sh bench/solvers.sh --chart CSV DIR    (the charts again, from a CSV)
#   sh bench/solvers.sh [BUILD_DIR] --out DIR --rows "P:N:SOLVER:NP[:R] ..."
#                       [--reps R]
#       only these rows again (e.g. taylor:28:petsc:2), each the run of
#       median wall time among R (per row, or --reps; default 3; the rows
#       take turns, one run each a round), in place of the same rows
#       of DIR/solvers.csv; then the table and the charts from the whole
#       CSV, the table's first line saying which rows are newer
#
# Two problems at growing sizes, each through `lac run --timings
# --no-output`:
#   taylor  the 3D Taylor patch test with hex8 (chapters/08-experiments/
#           taylor3d.scene, --set mesh.numbers=n=N: cubes of N and N-1
#           cells a side, 3 ((N+1)^3 + N^3) dofs; N = 55: 1,034,721 dofs
#           after the macro-mesh refinement), contact, exact lambda = -25;
#   cube    the clamped steel cube of bench_elasticity.c (bench/cube.scene,
#           N cells a side, 3 (N+1)^3 dofs; N = 69: 1,029,000 dofs), no
#           contact;
# with the direct path (taylor: the augmented strategy, a CHOLMOD
# Cholesky factor of K + C_A W C_A^T; cube: cholmod) as long as it fits in
# time and memory (up to N = 35 and 45), and the petsc strategy (projected
# CG and GAMG, chapter 13) on 1 and 2 processes (mpirun -n 2, process 0
# assembling), then GAMG against BoomerAMG (hypre) at the two largest
# sizes.  Writes into DIR (BUILD_DIR/solvers; the committed figures are
# `--out figures`):
#   solvers.csv        one row per run (columns below)
#   solvers.txt        the same as a markdown table, then the acceptance
#                      checks of the 1M-dof contact problem, and its wall
#                      time and CG iterations over the 1M-dof cube's
#                      (petsc, 2 processes; issue 26 asks <= 1.3 each)
#   solvers-time.png   wall time against dofs, per solver and processes
#   solvers-memory.png peak memory (summed over the processes) against dofs
# Columns: problem, n, dofs, multipliers, solver (direct | petsc |
#   petsc-hypre), np (processes), wall (s, the whole mpirun, as timed by
#   this script), mesh, assemble, solve, post (s, the stages, measured by
#   lac), iterations (Krylov, all solves), residual (true relative residual
#   of the last solve), peak_mb (peak resident memory summed over the
#   processes, lac's peak_rss_total_mb), err_lambda (taylor: max relative
#   error of lambda against 25), max_u, status (ok or the error).
#
# Every run is a heavy job (up to 2 minutes and 8 GB at 1M dofs): run this
# script alone on the machine.  Full: 15-25 minutes on 2 cores; --quick
# (N <= 20) about a minute.  Needs PETSc and mpirun (make installs them).
B=build
QUICK=0
OUT=
CHART=
ROWS=
REPS=3
while [ $# -gt 0 ]; do
  case $1 in
    --quick) QUICK=1 ;;
    --rows) shift; ROWS=${1:?--rows needs a list of PROBLEM:N:SOLVER:NP} ;;
    --reps) shift; REPS=${1:?--reps needs a number} ;;
    --out) shift; OUT=${1:?--out needs a directory} ;;
    --chart) shift; CHART=${1:?--chart needs a CSV}; shift; OUT=${1:?--chart CSV DIR} ;;
    -*) echo "solvers.sh: unknown option '$1'" >&2; exit 2 ;;
    *) B=$1 ;;
  esac
  shift
done
OUT=${OUT:-$B/solvers}
mkdir -p "$OUT" || exit 1
OUTABS=$(cd "$OUT" && pwd)
W=$B/solvers-work
mkdir -p "$W" || exit 1
CSV=$OUT/solvers.csv
# The mesh reader refuses a .geo whose run it estimates to need more than
# --max-memory (default 80 % of the machine); the estimate follows the
# strategy (io/lac_mesh_gmsh_estimate.c): 5.3 GB for the 1M-dof patch
# test with petsc (5.1 GB measured), a Cholesky factor's 31 GB without.
# What a run uses is measured (peak_mb).
HYPRE="-elast_pc_type hypre -elast_pc_hypre_boomeramg_strong_threshold 0.5 -elast_pc_hypre_boomeramg_coarsen_type HMIS -elast_pc_hypre_boomeramg_interp_type ext+i -elast_pc_hypre_boomeramg_P_max 4 -elast_pc_hypre_boomeramg_agg_nl 1"

# ---- the charts (gnuplot) ------------------------------------------------
chart () {
  command -v gnuplot > /dev/null || { echo "solvers.sh: gnuplot not found" >&2; return 1; }
  # one .dat per problem, solver and np: dofs, wall, peak_mb
  rm -f "$W"/c-*.dat
  awk -F, -v W="$W" 'NR > 1 && $17 == "ok" { print $3, $7, $14 > (W "/c-" $1 "-" $5 "-" $6 ".dat") }' "$1"
  for what in time memory; do
    {
      echo 'set terminal pngcairo size 1400,620 font "DejaVu Sans,13" enhanced'
      echo "set output '$OUTABS/solvers-$what.png'"
      if [ $what = time ]; then
        echo 'set multiplot layout 1,2 title "wall time of a whole run (mesh, assembly on process 0, solve, post) against the size" font ",14"'
        echo 'set ylabel "wall time (s)"'
      else
        echo 'set multiplot layout 1,2 title "peak resident memory, summed over the processes, against the size" font ",14"'
        echo 'set ylabel "peak memory (MB)"'
      fi
      echo 'set logscale xy; set grid; set key top left; set format x "10^{%L}"'
      echo 'set xlabel "dofs"; set xrange [1e3:2e6]'
      for p in taylor cube; do
        if [ $p = taylor ]; then
          echo 'set title "3D Taylor patch test, hex8, contact"'
        else
          echo 'set title "clamped cube, hex8, no contact"'
        fi
        printf 'plot '
        sep=''
        for s in direct-1 petsc-1 petsc-2 petsc-hypre-2; do
          case $s in
            direct-1) c='#d62728' pt=7 t='direct (CHOLMOD), 1 process' ;;
            petsc-1) c='#1f77b4' pt=5 t='CG + GAMG, 1 process' ;;
            petsc-2) c='#2ca02c' pt=9 t='CG + GAMG, 2 processes' ;;
            petsc-hypre-2) c='#9467bd' pt=11 t='CG + BoomerAMG, 2 processes' ;;
          esac
          f="c-$p-$s.dat"
          [ -f "$W/$f" ] || continue
          col=2; [ $what = memory ] && col=3
          printf "%s'%s' using 1:%s with linespoints pt %s ps 1.2 lw 2 lc rgb \"%s\" title \"%s\"" "$sep" "$f" "$col" "$pt" "$c" "$t"
          sep=', '
        done
        echo
      done
      echo 'unset multiplot'
    } > "$W/solvers-$what.gp"
    (cd "$W" && gnuplot "solvers-$what.gp") || { echo "solvers.sh: gnuplot failed on $W/solvers-$what.gp" >&2; return 1; }
  done
  return 0
}

if [ -n "$CHART" ]; then
  chart "$CHART"
  exit $?
fi

LAC=$B/lac
[ -x "$LAC" ] || ${MAKE:-make} -s B="$B" "$LAC" >&2 || exit 1
MPIRUN="mpirun"
if mpirun --version 2>&1 | grep -q "Open MPI"; then
  MPIRUN="$MPIRUN --oversubscribe"
  [ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
fi
command -v mpirun > /dev/null || { echo "solvers.sh: mpirun not found (Debian: openmpi-bin)" >&2; exit 1; }

HEAD="problem,n,dofs,multipliers,solver,np,wall,mesh,assemble,solve,post,iterations,residual,peak_mb,err_lambda,max_u,status"
if [ -n "$ROWS" ]; then
  [ -f "$CSV" ] && [ -f "$OUT/solvers.txt" ] || { echo "solvers.sh: --rows needs $CSV and $OUT/solvers.txt of a full sweep" >&2; exit 1; }
  FULL=$CSV
  CSV=$W/rows.csv
else
  FULL=
fi
echo "$HEAD" > "$CSV"
LOAD0=$(cut -d' ' -f1-3 /proc/loadavg)
value () { sed -n "s/^$2 = //p" "$1" | head -1; }

# run PROBLEM N SOLVER NP: one run, one row.
run () {
  prob=$1 n=$2 solver=$3 np=$4
  case $prob in
    taylor) scene=chapters/08-experiments/taylor3d.scene ;;
    cube) scene=bench/cube.scene ;;
  esac
  case $solver in
    direct) [ $prob = taylor ] && how="--strategy augmented" || how="--solver cholmod" ;;
    petsc) how="--strategy petsc" ;;
    petsc-hypre) how="--strategy petsc --petsc-options" ;;
  esac
  f="$W/$prob-$n-$solver-$np"
  echo "solvers.sh: $prob n=$n $solver, $np process(es) ..." >&2
  t0=$(date +%s.%N)
  if [ $solver = petsc-hypre ]; then
    # shellcheck disable=SC2086
    $MPIRUN -n "$np" "$LAC" run "$scene" --set mesh.numbers=n="$n" $how "$HYPRE" \
      --timings --no-output --quiet > "$f.out" 2> "$f.err"
  else
    # shellcheck disable=SC2086
    $MPIRUN -n "$np" "$LAC" run "$scene" --set mesh.numbers=n="$n" $how \
      --timings --no-output --quiet > "$f.out" 2> "$f.err"
  fi
  rc=$?
  t1=$(date +%s.%N)
  status=ok
  [ $rc = 0 ] || status="failed: $(tail -1 "$f.err" | tr ',' ';')"
  lmin=$(value "$f.out" lambda_min) lmax=$(value "$f.out" lambda_max)
  err=$(awk -v a="$lmin" -v b="$lmax" 'BEGIN { if (a == "") { print ""; exit }
    x = a + 25; if (x < 0) x = -x; y = b + 25; if (y < 0) y = -y
    printf "%.2e", (x > y ? x : y) / 25 }')
  echo "$prob,$n,$(value "$f.out" dofs),$(value "$f.out" multipliers),$solver,$np,$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }'),$(value "$f.out" time_mesh),$(value "$f.out" time_assemble),$(value "$f.out" time_solve),$(value "$f.out" time_post),$(value "$f.out" solver_iterations),$(value "$f.out" solver_residual),$(value "$f.out" peak_rss_total_mb),$err,$(value "$f.out" max_u),$status" >> "$CSV"
  tail -1 "$CSV" >&2
}

if [ -n "$ROWS" ]; then
  # each row REPS times, in rounds (every row once a round: a machine
  # that slows down or speeds up during the call does so for every row
  # alike); the run of median wall time replaces the row of the full sweep
  cp "$FULL" "$W/full.csv" || exit 1
  rm -f "$W"/row[0-9]*.csv
  i=0 most=0
  for spec in $ROWS; do
    i=$((i + 1))
    echo "$HEAD" > "$W/row$i.csv"
    reps=$(echo "$spec" | cut -d: -f5)
    [ "${reps:-$REPS}" -gt $most ] && most=${reps:-$REPS}
  done
  r=0
  while [ $r -lt $most ]; do
    i=0
    for spec in $ROWS; do
      i=$((i + 1))
      IFS=: read -r p n s np reps <<EOS
$spec
EOS
      [ $r -lt "${reps:-$REPS}" ] || continue
      echo "$HEAD" > "$CSV"
      run "$p" "$n" "$s" "$np"
      tail -1 "$CSV" >> "$W/row$i.csv"
    done
    r=$((r + 1))
  done
  for f in "$W"/row[0-9]*.csv; do     # not rows.csv, the last run
    k=$(( $(wc -l < "$f") - 1 ))
    med=$(tail -n +2 "$f" | sort -t, -k7,7g | sed -n "$(( (k + 1) / 2 ))p")
    awk -F, -v OFS=, -v row="$med" 'BEGIN { split(row, m, ",") }
      $1 == m[1] && $2 == m[2] && $5 == m[5] && $6 == m[6] { print row; next } { print }' \
      "$W/full.csv" > "$W/full.new" && mv "$W/full.new" "$W/full.csv"
  done
  FIRST=$(head -1 "$OUT/solvers.txt")
  NOTE="$FIRST Rows re-measured $(date -u +%Y-%m-%d) (each the median wall time of its runs, the rows taking turns, P:N:SOLVER:NP:RUNS, default $REPS; load average $LOAD0 at the start, $(cut -d' ' -f1-3 /proc/loadavg) at the end): $ROWS."
  cp "$W/full.csv" "$FULL" || exit 1
  CSV=$FULL
  TN= TD= CN= CD= TH= CH=
elif [ $QUICK = 1 ]; then
  TN="10 14 20" TD="10 14 20" CN="14 20" CD="14 20" TH="20" CH="20"
else
  TN="6 8 10 14 20 28 35 45 55" TD="6 8 10 14 20 28 35"
  CN="6 8 10 14 20 33 45 69" CD="6 8 10 14 20 33 45"
  TH="28 55" CH="33 69"
fi
for n in $TD; do run taylor "$n" direct 1; done
for n in $TN; do run taylor "$n" petsc 1; run taylor "$n" petsc 2; done
for n in $TH; do run taylor "$n" petsc-hypre 2; done
for n in $CD; do run cube "$n" direct 1; done
for n in $CN; do run cube "$n" petsc 1; run cube "$n" petsc 2; done
for n in $CH; do run cube "$n" petsc-hypre 2; done

# ---- the table and the checks --------------------------------------------
{
  echo "${NOTE:-Measured $(date -u +%Y-%m-%d) on $(nproc) cores, load average $LOAD0 at the start, $(cut -d' ' -f1-3 /proc/loadavg) at the end (other jobs share the machine); wall = the whole mpirun.}"
  echo
  echo "| problem | n | dofs | mult. | solver | np | wall s | mesh s | assemble s | solve s | post s | iterations | residual | peak MB (sum) | err lambda | status |"
  echo "|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  awk -F, 'NR > 1 { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
    $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $17 }' "$CSV"
  echo
  echo "Acceptance (taylor, petsc, 2 processes):"
  awk -F, 'NR > 1 && $1 == "taylor" && $5 == "petsc" && $6 == 2 && $3 >= 1000000 {
      printf "  %s dofs: lambda error %s (<= 1e-8: %s), wall %s s (<= 60: %s), memory %s MB (<= 8192: %s)\n",
        $3, $15, ($15 != "" && $15 + 0 <= 1e-8) ? "yes" : "NO", $7, ($7 <= 60) ? "yes" : "NO", $14, ($14 <= 8192) ? "yes" : "NO" }
    NR > 1 && $1 == "taylor" && $5 == "petsc" && $6 == 2 && $3 >= 120000 && $3 < 160000 {
      printf "  %s dofs: wall %s s (<= 5: %s), lambda error %s\n", $3, $7, ($7 <= 5) ? "yes" : "NO", $15 }' "$CSV"
  echo
  echo "Contact against plain elasticity (petsc, 2 processes, about a million dofs; rerun both rows with --rows to compare them in one run):"
  awk -F, 'NR > 1 && $5 == "petsc" && $6 == 2 && $3 >= 1000000 && $17 == "ok" { w[$1] = $7; it[$1] = $12 }
    END { if (!("taylor" in w) || !("cube" in w)) { print "  (needs both rows: --rows \"taylor:55:petsc:2 cube:69:petsc:2\")"; exit }
          rw = w["taylor"] / w["cube"]; ri = it["taylor"] / it["cube"]
          printf "  wall %s / %s s = %.2f (<= 1.3: %s), CG iterations %s / %s = %.2f (<= 1.3: %s)\n",
            w["taylor"], w["cube"], rw, rw <= 1.3 ? "yes" : "NO", it["taylor"], it["cube"], ri, ri <= 1.3 ? "yes" : "NO" }' "$CSV"
} > "$OUT/solvers.txt"
cat "$OUT/solvers.txt"
chart "$CSV"
