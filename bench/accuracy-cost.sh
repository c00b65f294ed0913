#!/bin/sh
# accuracy-cost.sh -- what accuracy costs in time           [LAC §5.2-5.3; ch. 12]
#
#   sh bench/accuracy-cost.sh [BUILD_DIR] [--quick] [--out DIR] [--from CSV]
#
# Runs the self-included spheres (axisymmetric tri6, quad8; 3D tet10, hex20,
# hex27) and the manufactured convergence problems (2D tri3, tri6, quad4,
# quad8; 3D tet4, tet10, hex8, hex20, hex27) over several mesh levels, each
# run with the contact strategies of solve/lac_strategy.h (chapter 07,
# section 4): auto (what a user gets: dense up to 600 unknowns, else schur,
# or split when a body is held by contact alone), then every other
# strategy that applies -- dense (at most DENSE_MAX dofs), schur (refused,
# and skipped, when a body is held by contact alone), augmented, split and
# saddle (in 3D at most SADDLE_MAX3D dofs) -- except the one auto chose
# (its row is the auto row: same code, same numbers).  petsc is left to
# chapter 13 (add it to STRATEGIES to try it).  Records, per run, the
# errors (u and lambda), the size and the time of every stage.  Writes
# into DIR (BUILD_DIR/accuracy-cost; `make figures` passes --out figures):
#   accuracy-cost.csv        one row per run (the columns are below)
#   accuracy-cost.txt        the same as a table, then the highlights
#   accuracy-cost-dofs.png   error against dofs (auto), one curve per element
#   accuracy-cost-time.png   error against time (auto), one curve per element
#   accuracy-cost-strategies.png  solve-stage time against dofs, per strategy
#   accuracy-cost-split.png  where the time goes: stages of the finest runs
#
# Columns: strategy = the one asked for, used = the one that solved (auto:
#   its choice; another: itself, or saddle after a fallback).
# Errors: err_u = rel_l2_err_u (||u - u_h||_0 / ||u||_0); err_lambda =
#   spheres: max_rel_err_lambda (max over macro-elements of |lambda_h -
#     lambda| / |lambda|, the paper's Tables 3-4), manufactured: l2_err_lambda
#     / ||lambda||_{0,Gamma_C} (relative L2 error, Tables 5-6 in relative
#     form; ||lambda|| = 0.0146488 in 2D, 0.0133600 in 3D, by hand from the
#     exact pressure).
# Times (seconds, wall clock, measured inside the run by the library: the
#   time_* lines of `lac run --timings`, which figures/figrun prints with
#   microseconds): mesh (gmsh meshing and reading), refine (macro-mesh
#   cuts), pairing, contact (the rest of the contact stage: marking the
#   contact nodes), material, assemble (K, F, and the LAC matrix C and gaps
#   G), factor_K (the strategy's analyses and factorizations: K for schur,
#   K + C_A W C_A^T for augmented, the two blocks for split, the whole
#   saddle matrix for dense and saddle), active_set (the rest of the
#   strategy's work in the active-set iterations: columns of the Schur
#   complement, Krylov iterations, substitutions, refinement), solve_other
#   (the rest of the solve stage: statuses, residuals, the check of the
#   bodies held), post (stresses, errors); total = all of them (the output
#   stage excluded, no files are written); wall = the whole process as
#   timed by this script (adds the program start, about 0.1 s, mostly
#   gmsh's initialisation).
#
# --from CSV: no runs, the table and charts from a CSV of this script
# (e.g. the rows of two runs put together).
# Environment: MAX_MEMORY (figrun's --max-memory, default 80 % of the
# machine: the limit of the estimate that guards a .geo's mesh; the 3D
# spheres at level 2 are estimated at 2-6 GB); STRATEGIES ("dense schur augmented split saddle"), tried
# after auto; DENSE_MAX (6000; 1500 with --quick) dofs for dense;
# SADDLE_MAX3D (40000) dofs for saddle in 3D; REPEAT (3; 1 with --quick)
# runs of each case under a second; CASES to run a subset
# ("manufactured2d:tri3 spheres3d:hex20 ...").  The full run takes 15-25
# minutes on 2 cores; --quick (levels 0-1) about half a minute.
ARGS="$*"
B=build
QUICK=0
OUT=
FROM=
while [ $# -gt 0 ]; do
  case $1 in
    --quick) QUICK=1 ;;
    --out) shift; OUT=${1:?--out needs a directory} ;;
    --from) shift; FROM=${1:?--from needs a CSV file} ;;
    -*) echo "accuracy-cost.sh: unknown option '$1'" >&2; exit 2 ;;
    *) B=$1 ;;
  esac
  shift
done
OUT=${OUT:-$B/accuracy-cost}
FIGRUN=$B/figures/figrun
${MAKE:-make} -s B="$B" "$FIGRUN" >&2 || exit 1     # up to date: nothing
command -v gnuplot > /dev/null || { echo "accuracy-cost.sh: gnuplot not found" >&2; exit 1; }
mkdir -p "$OUT" || exit 1
OUTABS=$(cd "$OUT" && pwd)
W=$B/accuracy-cost-work
[ $QUICK = 1 ] && W=$B/accuracy-cost-work-quick
rm -rf "$W"
mkdir -p "$W" || exit 1
D=chapters/09-spheres-rates
if [ $QUICK = 1 ]; then DENSE_MAX=${DENSE_MAX:-1500}; else DENSE_MAX=${DENSE_MAX:-6000}; fi
SADDLE_MAX3D=${SADDLE_MAX3D:-40000}
if [ $QUICK = 1 ]; then REPEAT=${REPEAT:-1}; else REPEAT=${REPEAT:-3}; fi
STRATEGIES=${STRATEGIES:-dense schur augmented split saddle}

# experiment:element:levels (full), and the quick levels
ALL="spheres-axi:tri6:0-4 spheres-axi:quad8:0-4
spheres3d:tet10:0-2 spheres3d:hex20:0-2 spheres3d:hex27:0-2
manufactured2d:tri3:0-5 manufactured2d:quad4:0-5 manufactured2d:tri6:0-5 manufactured2d:quad8:0-5
manufactured3d:tet4:0-4 manufactured3d:hex8:0-4 manufactured3d:tet10:0-3 manufactured3d:hex20:0-3 manufactured3d:hex27:0-3"
CASES=${CASES:-$ALL}

CSV=$W/runs.csv
echo "experiment,element,level,strategy,used,dofs,multipliers,active,h,err_u,err_h1_u,err_lambda,time_mesh,time_refine,time_pairing,time_contact,time_material,time_assemble,time_factor_K,time_active_set,time_solve_other,time_post,time_total,wall" > "$CSV"

now () { date +%s.%N; }
T0=$(date +%s)
load0=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)

# one EXP EL LEVEL STRATEGY: run (up to REPEAT times while a run takes
# less than a second: the fastest is kept, the usual defence against the
# noise of other jobs on the machine), append a CSV row; print the dofs
# and the strategy used.  Status 3: the strategy does not apply (schur
# with a body held by contact alone, split with every body held by its
# Dirichlet conditions), no row.
one () {
  exp=$1 el=$2 lv=$3 st=$4
  f=$W/$exp-$el-$lv-$st
  best='' k=0
  while [ $k -lt "$REPEAT" ]; do
    k=$((k + 1))
    t1=$(now)
    if ! "$FIGRUN" "$D/$exp.scene" --set element="$el" --set level="$lv" \
         --strategy "$st" ${MAX_MEMORY:+--max-memory "$MAX_MEMORY"} \
         --timings --no-output --quiet > "$f.try" 2> "$f.err"; then
      grep -q "needs every body held by its Dirichlet conditions" "$f.err" && return 3
      grep -q "needs a body held by contact alone" "$f.err" && return 3
      echo "accuracy-cost.sh: $exp $el level $lv $st failed: $(tail -1 "$f.err")" >&2
      return 1
    fi
    t2=$(now)
    tot=$(sed -n 's/^time_total = //p' "$f.try")
    if [ -z "$best" ] || awk -v a="$tot" -v b="$best" 'BEGIN { exit !(a < b) }'; then
      best=$tot
      mv "$f.try" "$f.sum"
      wt1=$t1 wt2=$t2
    fi
    awk -v a="$tot" 'BEGIN { exit !(a >= 1) }' && break
  done
  rm -f "$f.try"
  t1=$wt1 t2=$wt2
  awk -F' = ' -v ex="$exp" -v el="$el" -v lv="$lv" -v st="$st" -v t1="$t1" -v t2="$t2" '
    { v[$1] = $2 }
    END {
      if (ex ~ /^spheres/) el_lam = v["max_rel_err_lambda"]
      else el_lam = v["l2_err_lambda"] / (ex == "manufactured2d" ? 0.0146488 : 0.0133600)
      tc = v["time_contact"] - v["time_refine"] - v["time_pairing"]; if (tc < 0) tc = 0
      ts = v["time_solve"] - v["time_factor_K"] - v["time_active_set"]; if (ts < 0) ts = 0
      printf "%s,%s,%s,%s,%s,%d,%d,%d,%.6e,%.6e,%.6e,%.6e,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.3f\n",
        ex, el, lv, st, v["solver_used"], v["dofs"], v["multipliers"], v["active"], v["h"],
        v["rel_l2_err_u"], v["rel_h1_err_u"], el_lam,
        v["time_mesh"], v["time_refine"], v["time_pairing"], tc, v["time_material"],
        v["time_assemble"], v["time_factor_K"], v["time_active_set"], ts,
        v["time_post"], v["time_total"], t2 - t1 }' "$f.sum" >> "$CSV"
  echo "$(sed -n 's/^dofs = //p' "$f.sum") $(sed -n 's/^solver_used = //p' "$f.sum")"
}

nfail=0
[ -n "$FROM" ] && { cp "$FROM" "$CSV" || exit 1; CASES=; }
for c in $CASES; do
  exp=${c%%:*}; r=${c#*:}; el=${r%%:*}; lv=${r#*:}
  [ "$lv" = "$r" ] && lv=0-2
  lo=${lv%-*}; hi=${lv#*-}
  [ $QUICK = 1 ] && hi=$((lo + 1))
  dim=2; case $exp in *3d) dim=3 ;; esac
  l=$lo
  while [ "$l" -le "$hi" ]; do
    echo "accuracy-cost: $exp $el level $l ..." >&2
    r=$(one "$exp" "$el" "$l" auto) || { nfail=$((nfail + 1)); break; }
    n=${r% *} chosen=${r#* }
    for st in $STRATEGIES; do
      [ "$st" = "$chosen" ] && continue
      case $st in
        dense) [ "$n" -le "$DENSE_MAX" ] || continue ;;
        saddle) [ "$dim" = 2 ] || [ "$n" -le "$SADDLE_MAX3D" ] || continue ;;
      esac
      one "$exp" "$el" "$l" "$st" > /dev/null
      case $? in 0|3) ;; *) nfail=$((nfail + 1)) ;; esac
    done
    l=$((l + 1))
  done
done
load1=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)
cp "$CSV" "$OUT/accuracy-cost.csv"

# CSV fields: 1 experiment 2 element 3 level 4 strategy 5 used 6 dofs
# 7 multipliers 8 active 9 h 10 err_u 11 err_h1_u 12 err_lambda 13 mesh
# 14 refine 15 pairing 16 contact 17 material 18 assemble 19 factor_K
# 20 active_set 21 solve_other 22 post 23 total 24 wall.  The solve stage
# is 19 + 20 + 21.  A strategy's time on a run: its own row, or the auto
# row when auto chose it.

# ---- the readable table and the highlights ------------------------------
TXT=$OUT/accuracy-cost.txt
{
  echo "# accuracy-cost.txt -- written by: sh bench/accuracy-cost.sh $ARGS"
  echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average before/after: $load0 / $load1"
  echo "# err_u: relative L2 error of u; err_lam: spheres max relative error of lambda,"
  echo "# manufactured relative L2 error of lambda on Gamma_C.  Times in seconds (wall)."
  echo "# strategies tried after auto: $STRATEGIES (dense up to $DENSE_MAX dofs, saddle in 3D up to $SADDLE_MAX3D)"
  echo "# split of total: mesh refine pairing contact material assemble factor_K active_set solve_other post"
  echo
  awk -F, 'NR > 1 { printf "%-14s %-5s %2s %-9s %-9s %7d %10.3e %10.3e %9.4f | %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f %8.4f %8.4f %7.4f %7.4f %6.2f\n",
      $1, $2, $3, $4, $5, $6, $10, $12, $23, $13, $14, $15, $16, $17, $18, $19, $20, $21, $22, $24 }' "$CSV" \
  | awk 'BEGIN { printf "%-14s %-5s %2s %-9s %-9s %7s %10s %10s %9s | %7s %7s %7s %7s %7s %7s %8s %8s %7s %7s %6s\n",
      "experiment", "elem", "lv", "strategy", "used", "dofs", "err_u", "err_lam", "total",
      "mesh", "refine", "pairing", "contact", "materl", "assembl", "factorK", "act.set", "solve*", "post", "wall" } { print }'
  echo
  echo "## 1. what a target error costs: for each element, the first level (auto) that reaches it,"
  echo "##    cheapest first (total time of the run; '*' marks the fewest dofs)"
  awk -F, 'NR > 1 && $4 == "auto" {
      nu = split("1e-3 1e-4 1e-5 1e-6", tu, " "); nl = split("1e-1 1e-2 1e-3 1e-4", tl, " ")
      for (i = 1; i <= nu; i++) if ($10 + 0 <= tu[i] + 0) add($1 "  u <= " tu[i], $2, $3, $6, $23)
      for (i = 1; i <= nl; i++) if ($12 + 0 <= tl[i] + 0) add($1 "  lambda <= " tl[i], $2, $3, $6, $23) }
    function add(g, e, l, d, t) {
      if ((g, e) in done) return
      done[g, e] = 1; if (!(g in cnt)) gs[++ng] = g
      c = ++cnt[g]; E[g, c] = e; L[g, c] = l; Dd[g, c] = d; T[g, c] = t }
    END {
      for (i = 1; i <= ng; i++) for (j = i + 1; j <= ng; j++) if (gs[j] < gs[i]) { x = gs[i]; gs[i] = gs[j]; gs[j] = x }
      for (i = 1; i <= ng; i++) { g = gs[i]; n = cnt[g]; m = 0
        for (a = 1; a <= n; a++) { o[a] = a; if (m == 0 || Dd[g, a] < Dd[g, m]) m = a }
        for (a = 1; a <= n; a++) for (b = a + 1; b <= n; b++) if (T[g, o[b]] < T[g, o[a]]) { x = o[a]; o[a] = o[b]; o[b] = x }
        printf "  %-32s", g
        for (a = 1; a <= n; a++) { k = o[a]; printf "%s %s L%s %d%s dofs %.3f s", (a > 1 ? "," : ""), E[g, k], L[g, k], Dd[g, k], k == m ? "*" : "", T[g, k] }
        printf "\n" } }' "$CSV"
  echo
  echo "## 2. the strategies compared: time of the solve stage (factor_K + active_set + solve_other, s)"
  echo "##    of the same run; auto = what a user gets (the strategy it chose in brackets);"
  echo "##    ratio = auto / fastest; '-' not run (dense only up to $DENSE_MAX dofs, saddle in 3D up to $SADDLE_MAX3D)"
  awk -F, -v list="$STRATEGIES" 'NR > 1 { k = $1 " " $2 " L" $3
      if (!(k in seen)) { seen[k] = 1; o[++n] = k }
      s = $4; if (s == "auto") { s = $5; au[k] = $19 + $20 + $21; ch[k] = $5; tot[k] = $23; d[k] = $6 }
      else if ($5 != $4) fb[k] = fb[k] " " $4 "->" $5
      t[k, s] = $19 + $20 + $21 }
    END { ns = split(list, S, " ")
      printf "  %-26s %7s %8s", "run", "dofs", "total"
      printf " %18s", "auto"
      for (j = 1; j <= ns; j++) printf " %9s", S[j]
      printf " %6s\n", "ratio"
      for (i = 1; i <= n; i++) { k = o[i]; b = au[k]
        printf "  %-26s %7d %8.4f %9.4f %-8s", k, d[k], tot[k], au[k], "(" ch[k] ")"
        for (j = 1; j <= ns; j++) { if ((k, S[j]) in t) { x = t[k, S[j]]; printf " %9.4f", x; if (x < b) b = x } else printf " %9s", "-" }
        printf " %6.2f%s\n", au[k] / (b > 0 ? b : 1e-6), (k in fb) ? "  fallback:" fb[k] : "" } }' "$CSV"
  echo
  echo "## 2b. each strategy against the fastest on the same run (solve stage): median and range of"
  echo "##     the ratio, by size and dimension (2D = manufactured2d and spheres-axi)"
  awk -F, 'NR > 1 { k = $1 " " $2 " L" $3
      if (!(k in seen)) { seen[k] = 1; o[++n] = k; dd[k] = $6; dm[k] = ($1 ~ /3d$/) ? "3D" : "2D" }
      s = ($4 == "auto") ? $5 : $4; t[k, s] = $19 + $20 + $21; have[s] = 1 }
    END { na = split("dense schur augmented split saddle petsc", A, " "); ns = 0
      for (j = 1; j <= na; j++) if (A[j] in have) S[++ns] = A[j]
      nb = split("0 601 10000 1e12", B, " ")
      printf "  %-3s %-12s %5s", "dim", "dofs", "runs"
      for (j = 1; j <= ns; j++) printf " %22s", S[j]
      printf "\n"
      for (dmi = 1; dmi <= 2; dmi++) { D = dmi == 1 ? "2D" : "3D"
        for (bi = 1; bi < nb; bi++) { m = 0; delete cnt; delete r
          for (i = 1; i <= n; i++) { k = o[i]; if (dm[k] != D || dd[k] < B[bi] + 0 || dd[k] >= B[bi + 1] + 0) continue
            m++; best = -1
            for (j = 1; j <= ns; j++) if ((k, S[j]) in t && (best < 0 || t[k, S[j]] < best)) best = t[k, S[j]]
            for (j = 1; j <= ns; j++) if ((k, S[j]) in t) r[j, ++cnt[j]] = t[k, S[j]] / (best > 0 ? best : 1e-6) }
          if (m == 0) continue
          printf "  %-3s %-12s %5d", D, (bi + 1 == nb ? ">= " B[bi] : B[bi] "-" (B[bi + 1] - 1)), m
          for (j = 1; j <= ns; j++) { c = cnt[j] + 0
            if (c == 0) { printf " %22s", "-"; continue }
            for (a = 1; a <= c; a++) for (b = a + 1; b <= c; b++) if (r[j, b] < r[j, a]) { x = r[j, a]; r[j, a] = r[j, b]; r[j, b] = x }
            med = (c % 2) ? r[j, (c + 1) / 2] : (r[j, c / 2] + r[j, c / 2 + 1]) / 2
            printf " %22s", sprintf("%.2f (%.2f-%.2f) %d", med, r[j, 1], r[j, c], c) }
          printf "\n" } } }' "$CSV"
  echo "  (median (min-max) count; 1.00 = the fastest on every run)"
  echo
  echo "## 3. where the time goes: the finest auto run of each element (percent of total)"
  awk -F, 'NR > 1 && $4 == "auto" { k = $1 " " $2; if ($6 > d[k]) { d[k] = $6; r[k] = $0 }; if (!(k in seen)) { seen[k] = 1; o[++n] = k } }
    END { printf "  %-24s %7s %-7s %8s | %5s %6s %7s %7s %6s %8s %8s %7s %6s %5s\n", "run", "dofs", "used", "total s",
            "mesh", "refine", "pairing", "contact", "matrl", "assemble", "factorK", "act.set", "solve*", "post"
      for (i = 1; i <= n; i++) { split(r[o[i]], f, ","); tt = f[23] > 0 ? f[23] : 1
        printf "  %-24s %7d %-7s %8.3f | %5.1f %6.1f %7.1f %7.1f %6.1f %8.1f %8.1f %7.1f %6.1f %5.1f\n", o[i] " L" f[3], f[6], f[5], f[23],
          100*f[13]/tt, 100*f[14]/tt, 100*f[15]/tt, 100*f[16]/tt, 100*f[17]/tt, 100*f[18]/tt, 100*f[19]/tt, 100*f[20]/tt, 100*f[21]/tt, 100*f[22]/tt } }' "$CSV"
  echo "  (assemble includes the LAC matrix C and the gaps G; contact = the rest of the contact"
  echo "   stage; factorK = the strategy's factorizations; act.set = the rest of its work in the"
  echo "   active-set iterations; solve* = the rest of the solve stage: statuses, residuals)"
  echo
  echo "## 4. observed rates: slope of log(err) against log(dofs) between the last two levels (auto)"
  awk -F, 'NR > 1 && $4 == "auto" { k = $1 " " $2; if (k in pd) { su[k] = log($10 / pu[k]) / log($6 / pd[k]); sl[k] = log($12 / pl[k]) / log($6 / pd[k]) }
      pd[k] = $6; pu[k] = $10; pl[k] = $12; if (!(k in seen)) { seen[k] = 1; o[++n] = k }
      dim[k] = ($1 ~ /3d$/) ? 3 : 2 }
    END { printf "  %-22s %10s %12s   %s\n", "run", "err_u", "err_lambda", "(times dim = rate in h)"
      for (i = 1; i <= n; i++) if (o[i] in su)
        printf "  %-22s %10.2f %12.2f   h-rates %.2f %.2f\n", o[i], su[o[i]], sl[o[i]], -dim[o[i]] * su[o[i]], -dim[o[i]] * sl[o[i]] }' "$CSV"
  echo
  echo "## 5. the strategies agree: largest relative difference of err_u and err_lambda between"
  echo "##    the strategies of one run (the CSV keeps 7 digits), over all runs"
  awk -F, 'NR > 1 { k = $1 " " $2 " L" $3
      if (k in u0) { du = ($10 - u0[k]) / u0[k]; dl = ($12 - l0[k]) / l0[k]; if (du < 0) du = -du; if (dl < 0) dl = -dl
        if (du > mu) { mu = du; ku = k " " $4 } if (dl > ml) { ml = dl; kl = k " " $4 } ; m++ }
      else { u0[k] = $10; l0[k] = $12 }
      if ($4 != "auto" && $5 != $4) nf++ }
    END { printf "  %d comparisons: err_u %.1e%s, err_lambda %.1e%s; %d fallbacks to saddle\n", m,
            mu, (mu > 0 ? " (" ku ")" : ""), ml, (ml > 0 ? " (" kl ")" : ""), nf }' "$CSV"
} > "$TXT"

# ---- charts -------------------------------------------------------------
# data per experiment / element (auto): dofs err_u err_lambda total
awk -F, -v W="$W" 'NR > 1 && $4 == "auto" { f = W "/d-" $1 "-" $2 ".dat"; print $6, $10, $12, $23 > f }' "$CSV"
EXPS="spheres-axi spheres3d manufactured2d manufactured3d"
elems_of () { awk -F, -v e="$1" 'NR > 1 && $1 == e && !s[$2]++ { printf "%s ", $2 }' "$CSV"; }
title_of () {
  case $1 in
    spheres-axi) echo "spheres, axisymmetric" ;; spheres3d) echo "spheres, 3D octant" ;;
    manufactured2d) echo "manufactured 2D" ;; manufactured3d) echo "manufactured 3D" ;;
  esac
}
lamlabel_of () {
  case $1 in spheres*) echo "max relative error of {/Symbol l}" ;; *) echo "relative L^2 error of {/Symbol l}" ;; esac
}
color_of () {
  case $1 in
    tri3) echo "#440154" ;; quad4) echo "#3b528b" ;; tri6) echo "#21918c" ;; quad8) echo "#5ec962" ;;
    tet4) echo "#440154" ;; hex8) echo "#3b528b" ;; tet10) echo "#21918c" ;; hex20) echo "#5ec962" ;;
    hex27) echo "#e08000" ;; *) echo "black" ;;
  esac
}
pt_of () {
  case $1 in tri3|tet4) echo 7 ;; quad4|hex8) echo 5 ;; tri6|tet10) echo 9 ;; quad8|hex20) echo 11 ;; *) echo 13 ;; esac
}
# chart XCOL XLABEL FILE TITLE: 2 x 4 panels (rows: u, lambda; columns: experiments)
chart () {
  xcol=$1 xlabel=$2 file=$3 ttl=$4
  {
    echo 'set terminal pngcairo size 1800,950 font "DejaVu Sans,12" enhanced'
    echo "set output '$OUTABS/$file'"
    echo "set multiplot layout 2,4 title \"$ttl\" font \",15\""
    echo 'set logscale xy; set grid; set format y "10^{%L}"; set key top right samplen 2 font ",11"'
    echo 'set format x "10^{%L}"'
    for row in u lambda; do
      for e in $EXPS; do
        els=$(elems_of "$e")
        [ -n "$els" ] || { echo 'set multiplot next'; continue; }
        echo "set title \"$(title_of "$e")\""
        echo "set xlabel \"$xlabel\""
        if [ $row = u ]; then ycol=2; echo 'set ylabel "relative L^2 error of u"'
        else ycol=3; echo "set ylabel \"$(lamlabel_of "$e")\""; fi
        printf 'plot '
        sep=''
        for el in $els; do
          f=d-$e-$el.dat
          [ -f "$W/$f" ] || continue
          printf "%s'%s' using %s:%s with linespoints lw 2 pt %s ps 1.2 lc rgb \"%s\" title \"%s\"" \
            "$sep" "$f" "$xcol" "$ycol" "$(pt_of "$el")" "$(color_of "$el")" "$el"
          sep=', '
        done
        echo
      done
    done
    echo 'unset multiplot'
  } > "$W/$file.gp"
  (cd "$W" && gnuplot "$file.gp") || { echo "accuracy-cost.sh: gnuplot failed on $W/$file.gp" >&2; nfail=$((nfail + 1)); }
}
chart 1 "dofs" accuracy-cost-dofs.png "error against the number of dofs (strategy auto; one point per mesh level)"
chart 4 "total time of the run (s)" accuracy-cost-time.png "error against the time of the whole run (mesh to post, strategy auto; one point per mesh level)"

# solve-stage time against dofs for each strategy, 2D and 3D problems apart
awk -F, -v W="$W" 'NR > 1 { d = ($1 ~ /3d$/) ? "3d" : "2d"; s = ($4 == "auto") ? $5 : $4
    print $6, $19 + $20 + $21 > (W "/s-" d "-" s ".dat") }' "$CSV"
{
  echo 'set terminal pngcairo size 1400,620 font "DejaVu Sans,13" enhanced'
  echo "set output '$OUTABS/accuracy-cost-strategies.png'"
  echo 'set multiplot layout 1,2 title "time of the solve stage (factorizations and active-set iterations) against the size, for each strategy\\n(every run of the study: all experiments, elements and levels; the auto runs under the strategy auto chose)" font ",14"'
  echo 'set logscale xy; set grid; set key top left; set format x "10^{%L}"; set format y "10^{%L}"'
  echo 'set xlabel "dofs"; set ylabel "solve stage (s)"'
  for d in 2d 3d; do
    ls "$W"/s-$d-*.dat > /dev/null 2>&1 || { echo 'set multiplot next'; continue; }
    [ "$d" = 2d ] && echo 'set title "2D and axisymmetric"' || echo 'set title "3D"'
    printf 'plot '
    sep=''
    for s in dense saddle augmented split schur petsc; do
      case $s in
        dense) c='#d62728' p=7 ;; saddle) c='#1f77b4' p=5 ;; augmented) c='#9467bd' p=11 ;;
        split) c='#ff7f0e' p=13 ;; schur) c='#2ca02c' p=9 ;; petsc) c='#555555' p=3 ;;
      esac
      [ -f "$W/s-$d-$s.dat" ] || continue
      printf "%s's-%s-%s.dat' using 1:2 with points pt %s ps 1.1 lc rgb \"%s\" title \"%s\"" "$sep" "$d" "$s" "$p" "$c" "$s"
      sep=', '
    done
    echo
  done
  echo 'unset multiplot'
} > "$W/strategies.gp"
(cd "$W" && gnuplot strategies.gp) || { echo "accuracy-cost.sh: gnuplot failed on $W/strategies.gp" >&2; nfail=$((nfail + 1)); }

# the split: stacked percentages for the finest auto run of each element
awk -F, 'NR > 1 && $4 == "auto" { k = $1 " " $2; if ($6 > d[k]) { d[k] = $6; r[k] = $0 }; if (!(k in seen)) { seen[k] = 1; o[++n] = k } }
  END { for (i = 1; i <= n; i++) { split(r[o[i]], f, ","); tt = f[23] > 0 ? f[23] : 1
      e = f[1]; sub(/manufactured/, "man. ", e); sub(/spheres-axi/, "sph. axi", e); sub(/spheres3d/, "sph. 3d", e)
      lab = sprintf("%s %s L%s\\n%d dofs, %.3g s", e, f[2], f[3], f[6], f[23])
      printf "\"%s\"", lab
      for (j = 13; j <= 22; j++) printf " %.2f", 100 * f[j] / tt
      printf "\n" } }' "$CSV" > "$W/split.dat"
{
  echo 'set terminal pngcairo size 1800,800 font "DejaVu Sans,12" enhanced'
  echo "set output '$OUTABS/accuracy-cost-split.png'"
  echo 'set title "where the time goes: stages of the finest run of each element (strategy auto), percent of the run" font ",14"'
  echo 'set style data histograms; set style histogram rowstacked; set style fill solid 0.9 border -1; set boxwidth 0.75'
  echo 'set ylabel "percent of the total time"; set yrange [0:100]; set grid y'
  echo 'set key outside right top vertical'
  echo 'set xtics rotate by -40 left font ",11"'
  echo 'set bmargin 9'
  echo 'plot "split.dat" using 2:xtic(1) title "mesh (gmsh)" lc rgb "#9e9e9e", \'
  echo '  "" using 3 title "refine (macro-mesh)" lc rgb "#440154", \'
  echo '  "" using 4 title "pairing" lc rgb "#414487", \'
  echo '  "" using 5 title "contact stage, rest" lc rgb "#2a788e", \'
  echo '  "" using 6 title "materials" lc rgb "#bcbddc", \'
  echo '  "" using 7 title "assembly of K, F, C, G" lc rgb "#22a884", \'
  echo '  "" using 8 title "factorizations (strategy)" lc rgb "#7ad151", \'
  echo '  "" using 9 title "active-set iterations (strategy)" lc rgb "#fde725", \'
  echo '  "" using 10 title "solve stage, rest" lc rgb "#f4a261", \'
  echo '  "" using 11 title "post (stresses, errors)" lc rgb "#e76f51"'
} > "$W/split.gp"
(cd "$W" && gnuplot split.gp) || { echo "accuracy-cost.sh: gnuplot failed on $W/split.gp" >&2; nfail=$((nfail + 1)); }

echo "accuracy-cost: $(($(wc -l < "$CSV") - 1)) runs in $(( $(date +%s) - T0 )) s, $nfail failures; $OUT/accuracy-cost.{csv,txt} and accuracy-cost-*.png" >&2
[ $nfail -eq 0 ]
