# tests/cases-manufactured.sh -- convergence rates (sourced by tests/run.sh)
#
# The manufactured solutions [LAC §5.3, Tables 5-6] at CI sizes: the rates
# of ||u - u_h||_0 and ||lambda - lambda_h||_{0,Gamma_C}, least-squares
# slopes against h over a few small levels, must be within 0.15 of the
# values measured at those sizes (chapters/08-experiments/README.md,
# "Convergence rates"; the full table comes from rates.sh); and one small
# run per dimension must reproduce its golden summary
# (tests/golden/manufactured-*.out, compared with numcmp).  Same
# conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
C="$B/cases-manufactured"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

mfd_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
mfd_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

# mfd_rates SCENE ELEMENT "LEVELS" RATE_U RATE_LAMBDA: fitted rates within 0.15
mfd_rates () {
  mfd_n="rates-$2"
  : > "$C/$mfd_n.dat"
  for l in $3; do
    if ! "$LAC" run "chapters/09-spheres-rates/$1.scene" --set element="$2" --set level="$l" \
         --quiet --no-output > "$C/$mfd_n-$l.out" 2> "$C/$mfd_n-$l.err"; then
      mfd_fail "$mfd_n" "level $l: lac run failed: $(tail -1 "$C/$mfd_n-$l.err")"
      return
    fi
    awk -F' = ' '{ v[$1] = $2 } END { print v["h"], v["l2_err_u"], v["l2_err_lambda"] }' \
      "$C/$mfd_n-$l.out" >> "$C/$mfd_n.dat"
  done
  mfd_r=$(awk '
    function fit(c,   i, sx, sy, sxx, sxy, x, y) {
      sx = sy = sxx = sxy = 0
      for (i = 1; i <= n; i++) { x = log(h[i]); y = log(v[i, c]); sx += x; sy += y; sxx += x * x; sxy += x * y }
      return (n * sxy - sx * sy) / (n * sxx - sx * sx)
    }
    $1 > 0 && $2 > 0 && $3 > 0 { n++; h[n] = $1; v[n, 2] = $2; v[n, 3] = $3 }
    END { if (n >= 2) printf "%.3f %.3f\n", fit(2), fit(3) }' "$C/$mfd_n.dat")
  if [ -n "$mfd_r" ] && awk -v g="$mfd_r" -v u="$4" -v l="$5" 'BEGIN { split(g, r, " ")
       d1 = r[1] - u; d2 = r[2] - l; exit !(d1 <= 0.15 && d1 >= -0.15 && d2 <= 0.15 && d2 >= -0.15) }'; then
    mfd_ok "$mfd_n"
  else
    mfd_fail "$mfd_n" "levels $3: rates (u, lambda) = ${mfd_r:-none}, want $4 and $5 +- 0.15"
  fi
}

# rates measured at these sizes (README.md, "Convergence rates")
mfd_rates manufactured2d tri3 "1 2 3 4" 1.96 1.12
mfd_rates manufactured2d tri6 "0 1 2 3" 3.02 1.02
mfd_rates manufactured3d hex8 "1 2 3" 1.98 1.76

# mfd_golden NAME SCENE ELEMENT LEVEL: the summary against
# tests/golden/NAME.out (LAC_GOLDEN_UPDATE=1 rewrites it: check the diff).
mfd_golden () {
  mfd_n="golden-$1"
  mfd_g="tests/golden/$1.out"
  if ! "$LAC" run "chapters/09-spheres-rates/$2.scene" --set element="$3" --set level="$4" \
       --quiet --no-output > "$C/$1.out" 2> "$C/$1.err"; then
    mfd_fail "$mfd_n" "lac run failed: $(tail -1 "$C/$1.err")"
    return
  fi
  if [ -n "$LAC_GOLDEN_UPDATE" ]; then
    { echo "# numcmp: rtol=1e-6 atol=1e-12 int=exact"; cat "$C/$1.out"; } > "$mfd_g"
  fi
  if [ ! -f "$mfd_g" ]; then
    mfd_fail "$mfd_n" "no $mfd_g"
  elif "$B/tests/numcmp" "$mfd_g" "$C/$1.out" > "$C/$1.cmp" 2>&1; then
    mfd_ok "$mfd_n"
  else
    mfd_fail "$mfd_n" "differs from $mfd_g: $(head -1 "$C/$1.cmp")"
  fi
}

mfd_golden manufactured-2d-quad8 manufactured2d quad8 1
mfd_golden manufactured-3d-hex20 manufactured3d hex20 1
