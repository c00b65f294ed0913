# tests/cases-bad-sandbox.sh -- gmsh's child process, shut in and limited
# (sourced by tests/run.sh)
#
# A .geo of tests/bad/ that starts a program or writes a file (SystemCall,
# Save, Printf > FILE, CreateDir) ends with one line "lac: ..." naming the
# file and what it tried, exit status 1, nothing run or made, and the
# files of an earlier run left as they were; a stack or memory limit that
# stops gmsh is named in the message.  Chapter 01, bad-input.md, section 1.
# Uses $B, writes only under $B/cases-bad-sandbox/; POSIX sh.

B=${B:-build}
SBX="$B/cases-bad-sandbox"
SBX_LAC="$B/lac"
rm -rf "$SBX"
mkdir -p "$SBX"

sbx_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
sbx_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
sbx_sums () { (cd "$SBX/keep" && ls -A | sort && cksum * 2>/dev/null); }

if "$SBX_LAC" run tests/bad/box.scene --out "$SBX/keep" --quiet > /dev/null 2> "$SBX/keep.err"; then
  sbx_ok sandbox-keep
else
  sbx_fail sandbox-keep "tests/bad/box.scene did not run: $(head -1 "$SBX/keep.err")"
fi
sbx_sums > "$SBX/keep.sums"

# sbx_bad NAME 'WORD|WORD...' MADE ARGS...: lac ARGS exits with status 1,
# one line on stderr holding every WORD, $SBX/keep as it was, and the file
# MADE (a path, or -) does not exist.
sbx_bad () {
  name=$1; words=$2; made=$3; shift 3
  "$@" > "$SBX/$name.out" 2> "$SBX/$name.err"
  rc=$?
  msg=""
  if [ "$rc" -ne 1 ]; then
    msg="exit status $rc, expected 1"
  elif [ "$(wc -l < "$SBX/$name.err")" -ne 1 ]; then
    msg="$(wc -l < "$SBX/$name.err") lines on stderr, expected 1"
  else
    old_ifs=$IFS; IFS='|'
    for w in $words; do
      grep -qF -- "$w" "$SBX/$name.err" || msg="message lacks '$w'"
    done
    IFS=$old_ifs
  fi
  if [ "$made" != - ] && [ -e "$made" ]; then
    msg="${msg:+$msg; }$made was made"; rm -rf "$made"
  fi
  if [ -z "$msg" ] && ! sbx_sums | cmp -s - "$SBX/keep.sums"; then
    msg="the earlier files in $SBX/keep changed"
  fi
  if [ -z "$msg" ]; then sbx_ok "bad-$name"; else sbx_fail "bad-$name" "$msg: $(head -2 "$SBX/$name.err")"; fi
}

SBX_RUN="run tests/bad/box.scene --out $SBX/keep --quiet"

# ---- the sandbox: no programs, no writes ---------------------------------
for d in . tests/bad; do rm -rf "$d/lac_sandbox_touched"; done
sbx_bad systemcall "systemcall.geo|tried to start a program|SystemCall|not allowed" \
  lac_sandbox_touched "$SBX_LAC" $SBX_RUN --set mesh.file=systemcall.geo
[ -e tests/bad/lac_sandbox_touched ] && sbx_fail bad-systemcall-dir "tests/bad/lac_sandbox_touched was made"
sbx_bad save "save.geo|tried to write 'tests/bad/lac_sandbox_saved.msh' (openat)|writes outside lac's output are not allowed" \
  tests/bad/lac_sandbox_saved.msh "$SBX_LAC" $SBX_RUN --set mesh.file=save.geo
sbx_bad printf "printf.geo|tried to write 'tests/bad/lac_sandbox_printf.txt'|not allowed" \
  tests/bad/lac_sandbox_printf.txt "$SBX_LAC" $SBX_RUN --set mesh.file=printf.geo
sbx_bad createdir "createdir.geo|tried to create 'tests/bad/lac_sandbox_dir' (mkdir)|not allowed" \
  tests/bad/lac_sandbox_dir "$SBX_LAC" $SBX_RUN --set mesh.file=createdir.geo

# ---- limits that stop gmsh, named ----------------------------------------
# A stack of 64 KiB: gmsh overflows it while lac's own process does not
# (under AddressSanitizer lac needs more, and the child has no RLIMIT_AS).
case "$B" in
  *asan*) echo "SKIP case bad-stack (limits under AddressSanitizer)" ;;
  *)
    sbx_bad stack "box.geo|killed by signal 11|its stack overflowed (stack limit 64 KiB, ulimit -s)" \
      - sh -c 'ulimit -s 64; exec "$0" "$@"' "$SBX_LAC" $SBX_RUN ;;
esac
# (--max-memory 1, below what gmsh needs to start, is refused before the
# run: tests/cases-bad.sh, bad-max-memory.)

# ---- an address-space limit and OpenBLAS ---------------------------------
# ulimit -v: OpenBLAS 0.3.21 waited forever for a buffer the limit refused
# (in fork, at exit, in a factorization; src/cli/lac_cli_limits.h).  Now
# a run ends within the time limit: a result, or one line that names the
# limit or says "out of memory".  A limit below what lac's libraries and
# one buffer take (about 610 MB here), one that a split solve of the 3D
# patch test needs, one it does not fit in.
sbx_limit () {
  name=$1; v=$2; shift 2
  (ulimit -v "$v"; exec timeout 120 "$SBX_LAC" "$@") > "$SBX/$name.out" 2> "$SBX/$name.err"
  rc=$?
  if [ $rc -eq 0 ] && grep -q '^active_macro_elements\|^max_von_mises' "$SBX/$name.out"; then
    sbx_ok "limit-$name"
  elif [ $rc -eq 1 ] && [ "$(wc -l < "$SBX/$name.err")" -eq 1 ] \
       && grep -qE 'ulimit -v|out of memory' "$SBX/$name.err"; then
    sbx_ok "limit-$name"
  else
    sbx_fail "limit-$name" "exit status $rc (124: hung): $(head -2 "$SBX/$name.err")"
  fi
}
case "$B" in
  *asan*) echo "SKIP case limit-ulimit-v (AddressSanitizer cannot run under ulimit -v)" ;;
  *)
    sbx_limit v500M 500000 run tests/bad/box.scene --no-output --quiet
    sbx_limit v800M-split 800000 run chapters/08-experiments/taylor3d.scene \
      --set mesh.numbers=n=12 --strategy split --no-output --quiet
    sbx_limit v650M-split 650000 run chapters/08-experiments/taylor3d.scene \
      --set mesh.numbers=n=14 --strategy split --no-output --quiet ;;
esac
