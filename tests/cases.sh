# tests/cases.sh -- command-line cases for `lac run` (sourced by tests/run.sh)
#
# Uses $B (the build directory), writes only under $B/cases/, and adds to the
# shell variables pass and fail of tests/run.sh, printing "FAIL <case>" (and
# why) for each failure.  POSIX sh; runs in a few seconds.
#
#   good path: the demo scene runs, stdout = summary.txt, the three solvers
#              agree (tests/numcmp), VTU is well-formed with the right counts,
#              CSV has a row per node, overrides, --help, --version;
#   bad input: exit status in 1..127, exactly one line "lac: ..." on stderr
#              naming the file / line / key, and the files of an earlier run
#              in the same --out directory left untouched.

B=${B:-build}
C="$B/cases"
LAC="$B/lac"
NUMCMP="$B/tests/numcmp"
rm -rf "$C"
mkdir -p "$C"

case_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
case_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

# summary_value FILE KEY: the value of "KEY = value" in FILE
summary_value () { sed -n "s/^$2 = //p" "$1"; }

# Checksums of the files of an earlier run, to check a bad run left them.
keep_sums () { (cd "$C/keep" && ls -A | sort && cksum * 2>/dev/null) ; }

# ---- good path -----------------------------------------------------------

# The reference run whose files bad runs must not touch.
if "$LAC" run tests/bad/box.scene --out "$C/keep" --quiet > "$C/keep.out" 2> "$C/keep.err" \
   && [ -f "$C/keep/summary.txt" ] && [ -f "$C/keep/solution.vtu" ]; then
  case_ok keep-run
else
  case_fail keep-run "tests/bad/box.scene did not run: $(head -1 "$C/keep.err")"
fi
keep_sums > "$C/keep.sums"

# The demo: exit 0, stdout equal to summary.txt, progress on stderr.
if "$LAC" run chapters/01-problem/sphere-axi.scene --out "$C/demo" > "$C/demo.out" 2> "$C/demo.err"; then
  if ! cmp -s "$C/demo.out" "$C/demo/summary.txt"; then
    case_fail demo "stdout differs from summary.txt"
  elif ! grep -q '^lac: effects: axisymmetric, small strain, linear elastic material$' "$C/demo.err"; then
    case_fail demo "no effects line on stderr"
  elif [ "$(grep -c '^lac: \[[1-7]/7\]' "$C/demo.err")" -ne 7 ]; then
    case_fail demo "expected 7 progress lines on stderr"
  elif [ -z "$(summary_value "$C/demo.out" l2_err_u)" ] || [ -z "$(summary_value "$C/demo.out" rel_err_u_r_inner)" ]; then
    case_fail demo "no error lines in the summary"
  else
    case_ok demo
  fi
else
  case_fail demo "exit status $?: $(tail -1 "$C/demo.err")"
fi

# The demo is accurate: relative error of u_r at the inner surface < 1e-3.
e=$(summary_value "$C/demo.out" rel_err_u_r_inner)
if [ -n "$e" ] && awk -v e="$e" 'BEGIN { exit !(e < 1e-3) }'; then
  case_ok demo-accuracy
else
  case_fail demo-accuracy "rel_err_u_r_inner = '$e', expected < 1e-3"
fi

# The three solvers give the same summary (numbers within tolerance).
for s in dense umfpack cholmod; do
  "$LAC" run chapters/01-problem/sphere-axi.scene --solver "$s" --no-output --quiet \
    > "$C/solver-$s.out" 2> "$C/solver-$s.err" || echo "exit $?" >> "$C/solver-$s.out"
done
for s in dense umfpack; do
  if "$NUMCMP" --rtol 1e-7 --atol 1e-12 "$C/solver-cholmod.out" "$C/solver-$s.out" > "$C/solver-$s.cmp" 2>&1; then
    case_ok "solver-$s"
  else
    case_fail "solver-$s" "$s differs from cholmod: $(head -1 "$C/solver-$s.cmp")"
  fi
done

# Convergence: tri6 halves h from level 1 to level 2, L2 error / 8 (> 6).
"$LAC" run chapters/01-problem/sphere-axi.scene --set level=2 --no-output --quiet > "$C/level2.out" 2>&1
e1=$(summary_value "$C/demo.out" l2_err_u); e2=$(summary_value "$C/level2.out" l2_err_u)
if [ -n "$e1" ] && [ -n "$e2" ] && awk -v a="$e1" -v b="$e2" 'BEGIN { exit !(a / b > 6) }'; then
  case_ok convergence
else
  case_fail convergence "l2_err_u level 1 = '$e1', level 2 = '$e2': ratio not > 6"
fi

# VTU: well-formed XML, counts as in the summary; binary (appended raw,
# the default) and ascii (output.vtu_format = ascii) hold the same values.
nodes=$(summary_value "$C/demo.out" nodes); cells=$(summary_value "$C/demo.out" cells)
vtu="$C/demo/solution.vtu"
"$LAC" run chapters/01-problem/sphere-axi.scene --out "$C/demo-ascii" --quiet \
  --set output.vtu_format=ascii > /dev/null 2> "$C/demo-ascii.err"
if command -v python3 > /dev/null 2>&1; then
  msg=$(python3 - "$vtu" "$nodes" "$cells" "$C/demo-ascii/solution.vtu" <<'EOF' 2>&1
import sys
sys.path.insert(0, "tests")
from vtu import read
path, nodes, cells, apath = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
piece, arrays = read(path)
assert piece.find("Points/DataArray").get("format") == "appended", "binary by default"
assert int(piece.get("NumberOfPoints")) == nodes, "NumberOfPoints"
assert int(piece.get("NumberOfCells")) == cells, "NumberOfCells"
assert len(arrays["coordinates"]) == 3 * nodes, "coordinates"
assert len(arrays["displacement"]) == 3 * nodes, "displacement"
assert len(arrays["von_mises"]) == nodes, "von_mises"
assert len(arrays["types"]) == cells and set(arrays["types"]) == {22.0}, "types"
assert int(arrays["offsets"][-1]) == len(arrays["connectivity"]) == 6 * cells, "offsets"
assert max(int(i) for i in arrays["connectivity"]) < nodes, "connectivity"
assert len(arrays["body"]) == cells, "body"
apiece, aarr = read(apath)
assert apiece.find("Points/DataArray").get("format") == "ascii", "ascii on request"
assert sorted(aarr) == sorted(arrays), "the same arrays"
for name, v in arrays.items():
    w = aarr[name]
    assert len(v) == len(w), name
    assert all(abs(x - y) <= 1e-9 * max(1.0, abs(x)) for x, y in zip(v, w)), name
EOF
) && case_ok vtu || case_fail vtu "solution.vtu: $msg"
else
  if head -1 "$vtu" | grep -q '^<?xml' && tail -1 "$vtu" | grep -q '^</VTKFile>$' \
     && grep -q "NumberOfPoints=\"$nodes\" NumberOfCells=\"$cells\"" "$vtu"; then
    case_ok vtu
  else
    case_fail vtu "solution.vtu is not a VTU file with $nodes points and $cells cells"
  fi
fi

# CSV: a header and one row per node.
rows=$(wc -l < "$C/demo/nodes.csv")
if [ "$rows" -eq $((nodes + 1)) ] && head -1 "$C/demo/nodes.csv" | grep -q '^node,r,z,theta,u_r,u_z,s_rr,s_zz,s_tt,s_rz,von_mises$'; then
  case_ok csv
else
  case_fail csv "nodes.csv has $rows lines for $nodes nodes, or a wrong header"
fi

# Overrides: --set with aliases and named sections, the matrix output.
if "$LAC" run tests/bad/box.scene --out "$C/set" --quiet --set level=1 --set element=quad8 \
     --set material.steel.E=2000 --set output.matrix=yes --set output.vtu=no > "$C/set.out" 2> "$C/set.err" \
   && [ "$(summary_value "$C/set.out" element)" = quad8 ] \
   && [ "$(summary_value "$C/set.out" cells)" = 32 ] \
   && [ ! -f "$C/set/solution.vtu" ] \
   && head -1 "$C/set/K.mtx" | grep -q '^%%MatrixMarket matrix coordinate real'; then
  case_ok set
else
  case_fail set "overrides not applied: $(head -1 "$C/set.err")"
fi
# E doubled: displacements halved.
u1=$(summary_value "$C/keep.out" max_u)
"$LAC" run tests/bad/box.scene --no-output --quiet --set material.steel.E=2000 > "$C/set2.out" 2>&1
u2=$(summary_value "$C/set2.out" max_u)
if [ -n "$u1" ] && [ -n "$u2" ] && awk -v a="$u1" -v b="$u2" 'BEGIN { d = a / b - 2; exit !(d < 1e-9 && d > -1e-9) }'; then
  case_ok set-E
else
  case_fail set-E "max_u with E = 1000: '$u1', with E = 2000: '$u2'"
fi

# A mesh with a clockwise cell runs when flipping is on.
if "$LAC" run tests/bad/inverted-flip.scene --no-output --quiet > "$C/flip.out" 2> "$C/flip.err"; then
  case_ok inverted-flip
else
  case_fail inverted-flip "$(head -1 "$C/flip.err")"
fi

# --help, --version
if "$LAC" --help > "$C/help.out" 2>&1 && grep -q -- '--set KEY=VALUE' "$C/help.out" \
   && grep -q -- '--solver' "$C/help.out" && grep -q -- '--out DIR' "$C/help.out"; then
  case_ok help
else
  case_fail help "lac --help does not document run, --set, --solver, --out"
fi
if "$LAC" --version 2>&1 | grep -q '^lac [0-9]'; then
  case_ok version
else
  case_fail version "lac --version"
fi
# OpenBLAS's kernels (src/cli/lac_cli_openblas.h): on a CPU with AVX-512 or
# AVX2 lac does not run OpenBLAS's Prescott fallback, unless asked to.
blas=$("$LAC" --version 2>&1 | sed -n 's/^BLAS: //p')
old=$(OPENBLAS_CORETYPE=Prescott "$LAC" --version 2>&1 | sed -n 's/^BLAS: //p')
flags=$(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null)
wide=no
for f in avx2 fma; do
  case " $flags " in *" $f "*) wide=yes ;; *) wide=no; break ;; esac
done
if [ -z "$blas" ] && ! ldd "$LAC" | grep -q openblas; then
  case_ok blas-kernels                         # another BLAS: nothing to do
elif [ "$wide" = yes ] && printf '%s' "$blas" | grep -q Prescott; then
  case_fail blas-kernels "the CPU has AVX2, lac --version says: $blas"
elif ! printf '%s' "$old" | grep -q Prescott; then
  case_fail blas-kernels "OPENBLAS_CORETYPE=Prescott not kept: $old"
else
  case_ok blas-kernels
fi
# and its idle threads sleep at once, unless the user chose
spin=$("$LAC" --version 2>&1 | sed -n 's/^BLAS idle threads: //p')
mine=$(OPENBLAS_THREAD_TIMEOUT=20 "$LAC" --version 2>&1 |
       sed -n 's/^BLAS idle threads: //p')
one=$(OPENBLAS_NUM_THREADS=1 "$LAC" --version 2>&1 | grep -c 'idle threads')
if [ -z "$blas" ] || [ "$(nproc)" -lt 2 ]; then
  case_ok blas-spin                     # another BLAS, or one core
elif [ "$spin" != "spin 2^16 cycles" ] || [ "$mine" != "spin 2^20 cycles" ] \
     || [ "$one" != 0 ]; then
  case_fail blas-spin "lac --version: '$spin', with 20: '$mine', one thread: $one line(s)"
else
  case_ok blas-spin
fi

# ---- bad input -----------------------------------------------------------

# bad NAME STATUS 'WORD|WORD...' ARGS...: lac ARGS must exit with STATUS
# ("run": 1..127, "usage": 2), print exactly one line on stderr that starts
# with "lac: " and contains every WORD, and leave $C/keep untouched.
bad () {
  name=$1; want=$2; words=$3; shift 3
  "$LAC" "$@" > "$C/bad-$name.out" 2> "$C/bad-$name.err"
  rc=$?
  nl=$(wc -l < "$C/bad-$name.err")
  msg=""
  if [ "$rc" -eq 0 ]; then
    msg="exit status 0"
  elif [ "$rc" -ge 128 ]; then
    msg="crashed (exit status $rc)"
  elif [ "$want" = usage ] && [ "$rc" -ne 2 ]; then
    msg="exit status $rc, expected 2"
  elif [ "$nl" -ne 1 ]; then
    msg="$nl lines on stderr, expected 1"
  elif ! grep -q '^lac: ' "$C/bad-$name.err"; then
    msg="stderr does not start with 'lac: '"
  else
    old_ifs=$IFS; IFS='|'
    for w in $words; do
      grep -qF -- "$w" "$C/bad-$name.err" || msg="message lacks '$w'"
    done
    IFS=$old_ifs
  fi
  if [ -z "$msg" ] && ! keep_sums | cmp -s - "$C/keep.sums"; then
    msg="the earlier files in $C/keep changed"
  fi
  if [ -z "$msg" ]; then
    case_ok "bad-$name"
  else
    case_fail "bad-$name" "$msg: $(head -3 "$C/bad-$name.err")"
  fi
}

K="--out $C/keep --quiet"
D=tests/bad
bad missing-scene run "$D/does-not-exist.scene|cannot open" run $D/does-not-exist.scene $K
bad missing-mesh run "missing-mesh.scene:3:|[mesh] file = 'nothere.msh'|tests/bad/nothere.msh" run $D/missing-mesh.scene $K
bad garbage-msh run "garbage-msh.scene:3:|file = 'garbage.msh'|not a valid mesh" run $D/garbage-msh.scene $K
bad binary-msh run "--set|file = 'binary.msh'|not a valid mesh" run $D/garbage-msh.scene $K --set mesh.file=binary.msh
bad unknown-element run "unknown-element.scene:3:|element = 'tri7'|tri6" run $D/unknown-element.scene $K
bad missing-group run "missing-group.scene:11:|[dirichlet left] group = 'leftt'|no physical group|groups: corner, left, right" run $D/missing-group.scene $K
bad unknown-key run "unknown-key.scene:4:|levle|unknown key|level" run $D/unknown-key.scene $K
bad unknown-section run "unknown-section.scene:9:|[boundary left]|unknown section" run $D/unknown-section.scene $K
bad wrong-type run "wrong-type.scene:6:|E = 'abc'|expected a number" run $D/wrong-type.scene $K
bad vtu-format run "--set|[output] vtu_format = 'xml'|binary, ascii" run $D/box.scene $K --set output.vtu_format=xml
bad negative-E run "negative-E.scene:6:|E = '-1000'|> 0" run $D/negative-E.scene $K
bad nu-half run "nu-half.scene:7:|nu = '0.5'|(-1, 0.5)" run $D/nu-half.scene $K
bad singular run "singular.scene|singular|body 'body'|rigid motion" run $D/singular.scene $K
bad rotation-free run "singular|rotation about (0, 0)" run $D/box.scene $K --set dirichlet.left.group=corner
bad inverted run "inverted.scene:3:|inverted.msh|inverted" run $D/inverted.scene $K
bad syntax run "syntax.scene:4:|syntax error" run $D/syntax.scene $K
bad no-material run "no-material.scene|cell 4|group 'b'|has no material" run $D/no-material.scene $K
bad group-dim run "group-dim.scene:6:|group = 'left'|dimension 2" run $D/group-dim.scene $K
bad element-mismatch run "element-mismatch.scene:3:|element = 'tri6'|tri3 cells" run $D/element-mismatch.scene $K
bad set-unknown-key run "--set|[mesh] levle|unknown key" run $D/box.scene $K --set mesh.levle=2
bad set-wrong-type run "--set|[material steel] E = 'abc'|expected a number" run $D/box.scene $K --set material.steel.E=abc
bad set-no-section run "--set|no section [material copper]" run $D/box.scene $K --set material.copper.E=1
bad set-syntax run "--set|KEY=VALUE" run $D/box.scene $K --set level
bad set-enum run "--set|solver = 'mumps'|cholmod" run $D/box.scene $K --set solver=mumps
bad set-line-break run "--set|'scene.title=a...'|a line break" run $D/box.scene $K --set "scene.title=a
title = b"
bad solver usage "--solver|mumps" run $D/box.scene $K --solver mumps
bad option usage "unknown option|--bogus" run $D/box.scene $K --bogus
bad no-scene usage "no scene" run --quiet
bad command usage "unknown command|walk" walk $D/box.scene

# Without --quiet, a failing run prints its progress, then the error last.
"$LAC" run $D/singular.scene --out "$C/keep" > /dev/null 2> "$C/noisy.err"
if [ "$(tail -1 "$C/noisy.err" | cut -c1-5)" = "lac: " ] \
   && tail -1 "$C/noisy.err" | grep -q 'stiffness is singular' \
   && [ "$(grep -c 'stiffness is singular' "$C/noisy.err")" -eq 1 ]; then
  case_ok error-last
else
  case_fail error-last "the error is not the last line of stderr"
fi

# [mesh] size on a .geo whose curves are transfinite changes nothing: the
# mesh line says so (and the mesh is the same); without size, no warning.
"$LAC" run chapters/01-problem/sphere-axi.scene --set size=0.5 --no-output \
  > "$C/size.out" 2> "$C/size.err"
"$LAC" run chapters/01-problem/sphere-axi.scene --no-output \
  > "$C/nosize.out" 2> "$C/nosize.err"
if grep -q 'warning: \[mesh\] size = 0.5 does not change the transfinite curves of sphere-axi.geo' "$C/size.err" \
   && ! grep -q 'size = ' "$C/nosize.err" \
   && [ "$(summary_value "$C/size.out" nodes)" = "$(summary_value "$C/nosize.out" nodes)" ]; then
  case_ok size-transfinite
else
  case_fail size-transfinite "no warning for [mesh] size on a transfinite .geo"
fi
