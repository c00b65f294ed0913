# tests/cases-bad.sh -- input made to break lac (sourced by tests/run.sh)
#
# Malformed and hostile meshes, scene values and scene text, each kept in
# tests/bad/: every one must end with exactly one line "lac: ..." on stderr
# that names what is wrong, exit status 1 (never a signal, never 0), and
# leave the files of an earlier run in the same --out directory
# byte-identical.  Chapter 01 (scene-format.md, "When the input is wrong")
# explains each.  Uses $B, writes only under $B/cases-bad/; POSIX sh.

B=${B:-build}
RB="$B/cases-bad"
LAC="$B/lac"
rm -rf "$RB"
mkdir -p "$RB"

rb_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
rb_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }

# Checksums of the files of the earlier run.
rb_sums () { (cd "$RB/keep" && ls -A | sort && cksum * 2>/dev/null); }

if "$LAC" run tests/bad/box-msh.scene --out "$RB/keep" --quiet > "$RB/keep.out" 2> "$RB/keep.err" \
   && [ -f "$RB/keep/summary.txt" ]; then
  rb_ok bad-keep
else
  rb_fail bad-keep "tests/bad/box-msh.scene did not run: $(head -1 "$RB/keep.err")"
fi
rb_sums > "$RB/keep.sums"

# rbad NAME 'WORD|WORD...' ARGS...: lac ARGS exits with status 1, prints
# one line on stderr, starting "lac: " and holding every WORD, and leaves
# $RB/keep as it was.
rbad () {
  name=$1; words=$2; shift 2
  "$LAC" "$@" > "$RB/$name.out" 2> "$RB/$name.err"
  rc=$?
  nl=$(wc -l < "$RB/$name.err")
  msg=""
  if [ "$rc" -ne 1 ]; then
    msg="exit status $rc, expected 1"
  elif [ "$nl" -ne 1 ]; then
    msg="$nl lines on stderr, expected 1"
  elif ! grep -q '^lac: ' "$RB/$name.err"; then
    msg="stderr does not start with 'lac: '"
  else
    old_ifs=$IFS; IFS='|'
    for w in $words; do
      grep -qF -- "$w" "$RB/$name.err" || msg="message lacks '$w'"
    done
    IFS=$old_ifs
  fi
  if [ -z "$msg" ] && ! rb_sums | cmp -s - "$RB/keep.sums"; then
    msg="the earlier files in $RB/keep changed"
  fi
  if [ -z "$msg" ]; then
    rb_ok "bad-$name"
  else
    rb_fail "bad-$name" "$msg: $(head -3 "$RB/$name.err")"
  fi
}

KB="--out $RB/keep --quiet"
SB=tests/bad/box-msh.scene

# ---- meshes: gmsh in its child process -----------------------------------
rbad crash-segv "crash-segv.msh|gmsh could not read|killed by signal 11|malformed or truncated" \
  run $SB $KB --set mesh.file=crash-segv.msh
rbad crash-abort "crash-abort.msh|gmsh could not read|killed by signal 6|malformed or truncated" \
  run $SB $KB --set mesh.file=crash-abort.msh
rbad long-name "long-name.geo|gmsh could not mesh|killed by signal 6|beyond gmsh" \
  run $SB $KB --set mesh.file=long-name.geo

# ---- meshes: the lines of a .msh file ------------------------------------
rbad numtags "numtags.msh|line 51|element 19 (type 2) has 4 nodes after its tags" \
  run $SB $KB --set mesh.file=numtags.msh
rbad short-tri "short-tri.msh|line 51|element 19 (type 2) has 2 nodes after its tags" \
  run $SB $KB --set mesh.file=short-tri.msh
rbad huge-count "huge-count.msh|line 5|the file ends inside \$Nodes" \
  run $SB $KB --set mesh.file=huge-count.msh
# found by fuzz_mesh (make fuzz): a type or a tag count beyond int
rbad huge-type "huge-type.msh|line 51|element 19 has type 24989999994" \
  run $SB $KB --set mesh.file=huge-type.msh
rbad huge-tags "huge-tags.msh|line 51|integer '2000000000000000000' is too large" \
  run $SB $KB --set mesh.file=huge-tags.msh

# Tags: gmsh reads MSH 2 tags as int (2^32 + 1 became 1, "overlapping
# cells"), keeps the last coordinates of a node tag given twice and drops
# one of two elements of a tag (a hole, exit status 0).
rbad tag-wrap "tag-wrap.msh|line 29|node tag 4294967297 is too large|integers from 1 to 2147483647" \
  run $SB $KB --set mesh.file=tag-wrap.msh
rbad dup-node "dup-node.msh|line 29|node tag 3 is given twice (first at line 17)" \
  run $SB $KB --set mesh.file=dup-node.msh
rbad dup-element "dup-element.msh|line 61|element tag 29 is given twice (first at line 60)" \
  run $SB $KB --set mesh.file=dup-element.msh
rbad dup-node-v41 "dup-node-v41.msh|line 31|node tag 1 is given twice (first at line 28)" \
  run $SB $KB --set mesh.file=dup-node-v41.msh

# ---- meshes: the cells as a mesh -----------------------------------------
rbad dup-cell "dup-cell.msh|cells 19 and 30 have the same vertices" \
  run $SB $KB --set mesh.file=dup-cell.msh
rbad face3 "face3.msh|cells 15, 18 and 30 share a face" \
  run $SB $KB --set mesh.file=face3.msh
rbad folded "folded.msh|cells 18 and 19 overlap" \
  run $SB $KB --set mesh.file=folded.msh
rbad flat "flat.msh|cell 16 (tri3) is degenerate" \
  run $SB $KB --set mesh.file=flat.msh
# A ball in gmsh's all-hex subdivision: tangled, and the message says how
# to mesh it (transfinite blocks, chapter 10).
rbad ball-hex "ball-hex.geo|hex20) is degenerate or tangled|transfinite|chapter 10" \
  run tests/bad/ball-hex.scene $KB

# Nodes in no cell: a warning on the mesh line, the same answer.
"$LAC" run $SB --set mesh.file=unused-node.msh --no-output > "$RB/unused.out" 2> "$RB/unused.err"
rc=$?
if [ $rc -eq 0 ] && grep -q 'warning: 1 node of the file in no cell, left out' "$RB/unused.err" \
   && cmp -s "$RB/unused.out" "$RB/keep.out"; then
  rb_ok bad-unused-node
else
  rb_fail bad-unused-node "exit $rc, no warning or another answer: $(grep mesh "$RB/unused.err")"
fi

# The centre of a Circle is a construction point, not a lost node: the
# .geo files of chapters 01 and 09 mesh without the warning.
"$LAC" run chapters/01-problem/sphere-axi.scene --set level=0 --no-output > /dev/null 2> "$RB/centre.err"
rc=$?
"$LAC" run chapters/09-spheres-rates/spheres-axi.scene --set level=0 --no-output > /dev/null 2> "$RB/centre2.err"
rc2=$?
if [ $rc -eq 0 ] && [ $rc2 -eq 0 ] && ! grep -q 'in no cell' "$RB/centre.err" "$RB/centre2.err"; then
  rb_ok bad-unused-centre
else
  rb_fail bad-unused-centre "exit $rc $rc2 or a warning: $(grep mesh "$RB/centre.err" "$RB/centre2.err")"
fi

# ---- meshes: too large to make -------------------------------------------
# level 12: 32769 x 16385 = 5.4e8 tri6 nodes, counted from the transfinite
# curves; the 3D Taylor test at n = 2000: 1.6e10 hex8 nodes.
rbad level12 "[mesh] file = 'box.geo'|level = 12|an estimated 5.4e+08 nodes|--max-memory" \
  run tests/bad/box.scene $KB --set level=12
rbad max-memory "level = 2|an estimated|more than the limit of 0.1 GB" \
  run tests/bad/box.scene $KB --set level=2 --max-memory 100M
rbad huge-3d "[mesh] file = 'taylor3d.geo'|an estimated 1.6e+10 nodes|--max-memory" \
  run chapters/08-experiments/taylor3d.scene $KB --set mesh.numbers=n=2000

# The estimate against the nodes gmsh makes (src/io/lac_mesh_gmsh_estimate.c):
# within a factor of 2 for a transfinite hexahedral block (hex8, hex20,
# hex27), an unstructured tetrahedral cylinder (tet4, tet10), and, estimate
# only (too large to mesh here), the fine ring on block (hex20: 55,610
# nodes) and the 1M-dof 3D Taylor patch test (hex8, n = 55: 56^3 + 55^3 =
# 341,991 nodes), whose estimate with petsc stays below 8 GB and below
# that of a Cholesky factor.
est_line () { "$LAC" run "$@" --max-memory 100M --quiet --no-output 2>&1; }
est_nodes () { est_line "$@" | sed -n 's/.*an estimated \([0-9.e+]*\) nodes.*/\1/p'; }
est_gb () { est_line "$@" | sed -n 's/.*need about \([0-9.e+]*\) GB.*/\1/p'; }
real_nodes () {
  "$LAC" run "$@" --no-output 2>&1 | sed -n 's/.*\] mesh *\([0-9]*\) nodes.*/\1/p'
}
# within2 NAME ESTIMATE REAL
within2 () {
  if [ -n "$2" ] && [ -n "$3" ] \
     && awk -v e="$2" -v r="$3" 'BEGIN { exit !(e <= 2 * r && r <= 2 * e) }'; then
    rb_ok "estimate-$1"
  else
    rb_fail "estimate-$1" "estimated '$2' nodes, gmsh made '$3'"
  fi
}
T3=chapters/08-experiments/taylor3d.scene
for el in hex8 hex20 hex27; do
  within2 "taylor3d-$el" "$(est_nodes $T3 --set mesh.numbers=n=8 --set element=$el)" \
    "$(real_nodes $T3 --set mesh.numbers=n=8 --set element=$el)"
done
for el in tet4 tet10; do
  within2 "tets-$el" "$(est_nodes tests/bad/cylinder-tets.scene --set level=1 --set element=$el)" \
    "$(real_nodes tests/bad/cylinder-tets.scene --set level=1 --set element=$el)"
done
within2 ring-level1 "$(est_nodes chapters/10-large-deformation/ring.scene --set level=1)" 55610
within2 taylor3d-n55 "$(est_nodes $T3 --set mesh.numbers=n=55 --strategy petsc)" 341991
gp=$(est_gb $T3 --set mesh.numbers=n=55 --strategy petsc)
gc=$(est_gb $T3 --set mesh.numbers=n=55 --strategy schur)
if [ -n "$gp" ] && [ -n "$gc" ] \
   && awk -v p="$gp" -v c="$gc" 'BEGIN { exit !(p < 8 && p < c) }'; then
  rb_ok estimate-petsc-memory
else
  rb_fail estimate-petsc-memory "petsc '$gp' GB, Cholesky '$gc' GB"
fi

# lac infsup is checked against what it factors (src/io/lac_mesh_gmsh_estimate.c):
# the Cholesky factor of its norm matrix (its dense path), with the LU
# factor of the saddle-point matrix on its sparse path; a run against its
# strategy's solve.  tests/bad/strips.scene, two transfinite strips of
# quad4 (the node counts of the estimate exact):
ST=tests/bad/strips.scene
# 15,048 dofs at --max-memory 150M: a run's Cholesky factor (0.129 GB)
# fits, and so does lac infsup's dense path (0.137 GB), but not its sparse
# path (0.186 GB): refused before the mesh is made.
SA="--set mesh.numbers=nx=85,ny=43 --quiet"
if "$LAC" run $ST $SA --max-memory 150M --strategy augmented --no-output > "$RB/strips-run.out" 2> "$RB/strips-run.err" \
   && "$LAC" infsup $ST $SA --max-memory 150M > "$RB/strips-infsup.out" 2> "$RB/strips-infsup.err" \
   && grep -q '^path = dense' "$RB/strips-infsup.out"; then
  rb_ok infsup-memory-dense-fits
else
  rb_fail infsup-memory-dense-fits "$(tail -1 "$RB/strips-run.err") $(tail -1 "$RB/strips-infsup.err")"
fi
rbad infsup-memory-sparse "strips.geo|an estimated 7.5e+03 nodes|0.186 GB|lac infsup's Cholesky factor of the H1 Gram matrix and LU factor of the saddle-point matrix (its sparse path)|0.15 GB (--max-memory)" \
  infsup $ST $SA --max-memory 150M --sparse
# At 125M the run's Cholesky factor does not fit, and the strategy auto
# takes petsc (0.119 GB; with PETSc); lac infsup factors all the same,
# and its dense path (0.137 GB) is refused (it was estimated as the
# iterative solve of a run: accepted, then killed on a large mesh).
rbad infsup-memory-not-iterative "strips.geo|an estimated 7.5e+03 nodes|0.137 GB|lac infsup's Cholesky factor of the H1 Gram matrix (its dense path)|0.125 GB (--max-memory)" \
  infsup $ST $SA --max-memory 125M
if ! grep -qs LAC_HAVE_PETSC "$B"/config-petsc-*.mk; then
  echo "     (lac without PETSc: the run at 125M is refused too, not checked)"
elif env ASAN_OPTIONS="${ASAN_OPTIONS:-}${LAC_MPI_ASAN:-}" "$LAC" run $ST $SA --max-memory 125M --no-output \
       > "$RB/strips-petsc.out" 2> "$RB/strips-petsc.err" \
     && grep -q '^solver_iterations' "$RB/strips-petsc.out"; then
  rb_ok infsup-memory-run-petsc
else
  rb_fail infsup-memory-run-petsc "the run at 125M: $(tail -1 "$RB/strips-petsc.err")"
fi
# A run is estimated with its strategy's factor in large deformation too
# (saddle: an LU factor, twice a Cholesky factor's fill; petsc: none).
rbad memory-large-saddle "strips.geo|0.152 GB of memory with a sparse LU factor" \
  run $ST $SA $KB --set scene.large_deformation=yes --strategy saddle --max-memory 100M
# (petsc starts MPI: its unwinding under make test-asan, as in cases-petsc.sh)
env ASAN_OPTIONS="${ASAN_OPTIONS:-}${LAC_MPI_ASAN:-}" "$LAC" run $ST $SA $KB \
  --set scene.large_deformation=yes --strategy petsc --max-memory 100M \
  > "$RB/memory-large-petsc.out" 2> "$RB/memory-large-petsc.err"
rc=$?
if [ $rc -eq 1 ] && [ "$(wc -l < "$RB/memory-large-petsc.err")" -eq 1 ] \
   && grep -q "strips.geo.*0.119 GB of memory with an iterative solve" "$RB/memory-large-petsc.err"; then
  rb_ok bad-memory-large-petsc
else
  rb_fail bad-memory-large-petsc "exit $rc: $(head -3 "$RB/memory-large-petsc.err")"
fi
# 1099 multipliers, more than the dense path takes by default: the mesh
# stage passes (dense path 0.143 GB), then, the multipliers known, the
# sparse path (0.2 GB) is refused, and the message says that --dense
# (0.182 GB with its k x k matrices) fits.
rbad infsup-memory-multipliers "strips.scene|8802 nodes and 1099 multipliers (more than 1000: the sparse path; --dense fits)|0.2 GB|its sparse path|0.19 GB (--max-memory)" \
  infsup $ST --set "mesh.numbers=nx=2200, ny=1" --quiet --max-memory 190M

# A transfinite count gmsh would make 2 (3e9 nodes per curve: a mesh of 4
# nodes, exit status 0): refused with its line.
rbad transfinite-huge "transfinite-huge.geo|line 16|Transfinite Curve {...} = 3e9|above the largest allowed value 2147483647" \
  run tests/bad/box.scene $KB --set mesh.file=transfinite-huge.geo
# The same counts computed by the script (nx = 6e9 * 2^level; a mesh of
# 4 nodes, exit status 0): evaluated and refused with their line.
rbad transfinite-computed "transfinite-computed.geo|line 22|Transfinite Curve {...} = nx + 1|it computes to 6e+09, beyond 32-bit integers" \
  run tests/bad/box.scene $KB --set mesh.file=transfinite-computed.geo

# A size factor far below 1 on an unstructured mesh: gmsh's count of
# segments on a curve overflowed (size = 1e-10 gave fewer cells than size
# = 1, exit status 0); the estimate now reaches a small factor in steps
# and stops at the first that passes the limit.
for sz in 1e-10 1e-29; do
  rbad "size-$sz" "cylinder-tets.geo|size = $sz|already at size|(more at $sz)|--max-memory" \
    run tests/bad/cylinder-tets.scene $KB --set size=$sz
done
n1=$(real_nodes tests/bad/cylinder-tets.scene --set size=1)
nh=$(real_nodes tests/bad/cylinder-tets.scene --set size=0.5)
if [ -n "$n1" ] && [ -n "$nh" ] && [ "$nh" -gt $((2 * n1)) ]; then rb_ok bad-size-half
else rb_fail bad-size-half "size 0.5: '$nh' nodes, size 1: '$n1'"; fi

"$LAC" run tests/bad/box.scene $KB --max-memory 12Q > /dev/null 2> "$RB/mm-usage.err"
rc=$?
if [ $rc -eq 2 ] && grep -q -- "--max-memory '12Q': not a decimal number.*expected a size such as 8G, 500M or 2e9" "$RB/mm-usage.err"; then
  rb_ok bad-max-memory-usage
else
  rb_fail bad-max-memory-usage "exit $rc: $(head -1 "$RB/mm-usage.err")"
fi
# A size beyond any address space (it became a limit of a few bytes when
# cast to the kernel's 64 bits, and gmsh "failed to initialize"): refused
# as a usage error, for lac run and lac infsup.
for cmd in run infsup; do
  "$LAC" $cmd tests/bad/box.scene --quiet --max-memory 99999999999999999999G > /dev/null 2> "$RB/mm-huge.err"
  rc=$?
  if [ $rc -eq 2 ] && [ "$(wc -l < "$RB/mm-huge.err")" -eq 1 ] \
     && grep -q -- "--max-memory '99999999999999999999G': 1e+29 bytes, above the largest allowed size 1e+18 bytes" "$RB/mm-huge.err"; then
    rb_ok "bad-max-memory-huge-$cmd"
  else
    rb_fail "bad-max-memory-huge-$cmd" "exit $rc: $(head -1 "$RB/mm-huge.err")"
  fi
done

# ---- numbers: finite and in range ----------------------------------------
rbad E-huge "E-huge.scene:12:|E = '1e308'|magnitude at most 1e+30" \
  run tests/bad/E-huge.scene $KB
rbad nu-near-half "nu-near-half.scene:13:|nu = '0.4999999999999999'|too close to 0.5|lambda / mu" \
  run tests/bad/nu-near-half.scene $KB
rbad traction-huge "traction-huge.scene:21:|traction = '1e308 0'|magnitude at most 1e+30" \
  run tests/bad/traction-huge.scene $KB
rbad ux-huge "ux-huge.scene:17:|ux = '1e308'|magnitude at most 1e+30" \
  run tests/bad/ux-huge.scene $KB
rbad E-tiny "--set|E = '1e-300'|magnitude at least 1e-30" \
  run tests/bad/box.scene $KB --set material.steel.E=1e-300
rbad normal-two-bodies "--set|normal = 'slave'|an obstacle only" \
  run chapters/08-experiments/taylor2d.scene $KB --set contact.interface.normal=slave
# One checked parser (src/base/lac_number.c) for every number a user
# writes: beyond a double, subnormal, nan, inf, hexadecimal are refused
# with the limit they broke, never "expected a number" for a number.
rbad E-overflow "E-overflow.scene:12:|E = '1e400'|magnitude at most 1e+30|beyond the range of a double" \
  run tests/bad/E-overflow.scene $KB
rbad E-subnormal "--set|E = '4.9e-324'|magnitude at least 1e-30|too small for a double" \
  run tests/bad/box.scene $KB --set material.steel.E=4.9e-324
rbad traction-overflow "--set|traction = '1e400 0'|magnitude at most 1e+30|beyond the range" \
  run tests/bad/box.scene $KB --set "load.pull.traction=1e400 0"
rbad E-nan "--set|E = 'nan'|not a finite number" run tests/bad/box.scene $KB --set material.steel.E=nan
rbad E-hex "--set|E = '0x10'|not a decimal number" run tests/bad/box.scene $KB --set material.steel.E=0x10
rbad level-huge "--set|level = '3e9'|above the largest allowed value 12" \
  run tests/bad/box.scene $KB --set level=3e9
# The numbers a .geo receives: gmsh would make a count from nan, inf or
# above 2^31 - 1 into 2 (a 6-node mesh, exit status 0).
rbad numbers-nan "numbers-nan.scene:9:|numbers = 'n=nan'|not a finite number|gmsh makes a count beyond 32 bits" \
  run tests/bad/numbers-nan.scene $KB
for v in 1e400 3e9 -inf; do
  rbad "numbers-$v" "--set|n = '$v'|at most 2147483647 in magnitude" \
    run tests/bad/numbers-nan.scene $KB --set "mesh.numbers=n=$v"
done
rbad numbers-twice "--set|'n' given twice" run tests/bad/numbers-nan.scene $KB --set "mesh.numbers=n=2 n=3"
rbad numbers-level "--set|level is set by [mesh] level" \
  run tests/bad/numbers-nan.scene $KB --set "mesh.numbers=level=3"
"$LAC" run tests/bad/numbers-nan.scene --set mesh.numbers=n=3 --no-output > "$RB/numbers3.out" 2> "$RB/numbers3.err"
if grep -q '\] mesh *91 nodes' "$RB/numbers3.err"; then
  rb_ok bad-numbers-good
else
  rb_fail bad-numbers-good "n = 3 does not give the 13 x 7 nodes of tri6: $(grep mesh "$RB/numbers3.err")"
fi
# Command-line numbers: the same parser, a usage error (status 2) naming
# the limit.
"$LAC" run tests/bad/box.scene $KB --max-memory 1 > /dev/null 2> "$RB/mm-tiny.err"
rc=$?
if [ $rc -eq 2 ] && grep -q -- "--max-memory '1': 1 bytes, below the smallest allowed size 1e+08 bytes" "$RB/mm-tiny.err"; then
  rb_ok bad-max-memory-tiny
else
  rb_fail bad-max-memory-tiny "exit $rc: $(head -1 "$RB/mm-tiny.err")"
fi
"$LAC" render "$RB/keep" --width 1e9 > /dev/null 2> "$RB/width.err"
rc=$?
if [ $rc -eq 2 ] && grep -q -- "--width '1e9': above the largest allowed value 8192" "$RB/width.err"; then
  rb_ok bad-render-width
else
  rb_fail bad-render-width "exit $rc: $(head -1 "$RB/width.err")"
fi
rbad contrast "contrast.scene|stiffness is singular|every body is held against rigid motion|E from 1e-05 to 1e+20" \
  run tests/bad/contrast.scene $KB

# ---- contact: what the model cannot hold (bad-input.md, section 13) -------
rbad fit-chords "fit-chords.scene:33:|[contact fit] interference|0.312 of delta|interference_tolerance|quadratic cells" \
  run tests/bad/fit-chords.scene $KB
rbad cylinders-sliding "cylinders-sliding.scene:36:|[contact c]|slides macro-element|sliding_tolerance|large_deformation = yes" \
  run tests/bad/cylinders-sliding.scene $KB
rbad nts-overhang "nts-overhang.scene|slave node|misses the master surface|node-to-segment cannot hold it" \
  run tests/bad/nts-overhang.scene $KB
# node-to-segment slides too (its slots are nodes: it was not checked, and
# answered with a normal force 45 % high); a slide off the master's end
# (the deformed shape pairs nothing there: it was not checked either)
rbad nts-sliding "cylinders-sliding.scene:36:|[contact c]|slides slave node|along the master|sliding_tolerance" \
  run tests/bad/cylinders-sliding.scene $KB --set contact.c.method=nts
rbad slide-off "slide-off.scene:32:|[contact c]|slides macro-element 0|off the master|faces no master surface|sliding_tolerance" \
  run tests/bad/slide-off.scene $KB
rbad nts-slide-off "slide-off.scene:32:|[contact c]|slides slave node|off the master|faces no master surface" \
  run tests/bad/slide-off.scene $KB --set contact.c.method=nts

# ---- scene text ----------------------------------------------------------
rbad nul-byte "nul-byte.scene:19:|a NUL byte" run tests/bad/nul-byte.scene $KB
rbad cr-only "cr-only.scene:1:|a carriage return not followed by a line feed" \
  run tests/bad/cr-only.scene $KB
rbad latin1-key "latin1-key.scene:3:|not UTF-8|titr\\xE9" run tests/bad/latin1-key.scene $KB
rbad binary-key "binary-key.scene:12:|a control character|E\\x1B[31m" \
  run tests/bad/binary-key.scene $KB
rbad set-binary "--set|a control character|title=a\\x1Bb" \
  run tests/bad/box.scene $KB --set "$(printf 'title=a\033b')"

# CR LF line ends read like LF: the same summary as box.scene.
"$LAC" run tests/bad/box.scene --no-output --quiet > "$RB/lf.out" 2>&1
"$LAC" run tests/bad/crlf.scene --no-output --quiet > "$RB/crlf.out" 2>&1
if sed 1d "$RB/crlf.out" | cmp -s - "$(sed 1d "$RB/lf.out" > "$RB/lf1.out"; echo "$RB/lf1.out")"; then
  rb_ok bad-crlf
else
  rb_fail bad-crlf "crlf.scene does not give the summary of box.scene: $(head -2 "$RB/crlf.out")"
fi

# No message of this file holds a byte that is not printable ASCII: what
# the files held (binary, Latin-1) is shown as \xNN.
raw=$(LC_ALL=C grep -l '[^ -~]' "$RB"/*.err 2>/dev/null)
if [ -z "$raw" ]; then
  rb_ok bad-no-raw-bytes
else
  rb_fail bad-no-raw-bytes "raw bytes in: $raw"
fi

# ---- contradictions: an error naming both places ------------------------
rbad dirichlet-twice "dirichlet-twice.scene:22:|[dirichlet pushed]|ux = 0.5 at node 1|[dirichlet left] (line 17) imposes ux = 0|contradictory" \
  run tests/bad/dirichlet-twice.scene $KB
rbad dirichlet-node "dirichlet-node.scene:22:|[dirichlet lifted]|uy = 0.1 at node 1 at (0, 0)|[dirichlet left] (line 17) imposes uy = 0" \
  run tests/bad/dirichlet-node.scene $KB
# Equal values are not a contradiction: the clamped left side is also a
# symmetry plane x = 0, and the answer is that of box.scene.
sed 's/^ux = 0.5$/symmetry = x/' tests/bad/dirichlet-twice.scene > "$RB/dirichlet-equal.scene"
cp tests/bad/box.geo "$RB/box.geo"
"$LAC" run "$RB/dirichlet-equal.scene" --no-output --quiet > "$RB/dirichlet-equal.out" 2>&1
"$LAC" run tests/bad/box.scene --no-output --quiet > "$RB/box.out" 2>&1
if cmp -s "$RB/dirichlet-equal.out" "$RB/box.out"; then rb_ok bad-dirichlet-equal
else rb_fail bad-dirichlet-equal "$(tail -1 "$RB/dirichlet-equal.out")"; fi
rbad interior-load "interior-load.scene:22:|[load inside] group = 'mid'|inside the body" \
  run tests/bad/interior-load.scene $KB
# A tri6 among tri3 cells: gmsh drops it from the entity (a hole, exit
# status 0 with a warning); in an entity of its own it is not conforming.
rbad mixed-order "mixed-order.msh|16 2D elements (15 tri3, 1 tri6), gmsh read 15|hole" \
  run $SB $KB --set mesh.file=mixed-order.msh --set element=tri3
rbad mixed-order-entity "mixed-order-entity.msh|cells 18 (tri3) and 19 (tri6) share the vertices of a face but not all its nodes|not conforming" \
  run $SB $KB --set mesh.file=mixed-order-entity.msh --set element=tri3
rbad curve-collision "--set|curve = 'solution.vtu'|another output under this name" \
  run chapters/10-large-deformation/ring.scene $KB --set steps.curve=solution.vtu
rbad curve-path "--set|curve = '../curve.csv'|without '/'" \
  run chapters/10-large-deformation/ring.scene $KB --set steps.curve=../curve.csv
"$LAC" render "$RB/keep" --out "$RB/keep/nodes.csv" > /dev/null 2> "$RB/render-out.err"
rc=$?
if [ $rc -eq 2 ] && grep -q "expected a file name ending in .png" "$RB/render-out.err" \
   && rb_sums | cmp -s - "$RB/keep.sums"; then rb_ok bad-render-out
else rb_fail bad-render-out "exit $rc: $(head -1 "$RB/render-out.err")"; fi

# ---- messages that blamed the wrong thing -------------------------------
# gmsh crashing under a small stack limit: the limit is named, not the
# .geo (not under AddressSanitizer, whose own stack use is larger).
if [ -z "$ASAN_OPTIONS" ]; then
  (ulimit -s 64; "$LAC" run tests/bad/box.scene $KB > "$RB/stack.out" 2> "$RB/stack.err")
  if grep -q "stack limit 64 KiB, ulimit -s" "$RB/stack.err" && [ "$(wc -l < "$RB/stack.err")" -eq 1 ]; then
    rb_ok bad-stack-limit
  else
    rb_fail bad-stack-limit "$(head -1 "$RB/stack.err")"
  fi
fi
# lac infsup with one multiplier: no second eigenvalue, and no nan.
"$LAC" infsup chapters/08-experiments/taylor2d.scene --quiet > "$RB/infsup1.out" 2> "$RB/infsup1.err"
rc=$?
if [ $rc -eq 0 ] && grep -q '^multipliers = 1$' "$RB/infsup1.out" \
   && ! grep -qi 'nan' "$RB/infsup1.out" && ! grep -q '^lambda_2' "$RB/infsup1.out"; then
  rb_ok bad-infsup-one
else
  rb_fail bad-infsup-one "exit $rc: $(grep -i 'nan\|lambda_2' "$RB/infsup1.out" | head -2)"
fi

# ---- inputs: regular files of bounded size ------------------------------
# A scene or mesh path is checked for what it is before a byte is read
# (src/base/lac_input.c): /dev/zero was read without end, a named pipe
# without a writer blocked forever, a symbolic link to /dev/zero made
# lac's process grow past 6 GB.  `timeout` turns a hang into a failure.
mkfifo "$RB/pipe.scene" "$RB/pipe.msh" 2> /dev/null
ln -sf /dev/zero "$RB/zero.msh"
truncate -s 5M "$RB/huge.scene"
truncate -s 200M "$RB/huge.msh"
LACT="$LAC"; LAC="$RB/lac-timeout"
printf '#!/bin/sh\nexec timeout 60 "%s" "$@"\n' "$(pwd)/$LACT" > "$LAC"
chmod +x "$LAC"
rbad dev-zero "/dev/zero: a character device, not a regular file" run /dev/zero $KB
rbad pipe-scene "pipe.scene: a named pipe, not a regular file" run "$RB/pipe.scene" $KB
rbad dir-scene "tests/bad: a directory, not a regular file" run tests/bad $KB
rbad huge-scene "huge.scene: 5.24 MB, more than the limit of 4 MB" run "$RB/huge.scene" $KB
rbad pipe-mesh "[mesh] file|pipe.msh: a named pipe, not a regular file" \
  run $SB $KB --set "mesh.file=$(pwd)/$RB/pipe.msh"
rbad zero-mesh "[mesh] file|zero.msh: a character device, not a regular file" \
  run $SB $KB --set "mesh.file=$(pwd)/$RB/zero.msh"
rbad huge-msh "[mesh] file|huge.msh: 210 MB, more than the limit of 100 MB (--max-memory)" \
  run $SB $KB --set "mesh.file=$(pwd)/$RB/huge.msh" --max-memory 100M
mkdir -p "$RB/pipe-result" && mkfifo "$RB/pipe-result/solution.vtu" 2> /dev/null
rbad render-pipe "pipe-result/solution.vtu: a named pipe, not a regular file" render "$RB/pipe-result"
LAC="$LACT"
cp tests/bad/box.geo "$RB/box.geo"
# Linear time in the number of sections: 80,000 materials (a pairwise
# check of their groups took minutes) and 50,000 loads and Dirichlet
# sections are read, checked and run in seconds.
awk 'BEGIN { while ((getline l < "tests/bad/box.scene") > 0) print l
             for (k = 0; k < 80000; k++) printf "[material m%d]\ngroup = g%d\nE = 1\nnu = 0.3\n", k, k }' \
  > "$RB/many-materials.scene"
t0=$(date +%s)
rbad many-materials "many-materials.scene|[material m0] group = 'g0'|no physical group" \
  run "$RB/many-materials.scene" $KB
t1=$(date +%s)
if [ $((t1 - t0)) -le 30 ]; then rb_ok bad-many-materials-time
else rb_fail bad-many-materials-time "80,000 materials took $((t1 - t0)) s"; fi
awk 'BEGIN { while ((getline l < "tests/bad/box.scene") > 0) print l
             for (k = 0; k < 50000; k++)
               if (k % 2) printf "[dirichlet d%d]\ngroup = left\nclamp = yes\n", k
               else printf "[load l%d]\ngroup = right\ntraction = 1e-5 0\n", k }' \
  > "$RB/many-loads.scene"
t0=$(date +%s)
if "$LAC" run "$RB/many-loads.scene" --no-output --quiet > "$RB/many-loads.out" 2> "$RB/many-loads.err" \
   && [ $(($(date +%s) - t0)) -le 30 ]; then
  rb_ok bad-many-sections
else
  rb_fail bad-many-sections "exit or time ($(($(date +%s) - t0)) s): $(head -1 "$RB/many-loads.err")"
fi

# ---- messages: the place and the reason, never a function ----------------
# A message longer than the buffer (here the scene's path twice, 4,200
# bytes) loses its middle, not its reason.
deep="$RB/$(awk 'BEGIN { for (k = 0; k < 300; k++) printf "dir%d/", k }')"
mkdir -p "$deep" && cp $SB "$deep/"
rbad long-path "box-msh.scene:10: [mesh] file = 'box.msh': |...|dir299//box.msh: cannot open (No such file or directory)" \
  run "$deep/box-msh.scene" $KB
rbad long-set "--set|3000 characters, at most 511" \
  run $SB $KB --set "mesh.file=$(awk 'BEGIN { for (k = 0; k < 2990; k++) printf "a" }')"
# An output path that is a link to a file: refused before the run, with
# the scene, the path and what it is.
ln -sf /etc/hostname "$RB/not-a-dir"
rbad out-not-dir "box.scene: the output directory|not-a-dir' is a symbolic link|not a directory" \
  run tests/bad/box.scene --quiet --out "$RB/not-a-dir"
# No message of this file names a function of lac ('lac_x_y: ...').
named=$(grep -lE '(^lac: |: )[a-z][a-z0-9]*_[a-z0-9_]*: ' "$RB"/*.err 2>/dev/null)
if [ -z "$named" ]; then
  rb_ok bad-no-function-names
else
  rb_fail bad-no-function-names "in $named: $(cat $named | head -2)"
fi

# ---- outputs: all or nothing ---------------------------------------------
# A write that fails half-way (file size limit: the write gets EFBIG): the
# earlier results stay, byte for byte, and no temporary is left beside.
# (SIGXFSZ ignored so that the write fails instead of killing lac.)
(trap '' XFSZ; ulimit -f 2; "$LAC" run tests/bad/box-msh.scene --out "$RB/keep" --quiet \
   --set mesh.file=box.msh --set material.steel.E=2000 > /dev/null 2> "$RB/efbig.err")
rc=$?
left=$(ls -A "$RB" | grep -E 'lac-(new|old)-')
if [ $rc -eq 1 ] && grep -q "cannot write" "$RB/efbig.err" && rb_sums | cmp -s - "$RB/keep.sums" \
   && [ -z "$left" ]; then
  rb_ok bad-output-efbig
else
  rb_fail bad-output-efbig "exit $rc, temporaries '$left': $(head -1 "$RB/efbig.err")"
fi

# lac render: a PNG that cannot be written leaves the earlier one.
"$LAC" render "$RB/keep" --field u --out "$RB/u.png" > /dev/null 2> "$RB/render1.err"
cksum < "$RB/u.png" > "$RB/u.sum" 2> /dev/null
(trap '' XFSZ; ulimit -f 4; "$LAC" render "$RB/keep" --field u --width 1600 --height 1200 \
   --out "$RB/u.png" > /dev/null 2> "$RB/render2.err")
rc=$?
if [ -s "$RB/u.png" ] && [ $rc -eq 1 ] && cksum < "$RB/u.png" | cmp -s - "$RB/u.sum" \
   && [ -z "$(ls -A "$RB" | grep lac-tmp)" ]; then
  rb_ok bad-render-efbig
else
  rb_fail bad-render-efbig "exit $rc: $(head -1 "$RB/render1.err" "$RB/render2.err")"
fi

# SIGINT and SIGTERM at random moments (3 runs here; tests/interrupt.sh
# does 20 on a larger run): one complete set of files, no temporaries.
if sh tests/interrupt.sh "$B" 3 3 > "$RB/interrupt.out" 2>&1; then
  rb_ok bad-interrupt
else
  rb_fail bad-interrupt "$(grep -E 'MIXED|TEMPORARIES|failed' "$RB/interrupt.out" | head -3)"
fi

# The inputs that once crashed a harness of make fuzz (fuzz/README.md),
# replayed by the same harness built without libFuzzer.
for d in tests/bad/fuzz/*/; do
  h=$(basename "$d")
  [ -x "$B/tests/replay_$h" ] || continue
  for f in "$d"*; do
    [ -f "$f" ] || continue
    if "$B/tests/replay_$h" "$f" > "$RB/replay.out" 2>&1; then
      rb_ok "bad-fuzz-$h-$(basename "$f")"
    else
      rb_fail "bad-fuzz-$h-$(basename "$f")" "$(head -2 "$RB/replay.out")"
    fi
  done
done

# Out of memory at every 15th allocation of a contact run (make
# test-nomem: at every one, of a 3D run too, and every malloc of the
# process): exit status 1, one line, the earlier files intact, no signal.
if sh tests/nomem.sh "$B" 15 0 chapters/08-experiments/taylor2d.scene > "$RB/nomem.out" 2>&1; then
  rb_ok bad-nomem
else
  rb_fail bad-nomem "$(grep -v '^nomem: [0-9]* allocations' "$RB/nomem.out" | head -3)"
fi
