# tests/cases-figures.sh -- the figures of the paper's experiments (sourced
# by tests/run.sh; same conventions as tests/cases.sh: $B, pass, fail)
#
# Runs `sh figures/make-figures.sh $B --quick --out DIR` (coarse meshes,
# into $B/cases-figures, never into figures/) and a small accuracy-cost
# study (bench/accuracy-cost.sh --quick on three cases), then checks every
# expected PNG with figures/pngcheck.c: readable, of the expected size, and
# not blank (enough pixels off the background, enough colours: a colour map
# or curves).  No display is needed (OSMesa, gnuplot pngcairo).  About 20 s.

B=${B:-build}
C="$B/cases-figures"
rm -rf "$C"
mkdir -p "$C"

fig_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
fig_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

PNGCHECK=$B/figures/pngcheck
if [ ! -x "$PNGCHECK" ] || [ ! -x "$B/figures/figrun" ]; then
  ${MAKE:-make} -s B="$B" "$PNGCHECK" "$B/figures/figrun" > "$C/make.out" 2>&1
fi

# png_check NAME FILE WIDTH HEIGHT MIN_INK MIN_COLOURS (WIDTH, HEIGHT - : any)
png_check () {
  if [ ! -f "$2" ]; then
    fig_fail "$1" "$2 was not written"
    return
  fi
  line=$("$PNGCHECK" "$2" 2>&1) || { fig_fail "$1" "$line"; return; }
  set -- "$1" "$2" "$3" "$4" "$5" "$6" $line
  # $7 file, $8 width, $9 height, ${10} ink, ${11} colours
  if { [ "$3" = - ] || [ "$8" = "$3" ]; } && { [ "$4" = - ] || [ "$9" = "$4" ]; } \
     && awk -v i="${10}" -v c="${11}" -v mi="$5" -v mc="$6" 'BEGIN { exit !(i >= mi && c >= mc) }'; then
    fig_ok "$1"
  else
    fig_fail "$1" "$2: ${8}x$9 (want ${3}x$4), ink ${10} (want >= $5), ${11} colours (want >= $6)"
  fi
}

stamp="$C/stamp"
: > "$stamp"
if [ ! -x "$PNGCHECK" ]; then
  fig_fail figures-build "could not build $PNGCHECK: $(tail -3 "$C/make.out")"
else
  # every picture is checked even if one figure failed (the status says which)
  if sh figures/make-figures.sh "$B" --quick --out "$C/png" > "$C/make-figures.out" 2> "$C/make-figures.err"; then
    fig_ok make-figures-quick
  else
    fig_fail make-figures-quick "exit status 1: $(grep FAILED "$C/make-figures.err" | head -3)"
  fi
  # a render: 800 x 600, a mesh or surface covering >= 10 % of the frame
  for f in fig01-sphere-axi-u-r fig03-taylor2d-quad4-sigma-yy fig04-taylor3d-hex8-sigma-zz \
           fig04-taylor3d-hex8-lambda fig04-taylor3d-hex8-gap \
           fig05-spheres-axi-tri6-u-r fig05-spheres-axi-tri6-von-mises \
           fig05-spheres-axi-tri6-sigma-rr fig05-spheres-axi-tri6-lambda \
           fig06-spheres3d-tet10-u-r fig06-spheres3d-tet10-von-mises \
           fig06-spheres3d-tet10-sigma-rr fig06-spheres3d-tet10-lambda \
           fig07-manufactured2d-quad8-u fig08-manufactured3d-hex20-u \
           fig08-manufactured3d-hex20-lambda fig13-blocks-quad4-von-mises \
           fig13-blocks-quad4-lambda fig16-compound-lambda fig16-compound-von-mises; do
    png_check "png-$f" "$C/png/$f.png" 800 600 0.10 100
  done
  # a gnuplot chart: 900 x 620, curves and text
  for f in fig03-taylor2d-quad4-lambda-gap fig05-spheres-axi-tri6-lambda-curve \
           fig06-spheres3d-tet10-lambda-curve fig07-manufactured2d-quad8-lambda; do
    png_check "png-$f" "$C/png/$f.png" 900 620 0.02 50
  done
  png_check png-fig01-sphere-axi-profiles "$C/png/fig01-sphere-axi-profiles.png" 1500 620 0.02 50
  # Figure 2 (figures/fig02-refine.c, gnuplot): the refined cells per type
  png_check png-fig02-refinement-2d "$C/png/fig02-refinement-2d.png" 1100 1000 0.03 50
  png_check png-fig02-refinement-3d "$C/png/fig02-refinement-3d.png" 1100 2900 0.03 50
  if [ -f chapters/10-large-deformation/ring.scene ]; then
    n=$(ls "$C"/png/fig10-*.png "$C"/png/fig11-*.png 2> /dev/null | wc -l)
    if [ "$n" -ge 2 ]; then
      for f in "$C"/png/fig10-*.png "$C"/png/fig11-*.png; do
        png_check "png-$(basename "$f" .png)" "$f" - - 0.02 20
      done
    else
      fig_fail ring-figures "ring.scene exists but make-figures.sh drew no fig10/fig11: $(grep ring "$C/make-figures.err")"
    fi
  elif grep -q "ring scene not available: fig10/fig11 not regenerated" "$C/make-figures.err"; then
    fig_ok ring-skipped-with-message
  else
    fig_fail ring-skipped-with-message "no ring.scene, and make-figures.sh did not say so"
  fi
  # --out: the committed figures are untouched
  newer=$(find figures -name '*.png' -newer "$stamp" 2> /dev/null | head -3)
  if [ -z "$newer" ]; then fig_ok figures-untouched
  else fig_fail figures-untouched "make-figures.sh --out wrote into figures/: $newer"; fi
fi

# the accuracy-cost study on three small cases: table, CSV and the four charts
if CASES="manufactured2d:quad4:0-1 spheres-axi:tri6:0-1 manufactured3d:hex8:0-1" \
   sh bench/accuracy-cost.sh "$B" --quick --out "$C/ac" > "$C/ac.out" 2> "$C/ac.err"; then
  rows=$(($(wc -l < "$C/ac/accuracy-cost.csv") - 1))
  # 3 cases x 2 levels x 4 strategies (auto, then dense, schur, augmented,
  # saddle but the one auto chose; split is refused, and skipped, since
  # every body of these scenes is held by its Dirichlet conditions);
  # errors in (0, 1), times > 0
  if [ "$rows" = 24 ] && grep -q "^## 3. where the time goes" "$C/ac/accuracy-cost.txt" \
     && awk -F, 'NR > 1 && !($10 > 0 && $10 < 1 && $23 > 0) { bad = 1 } END { exit bad }' "$C/ac/accuracy-cost.csv"; then
    fig_ok accuracy-cost-table
  else
    fig_fail accuracy-cost-table "$rows rows in accuracy-cost.csv (want 24), or no time split in accuracy-cost.txt, or an error/time out of range"
  fi
  # one auto row per run, and every strategy of a run gives its errors
  # (7 digits in the CSV) to a relative 1e-6
  bad=$(awk -F, 'NR > 1 { k = $1 " " $2 " " $3; na[k] += ($4 == "auto")
      if (k in u) { if ($10 < u[k] * (1 - 1e-6) || $10 > u[k] * (1 + 1e-6) || $12 < l[k] * (1 - 1e-6) || $12 > l[k] * (1 + 1e-6)) print k, $4 }
      else { u[k] = $10; l[k] = $12 } }
    END { for (k in na) if (na[k] != 1) print k, na[k], "auto rows" }' "$C/ac/accuracy-cost.csv")
  if [ -z "$bad" ]; then fig_ok accuracy-cost-strategies-agree
  else fig_fail accuracy-cost-strategies-agree "$(echo "$bad" | head -3)"; fi
  png_check accuracy-cost-dofs "$C/ac/accuracy-cost-dofs.png" 1800 950 0.02 50
  png_check accuracy-cost-time "$C/ac/accuracy-cost-time.png" 1800 950 0.02 50
  png_check accuracy-cost-strategies "$C/ac/accuracy-cost-strategies.png" 1400 620 0.02 20
  png_check accuracy-cost-split "$C/ac/accuracy-cost-split.png" 1800 800 0.10 20
else
  fig_fail accuracy-cost-quick "exit status $?: $(tail -3 "$C/ac.err")"
fi
