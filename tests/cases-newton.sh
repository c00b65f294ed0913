# tests/cases-newton.sh -- the one loop of Algorithm 1 on whole scenes
#                          (sourced by tests/run.sh)       [LAC §4.5, Alg. 1]
#
# Checked through `lac run`:
#   - no silent penetration: chapter 07's two columns, one standing on the
#     base and one 5 mm above it, both pushed down by 6 mm.  From level 2
#     on the pairing of the reference shape does not reach the second
#     column; at every level 0-3 the run must end with the contact force
#     of the two compressed columns, -E/(1-nu^2) * 6 * (6+1)/20 =
#     -4615.38 N/mm, to 1e-3 (the base is stiff, not rigid), and say that
#     it paired again (pairing_widened) where it had to;
#   - the large-deformation loop in the axisymmetric model: the spheres of
#     chapter 09 at 1e-4 of their pressure (tests/hard/spheres-axi-ld.scene)
#     give the small-strain multipliers to 1e-6 of the largest, once
#     compared as forces: lambda is a pressure on the deformed surface,
#     which the inner pressure has stretched by 2 u_R / R = 1.4e-6, so
#     lambda itself is smaller by that (measured 1.3e-6 to 1.7e-6 at this
#     load, 1.1e-5 at ten times it: a true difference of the two
#     theories, not an error); lambda |T^m cap Gamma_C| is the force on
#     the macro-element, the same in both to second order;
#   - the rules of the loop (chapter 07, section 5), each switched off
#     alone: the same answer, more iterations without first_contact (the
#     cylinder on a flat), held_start (chapter 10's ball on a rigid flat)
#     and line_search (the ring in 3 load steps, frozen tangent), more GMRES iterations without inexact (the cylinder on a
#     block in large deformation); a rule that does not exist is named;
#   - why the loop stops: a mean gap at the rounding level of its terms
#     is closed (the sliver with epsilon = 1e-14; a shrink fit of 1e8 and
#     1e9, the pressure linear in delta to 1e-9), and the iteration limit
#     says that the statuses still change.
# Same conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
C="$B/cases-newton"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

newton_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
newton_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

# ---- no silent penetration --------------------------------------------------
for level in 0 1 2 3; do
  name="two-columns-level$level"
  if "$LAC" run chapters/07-newton/two-columns.scene --set level=$level \
       --quiet --no-output > "$C/$name.out" 2> "$C/$name.err"; then
    f=$(sed -n 's/^contact_force = //p' "$C/$name.out")
    w=$(sed -n 's/^pairing_widened = //p' "$C/$name.out")
    if awk -v f="$f" -v w="${w:-0}" -v l="$level" 'BEGIN {
         want = -2000 / (1 - 0.09) * 6 * 7 / 20
         exit !(f != "" && (f - want) ^ 2 <= (1e-3 * want) ^ 2 \
                && (l < 2 || w >= 1)) }'; then
      newton_ok "$name"
    else
      newton_fail "$name" "contact_force = $f (want -4615.38 to 1e-3), pairing_widened = ${w:-none}"
    fi
  else
    newton_fail "$name" "lac run failed: $(tail -1 "$C/$name.err")"
  fi
done

# ---- axisymmetric large deformation at a small load -------------------------
S=tests/hard/spheres-axi-ld.scene
if "$LAC" run "$S" --quiet --out "$C/ld" > "$C/ld.out" 2> "$C/ld.err" \
   && "$LAC" run "$S" --set scene.large_deformation=no --quiet --out "$C/lin" \
        > "$C/lin.out" 2> "$C/lin.err"; then
  # the force lambda |T^m cap Gamma_C| per macro-element: contact.csv
  # (small strain) against the last step of contact_steps.csv (large
  # deformation, on the deformed surface)
  res=$(awk -F, '
    FNR == 1 { for (k = 1; k <= NF; k++) col[FILENAME, $k] = k; next }
    FILENAME ~ /lin/ { if ($(col[FILENAME, "multiplier"]) != "")
                         lin[$(col[FILENAME, "macro"])] = $(col[FILENAME, "lambda"]) * $(col[FILENAME, "covered"]); next }
    { ld[$(col[FILENAME, "macro"])] = $(col[FILENAME, "lambda"]) * $(col[FILENAME, "covered"]) }
    END {
      n = 0; m = 0; d = 0
      for (k in lin) { n++; a = lin[k] < 0 ? -lin[k] : lin[k]; if (a > m) m = a
                       e = lin[k] - ld[k]; e = e < 0 ? -e : e; if (e > d) d = e }
      printf "%d %.3e %.3e", n, m, (m > 0 ? d / m : 1) }' \
      "$C/lin/contact.csv" "$C/ld/contact_steps.csv")
  if echo "$res" | awk '{ exit !($1 > 0 && $2 > 0 && $3 <= 1e-6) }'; then
    newton_ok axisym-large-deformation
  else
    newton_fail axisym-large-deformation "multipliers, largest force, max |f_ld - f_lin| / it: $res (want <= 1e-6)"
  fi
else
  newton_fail axisym-large-deformation "lac run failed: $(tail -1 "$C/ld.err") $(tail -1 "$C/lin.err")"
fi

# ---- the rules of the loop (chapter 07, section 5) --------------------------
# Each rule switched off alone ([contact] rules = the other five): the
# same answer, and what the rule is for.  newton_rules SCENE PAIR OFF
# [--set ...]: the summary of the run without rule OFF in $C/rules-OFF.out
rules_all="held_start all_active first_contact cycle_guard line_search inexact"
newton_rules () {
  sc=$1; pr=$2; off=$3; shift 3
  on=$(echo $rules_all | tr ' ' '\n' | grep -vx "$off" | paste -sd, -)
  "$LAC" run "$sc" --set "contact.$pr.rules=$on" "$@" --no-output \
    > "$C/rules-$off.out" 2> "$C/rules-$off.err"
}
newton_val () { sed -n "s/^$2 = //p" "$1"; }
# newton_rule_case NAME OFF_OUT ALL_OUT KEY RTOL: the two runs agree on KEY
# and the one without the rule took more iterations (or, with "gmres",
# more GMRES iterations in its progress lines)
newton_rule_case () {
  a=$(newton_val "$3" "$4"); b=$(newton_val "$2" "$4")
  ia=$(newton_val "$3" newton_iterations); ib=$(newton_val "$2" newton_iterations)
  if [ "$6" = gmres ]; then
    ia=$(sed -n 's/.* \([0-9]*\) GMRES .*/\1/p' "${3%.out}.err" | awk '{ s += $1 } END { print s + 0 }')
    ib=$(sed -n 's/.* \([0-9]*\) GMRES .*/\1/p' "${2%.out}.err" | awk '{ s += $1 } END { print s + 0 }')
  fi
  if awk -v a="$a" -v b="$b" -v ia="$ia" -v ib="$ib" -v r="$5" 'BEGIN {
       d = a - b; d = d < 0 ? -d : d; m = a < 0 ? -a : a
       exit !(a != "" && b != "" && d <= r * m && ia + 0 > 0 && ib + 0 > ia + 0) }'
  then newton_ok "$1"
  else newton_fail "$1" "$4: $a with the rule, $b without (rtol $5); iterations $ia with, $ib without (want more)"
  fi
}
S=chapters/07-newton/cylinder-flat.scene
if "$LAC" run "$S" --set level=4 --quiet --no-output > "$C/rules-all.out" 2>&1 \
   && newton_rules "$S" flat first_contact --set level=4; then
  newton_rule_case rules-first-contact "$C/rules-first_contact.out" \
    "$C/rules-all.out" contact_force 1e-10
else newton_fail rules-first-contact "lac run failed: $(tail -1 "$C/rules-first_contact.err")"
fi
S=chapters/10-large-deformation/hertz-sphere.scene
if "$LAC" run "$S" --quiet --no-output > "$C/rules-all.out" 2>&1 \
   && newton_rules "$S" flat held_start; then
  newton_rule_case rules-held-start "$C/rules-held_start.out" \
    "$C/rules-all.out" contact_force 1e-10
else newton_fail rules-held-start "lac run failed: $(tail -1 "$C/rules-held_start.err")"
fi
S=chapters/10-large-deformation/ring.scene
if "$LAC" run "$S" --set element=hex8 --set steps.n=3 --set steps.tangent=frozen \
     --quiet --no-output > "$C/rules-all.out" 2>&1 \
   && newton_rules "$S" ring line_search --set element=hex8 --set steps.n=3 \
        --set steps.tangent=frozen; then
  newton_rule_case rules-line-search "$C/rules-line_search.out" \
    "$C/rules-all.out" monitor_uz 1e-6
else newton_fail rules-line-search "lac run failed: $(tail -1 "$C/rules-line_search.err")"
fi
S=chapters/10-large-deformation/hertz-cylinder-block.scene
if "$LAC" run "$S" --set scene.large_deformation=yes --no-output \
     > "$C/rules-all.out" 2> "$C/rules-all.err" \
   && newton_rules "$S" interface inexact --set scene.large_deformation=yes; then
  newton_rule_case rules-inexact "$C/rules-inexact.out" "$C/rules-all.out" \
    contact_force 1e-8 gmres
else newton_fail rules-inexact "lac run failed: $(tail -1 "$C/rules-inexact.err")"
fi

# ---- why the loop stops ------------------------------------------------------
# Converged when the statuses settle and the residuals are at rounding
# level: the sliver of chapter 11 kept with epsilon = 1e-14 (its mean gap
# is 1e-23 of a measure of 1e-14) and a shrink fit of 1e8 (gaps of 1e8
# closed to rounding).  Otherwise the message names what failed.
if "$LAC" run tests/hard/sliver2d.scene --set contact.interface.epsilon=1e-14 \
     --quiet --no-output > "$C/sliver.out" 2> "$C/sliver.err" \
   && [ "$(newton_val "$C/sliver.out" active)" = 2 ]; then
  newton_ok stop-sliver-rounding
else newton_fail stop-sliver-rounding "$(tail -1 "$C/sliver.err")"
fi
S=chapters/08-experiments/shrink-fit.scene
if "$LAC" run "$S" --set contact.fit.interference=1e8 --quiet --no-output \
     > "$C/fit8.out" 2> "$C/fit8.err" \
   && "$LAC" run "$S" --set contact.fit.interference=1e9 --quiet --no-output \
     > "$C/fit9.out" 2> "$C/fit9.err" \
   && awk -v a="$(newton_val "$C/fit8.out" max_contact_pressure)" \
          -v b="$(newton_val "$C/fit9.out" max_contact_pressure)" \
          'BEGIN { r = b / a / 10 - 1; exit !(a > 0 && r < 1e-9 && r > -1e-9) }'
then newton_ok stop-interference-rounding
else newton_fail stop-interference-rounding "$(tail -1 "$C/fit8.err") $(tail -1 "$C/fit9.err") (the pressure linear in delta)"
fi
if "$LAC" run chapters/07-newton/cylinder-flat.scene --set level=4 \
     --set contact.flat.max_iterations=2 --quiet --no-output \
     > "$C/stop.out" 2> "$C/stop.err"; then
  newton_fail stop-message "exit 0 at the iteration limit"
elif grep -q "no convergence in 2 iterations of Algorithm 1: the statuses still change" "$C/stop.err"
then newton_ok stop-message
else newton_fail stop-message "$(tail -1 "$C/stop.err")"
fi
if "$LAC" run chapters/07-newton/cylinder-flat.scene --set level=4 \
     --set contact.flat.rules=held_start,cycle \
     --quiet --no-output > "$C/badrule.out" 2> "$C/badrule.err"; then
  newton_fail rules-bad "exit 0 with a rule that does not exist"
elif grep -q "rules.*'cycle' is not a rule of the loop" "$C/badrule.err"
then newton_ok rules-bad
else newton_fail rules-bad "$(tail -1 "$C/badrule.err")"
fi
