# tests/cases-setups-exercises.sh -- the answers of
# chapters/16-setups/exercises.md (sourced by tests/run.sh; same
# conventions as tests/cases.sh: $B, pass, fail)        [LAC (18); chapter 16]
#
#   ex1  the shrink fit of chapters/08-experiments/shrink-fit.scene with
#        delta = 0.03 and nu = 0.25, level 2: every multiplier within
#        5e-4 of -p, p = E' delta (c^2 - b^2)(b^2 - a^2) / (2 b^3 (c^2 -
#        a^2)) with E' = E / (1 - nu^2) (nu' cancels), computed here;
#   ex2  the compound ring (chapters/16-setups/compound.scene): without the
#        bore pressure both reactions vanish (<= 1e-10: the fits are
#        self-equilibrated), with it and the sector opened to 90 degrees
#        reaction.cut0 = (0, -a p) and reaction.cut1 = (-a p, 0) to 1e-10
#        (statically determined), whatever the interferences;
#   ex3  quad4 on the shrink fit: interference_gap at levels 0, 1, 2
#        within 5 % of R (alpha_i^2 - alpha_o^2) / (12 delta) (the chords'
#        mean sagittas, alpha = the angle of a chord: 8 and 6 cells on a
#        quarter at level 0); level 2 refused (exit status 1, the message
#        names interference_tolerance), level 3 accepted with a warning;
#        at level 2 with delta = 0.04 accepted and lambda within 1 % of
#        the pressure of delta + |g| (the chords' gap added to delta);
#   ex4  the cylinder on the flat of chapter 07 pressed and released
#        (curve = 0 0 1 1 2 0, 8 steps): the contact force at t = 0.5 and
#        t = 1.5 equal to 1e-10 (no memory), below half the force at t = 1
#        (the contact zone grows), and nothing active at the end.
# About 5 s.

B=${B:-build}
C="$B/cases-setups-exercises"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

su_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
su_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
su_value () { sed -n "s/^$2 = //p" "$C/$1.out"; }

# su_run NAME ARGS...: lac run into $C/NAME.out; 0 or a FAIL line.
su_run () {
  sr_name=$1
  shift
  if "$LAC" run "$@" --quiet --no-output > "$C/$sr_name.out" 2> "$C/$sr_name.err"; then
    return 0
  fi
  su_fail "$sr_name" "lac run $* failed: $(tail -1 "$C/$sr_name.err")"
  return 1
}

# su_check NAME STATEMENTS CONDITION MESSAGE -v VAR=VALUE...: awk runs the
# statements (the expected values), then decides
su_check () {
  sc_name=$1 sc_pre=$2 sc_cond=$3 sc_msg=$4
  shift 4
  if awk "$@" "function abs(x) { return x < 0 ? -x : x }
               BEGIN { $sc_pre; exit !($sc_cond) }"; then su_ok "$sc_name"
  else su_fail "$sc_name" "$sc_msg"; fi
}

FIT=chapters/08-experiments/shrink-fit.scene
RING=chapters/16-setups/compound.scene

# ---- exercise 1: the shrink-fit formula -----------------------------------
if su_run ex1 $FIT --set level=2 --set contact.fit.interference=0.03 --set material.steel.nu=0.25; then
  lo=$(su_value ex1 lambda_min) hi=$(su_value ex1 lambda_max)
  su_check "ex1 fit pressure" \
    "p = 2000 / (1 - 0.25 ^ 2) * 0.03 * (900 - 400) * (400 - 100) / (2 * 8000 * (900 - 100))" \
    "abs(lo + p) <= 5e-4 * p && abs(hi + p) <= 5e-4 * p" \
    "lambda from $lo to $hi, want -p within 5e-4 (p = 0.75)" -v lo="$lo" -v hi="$hi"
fi

# ---- exercise 2: reactions of the compound ring ----------------------------
if su_run ex2-fits $RING --set load.bore.pressure=0; then
  r0=$(su_value ex2-fits reaction.cut0) r1=$(su_value ex2-fits reaction.cut1)
  su_check "ex2 fits alone: no reaction" \
    "na = split(r0, a, \" \"); nb = split(r1, b, \" \")" "na == 2 && nb == 2 && abs(a[1]) + abs(a[2]) + abs(b[1]) + abs(b[2]) <= 1e-10" \
    "reaction.cut0 = $r0, reaction.cut1 = $r1 (want 0 to 1e-10)" -v r0="$r0" -v r1="$r1"
fi
for d in 0.01 0; do
  if su_run "ex2-90-$d" $RING --set mesh.numbers=angle=90 --set contact.fit12.interference=$d \
       --set contact.fit23.interference=$d --set load.bore.pressure=2; then
    r0=$(su_value "ex2-90-$d" reaction.cut0) r1=$(su_value "ex2-90-$d" reaction.cut1)
    su_check "ex2 quarter, delta = $d: reactions a p" \
      "na = split(r0, a, \" \"); nb = split(r1, b, \" \")" "na == 2 && nb == 2 && abs(a[1]) + abs(a[2] + 20) + abs(b[1] + 20) + abs(b[2]) <= 1e-10 * 20" \
      "reaction.cut0 = $r0 (want 0 -20), reaction.cut1 = $r1 (want -20 0)" -v r0="$r0" -v r1="$r1"
  fi
done

# ---- exercise 3: the chords' gap against delta ------------------------------
for l in 0 1 2; do
  if su_run "ex3-$l" $FIT --set element=quad4 --set level=$l --set contact.fit.interference_tolerance=1e9; then
    r=$(su_value "ex3-$l" interference_gap)
    su_check "ex3 level $l: r from the sagittas" \
      "pi = atan2(0, -1); ai = pi / 2 / (8 * 2 ^ l); ao = pi / 2 / (6 * 2 ^ l)
       want = 20 * (ao * ao - ai * ai) / (12 * 0.01)" "abs(r - want) <= 0.05 * want" \
      "interference_gap = $r at level $l, want R (alpha_o^2 - alpha_i^2) / (12 delta) within 5 %" -v r="$r" -v l="$l"
  fi
done
"$LAC" run $FIT --set element=quad4 --set level=2 --quiet --no-output > "$C/ex3-refused.out" 2> "$C/ex3-refused.err"
rc=$?
if [ $rc = 1 ] && grep -q "interference_tolerance = 0.1" "$C/ex3-refused.err" && [ ! -s "$C/ex3-refused.out" ]; then
  su_ok "ex3 level 2 refused"
else
  su_fail "ex3 level 2 refused" "exit status $rc (want 1): $(tail -1 "$C/ex3-refused.err")"
fi
if "$LAC" run $FIT --set element=quad4 --set level=3 --no-output > "$C/ex3-3.out" 2> "$C/ex3-3.err" \
   && grep -q "warning: \[contact fit\]" "$C/ex3-3.err"; then
  su_ok "ex3 level 3 warned"
else
  su_fail "ex3 level 3 warned" "no run or no warning: $(tail -1 "$C/ex3-3.err")"
fi
if su_run ex3-04 $FIT --set element=quad4 --set level=2 --set contact.fit.interference=0.04 \
     && su_run ex3-g $FIT --set element=quad4 --set level=2 --set contact.fit.interference_tolerance=1e9; then
  lo=$(su_value ex3-04 lambda_min) g=$(su_value ex3-g interference_gap)
  su_check "ex3 delta = 0.04: the fit of delta + |g|" \
    "p = 2000 / (1 - 0.09) * (0.04 + g * 0.01) * 500 * 300 / (2 * 8000 * 800)" "abs(lo + p) <= 0.01 * p" \
    "lambda_min = $lo, want -p(delta + |g|) within 1 % (|g| = $g delta)" -v lo="$lo" -v g="$g"
fi

# ---- exercise 4: pressed and released ---------------------------------------
if "$LAC" run chapters/07-newton/cylinder-flat.scene --set steps.n=8 --set steps.end=2 \
     --set "dirichlet.top.curve=0 0 1 1 2 0" --out "$C/ex4" --quiet > "$C/ex4.out" 2> "$C/ex4.err"; then
  if msg=$(awk -F, 'NR > 1 { f[$2 + 0] = $11; a[$2 + 0] = $10 }
       END { up = f[0.5]; dn = f[1.5]; top = f[1]; d = up - dn; if (d < 0) d = -d
             if (!(up < 0 && d <= 1e-10 * -up && up / top < 0.5 && a[2] == 0 && f[2] == 0)) {
               printf "force at t = 0.5, 1.5, 1: %s %s %s; active at the end %s", up, dn, top, a[2]; exit 1 } }' \
       "$C/ex4/curve.csv" 2>&1); then
    su_ok "ex4 no memory"
  else
    su_fail "ex4 no memory" "$msg"
  fi
else
  su_fail "ex4 no memory" "lac run failed: $(tail -1 "$C/ex4.err")"
fi
