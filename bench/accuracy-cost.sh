#!/bin/sh
# accuracy-cost.sh -- what accuracy costs in time           [LAC §5.2-5.3; ch. 10]
#
#   sh bench/accuracy-cost.sh [BUILD_DIR] [--quick] [--out DIR]
#
# Runs the self-included spheres (axisymmetric tri6, quad8; 3D tet10, hex20,
# hex27) and the manufactured convergence problems (2D tri3, tri6, quad4,
# quad8; 3D tet4, tet10, hex8, hex20, hex27) over several mesh levels with
# each solver back end -- cholmod (the default), umfpack, and dense where it
# makes sense (at most DENSE_MAX dofs) -- and records, per run, the errors
# (u and lambda), the size and the time of every stage.  Writes into DIR
# (BUILD_DIR/accuracy-cost; `make figures` passes --out figures):
#   accuracy-cost.csv        one row per run (the columns are below)
#   accuracy-cost.txt        the same as a table, then the highlights
#   accuracy-cost-dofs.png   error against dofs (cholmod), one curve per element
#   accuracy-cost-time.png   error against time (cholmod), one curve per element
#   accuracy-cost-solvers.png  solve-stage time against dofs for each solver
#   accuracy-cost-split.png  where the time goes: stages of the finest runs
#
# Errors: err_u = rel_l2_err_u (||u - u_h||_0 / ||u||_0); err_lambda =
#   spheres: max_rel_err_lambda (max over macro-elements of |lambda_h -
#     lambda| / |lambda|, the paper's Tables 3-4), manufactured: l2_err_lambda
#     / ||lambda||_{0,Gamma_C} (relative L2 error, Tables 5-6 in relative
#     form; ||lambda|| = 0.0146488 in 2D, 0.0133600 in 3D, by hand from the
#     exact pressure).
# Times (seconds, wall clock, measured inside the run by the library:
#   figures/figrun prints `lac run --timings` with microseconds): the stages
#   mesh (gmsh meshing and reading), refine (macro-mesh cuts), pairing,
#   contact (the rest of the contact stage: marking the contact nodes),
#   assemble (materials, K, F, and the LAC matrix C and gaps G), factor_K (cholmod: the Cholesky factor of
#   K and the Schur complement), active_set (the active-set iterations:
#   saddle-point factorizations and solves), solve_other (the rest of the
#   solve stage: e.g. cholmod's failed attempt on a K made singular by a
#   body held by contact alone, before the umfpack fallback), post
#   (stresses, errors); total = all of them (the output stage excluded, no
#   files are written); wall = the whole process as timed by this script
#   (adds the program start, about 0.2 s, mostly gmsh's initialisation).
#
# Environment: DENSE_MAX (6000; 1500 with --quick) dofs for the dense
# solver; UMF_MAX3D (40000) dofs for umfpack in 3D; REPEAT (3; 1 with
# --quick) runs of each case under a second; CASES to run a subset
# ("manufactured2d:tri3 spheres3d:hex20 ...").  The full run takes 10-20
# minutes on 2 cores; --quick (levels 0-1) about a minute.
ARGS="$*"
B=build
QUICK=0
OUT=
while [ $# -gt 0 ]; do
  case $1 in
    --quick) QUICK=1 ;;
    --out) shift; OUT=${1:?--out needs a directory} ;;
    -*) echo "accuracy-cost.sh: unknown option '$1'" >&2; exit 2 ;;
    *) B=$1 ;;
  esac
  shift
done
OUT=${OUT:-$B/accuracy-cost}
FIGRUN=$B/figures/figrun
if [ ! -x "$FIGRUN" ]; then
  ${MAKE:-make} -s B="$B" "$FIGRUN" >&2 || exit 1
fi
command -v gnuplot > /dev/null || { echo "accuracy-cost.sh: gnuplot not found" >&2; exit 1; }
mkdir -p "$OUT" || exit 1
OUTABS=$(cd "$OUT" && pwd)
W=$B/accuracy-cost-work
[ $QUICK = 1 ] && W=$B/accuracy-cost-work-quick
rm -rf "$W"
mkdir -p "$W" || exit 1
D=chapters/08-experiments
if [ $QUICK = 1 ]; then DENSE_MAX=${DENSE_MAX:-1500}; else DENSE_MAX=${DENSE_MAX:-6000}; fi
UMF_MAX3D=${UMF_MAX3D:-40000}
if [ $QUICK = 1 ]; then REPEAT=${REPEAT:-1}; else REPEAT=${REPEAT:-3}; fi

# experiment:element:levels (full), and the quick levels
ALL="spheres-axi:tri6:0-4 spheres-axi:quad8:0-4
spheres3d:tet10:0-2 spheres3d:hex20:0-2 spheres3d:hex27:0-2
manufactured2d:tri3:0-5 manufactured2d:quad4:0-5 manufactured2d:tri6:0-5 manufactured2d:quad8:0-5
manufactured3d:tet4:0-4 manufactured3d:hex8:0-4 manufactured3d:tet10:0-3 manufactured3d:hex20:0-3 manufactured3d:hex27:0-3"
CASES=${CASES:-$ALL}

CSV=$W/runs.csv
echo "experiment,element,level,solver,solver_used,dofs,multipliers,active,h,err_u,err_h1_u,err_lambda,time_mesh,time_refine,time_pairing,time_contact,time_assemble,time_factor_K,time_active_set,time_solve_other,time_post,time_total,wall" > "$CSV"

now () { date +%s.%N; }
T0=$(date +%s)
load0=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)

# one EXP EL LEVEL SOLVER: run (up to REPEAT times while a run takes less
# than a second: the fastest is kept, the usual defence against the noise
# of other jobs on the machine), append a CSV row; print the dofs
one () {
  exp=$1 el=$2 lv=$3 sol=$4
  f=$W/$exp-$el-$lv-$sol
  best='' k=0
  while [ $k -lt "$REPEAT" ]; do
    k=$((k + 1))
    t1=$(now)
    if ! "$FIGRUN" "$D/$exp.scene" --set element="$el" --set level="$lv" \
         --solver "$sol" --timings --no-output --quiet > "$f.try" 2> "$f.err"; then
      echo "accuracy-cost.sh: $exp $el level $lv $sol failed: $(tail -1 "$f.err")" >&2
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
  awk -F' = ' -v ex="$exp" -v el="$el" -v lv="$lv" -v sol="$sol" -v t1="$t1" -v t2="$t2" '
    { v[$1] = $2 }
    END {
      if (ex ~ /^spheres/) el_lam = v["max_rel_err_lambda"]
      else el_lam = v["l2_err_lambda"] / (ex == "manufactured2d" ? 0.0146488 : 0.0133600)
      tc = v["time_contact"] - v["time_refine"] - v["time_pairing"]; if (tc < 0) tc = 0
      ts = v["time_solve"] - v["time_factor_K"] - v["time_active_set"]; if (ts < 0) ts = 0
      printf "%s,%s,%s,%s,%s,%d,%d,%d,%.6e,%.6e,%.6e,%.6e,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.3f\n",
        ex, el, lv, sol, v["solver_used"], v["dofs"], v["multipliers"], v["active"], v["h"],
        v["rel_l2_err_u"], v["rel_h1_err_u"], el_lam,
        v["time_mesh"], v["time_refine"], v["time_pairing"], tc,
        v["time_material"] + v["time_assemble"], v["time_factor_K"], v["time_active_set"], ts,
        v["time_post"], v["time_total"], t2 - t1 }' "$f.sum" >> "$CSV"
  sed -n 's/^dofs = //p' "$f.sum"
}

nfail=0
for c in $CASES; do
  exp=${c%%:*}; r=${c#*:}; el=${r%%:*}; lv=${r#*:}
  [ "$lv" = "$r" ] && lv=0-2
  lo=${lv%-*}; hi=${lv#*-}
  [ $QUICK = 1 ] && hi=$((lo + 1))
  dim=2; case $exp in *3d) dim=3 ;; esac
  l=$lo
  while [ "$l" -le "$hi" ]; do
    echo "accuracy-cost: $exp $el level $l ..." >&2
    n=$(one "$exp" "$el" "$l" cholmod) || { nfail=$((nfail + 1)); break; }
    if [ "$dim" = 2 ] || [ "$n" -le "$UMF_MAX3D" ]; then
      one "$exp" "$el" "$l" umfpack > /dev/null || nfail=$((nfail + 1))
    fi
    if [ "$n" -le "$DENSE_MAX" ]; then
      one "$exp" "$el" "$l" dense > /dev/null || nfail=$((nfail + 1))
    fi
    l=$((l + 1))
  done
done
load1=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)
cp "$CSV" "$OUT/accuracy-cost.csv"

# ---- the readable table and the highlights ------------------------------
TXT=$OUT/accuracy-cost.txt
{
  echo "# accuracy-cost.txt -- written by: sh bench/accuracy-cost.sh $ARGS"
  echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average before/after: $load0 / $load1"
  echo "# err_u: relative L2 error of u; err_lam: spheres max relative error of lambda,"
  echo "# manufactured relative L2 error of lambda on Gamma_C.  Times in seconds (wall)."
  echo "# split of total: mesh refine pairing contact assemble factor_K active_set solve_other post"
  echo
  awk -F, 'NR > 1 { printf "%-14s %-5s %2s %-7s %-7s %7d %10.3e %10.3e %9.4f | %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f %8.4f %7.4f %7.4f %6.2f\n",
      $1, $2, $3, $4, $5, $6, $10, $12, $22, $13, $14, $15, $16, $17, $18, $19, $20, $21, $23 }' "$CSV" \
  | awk 'BEGIN { printf "%-14s %-5s %2s %-7s %-7s %7s %10s %10s %9s | %7s %7s %7s %7s %7s %7s %8s %7s %7s %6s\n",
      "experiment", "elem", "lv", "solver", "used", "dofs", "err_u", "err_lam", "total",
      "mesh", "refine", "pairing", "contact", "assembl", "factorK", "act.set", "solve*", "post", "wall" } { print }'
  echo
  echo "## 1. what a target error costs: for each element, the first level (cholmod) that reaches it,"
  echo "##    cheapest first (total time of the run; '*' marks the fewest dofs)"
  awk -F, 'NR > 1 && $4 == "cholmod" {
      nu = split("1e-3 1e-4 1e-5 1e-6", tu, " "); nl = split("1e-1 1e-2 1e-3 1e-4", tl, " ")
      for (i = 1; i <= nu; i++) if ($10 + 0 <= tu[i] + 0) add($1 "  u <= " tu[i], $2, $3, $6, $22)
      for (i = 1; i <= nl; i++) if ($12 + 0 <= tl[i] + 0) add($1 "  lambda <= " tl[i], $2, $3, $6, $22) }
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
  echo "## 2. dense against the sparse solvers (same run, total time in s; dense only up to $DENSE_MAX dofs)"
  awk -F, 'NR > 1 { k = $1 " " $2 " L" $3; t[k, $4] = $22; d[k] = $6; if (!(k in seen)) { seen[k] = 1; o[++n] = k } }
    END { printf "  %-26s %7s %9s %9s %9s  %s\n", "run", "dofs", "cholmod", "umfpack", "dense", "dense/best sparse"
      for (i = 1; i <= n; i++) { k = o[i]; if (!((k, "dense") in t)) continue
        s = t[k, "cholmod"]; if ((k, "umfpack") in t && t[k, "umfpack"] < s) s = t[k, "umfpack"]
        printf "  %-26s %7d %9.4f %9s %9.4f  %6.1f\n", k, d[k], t[k, "cholmod"],
          ((k, "umfpack") in t) ? sprintf("%.4f", t[k, "umfpack"]) : "-", t[k, "dense"], t[k, "dense"] / (s > 0 ? s : 1e-6) } }' "$CSV"
  echo
  echo "## 3. where the time goes: the finest cholmod run of each element (percent of total)"
  awk -F, 'NR > 1 && $4 == "cholmod" { k = $1 " " $2; if ($6 > d[k]) { d[k] = $6; r[k] = $0 }; if (!(k in seen)) { seen[k] = 1; o[++n] = k } }
    END { printf "  %-22s %7s %8s | %5s %6s %7s %7s %8s %8s %7s %6s %5s\n", "run", "dofs", "total s",
            "mesh", "refine", "pairing", "contact", "assemble", "factorK", "act.set", "solve*", "post"
      for (i = 1; i <= n; i++) { split(r[o[i]], f, ","); tt = f[22] > 0 ? f[22] : 1
        printf "  %-22s %7d %8.3f | %5.1f %6.1f %7.1f %7.1f %8.1f %8.1f %7.1f %6.1f %5.1f\n", o[i] " L" f[3], f[6], f[22],
          100*f[13]/tt, 100*f[14]/tt, 100*f[15]/tt, 100*f[16]/tt, 100*f[17]/tt, 100*f[18]/tt, 100*f[19]/tt, 100*f[20]/tt, 100*f[21]/tt } }' "$CSV"
  echo "  (assemble includes the LAC matrix C and the gaps G; contact = the rest of the contact"
  echo "   stage; solve* = the rest of the solve stage, e.g. a failed cholmod attempt on a"
  echo "   singular K before the umfpack fallback)"
  echo
  echo "## 4. observed rates: slope of log(err) against log(dofs) between the last two levels (cholmod)"
  awk -F, 'NR > 1 && $4 == "cholmod" { k = $1 " " $2; if (k in pd) { su[k] = log($10 / pu[k]) / log($6 / pd[k]); sl[k] = log($12 / pl[k]) / log($6 / pd[k]) }
      pd[k] = $6; pu[k] = $10; pl[k] = $12; if (!(k in seen)) { seen[k] = 1; o[++n] = k }
      dim[k] = ($1 ~ /3d$/) ? 3 : 2 }
    END { printf "  %-22s %10s %12s   %s\n", "run", "err_u", "err_lambda", "(times dim = rate in h)"
      for (i = 1; i <= n; i++) if (o[i] in su)
        printf "  %-22s %10.2f %12.2f   h-rates %.2f %.2f\n", o[i], su[o[i]], sl[o[i]], -dim[o[i]] * su[o[i]], -dim[o[i]] * sl[o[i]] }' "$CSV"
} > "$TXT"

# ---- charts -------------------------------------------------------------
# data per experiment / element / solver: dofs err_u err_lambda total
awk -F, -v W="$W" 'NR > 1 { f = W "/d-" $1 "-" $2 "-" $4 ".dat"; print $6, $10, $12, $22 > f }' "$CSV"
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
          f=d-$e-$el-cholmod.dat
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
chart 1 "dofs" accuracy-cost-dofs.png "error against the number of dofs (cholmod; one point per mesh level)"
chart 4 "total time of the run (s)" accuracy-cost-time.png "error against the time of the whole run (mesh to post, cholmod; one point per mesh level)"

# time against dofs for each solver, 2D and 3D problems apart
awk -F, -v W="$W" 'NR > 1 { d = ($1 ~ /3d$/) ? "3d" : "2d"; print $6, $18 + $19 + $20 > (W "/s-" d "-" $4 ".dat") }' "$CSV"
{
  echo 'set terminal pngcairo size 1400,620 font "DejaVu Sans,13" enhanced'
  echo "set output '$OUTABS/accuracy-cost-solvers.png'"
  echo 'set multiplot layout 1,2 title "time of the solve stage (factorization and active-set iterations) against the size, for each solver\\n(every run of the study: all experiments, elements and levels)" font ",14"'
  echo 'set logscale xy; set grid; set key top left; set format x "10^{%L}"; set format y "10^{%L}"'
  echo 'set xlabel "dofs"; set ylabel "solve stage (s)"'
  for d in 2d 3d; do
    ls "$W"/s-$d-*.dat > /dev/null 2>&1 || { echo 'set multiplot next'; continue; }
    [ "$d" = 2d ] && echo 'set title "2D and axisymmetric"' || echo 'set title "3D"'
    printf 'plot '
    sep=''
    for s in dense umfpack cholmod; do
      case $s in dense) c='#d62728' p=7 ;; umfpack) c='#1f77b4' p=5 ;; cholmod) c='#2ca02c' p=9 ;; esac
      [ -f "$W/s-$d-$s.dat" ] || continue
      printf "%s's-%s-%s.dat' using 1:2 with points pt %s ps 1.1 lc rgb \"%s\" title \"%s\"" "$sep" "$d" "$s" "$p" "$c" "$s"
      sep=', '
    done
    echo
  done
  echo 'unset multiplot'
} > "$W/solvers.gp"
(cd "$W" && gnuplot solvers.gp) || { echo "accuracy-cost.sh: gnuplot failed on $W/solvers.gp" >&2; nfail=$((nfail + 1)); }

# the split: stacked percentages for the finest cholmod run of each element
awk -F, 'NR > 1 && $4 == "cholmod" { k = $1 " " $2; if ($6 > d[k]) { d[k] = $6; r[k] = $0 }; if (!(k in seen)) { seen[k] = 1; o[++n] = k } }
  END { for (i = 1; i <= n; i++) { split(r[o[i]], f, ","); tt = f[22] > 0 ? f[22] : 1
      e = f[1]; sub(/manufactured/, "man. ", e); sub(/spheres-axi/, "sph. axi", e); sub(/spheres3d/, "sph. 3d", e)
      lab = sprintf("%s %s L%s\\n%d dofs, %.3g s", e, f[2], f[3], f[6], f[22])
      printf "\"%s\"", lab
      for (j = 13; j <= 21; j++) printf " %.2f", 100 * f[j] / tt
      printf "\n" } }' "$CSV" > "$W/split.dat"
{
  echo 'set terminal pngcairo size 1800,800 font "DejaVu Sans,12" enhanced'
  echo "set output '$OUTABS/accuracy-cost-split.png'"
  echo 'set title "where the time goes: stages of the finest run of each element (cholmod), percent of the run" font ",14"'
  echo 'set style data histograms; set style histogram rowstacked; set style fill solid 0.9 border -1; set boxwidth 0.75'
  echo 'set ylabel "percent of the total time"; set yrange [0:100]; set grid y'
  echo 'set key outside right top vertical'
  echo 'set xtics rotate by -40 left font ",11"'
  echo 'set bmargin 9'
  echo 'plot "split.dat" using 2:xtic(1) title "mesh (gmsh)" lc rgb "#9e9e9e", \'
  echo '  "" using 3 title "refine (macro-mesh)" lc rgb "#440154", \'
  echo '  "" using 4 title "pairing" lc rgb "#414487", \'
  echo '  "" using 5 title "contact stage, rest" lc rgb "#2a788e", \'
  echo '  "" using 6 title "assembly of K, F, C, G" lc rgb "#22a884", \'
  echo '  "" using 7 title "factorization of K" lc rgb "#7ad151", \'
  echo '  "" using 8 title "active set (saddle solves)" lc rgb "#fde725", \'
  echo '  "" using 9 title "solve stage, rest" lc rgb "#f4a261", \'
  echo '  "" using 10 title "post (stresses, errors)" lc rgb "#e76f51"'
} > "$W/split.gp"
(cd "$W" && gnuplot split.gp) || { echo "accuracy-cost.sh: gnuplot failed on $W/split.gp" >&2; nfail=$((nfail + 1)); }

echo "accuracy-cost: $(($(wc -l < "$CSV") - 1)) runs in $(( $(date +%s) - T0 )) s, $nfail failures; $OUT/accuracy-cost.{csv,txt} and accuracy-cost-*.png" >&2
[ $nfail -eq 0 ]
