# tests/cases-hertz.sh -- Hertz contact in 2D and 3D (sourced by tests/run.sh)
#
# chapters/10-large-deformation/hertz.sh on the four 2D cases (a cylinder on a
# rigid flat and on an elastic block, quad8 and tri6) at levels 0 1 2:
# from one level to the next the errors of the peak pressure and of the
# half-width against Hertz's values must decrease, at level 2 both must be
# below 0.5 %, and at every level the contact force must equal the load
# to 1e-10 relative.  One run per case at level 1 must reproduce its
# golden summary (tests/golden/hertz-*.out, numcmp).  In 3D (a sphere on
# a rigid flat, tet10, and on an elastic block, hex20) one run each at
# level 0 against its golden summary; their convergence to 1 % takes
# minutes (chapter 10).  Same conventions as tests/cases.sh ($B, pass,
# fail).

B=${B:-build}
C="$B/cases-hertz"
NUMCMP="$B/tests/numcmp"
rm -rf "$C"
mkdir -p "$C"

hz_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
hz_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

if B="$B" OUT="$C" sh chapters/10-large-deformation/hertz.sh \
     "cyl-rigid:quad8 cyl-rigid:tri6 cyl-block:quad8 cyl-block:tri6" "0 1 2" \
     > "$C/table.txt" 2> "$C/table.err"; then
  for c in cyl-rigid:quad8 cyl-rigid:tri6 cyl-block:quad8 cyl-block:tri6; do
    bad=$(awk -v c="$c" '$1 == c { n++; p[n] = $5 < 0 ? -$5 : $5; a[n] = $7 < 0 ? -$7 : $7; f[n] = $9 }
      END { b = n != 3 ? "levels " n : ""
        for (i = 2; i <= n; i++) if (p[i] >= p[i-1] || a[i] >= a[i-1]) b = b " level " i - 1 " not better"
        if (p[n] >= 0.5 || a[n] >= 0.5) b = b " level 2 error >= 0.5 %"
        for (i = 1; i <= n; i++) if (f[i] > 1e-10) b = b " |F - P|/P = " f[i]
        print b }' "$C/table.txt")
    if [ -z "$bad" ]; then hz_ok "hertz-$c"; else hz_fail "hertz-$c" "$bad: $(grep "^$c " "$C/table.txt" | tr -s ' ' | tr '\n' ';')"; fi
  done
else
  hz_fail hertz-table "hertz.sh failed: $(tail -1 "$C/table.err")"
fi

# hz_golden NAME [LEVEL]: $C/NAME-LEVEL.out (level 1 unless given) against
# tests/golden/hertz-NAME.out
hz_golden () {
  run="$C/$1-${2:-1}.out"
  if [ -n "$LAC_GOLDEN_UPDATE" ]; then
    { echo "# numcmp: rtol=1e-6 atol=1e-12 int=exact"; cat "$run"; } > "tests/golden/hertz-$1.out"
  fi
  if [ ! -f "$run" ]; then
    hz_fail "golden-hertz-$1" "no run $run"
  elif "$NUMCMP" "tests/golden/hertz-$1.out" "$run" > "$C/$1.cmp" 2>&1; then
    hz_ok "golden-hertz-$1"
  else
    hz_fail "golden-hertz-$1" "differs from tests/golden/hertz-$1.out: $(head -1 "$C/$1.cmp")"
  fi
}
for g in cyl-rigid-quad8 cyl-rigid-tri6 cyl-block-quad8 cyl-block-tri6; do hz_golden "$g"; done

# 3D: level 0 of a sphere on a rigid flat (tet10) and on an elastic block
# (hex20)
if ! B="$B" OUT="$C" sh chapters/10-large-deformation/hertz.sh \
     "sph-rigid:tet10 sph-block:hex20" 0 > "$C/table3d.txt" 2> "$C/table3d.err"; then
  hz_fail hertz-table-3d "hertz.sh failed: $(tail -1 "$C/table3d.err")"
fi
for g in sph-rigid-tet10 sph-block-hex20; do hz_golden "$g" 0; done
