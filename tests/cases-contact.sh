# tests/cases-contact.sh -- contact scenes (sourced by tests/run.sh)
#
# The Taylor patch test [LAC §5.1, Tables 1-2] through `lac run`, for the
# nine element types of the paper in 2D and 3D, with the slave and master
# surfaces as in the scene and swapped, through every strategy that
# applies (the upper body is held by contact alone: dense, saddle,
# augmented, split; schur is refused): the maximum relative errors of lambda and
# of the stresses must be <= 1e-12 and the active set must settle in <= 3
# iterations.  Same conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
C="$B/cases-contact"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

contact_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
contact_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
value_of () { sed -n "s/^$2 = //p" "$1"; }

# taylor SCENE ELEMENT SWAP STRATEGY: run and check the three acceptance
# numbers.
taylor () {
  name="taylor-$2-swap$3-$4"
  swap=""
  [ "$3" = 1 ] && swap="--set contact.interface.slave=lower_top --set contact.interface.master=upper_bottom"
  # shellcheck disable=SC2086
  if ! "$LAC" run "chapters/08-experiments/$1.scene" --set element="$2" $swap \
       --strategy "$4" --quiet --no-output > "$C/$name.out" 2> "$C/$name.err"; then
    contact_fail "$name" "lac run failed: $(tail -1 "$C/$name.err")"
    return
  fi
  el=$(value_of "$C/$name.out" max_rel_err_lambda)
  es=$(value_of "$C/$name.out" max_rel_err_sigma)
  it=$(value_of "$C/$name.out" newton_iterations)
  if awk -v a="$el" -v b="$es" -v n="$it" 'BEGIN { exit !(a != "" && a <= 1e-12 && b != "" && b <= 1e-12 && n >= 1 && n <= 3) }'; then
    contact_ok "$name"
  else
    contact_fail "$name" "max_rel_err_lambda = $el, max_rel_err_sigma = $es (want <= 1e-12), newton_iterations = $it (want <= 3)"
  fi
}

for s in dense saddle augmented split; do
  for e in tri3 quad4 tri6 quad8; do
    taylor taylor2d "$e" 0 "$s"
    taylor taylor2d "$e" 1 "$s"
  done
  for e in tet4 hex8 tet10 hex20 hex27; do
    taylor taylor3d "$e" 0 "$s"
    taylor taylor3d "$e" 1 "$s"
  done
done

# The mesh-size ratio at the interface is >= 1.3 and the meshes do not
# match: the lower body has 4 cells per side, the upper 3 (level 0).
if "$LAC" run chapters/08-experiments/taylor3d.scene --set element=hex8 --set level=1 \
     --quiet --no-output > "$C/level1.out" 2> "$C/level1.err" \
   && [ "$(value_of "$C/level1.out" macro_elements)" = 25 ]; then
  contact_ok taylor-level1
else
  contact_fail taylor-level1 "level 1 (7 and 5 cells per edge): $(tail -1 "$C/level1.err"), macro_elements = $(value_of "$C/level1.out" macro_elements) (want 25)"
fi

# ---- bad contact input: exit status 1, one line "lac: ..." naming the
# scene line and key, no crash ------------------------------------------
# contact_bad NAME "WORD|WORD..." ARGS...: every word must be in the message
contact_bad () {
  name=$1 words=$2
  shift 2
  "$LAC" run "$@" --quiet --no-output > "$C/$name.out" 2> "$C/$name.err"
  rc=$?
  msg=$(cat "$C/$name.err")
  ok=1
  [ "$rc" -ge 1 ] && [ "$rc" -lt 128 ] || ok=0
  [ "$(wc -l < "$C/$name.err")" -eq 1 ] || ok=0
  old_ifs=$IFS; IFS='|'
  for w in $words; do
    case "$msg" in *"$w"*) ;; *) ok=0 ;; esac
  done
  IFS=$old_ifs
  if [ $ok = 1 ]; then contact_ok "bad-$name"; else contact_fail "bad-$name" "exit $rc, stderr: $msg (want: $words)"; fi
}

T2=chapters/08-experiments/taylor2d.scene
contact_bad missing-slave "--set|[contact interface] slave = 'nosuch'|no physical group" \
  $T2 --set contact.interface.slave=nosuch
contact_bad missing-master "[contact interface] master = 'nosuch'|no physical group" \
  $T2 --set contact.interface.master=nosuch
contact_bad volume-slave "slave = 'upper'|not a group of boundary facets" \
  $T2 --set contact.interface.slave=upper
contact_bad no-overlap "taylor2d.scene:|[contact interface]|no slave facet overlaps a master facet" \
  $T2 --set contact.interface.master=lower_bottom
contact_bad epsilon-zero "--set|epsilon = '0'|(0, 1]" $T2 --set contact.interface.epsilon=0
contact_bad epsilon-big "--set|epsilon = '1.5'|(0, 1]" $T2 --set contact.interface.epsilon=1.5
contact_bad master-and-obstacle "[contact interface]|exactly one of master" \
  $T2 --set contact.interface.obstacle=graph
contact_bad same-groups "master = 'upper_bottom'|must differ" \
  $T2 --set contact.interface.master=upper_bottom
# An interference of 1e8 on the shrink fit of chapter 08 (rings of 10 to
# 30 mm, the documented bound is 1e30): the loop solves to rounding but
# does not stop, its gaps carrying the rounding of displacements of 1e8;
# it converges (a later stopping test) or names the interference, never
# "raise the iteration limit" alone.
SF=chapters/08-experiments/shrink-fit.scene
if "$LAC" run $SF --set contact.fit.interference=1e8 --quiet --no-output \
     > "$C/sf-huge.out" 2> "$C/sf-huge.err"; then
  contact_ok interference-huge
else
  contact_bad interference-huge "shrink-fit.scene|[contact fit] interference = 1e+08 is|times the size of its macro-elements|the stopping test" \
    $SF --set contact.fit.interference=1e8
fi

# ---- comparison methods [LAC §4.2, §5.1] --------------------------------
# Node-to-segment collocation fails the patch test with non-matching
# meshes (the pressure oscillates); P0 on a fine linear slave trace has more
# multipliers than the master can control (no interior d.o.f.: Hypothesis 1
# fails) and its saddle-point system is singular: a clear message.
if "$LAC" run $T2 --set element=quad4 --set level=1 --set contact.interface.method=nts \
     --quiet --no-output > "$C/nts.out" 2> "$C/nts.err" \
   && awk -v a="$(value_of "$C/nts.out" max_rel_err_lambda)" 'BEGIN { exit !(a > 1e-3) }'; then
  contact_ok nts-oscillates
else
  contact_fail nts-oscillates "nts on the patch test: max_rel_err_lambda = $(value_of "$C/nts.out" max_rel_err_lambda) (want > 1e-3) $(tail -1 "$C/nts.err")"
fi
# A body held by contact alone, pulled off: the message names it and its
# free motion (never a NaN).
contact_bad pulled-off "body 'upper'|translation along z|held by contact alone|active-set iteration" \
  chapters/08-experiments/taylor3d.scene --set load.top.pressure=-25
contact_bad schur-floating "strategy schur|held by contact alone" \
  chapters/08-experiments/taylor3d.scene --strategy schur
contact_bad p0-singular "singular|inf-sup" chapters/08-experiments/taylor3d.scene \
  --set element=tet4 --set level=1 --set contact.interface.method=p0 \
  --set contact.interface.slave=lower_top --set contact.interface.master=upper_bottom

# beta_h [LAC (10)]: P0 on the raw trace decays with h, LAC stays bounded
# (Taylor 2D quad4, the finer body as slave, levels 0 and 3).
beta_of () {
  # shellcheck disable=SC2086
  "$LAC" infsup $T2 --set element=quad4 --set level="$1" \
    --set contact.interface.slave=lower_top --set contact.interface.master=upper_bottom \
    --set contact.interface.method="$2" --quiet 2>/dev/null | sed -n 's/^beta_h = //p'
}
bl0=$(beta_of 0 lac); bl3=$(beta_of 3 lac); bp0=$(beta_of 0 p0); bp3=$(beta_of 3 p0)
if awk -v a="$bl0" -v b="$bl3" -v c="$bp0" -v d="$bp3" \
     'BEGIN { exit !(a > 0 && c > 0 && b / a > 0.5 && d / c < 0.5 && b > 3 * d) }'; then
  contact_ok infsup-p0-vs-lac
else
  contact_fail infsup-p0-vs-lac "beta_h LAC $bl0 -> $bl3, P0 $bp0 -> $bp3 (want LAC ratio > 0.5, P0 ratio < 0.5)"
fi

# `lac infsup` prints beta_h for any contact scene: every method, and a
# rigid obstacle.
for args in "$T2 --set contact.interface.method=nts" "$T2 --set contact.interface.method=p0" \
            "chapters/09-spheres-rates/manufactured2d.scene"; do
  # shellcheck disable=SC2086
  b=$("$LAC" infsup $args --quiet 2>"$C/infsup.err" | sed -n 's/^beta_h = //p')
  if awk -v b="$b" 'BEGIN { exit !(b != "" && b > 0) }'; then
    contact_ok "infsup $args"
  else
    contact_fail "infsup $args" "beta_h = '$b': $(tail -1 "$C/infsup.err")"
  fi
done

# ---- curved contact: few active-set iterations ([contact] strategy auto) --
# The three curved scenes of chapter 07 (a cylinder on a rigid flat, a ball
# on a rigid plane, a cylinder on an elastic block) settle in <= 8
# iterations at every level run here, with a contact zone strictly inside
# the candidates (some multiplier inactive), and contact.csv satisfies the
# conditions of [LAC (18)] up to rounding: active rows have a mean gap
# <= 1e-10 max |mean gap| in size and lambda <= 0, inactive rows lambda = 0
# and a mean gap >= -1e-10 max |mean gap|.
curved () {
  name="curved-$1-level$2"
  if ! "$LAC" run "chapters/07-newton/$1.scene" --set level="$2" --quiet \
       --out "$C/$name" > "$C/$name.out" 2> "$C/$name.err"; then
    contact_fail "$name" "lac run failed: $(tail -1 "$C/$name.err")"
    return
  fi
  it=$(value_of "$C/$name.out" newton_iterations)
  na=$(value_of "$C/$name.out" active)
  nm=$(value_of "$C/$name.out" multipliers)
  kkt=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
    $col["multiplier"] != "" { n++; g[n] = $col["mean_gap"]; l[n] = $col["lambda"];
      a[n] = $col["active"]; m = (g[n] < 0 ? -g[n] : g[n]) > m ? (g[n] < 0 ? -g[n] : g[n]) : m }
    END { bad = 0; t = 1e-10 * m
      for (i = 1; i <= n; i++)
        if (a[i] == 1 ? (g[i] > t || g[i] < -t || l[i] > 0) : (l[i] != 0 || g[i] < -t)) bad++
      print bad }' "$C/$name/contact.csv")
  if awk -v n="$it" -v a="$na" -v m="$nm" -v k="$kkt" \
       'BEGIN { exit !(n >= 2 && n <= 8 && a > 0 && a < m && k == 0) }'; then
    contact_ok "$name"
  else
    contact_fail "$name" "newton_iterations = $it (want 2..8), active = $na of $nm, $kkt rows of contact.csv violate (18)"
  fi
}
for l in 0 2 4; do
  curved cylinder-flat $l
  curved cylinder-block $l
done
curved sphere-plane 0
curved sphere-plane 1

# ---- contact outputs: summary keys, contact.csv, contact.vtu -------------
# The Taylor patch test, either body as slave, 2D and 3D: the upper body is
# held by contact alone, so the resultant of the multipliers balances the
# load p |top| exactly: contact_force = -p |top| to 1e-10 relative (the
# sign of lambda), contact_area = |top|, max_contact_pressure = p, every
# multiplier active; the force_* columns of contact.csv sum to the same
# resultant along contact_axis.
balance () {
  name="balance-$1-$2-swap$3"
  swap=""
  [ "$3" = 1 ] && swap="--set contact.interface.slave=lower_top --set contact.interface.master=upper_bottom"
  # shellcheck disable=SC2086
  if ! "$LAC" run "chapters/08-experiments/$1.scene" --set element="$2" $swap \
       --quiet --out "$C/$name" > "$C/$name.out" 2> "$C/$name.err"; then
    contact_fail "$name" "lac run failed: $(tail -1 "$C/$name.err")"
    return
  fi
  f=$(value_of "$C/$name.out" contact_force); a=$(value_of "$C/$name.out" contact_area)
  p=$(value_of "$C/$name.out" max_contact_pressure); ax=$(value_of "$C/$name.out" contact_axis)
  na=$(value_of "$C/$name.out" active_macro_elements); nm=$(value_of "$C/$name.out" multipliers)
  col=force_$(echo "$ax" | tr -d '+-')
  sum=$(awk -F, -v c="$col" 'NR == 1 { for (k = 1; k <= NF; k++) if ($k == c) j = k; next }
        { s += $j } END { printf "%.17g", s }' "$C/$name/contact.csv")
  case "$ax" in -*) sum=$(awk -v s="$sum" 'BEGIN { printf "%.17g", -s }') ;; esac
  if awk -v f="$f" -v a="$a" -v p="$p" -v A="$4" -v s="$sum" -v na="$na" -v nm="$nm" 'BEGIN {
       F = -25 * A; ok = f != "" && (f - F) ^ 2 <= (1e-10 * F) ^ 2
       ok = ok && (a - A) ^ 2 <= (1e-10 * A) ^ 2 && (p - 25) ^ 2 <= 1e-18
       ok = ok && (s - f) ^ 2 <= (1e-10 * F) ^ 2 && na == nm && na > 0
       exit !ok }'; then
    contact_ok "$name"
  else
    contact_fail "$name" "contact_force = $f (want -25 x $4), contact_area = $a, max_contact_pressure = $p, sum of $col = $sum, active $na of $nm"
  fi
}
for sw in 0 1; do
  balance taylor2d quad8 $sw 50
  balance taylor2d tri3 $sw 50
  balance taylor3d hex20 $sw 2500
  balance taylor3d tet10 $sw 2500
done

# A rigid obstacle: the progress line counts the slave facets on it (no
# "0 pairs"); contact.csv has a position and an abscissa on every row, z
# empty (2D), lambda_exact empty (no [exact]), the multiplier columns empty
# only where there is no multiplier, s growing with x along the arc from
# the symmetry axis; contact.vtu: one cell per slave facet, its lambda that
# of its macro-element in contact.csv.
R="$C/curved-cylinder-flat-level2"
"$LAC" run chapters/07-newton/cylinder-flat.scene --no-output > /dev/null 2> "$C/obstacle.err"
if grep -q '\[2/7\] contact .* [1-9][0-9]* slave facets on the rigid obstacle ([1-9][0-9]* integration points)' \
     "$C/obstacle.err" && ! grep -q '0 pairs' "$C/obstacle.err"; then
  contact_ok obstacle-progress
else
  contact_fail obstacle-progress "$(grep '\[2/7\]' "$C/obstacle.err")"
fi
bad=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
  { if ($col["x"] == "" || $col["y"] == "" || $col["z"] != "" || $col["s"] == "" \
        || $col["lambda_exact"] != "") b++
    if (($col["multiplier"] == "") != ($col["lambda"] == "") \
        || ($col["multiplier"] == "") != ($col["force_x"] == "")) b++
    if (NR > 2 && ($col["s"] <= s || $col["x"] <= x)) b++
    s = $col["s"]; x = $col["x"] }
  END { print b + 0 }' "$R/contact.csv")
if [ "$bad" = 0 ] && [ "$(wc -l < "$R/contact.csv")" -gt 2 ]; then
  contact_ok obstacle-contact-csv
else
  contact_fail obstacle-contact-csv "$bad bad rows in $R/contact.csv"
fi
if command -v python3 > /dev/null 2>&1; then
  msg=$(python3 - "$R/contact.vtu" "$R/contact.csv" <<'EOF' 2>&1
import sys, csv, math
sys.path.insert(0, "tests")
from vtu import read
piece, a = read(sys.argv[1])
rows = list(csv.DictReader(open(sys.argv[2])))
nc = int(piece.get("NumberOfCells"))
assert nc >= len(rows), "a cell per slave facet"
assert len(a["macro"]) == len(a["lambda"]) == len(a["status"]) == nc, "cell data"
assert len(a["displacement"]) == 3 * int(piece.get("NumberOfPoints")), "displacement"
assert set(a["types"]) == {21.0}, "seg3 cells"
for m, lam, st in zip(a["macro"], a["lambda"], a["status"]):
    r = rows[int(m)]
    want = float(r["lambda"]) if r["lambda"] else math.nan
    assert (math.isnan(lam) and math.isnan(want)) or abs(lam - want) <= 1e-9 * abs(want), "lambda of macro %d" % m
    assert st == (int(r["active"]) if r["active"] else -1), "status of macro %d" % m
EOF
) && contact_ok obstacle-contact-vtu || contact_fail obstacle-contact-vtu "$msg"
fi

# With [exact] (Taylor): lambda_exact on every row with a multiplier.
R="$C/balance-taylor2d-quad8-swap0"
if awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
     $col["multiplier"] != "" && $col["lambda_exact"] == "" { b++ } END { exit b > 0 || NR < 2 }' \
     "$R/contact.csv"; then
  contact_ok taylor-lambda-exact
else
  contact_fail taylor-lambda-exact "empty lambda_exact in $R/contact.csv"
fi
