# tests/cases-friction-exercises.sh -- the answers of
# chapters/15-friction/exercises.md (sourced by tests/run.sh; same
# conventions as tests/cases.sh: $B, pass, fail)          [chapter 15]
#
#   ex1  block-pull.scene: T = 59 converges with friction_force -59 to
#        1e-10; T = 61 stops with exit status 1 naming the block;
#   ex2  cattaneo2d.scene, P and Q = 0.6 mu P together, level 1: in 1, 4
#        and 16 steps the slipping macro-elements decrease, some in one
#        step, none in 16;
#   ex3  pushout.scene with mu = 0.1, d = 0.02: every macro-element of the
#        fit slips and F_z / N = 0.1 to 1e-12;
#   ex4  apparent.sh at level 1 and P = 700: with P in 16 steps the curved
#        slave's tangential traction is larger than the flat slave's, and
#        the flat slave's is larger with P in one step than in 16; at
#        P = 7 every column is smaller than at 700.
# About 15 s.

B=${B:-build}
FX="$B/cases-friction-exercises"
LAC="$B/lac"
rm -rf "$FX"
mkdir -p "$FX"

fx_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
fx_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
fx_value () { sed -n "s/^$2 = //p" "$FX/$1.out"; }
FXS=chapters/15-friction

# ---- exercise 1: the stick limit ----------------------------------------------
if "$LAC" run "$FXS/block-pull.scene" --set "load.top.traction=2.95 -10" \
     --quiet --no-output > "$FX/t59.out" 2> "$FX/t59.err" \
   && awk -v f="$(fx_value t59 friction_force)" \
        'BEGIN { split (f, v, " "); d = v[1] + 59; exit !(d < 1e-10 && d > -1e-10) }'
then fx_ok friction-ex1-below
else fx_fail friction-ex1-below "T = 59: $(tail -1 "$FX/t59.err") $(fx_value t59 friction_force)"
fi
"$LAC" run "$FXS/block-pull.scene" --set "load.top.traction=3.05 -10" \
  --quiet --no-output > "$FX/t61.out" 2> "$FX/t61.err"
st=$?
if [ "$st" -eq 1 ] && grep -q "no static solution with friction: body 'block'" "$FX/t61.err"; then
  fx_ok friction-ex1-above
else fx_fail friction-ex1-above "T = 61: exit status $st, $(tail -1 "$FX/t61.err")"
fi

# ---- exercise 2: proportional loading in 1, 4, 16 steps --------------------------
slips=""
for n in 1 4 16; do
  if "$LAC" run "$FXS/cattaneo2d.scene" --set level=1 --set steps.n=$n \
       --set steps.end=1 --set "load.pull.curve=0 0 1 1" --quiet --no-output \
       > "$FX/prop$n.out" 2> "$FX/prop$n.err"; then
    slips="$slips $(fx_value prop$n slip_macro_elements)"
  else slips="$slips failed"
  fi
done
if echo "$slips" | awk '{ exit !(NF == 3 && $1 > $2 && $2 > $3 && $3 == 0) }'; then
  fx_ok friction-ex2-proportional
else fx_fail friction-ex2-proportional "slipping macro-elements in 1, 4, 16 steps:$slips"
fi

# ---- exercise 3: the push-out with mu = 0.1 -----------------------------------------
if "$LAC" run "$FXS/pushout.scene" --set contact.fit.friction=0.1 \
     --set dirichlet.pull.uz=0.02 --quiet --no-output > "$FX/po.out" 2> "$FX/po.err" \
   && awk -v n="$(fx_value po contact_normal_force)" -v f="$(fx_value po friction_force)" \
          -v s="$(fx_value po slip_macro_elements)" -v k="$(fx_value po active_macro_elements)" \
        'BEGIN { split (f, v, " "); r = v[2] / n - 0.1; r = r < 0 ? -r : r
                 exit !(s == k && s > 0 && r <= 1e-12) }'
then fx_ok friction-ex3-pushout
else fx_fail friction-ex3-pushout "$(tail -1 "$FX/po.err") $(grep -E 'normal_force|friction_force|slip_' "$FX/po.out" | tr '\n' ' ')"
fi

# ---- exercise 4: the curved slave ---------------------------------------------------
if sh "$FXS/apparent.sh" "$B" 1 700 > "$FX/apparent700.txt" 2>&1 \
   && sh "$FXS/apparent.sh" "$B" 1 > "$FX/apparent7.txt" 2>&1 \
   && awk 'FNR == 3 { v[++n, 1] = $2; v[n, 2] = $3; v[n, 3] = $4 }
        END { exit !(n == 2 && v[1, 3] > v[1, 2] && v[1, 1] > v[1, 2] && v[1, 2] >= 0 \
                     && v[2, 1] < v[1, 1] && v[2, 2] < v[1, 2] && v[2, 3] < v[1, 3]) }' \
        "$FX/apparent700.txt" "$FX/apparent7.txt"; then
  fx_ok friction-ex4-slave
else fx_fail friction-ex4-slave "$(cat "$FX/apparent700.txt" "$FX/apparent7.txt")"
fi
