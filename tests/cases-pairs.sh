# tests/cases-pairs.sh -- several contact pairs (sourced by tests/run.sh)
#
# The scenes of chapter 16, sections 1-2 (in chapters/06-assembly), through `lac run`:
#   stacked   three stacked blocks, two non-matching interfaces (two
#             [contact] sections, the middle block slave of one and master
#             of the other, held by contact alone), the ten element types,
#             also with a middle block 5 mm thin (one cell across, thinner
#             than a facet of its neighbours), and axisymmetric (three
#             stacked cylinders): the relative errors of
#             lambda (-p on every macro-element of both interfaces) and of
#             the stresses <= 1e-12, every multiplier active, <= 3
#             active-set iterations;
#   corner    a block pressed into the inner corner of an L-shaped body
#             (one slave surface turning 90 degrees; quad4, hex8 with
#             both cuts): lambda = -p on both faces to 1e-12, and no
#             macro-element spans the corner (the centroid of each lies on
#             one of the two faces);
#   blocks    five bodies, six pairs, a crosspoint (quad4, quad8): every
#             body is in equilibrium to 1e-10 (the forces of its pairs,
#             contact_force.NAME on the slave and minus it on the master,
#             its loads, and for the clamped ones reaction.NAME), the
#             active set settles;
#   outputs   the per-pair keys of the summary, the pair column of
#             contact.csv, the pair field of contact.vtu;
#   rollers   the stacked blocks turned by 30 degrees on rollers, with an
#             interference on each pair (chapter 16, sections 1-5
#             together), small strain and large deformation;
#   bad       the roles of the pairs checked, messages naming the section.
# Same conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
PC="$B/cases-pairs"
LAC="$B/lac"
rm -rf "$PC"
mkdir -p "$PC"
PD=chapters/06-assembly

pairs_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
pairs_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
pairs_val () { sed -n "s/^$2 = //p" "$1"; }

# patch NAME SCENE ARGS...: lambda and sigma exact to 1e-12, all active
patch () {
  name=$1 scene=$2
  shift 2
  if ! "$LAC" run "$PD/$scene.scene" "$@" --quiet --no-output > "$PC/$name.out" 2> "$PC/$name.err"; then
    pairs_fail "$name" "lac run failed: $(tail -1 "$PC/$name.err")"
    return
  fi
  el=$(pairs_val "$PC/$name.out" max_rel_err_lambda)
  es=$(pairs_val "$PC/$name.out" max_rel_err_sigma)
  it=$(pairs_val "$PC/$name.out" newton_iterations)
  na=$(pairs_val "$PC/$name.out" active)
  nm=$(pairs_val "$PC/$name.out" multipliers)
  if awk -v a="$el" -v b="$es" -v n="$it" -v na="$na" -v nm="$nm" 'BEGIN {
       exit !(a != "" && a <= 1e-12 && b != "" && b <= 1e-12 && n >= 1 && n <= 3 && na == nm && nm > 0) }'; then
    pairs_ok "$name"
  else
    pairs_fail "$name" "max_rel_err_lambda = $el, max_rel_err_sigma = $es (want <= 1e-12), newton_iterations = $it (want <= 3), active = $na of $nm"
  fi
}

for t in 50 5; do
  for e in tri3 tri6 quad4 quad8 quad9; do
    patch "stacked2d-$e-t$t" stacked2d --set element="$e" --set mesh.numbers=t="$t"
  done
  for e in tet4 tet10 hex8 hex20 hex27; do
    patch "stacked3d-$e-t$t" stacked3d --set element="$e" --set mesh.numbers=t="$t"
  done
done
# axisymmetric: three stacked cylinders, the same uniform pressure
for e in quad4 tri6; do
  patch "stacked-axi-$e" stacked2d --set element="$e" --set scene.model=axisymmetric \
    --set dirichlet.lower_left.symmetry=r --set dirichlet.middle_left.symmetry=r \
    --set dirichlet.upper_left.symmetry=r --set dirichlet.bottom.symmetry=z
done
# the strategies that take bodies held by contact alone
for s in dense saddle augmented split; do
  patch "stacked2d-quad8-t5-$s" stacked2d --set element=quad8 --set mesh.numbers=t=5 --strategy "$s"
done

# ---- the inner corner -----------------------------------------------------
# corner NAME SCENE ARGS...: the patch test, then no macro-element whose
# centroid is off both faces x = 50 and y = 50
corner () {
  name=$1 scene=$2
  shift 2
  patch "$name" "$scene" "$@"
  rm -rf "$PC/$name.d"
  if "$LAC" run "$PD/$scene.scene" "$@" --out "$PC/$name.d" --quiet > /dev/null 2>&1; then
    bad=$(awk -F, 'NR > 1 { dx = $2 - 50; dy = $3 - 50; if (dx * dx > 1e-18 && dy * dy > 1e-18) b++ }
                   END { print b + 0 }' "$PC/$name.d/contact.csv")
    nx=$(awk -F, 'NR > 1 && ($2 - 50)^2 <= 1e-18 { n++ } END { print n + 0 }' "$PC/$name.d/contact.csv")
    ny=$(awk -F, 'NR > 1 && ($3 - 50)^2 <= 1e-18 { n++ } END { print n + 0 }' "$PC/$name.d/contact.csv")
  else
    bad=run-failed nx=0 ny=0
  fi
  if [ "$bad" = 0 ] && [ "$nx" -gt 0 ] && [ "$ny" -gt 0 ]; then
    pairs_ok "$name-no-straddle"
  else
    pairs_fail "$name-no-straddle" "$bad macro-elements span the corner ($nx on x = 50, $ny on y = 50)"
  fi
}
corner corner2d-quad4 corner2d
corner corner2d-quad4-level1 corner2d --set level=1
corner corner3d-hex8 corner3d
corner corner3d-hex8-six corner3d --set contact.corner.hex_cut=six

# ---- five bodies, six pairs: the equilibrium of every body ----------------
# blocks NAME ARGS...: B, C, D balance their loads with their pairs, the
# clamped A and W their pairs with the reactions of their supports
blocks () {
  name=$1
  shift
  if ! "$LAC" run "$PD/blocks.scene" "$@" --set output.reactions=yes --quiet --no-output > "$PC/$name.out" 2> "$PC/$name.err"; then
    pairs_fail "$name" "lac run failed: $(tail -1 "$PC/$name.err")"
    return
  fi
  res=$(awk '
    / = / { v[$1] = $3; w[$1] = $4 }
    END {
      # the loads (N/mm): C pushed left by 25 MPa x 40 and down by 10 x 50,
      # D left by 20 x 30 and down by 25 x 50
      bx = v["contact_force.B_on_A"] + v["contact_force.B_on_W"] - v["contact_force.C_on_B"] - v["contact_force.D_on_B"]
      by = w["contact_force.B_on_A"] + w["contact_force.B_on_W"] - w["contact_force.C_on_B"] - w["contact_force.D_on_B"]
      cx = v["contact_force.C_on_B"] + v["contact_force.C_on_A"] - 1000
      cy = w["contact_force.C_on_B"] + w["contact_force.C_on_A"] - 500
      dx = v["contact_force.D_on_B"] + v["contact_force.D_on_W"] - 600
      dy = w["contact_force.D_on_B"] + w["contact_force.D_on_W"] - 1250
      # the clamped slab A and wall W: their supports (reaction.NAME, the
      # force of the support on the body) against the pairs they master
      ax = v["reaction.slab"] - v["contact_force.B_on_A"] - v["contact_force.C_on_A"]
      ay = w["reaction.slab"] - w["contact_force.B_on_A"] - w["contact_force.C_on_A"]
      wx = v["reaction.wall"] - v["contact_force.B_on_W"] - v["contact_force.D_on_W"]
      wy = w["reaction.wall"] - w["contact_force.B_on_W"] - w["contact_force.D_on_W"]
      m = ("reaction.slab" in v && "reaction.wall" in v) ? 0 : 1
      split(bx " " by " " cx " " cy " " dx " " dy " " ax " " ay " " wx " " wy, r, " ")
      for (i = 1; i <= 10; i++) { a = r[i] < 0 ? -r[i] : r[i]; if (a > m) m = a }
      printf "%.3e", m / 1250
    }' "$PC/$name.out")
  it=$(pairs_val "$PC/$name.out" newton_iterations)
  np=$(grep -c '^contact_force\.' "$PC/$name.out")
  if awk -v r="$res" -v n="$it" -v np="$np" 'BEGIN { exit !(r != "" && r <= 1e-10 && n >= 1 && n <= 10 && np == 6) }'; then
    pairs_ok "$name"
  else
    pairs_fail "$name" "largest imbalance of A, W, B, C, D / 1250 N = $res (want <= 1e-10), newton_iterations = $it, $np contact_force.NAME lines (want 6)"
  fi
}
blocks blocks-quad4
blocks blocks-quad8 --set element=quad8
blocks blocks-quad4-level1 --set level=1

# ---- outputs: summary keys, contact.csv pair column, contact.vtu pair -----
rm -rf "$PC/out"
if "$LAC" run "$PD/stacked2d.scene" --set element=quad8 --set output.vtu_format=ascii \
     --out "$PC/out" --quiet > "$PC/out.sum" 2> "$PC/out.err"; then
  nl=$(awk -F, 'NR > 1 && $18 == "lower"' "$PC/out/contact.csv" | wc -l)
  nu=$(awk -F, 'NR > 1 && $18 == "upper"' "$PC/out/contact.csv" | wc -l)
  al=$(pairs_val "$PC/out.sum" active_macro_elements.lower)
  au=$(pairs_val "$PC/out.sum" active_macro_elements.upper)
  fl=$(pairs_val "$PC/out.sum" contact_normal_force.lower)
  fv=$(pairs_val "$PC/out.sum" contact_force.upper)
  rv=$(pairs_val "$PC/out.sum" contact_resultant)
  # each interface carries the whole load, 25 MPa x 50 mm
  if [ "$nl" -gt 0 ] && [ "$nl" = "$al" ] && [ "$nu" = "$au" ] \
     && awk -v f="$fl" -v v="$fv" -v r="$rv" 'BEGIN { split(v, a, " "); split(r, b, " ")
          exit !((f + 1250)^2 < 1e-16 && (a[2] - 1250)^2 < 1e-16 && a[1]^2 < 1e-16 && (b[2] - 2500)^2 < 1e-16) }'; then
    pairs_ok pairs-summary-csv
  else
    pairs_fail pairs-summary-csv "contact.csv rows lower $nl upper $nu, active_macro_elements.lower $al .upper $au, contact_normal_force.lower = $fl, contact_force.upper = $fv, contact_resultant = $rv"
  fi
  if grep -q 'Name="pair"' "$PC/out/contact.vtu" \
     && awk '/Name="pair"/ { on = 1; next } on && /<\/DataArray>/ { exit } on { for (i = 1; i <= NF; i++) seen[$i] = 1 }
             END { exit !(seen[0] && seen[1]) }' "$PC/out/contact.vtu"; then
    pairs_ok pairs-vtu
  else
    pairs_fail pairs-vtu "contact.vtu has no pair field with the values 0 and 1"
  fi
else
  pairs_fail pairs-outputs "lac run failed: $(tail -1 "$PC/out.err")"
fi

# ---- read back: every digit of the summary, names a reader keeps ---------
# With loads that are no round numbers, the clamped slab A and wall W of
# blocks.scene balance the pairs they master with reaction.NAME to
# rounding (1e-13 of the 1250 N scale) from the printed text alone: every
# real of the summary has 17 significant digits.
P4="--set load.D_top.pressure=25.1234567891 --set load.D_right.pressure=20.9876543211"
P4="$P4 --set load.C_top.pressure=10.3141592653 --set load.C_right.pressure=24.2718281828"
# shellcheck disable=SC2086
if "$LAC" run "$PD/blocks.scene" $P4 --set output.reactions=yes --quiet --no-output \
     > "$PC/digits.out" 2> "$PC/digits.err"; then
  res=$(awk -F' = ' '{ n = split($2, c, " "); x[$1] = c[1]; y[$1] = c[2] }
    END { a[1] = x["reaction.slab"] - x["contact_force.B_on_A"] - x["contact_force.C_on_A"]
          a[2] = y["reaction.slab"] - y["contact_force.B_on_A"] - y["contact_force.C_on_A"]
          a[3] = x["reaction.wall"] - x["contact_force.B_on_W"] - x["contact_force.D_on_W"]
          a[4] = y["reaction.wall"] - y["contact_force.B_on_W"] - y["contact_force.D_on_W"]
          m = ("reaction.slab" in x && "reaction.wall" in x && y["reaction.slab"] > 1000) ? 0 : 1
          for (i = 1; i <= 4; i++) { v = a[i] < 0 ? -a[i] : a[i]; if (v > m) m = v }
          printf "%.3e", m / 1250 }' "$PC/digits.out")
  if awk -v r="$res" 'BEGIN { exit !(r != "" && r <= 1e-13) }'; then
    pairs_ok pairs-summary-digits
  else
    pairs_fail pairs-summary-digits "largest imbalance of A and W / 1250 N = $res from the summary (want <= 1e-13): $(grep -E '^reaction' "$PC/digits.out" | tr '\n' ' ')"
  fi
else
  pairs_fail pairs-summary-digits "lac run failed: $(tail -1 "$PC/digits.err")"
fi
# Names of the alphabet ('.', '-', '_') read back from contact.csv by a
# CSV reader (Python's csv module) and from the summary's "key = value".
mkdir -p "$PC/names"
cp "$PD/stacked2d.geo" "$PC/names/"
sed -e 's/^\[contact lower\]/[contact lo.wer-1]/' -e 's/^\[contact upper\]/[contact Up_2]/' \
  "$PD/stacked2d.scene" > "$PC/names/names.scene"
if ! command -v python3 > /dev/null 2>&1; then
  echo "     (python3 not found: contact.csv not read back)"
elif "$LAC" run "$PC/names/names.scene" --out "$PC/names/out" --quiet \
     > "$PC/names/sum" 2> "$PC/names/err"; then
  if msg=$(python3 - "$PC/names/out/contact.csv" "$PC/names/sum" <<'PYEOF' 2>&1
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
head = rows[0]
assert head[-1] == "pair", head
bad = [r for r in rows[1:] if len(r) != len(head)]
assert not bad, "rows of %d fields: %s" % (len(head), bad[:1])
names = set(r[-1] for r in rows[1:])
assert names == {"lo.wer-1", "Up_2"}, names
keys = [l.rstrip("\n").split(" = ") for l in open(sys.argv[2])]
assert all(len(k) == 2 for k in keys), [k for k in keys if len(k) != 2]
assert "contact_force.lo.wer-1" in dict(keys), "no contact_force.lo.wer-1"
PYEOF
      ); then
    pairs_ok pairs-names-read-back
  else
    pairs_fail pairs-names-read-back "$msg"
  fi
else
  pairs_fail pairs-names-read-back "lac run failed: $(tail -1 "$PC/names/err")"
fi

# the large-deformation loop over two pairs: Newton converges, each
# interface carries the load (its normal force and its force vector)
sed '/^\[exact\]/,$d' "$PD/stacked2d.scene" > "$PC/ld.scene"
cp "$PD/stacked2d.geo" "$PC/"
if "$LAC" run "$PC/ld.scene" --set scene.large_deformation=yes --set material.all.E=200 \
     --quiet --no-output > "$PC/ld.out" 2> "$PC/ld.err" \
   && awk -v a="$(pairs_val "$PC/ld.out" contact_normal_force.lower)" \
          -v b="$(pairs_val "$PC/ld.out" contact_normal_force.upper)" \
          -v f="$(pairs_val "$PC/ld.out" contact_force.upper)" \
          -v n="$(pairs_val "$PC/ld.out" newton_iterations)" \
          'BEGIN { split(f, v, " ")
                   exit !((a + 1250)^2 < 1e-12 && (b + 1250)^2 < 1e-12 && (v[2] - 1250)^2 < 1e-12 && v[1]^2 < 1e-12 && n <= 6) }'; then
  pairs_ok pairs-large-deformation
else
  pairs_fail pairs-large-deformation "$(tail -1 "$PC/ld.err"); $(grep -E 'contact_normal_force|newton_iterations' "$PC/ld.out" | tr '\n' ' ')"
fi

# ---- rollers and interference on two pairs --------------------------------
# tests/meshes/stacked2d-rotated.scene: the stacked blocks turned by 30
# degrees, every symmetry plane a roller (normal = 0: nodal frames, also at
# the nodes the rollers share with both contact surfaces), both
# interfaces inclined; then an interference on each pair, its own delta
# (0.02 lower, 0.01 upper).  The stress stays uniform: lambda = -25 on
# every macro-element of both pairs, each pair's force 1250 (-sin 30,
# cos 30) and so the bottom reaction; each interference only moves the
# bodies above it by its delta along the turned normal n, so that against
# the run without, u changes by 0 below the lower interface, 0.02 n
# between the two, 0.03 n above (a node on an interface: either side's).
# Small strain (1e-12, lambda and u to their printed digits) and large
# deformation (1e-10, u to 1e-8; lambda uniform, on the deformed area).
ROT=tests/meshes/stacked2d-rotated.scene
# rot_run NAME ARGS...: the run into $PC/NAME (summary in NAME.out)
rot_run () {
  rn=$1
  shift
  "$LAC" run "$ROT" "$@" --set output.reactions=yes --quiet --out "$PC/$rn" \
    > "$PC/$rn.out" 2> "$PC/$rn.err" \
    || { pairs_fail "$rn" "lac run failed: $(tail -1 "$PC/$rn.err")"; return 1; }
}
# rot_check NAME BASE TOL UTOL [LAMBDA]: NAME's forces, reaction and
# multipliers (all active, all equal: to LAMBDA if given), and its u
# against BASE's (no interference) shifted by each pair's delta
rot_check () {
  rn=$1 base=$2 tol=$3 utol=$4 lam=${5:-}
  if msg=$(awk -v tol="$tol" -v utol="$utol" -v lam="$lam" -v dl=0.02 -v du=0.01 '
    function bad(w) { if (!why) why = w }
    function near(a, b, t) { d = a - b; if (d < 0) d = -d; return d <= t }
    BEGIN { FS = " = "; s = sin(atan2(1, 1) / 1.5); c = cos(atan2(1, 1) / 1.5)
            fx = -1250 * s; fy = 1250 * c }
    FILENAME ~ /\.out$/ && $1 ~ /^(contact_force\.(lower|upper)|reaction\.bottom)$/ {
      split($2, v, " "); t = $1 ~ /reaction/ ? 1e-10 : tol; seen++
      if (!near(v[1], fx, t * 1250) || !near(v[2], fy, t * 1250))
        bad($1 " = " $2) }
    FILENAME ~ /contact\.csv$/ && FNR == 1 {
      n = split($0, h, ","); for (k = 1; k <= n; k++) col[h[k]] = k }
    FILENAME ~ /contact\.csv$/ && FNR > 1 {
      split($0, f, ","); l = f[col["lambda"]]; nl++; if (nl == 1) l0 = lam == "" ? l : lam
      if (!near(l, l0, 1e-9 * 25) || f[col["active"]] != 1)
        bad("lambda " l " (want " l0 "), active " f[col["active"]]) }
    FILENAME ~ /base/ && FNR > 1 { split($0, f, ","); u0x[FNR] = f[5]; u0y[FNR] = f[6] }
    FILENAME ~ /nodes\.csv$/ && FILENAME !~ /base/ && FNR > 1 {
      split($0, f, ","); nn++
      eta = -f[2] * s + f[3] * c                     # height along the turned normal
      ex = f[5] - u0x[FNR]; ey = f[6] - u0y[FNR]; sh = -ex * s + ey * c
      if (!near(ex * c + ey * s, 0, utol)) bad("node " f[1] ": u moved along the interfaces")
      else if (eta < 50 - 1e-6 && !near(sh, 0, utol)) bad("node " f[1] ": lower block moved " sh)
      else if (eta > 50 + 1e-6 && eta < 100 - 1e-6 && !near(sh, dl, utol)) bad("node " f[1] ": middle block moved " sh)
      else if (eta > 100 + 1e-6 && !near(sh, dl + du, utol)) bad("node " f[1] ": upper block moved " sh)
      else if (near(eta, 50, 1e-6) && !near(sh, 0, utol) && !near(sh, dl, utol)) bad("node " f[1] " on the lower interface moved " sh)
      else if (near(eta, 100, 1e-6) && !near(sh, dl, utol) && !near(sh, dl + du, utol)) bad("node " f[1] " on the upper interface moved " sh) }
    END { if (seen != 3 || nl < 3 || nn < 50) bad("missing results (" seen " keys, " nl " multipliers, " nn " nodes)")
          if (why) { print why; exit 1 } }' \
    "$PC/$rn.out" "$PC/$rn/contact.csv" "$PC/$base/nodes.csv" "$PC/$rn/nodes.csv" 2>&1); then
    pairs_ok "$rn"
  else
    pairs_fail "$rn" "$msg"
  fi
}
for e in quad4 tri6 quad8; do
  rot_run "rollers-$e-base" --set element="$e" \
    && rot_run "rollers-$e-interference" --set element="$e" \
         --set contact.lower.interference=0.02 --set contact.upper.interference=0.01 \
    && rot_check "rollers-$e-interference" "rollers-$e-base" 1e-12 2e-10 -25
done
rot_run rollers-large-base --set scene.large_deformation=yes \
  && rot_run rollers-large-interference --set scene.large_deformation=yes \
       --set contact.lower.interference=0.02 --set contact.upper.interference=0.01 \
  && rot_check rollers-large-interference rollers-large-base 1e-10 1e-8

# ---- bad input: one line naming the section -------------------------------
# pairs_bad NAME "WORD|WORD..." ARGS...
pairs_bad () {
  name=$1 words=$2
  shift 2
  "$LAC" run "$@" --quiet --no-output > "$PC/$name.out" 2> "$PC/$name.err"
  rc=$?
  msg=$(cat "$PC/$name.err")
  ok=1
  [ "$rc" -ge 1 ] && [ "$rc" -lt 128 ] || ok=0
  [ "$(wc -l < "$PC/$name.err")" -eq 1 ] || ok=0
  old_ifs=$IFS; IFS='|'
  for w in $words; do
    case "$msg" in *"$w"*) ;; *) ok=0 ;; esac
  done
  IFS=$old_ifs
  if [ $ok = 1 ]; then pairs_ok "bad-$name"; else pairs_fail "bad-$name" "exit $rc, stderr: $msg (want: $words)"; fi
}
S2="$PD/stacked2d.scene"
pairs_bad slave-and-master "[contact upper] master = 'middle_bottom'|slave facet of [contact lower]|constrained twice" \
  "$S2" --set contact.upper.master=middle_bottom
pairs_bad slave-twice "[contact upper] slave = 'middle_bottom'|already the slave group of [contact lower]" \
  "$S2" --set contact.upper.slave=middle_bottom
pairs_bad nts-pairs "[contact upper] method = 'nts'|one [contact] section" \
  "$S2" --set contact.upper.method=nts
pairs_bad loop-keys "[contact upper] strategy = 'saddle'|one loop|differs from [contact lower]" \
  "$S2" --set contact.lower.strategy=dense --set contact.upper.strategy=saddle
pairs_bad second-pair "[contact upper]|no slave facet overlaps" \
  "$S2" --set contact.upper.master=lower_bottom
pairs_bad pulled-off "(translation along y)|held by contact alone|active-set iteration" \
  "$S2" --set load.top.pressure=-25
# a name outside the alphabet of names: refused at its header, not
# written into contact.csv (a comma, a quote: one more field) or the
# summary (a blank, an '=': another key)
names_bad () {
  sed "s/^\[contact lower\]/[contact $2]/" "$S2" > "$PC/names/bad.scene"
  pairs_bad "name-$1" "bad.scene:46: [contact $2]: the name|letters, digits, '_', '-' and '.'" \
    "$PC/names/bad.scene"
}
names_bad comma 'lo,wer'
names_bad quote '"lo"wer'
names_bad blank 'lo wer'
names_bad equals 'lo=wer'
# One pair for both interfaces of the stacked blocks (the slave groups
# joined, and the master groups): the middle block is slave and master of
# one pair and, 5 mm thin, was paired through itself (the loop blamed a
# load); refused, naming the pair and the body.
cp "$PD/stacked2d.geo" "$PC/names/union.geo"
printf 'Physical Curve("slaves") = {5, 9};\nPhysical Curve("masters") = {3, 7};\n' >> "$PC/names/union.geo"
sed -e '/^\[contact lower\]/,$d' -e 's/stacked2d.geo/union.geo/' "$S2" > "$PC/names/union.scene"
printf '[contact both]\nslave = slaves\nmaster = masters\n' >> "$PC/names/union.scene"
pairs_bad own-body "union.scene:|[contact both] master = 'masters'|on one body 'middle'|its own [contact] section" \
  "$PC/names/union.scene" --set mesh.numbers=t=5
# A middle block 1e-6 mm thin: K singular to rounding; the message names
# the layer (it said only: check the Dirichlet conditions and the inf-sup
# condition).
pairs_bad thin-layer "stacked2d.scene:|body 'middle' has cells 1.7e+07 times wider than thick|make the layer thicker|what the solver saw" \
  "$S2" --set mesh.numbers=t=1e-6
# Large deformation with an interference of 80 mm on each pair of 50 mm
# blocks: the surfaces move apart by it, beyond the pairing's reach; the
# message names the interference (it blamed a load that pulls a body off).
pairs_bad interference-separates "[contact lower] interference = 80|no facet pair left|t delta = 80" \
  "$ROT" --set scene.large_deformation=yes --set contact.lower.interference=80 \
  --set contact.upper.interference=80
pairs_bad hex20-pyramids "[contact corner] slave = 'block_inner'|pyramids|hex_cut = six" \
  "$PD/corner3d.scene" --set element=hex20 --set contact.corner.hex_cut=pyramids
