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
