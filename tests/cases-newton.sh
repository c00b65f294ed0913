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
#     the macro-element, the same in both to second order.
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
