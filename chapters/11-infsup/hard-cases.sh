#!/bin/sh
# hard-cases.sh -- the table of the hard cases (issue 6 item 3)
#
#   sh chapters/11-infsup/hard-cases.sh [build-dir]    (from the repository root)
#
# One row per case: k (multipliers), active-set iterations, beta_h (H1 norm,
# dense path: lac_infsup), the error against the exact solution where there
# is one (lambda: max relative error of the multipliers; force: relative
# error of the contact force against the load; u-u_free: against the
# solution without contact; rel L2 u: relative L2 error of u), and the
# status: ok or FAILS (whether the test's assertions on the case hold),
# then, for a case that stops, "stops:" with the stage, the status and the
# beginning of the one-line message (the lac run rows have no assertions:
# only "ok" or "stops:").
#
# The rows come from the hard-case tests tests/unit/t95x, t96x (run with
# LAC_HARD_TABLE=1; they assert the bounds stated in their headers) and
# from `lac run` / `lac infsup` on the scenes of tests/hard/ and chapter 08
# (the same cases through the command line; nu = 0.499 on the manufactured
# solution shows the locking of linear elements).  "-": not applicable.
B=${1:-build}
LAC=${LAC:-$B/lac}
tests=""
for f in tests/unit/t95[0-9]-*.c tests/unit/t96[0-9]-*.c; do
  [ -f "$f" ] && tests="$tests $B/tests/$(basename "$f" .c)"
done
make -s B="$B" $tests "$LAC" >/dev/null || exit 1

row () {   # case k iters beta error status
  st=$(printf '%s' "$6" | sed -E 's/^(([A-Za-z]+, )?stops: ([a-z]+ [A-Z]+: )?)[a-z_]+: /\1/')
  [ ${#st} -gt 84 ] && st="$(printf '%s' "$st" | cut -c1-81)..."
  printf '%-46s %4s %5s %10s  %-17s %s\n' "$1" "$2" "$3" "$4" "$5" "$st"
}

row case k iters beta_h error status
for t in $tests; do
  LAC_HARD_TABLE=1 "./$t" | grep '^row|' |
    while IFS='|' read -r _ name k it beta err st; do
      [ "$k" = -1 ] && k=-
      [ "$it" = -1 ] && it=-
      row "$name" "$k" "$it" "$beta" "$err" "$st"
    done
done

# ---- the command line -----------------------------------------------------
# run SCENE ARGS... -> "k iters lambda_min lambda_max status" ; beta SCENE ARGS
run () {
  out=$("$LAC" run "$@" --quiet --no-output 2>&1)
  if [ $? -eq 0 ]; then
    printf '%s\n' "$out" | awk -F' = ' '{ v[$1] = $2 }
      END { printf "%s %s %s %s ok\n", v["multipliers"], v["newton_iterations"],
            v["lambda_min"], v["lambda_max"] }'
  else
    printf -- '- - - - stops: %s\n' "$(printf '%s' "$out" | grep '^lac:' | head -1 | sed 's/^lac: //')"
  fi
}
beta () {
  "$LAC" infsup "$@" --quiet 2>/dev/null | awk -F' = ' '$1 == "beta_h" { printf "%.4e", $2 }'
}
lerr () {   # what lambda_min lambda_max exact -> max relative error
  awk -v w="$1" -v a="$2" -v b="$3" -v e="$4" 'BEGIN { x = (a - e) / e;
    y = (b - e) / e; if (x <= 0) x = -x; if (y <= 0) y = -y;
    printf "%s %.2e", w, (x > y ? x : y) }'
}
cli () {   # name what exact scene args...   (exact "-": no error column)
  name=$1 what=$2 exact=$3; shift 3
  set -- "$@"
  r=$(run "$@")
  k=${r%% *}; r=${r#* }; it=${r%% *}; r=${r#* }
  lmin=${r%% *}; r=${r#* }; lmax=${r%% *}; st=${r#* }
  b=$(beta "$@"); [ -n "$b" ] || b=-
  e=-
  [ "$exact" != - ] && [ "$lmin" != - ] && e=$(lerr "$what" "$lmin" "$lmax" "$exact")
  row "$name" "$k" "$it" "$b" "$e" "$st"
}

cli "lac run: grazing bump, quad4" - - tests/hard/grazing2d.scene
cli "lac run: grazing bump, quad8 level 1" - - tests/hard/grazing2d.scene \
    --set element=quad8 --set level=1
cli "lac run: sliver 1e-8 h, eps 1e-14" - - tests/hard/sliver2d.scene
# one multiplier left on [0, 25] under the load 25 x 50: its mean is -50
cli "lac run: sliver 1e-8 h, eps 1e-2" force -50 tests/hard/sliver2d.scene \
    --set contact.interface.epsilon=0.01
cli "lac run: E 2e3 / 2e9 above (contrast2d)" lambda -25 \
    tests/hard/contrast2d.scene
cli "lac run: E 2e9 / 2e3, quad8 level 4" lambda -25 tests/hard/contrast2d.scene \
    --set material.lower.E=2e9 --set material.upper.E=2e3 --set element=quad8 \
    --set level=4
cli "lac run: E 2e9 / 2e3, quad8 level 5" lambda -25 tests/hard/contrast2d.scene \
    --set material.lower.E=2e9 --set material.upper.E=2e3 --set element=quad8 \
    --set level=5

# nu = 0.499 on the manufactured solution of chapter 09 (level 2): the
# error of linear elements grows (locking), quadratic ones much less
for e in tri3 quad4 tri6; do
  for nu in 0 0.499; do
    s=chapters/09-spheres-rates/manufactured2d.scene
    out=$("$LAC" run $s --set element=$e --set level=2 --set material.body.nu=$nu \
          --set exact.nu=$nu --quiet --no-output 2>&1)
    st=ok; [ $? -eq 0 ] || st="stops: $(printf '%s' "$out" | grep '^lac:' | head -1 | sed 's/^lac: //')"
    v=$(printf '%s\n' "$out" | awk -F' = ' '{ v[$1] = $2 }
        END { printf "%s %s %.2e", v["multipliers"], v["newton_iterations"], v["rel_l2_err_u"] }')
    set -- $v
    b=$(beta $s --set element=$e --set level=2 --set material.body.nu=$nu --set exact.nu=$nu)
    row "lac run: manufactured2d nu=$nu $e level 2" "$1" "$2" "$b" "rel L2 u $3" "$st"
  done
done
