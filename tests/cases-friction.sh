# tests/cases-friction.sh -- Coulomb friction through `lac run`
#                            (sourced by tests/run.sh; chapter 15)
#
# Checked:
#   frictionless   friction = 0, given or not, runs the frictionless path:
#                  the Taylor patch test's summary.txt and contact.csv are
#                  byte for byte the same with `--set
#                  contact.interface.friction=0` and without;
#   effects        the effects line names "Coulomb friction (LAC; mu = 0.4)";
#   outputs        contact.csv has lambda_t, status and slip (2D), lambda_t1,
#                  lambda_t2, status, slip1, slip2 (3D); contact.vtu the
#                  fields lambda_t and slip (tests/vtu.py); the summary's
#                  friction_force, stick_, slip_ and open_macro_elements,
#                  per pair with two pairs;
#   the limit      a block pulled beyond mu P on a rigid flat: exit status
#                  1, one line naming the block, earlier outputs intact;
#   strategies     augmented and split (no direct solve of friction's
#                  unsymmetric equations: GMRES preconditioned by their own
#                  solve, solve/lac_rows.h) give the patch test's friction
#                  force to 1e-10;
#   render         lac render --contact of Cattaneo-Mindlin (level 1): the
#                  tangential panel agrees with contact.csv; --compare,
#                  --srange, and their bad values;
#   bad input      friction = -1 and nan, friction with large deformation,
#                  with method = nts: one line naming the key and the way
#                  out, exit status 1.
# Same conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
FC="$B/cases-friction"
LAC="$B/lac"
rm -rf "$FC"
mkdir -p "$FC"

fric_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
fric_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

# ---- friction = 0 is the frictionless path -----------------------------------
T=chapters/08-experiments/taylor2d.scene
if "$LAC" run "$T" --quiet --out "$FC/none" > /dev/null 2>&1 \
   && "$LAC" run "$T" --set contact.interface.friction=0 --quiet \
        --out "$FC/zero" > /dev/null 2>&1 \
   && cmp -s "$FC/none/summary.txt" "$FC/zero/summary.txt" \
   && cmp -s "$FC/none/contact.csv" "$FC/zero/contact.csv"; then
  fric_ok frictionless-bytes
else fric_fail frictionless-bytes "friction = 0 changed summary.txt or contact.csv"
fi

# ---- a frictional run: effects, outputs ---------------------------------------
S=tests/friction/patch2d-stick.scene
if "$LAC" run "$S" --out "$FC/stick" > "$FC/stick.out" 2> "$FC/stick.err"; then
  if grep -q "^lac: effects: .*Coulomb friction (LAC; mu = 0.4)" "$FC/stick.err"
  then fric_ok friction-effects
  else fric_fail friction-effects "$(grep effects "$FC/stick.err")"
  fi
  h=$(head -1 "$FC/stick/contact.csv")
  case $h in *,lambda_t,status,slip,pair) fric_ok friction-csv-2d ;;
    *) fric_fail friction-csv-2d "contact.csv header: $h" ;; esac
  if python3 -c "
import sys; sys.path.insert(0, 'tests')
import vtu
p, a = vtu.read('$FC/stick/contact.vtu')
assert len(a['lambda_t']) == len(a['status']) and len(a['slip']) == len(a['status'])
assert all(abs(v + 5) < 1e-9 for v, s in zip(a['lambda_t'], a['status']) if s == 1)
" 2> "$FC/vtu.err"; then fric_ok friction-vtu
  else fric_fail friction-vtu "$(tail -1 "$FC/vtu.err")"
  fi
  f=$(sed -n 's/^friction_force = //p' "$FC/stick.out")
  n=$(sed -n 's/^stick_macro_elements = //p' "$FC/stick.out")
  if awk -v f="$f" -v n="$n" 'BEGIN { split (f, v, " ");
       d = v[1] + 250; d = d < 0 ? -d : d; exit !(d <= 1e-9 && n > 0) }'
  then fric_ok friction-summary
  else fric_fail friction-summary "friction_force = $f (want -250 0), stick $n"
  fi
else fric_fail friction-run "$(tail -1 "$FC/stick.err")"
fi
if "$LAC" run tests/friction/patch3d-stick.scene --out "$FC/stick3" --quiet \
     > /dev/null 2> "$FC/stick3.err"; then
  h=$(head -1 "$FC/stick3/contact.csv")
  case $h in *,lambda_t1,lambda_t2,status,slip1,slip2,pair) fric_ok friction-csv-3d ;;
    *) fric_fail friction-csv-3d "contact.csv header: $h" ;; esac
else fric_fail friction-csv-3d "$(tail -1 "$FC/stick3.err")"
fi

# ---- no static solution: refused, earlier outputs intact -----------------------
P=chapters/15-friction/block-pull.scene
if "$LAC" run "$P" --out "$FC/pull" --quiet > /dev/null 2>&1; then
  cp "$FC/pull/summary.txt" "$FC/pull.keep"
  if "$LAC" run "$P" --set "load.top.traction=3.1 -10" --out "$FC/pull" \
       > "$FC/pull.out" 2> "$FC/pull.err"; then
    fric_fail friction-limit "exit 0 beyond the stick limit"
  elif grep -q "no static solution with friction: body 'block'" "$FC/pull.err" \
       && [ "$(grep -c '^lac: .*scene' "$FC/pull.err")" -le 2 ] \
       && cmp -s "$FC/pull/summary.txt" "$FC/pull.keep"; then
    fric_ok friction-limit
  else fric_fail friction-limit "$(tail -1 "$FC/pull.err")"
  fi
else fric_fail friction-limit "the block below the limit failed"
fi

# ---- bad input ----------------------------------------------------------------
# fric_bad NAME EXPECTED ARGS...: exit status 1 and EXPECTED in the last line
fric_bad () {
  name=$1; want=$2; shift 2
  if "$LAC" run "$@" --quiet --no-output > "$FC/$name.out" 2> "$FC/$name.err"
  then fric_fail "$name" "exit 0"
  elif tail -1 "$FC/$name.err" | grep -q -- "$want"; then fric_ok "$name"
  else fric_fail "$name" "$(tail -1 "$FC/$name.err") (want: $want)"
  fi
}
fric_bad friction-negative "friction = .-1.: expected a number >= 0" "$S" \
  --set contact.interface.friction=-1
fric_bad friction-nan "friction" "$S" --set contact.interface.friction=nan
fric_bad friction-large "friction is a small-strain law" chapters/15-friction/block-pull.scene \
  --set scene.large_deformation=yes
fric_bad friction-nts "not with nts" "$S" --set contact.interface.method=nts

# ---- every strategy: those without a direct solve of the law's equations
# ---- (augmented, split) by GMRES preconditioned by their own solve
for st in augmented split; do
  if "$LAC" run "$S" --set contact.interface.strategy=$st --quiet --no-output \
       > "$FC/$st.out" 2> "$FC/$st.err" \
     && awk -v f="$(sed -n 's/^friction_force = //p' "$FC/$st.out")" \
          'BEGIN { split (f, v, " "); d = v[1] + 250; d = d < 0 ? -d : d
                   exit !(d <= 250e-10) }'
  then fric_ok "friction-$st"
  else fric_fail "friction-$st" "$(tail -1 "$FC/$st.err") $(grep friction_force "$FC/$st.out")"
  fi
done

# ---- Cattaneo-Mindlin (chapter 15, cattaneo2d.scene) ----------------------------
# quad8 at levels 1, 2, 3 and Q / (mu P) = 0.3, 0.6, 0.9: the half-width c
# of the stick zone within 1 % of Cattaneo's at level 3, the L2 error of
# the tangential traction decreasing from level to level, at most 10
# iterations per load step (chapters/15-friction/cattaneo.sh prints them).
CM=chapters/15-friction
for r in 0.3 0.6 0.9; do
  Q=$(awk -v r="$r" 'BEGIN { printf "%.10g", r * 0.3 * 7 }')
  line=""
  for L in 1 2 3; do
    d="$FC/cm-$L-$r"
    if "$LAC" run "$CM/cattaneo2d.scene" --set level=$L \
         --set "load.pull.point_force=$Q 0" --quiet --out "$d" \
         > /dev/null 2> "$d.err"; then
      line="$line $(python3 "$CM/cattaneo.py" "$d" "$r")"
    else line="$line failed"
    fi
  done
  # fields per level: macros c/a exact error% L2 iters
  if echo "$line" | awk '{ exit !(NF == 18 && $16 + 0 < 1 && $16 + 0 > -1 \
       && $11 < $5 && $17 < $11 && $6 <= 10 && $12 <= 10 && $18 <= 10) }'; then
    fric_ok "cattaneo-$r"
  else fric_fail "cattaneo-$r" "levels 1 2 3: $line"
  fi
done

# ---- lac render --contact of a partial slip (level 1, Q / (mu P) = 0.6) ---------
# The third panel: contact.dat has lambda_t and the stick flag of every
# admissible macro-element of contact.csv, contact.gp draws lambda_t, mu
# |lambda| (mu = 0.3 from summary.txt) and the shaded stick zone; --compare
# and --srange reach the script; a bad compare file (exit 1, FILE:LINE) or
# range (exit 2) leaves the picture as it was.
d="$FC/cm-1-0.6"
if [ -f "$d/contact.csv" ] && "$LAC" render "$d" --contact > "$FC/render.out" 2> "$FC/render.err" \
   && [ "$(cat "$FC/render.out")" = "$d/contact.png" ] \
   && awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
        $(c["admissible"]) == 1 { printf "%.10e %d\n", $(c["lambda_t"]), $(c["status"]) == "stick" }' \
        "$d/contact.csv" | sort > "$FC/render-csv.txt" \
   && awk '!/^#/ && NF && ++n % 2 == 0 { printf "%.10e %d\n", $5, $6 }' "$d/contact.dat" | sort > "$FC/render-dat.txt" \
   && grep -q " 1$" "$FC/render-csv.txt" && grep -q " 0$" "$FC/render-csv.txt" \
   && cmp -s "$FC/render-csv.txt" "$FC/render-dat.txt" \
   && grep -q "layout 3,1" "$d/contact.gp" && grep -q "^mu = 0.3$" "$d/contact.gp" \
   && grep -q "using 1:5 .*mu \* abs(\$2).*stick shaded" "$d/contact.gp"; then
  fric_ok render-partial-slip
else fric_fail render-partial-slip "$(cat "$FC/render.err") (contact.dat against contact.csv: $FC/render-*.txt)"
fi
printf '# a line\n3.4 -100\n3.6 -200\n' > "$FC/render-q.txt"
printf '# a line\n3.4 -100\n3.6\n' > "$FC/render-bad.txt"
cp "$d/contact.png" "$FC/render-before.png" 2> /dev/null
if "$LAC" render "$d" --contact --compare "$FC/render-q.txt" --srange 3.3:3.9 \
     > /dev/null 2>> "$FC/render.err" \
   && grep -q "^set xrange \[3.3:3.9\]$" "$d/contact.gp" \
   && grep -q "'contact-compare.dat' using 1:2 .* title 'a line'" "$d/contact.gp"; then
  fric_ok render-compare-srange
else fric_fail render-compare-srange "$(tail -1 "$FC/render.err")"
fi
cp "$d/contact.png" "$FC/render-before.png" 2> /dev/null
"$LAC" render "$d" --contact --compare "$FC/render-bad.txt" > /dev/null 2> "$FC/render-bad.err"
rc1=$?
"$LAC" render "$d" --contact --srange 3.9:3.3 > /dev/null 2>> "$FC/render-bad.err"
rc2=$?
if [ $rc1 = 1 ] && [ $rc2 = 2 ] && grep -q "render-bad.txt:3: expected two numbers" "$FC/render-bad.err" \
   && grep -q "srange '3.9:3.3': expected S0:S1" "$FC/render-bad.err" \
   && cmp -s "$d/contact.png" "$FC/render-before.png"; then
  fric_ok render-bad-compare-srange
else fric_fail render-bad-compare-srange "exit $rc1, $rc2: $(cat "$FC/render-bad.err")"
fi

# ---- the path: monotone Q in 1 or 10 steps; unloading ---------------------------
# Cattaneo's state does not depend on how Q grows at fixed P: P in one step,
# then Q in one step or in ten, the same multipliers to 1e-6 of the largest.
# Q back to 0 (Mindlin-Deresiewicz): a tangential traction remains, and the
# displacement of the cylinder at a given Q is larger unloading than loading.
if "$LAC" run "$CM/cattaneo2d.scene" --set level=1 --quiet --out "$FC/cm-1step" \
     > /dev/null 2>&1 \
   && "$LAC" run "$CM/cattaneo2d.scene" --set level=1 --set steps.n=11 \
        --set steps.end=11 --set "load.pull.curve=0 0 1 0 11 1" --quiet \
        --out "$FC/cm-10steps" > /dev/null 2>&1 \
   && paste -d, "$FC/cm-1step/contact.csv" "$FC/cm-10steps/contact.csv" | awk -F, '
        NR == 1 { n = NF / 2; for (k = 1; k <= n; k++) c[$k] = k; next }
        $(c["multiplier"]) != "" {
          for (j = 0; j < 2; j++) {
            a = $(c[j ? "lambda_t" : "lambda"]); b = $(c[j ? "lambda_t" : "lambda"] + n)
            d = a - b; d = d < 0 ? -d : d; if (d > m) m = d
            a = a < 0 ? -a : a; if (a > big) big = a } }
        END { exit !(big > 0 && m <= 1e-6 * big) }'; then
  fric_ok cattaneo-path
else fric_fail cattaneo-path "P then Q in 1 and in 10 steps differ"
fi
if "$LAC" run "$CM/cattaneo2d.scene" --set level=1 --set steps.n=30 \
     --set steps.end=3 --set "load.pull.curve=0 0 1 0 2 1 3 0" \
     --set steps.monitor=corner --quiet --out "$FC/cm-unload" > /dev/null 2>&1 \
   && awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
        $(c["multiplier"]) != "" { t = $(c["lambda_t"]); t = t < 0 ? -t : t
                                   if (t > m) m = t }
        END { exit !(m > 10) }' "$FC/cm-unload/contact.csv" \
   && awk -F, 'NR > 1 { t = $2 + 0; u[sprintf ("%.4f", t)] = $4 }
        END { up = u["1.5000"]; down = u["2.5000"]
              exit !(up != "" && down != "" && down > up) }' \
        "$FC/cm-unload/curve.csv"; then
  fric_ok cattaneo-unloading
else fric_fail cattaneo-unloading "no residual traction or no hysteresis (contact.csv, curve.csv of $FC/cm-unload)"
fi

# ---- the push-out of a shrink fit (axisymmetric) ------------------------------
# Pulled far, the whole fit slips: the axial force is mu times the normal
# force, to rounding.
if "$LAC" run "$CM/pushout.scene" --quiet --no-output > "$FC/pushout.out" \
     2> "$FC/pushout.err" \
   && awk -v n="$(sed -n 's/^contact_normal_force = //p' "$FC/pushout.out")" \
          -v f="$(sed -n 's/^friction_force = //p' "$FC/pushout.out")" \
          -v s="$(sed -n 's/^slip_macro_elements = //p' "$FC/pushout.out")" \
          -v k="$(sed -n 's/^active_macro_elements = //p' "$FC/pushout.out")" \
          'BEGIN { split (f, v, " "); r = v[2] / n - 0.2; r = r < 0 ? -r : r
                   exit !(s == k && s > 0 && r <= 1e-12) }'; then
  fric_ok pushout-full-slip
else fric_fail pushout-full-slip "$(tail -1 "$FC/pushout.err") $(grep -E 'normal_force|friction_force|slip_' "$FC/pushout.out" | tr '\n' ' ')"
fi
