# tests/cases-bad-output.sh -- a run whose outputs cannot all be written
# (sourced by tests/run.sh)
#
# The files of a run are published last (chapter 01, bad-input.md, section
# 7): a summary that stdout does not take (a full device, a pipe whose
# reader is gone, a closed stdout), a progress line that stderr does not
# take, an output directory that is not a writable directory: each is exit
# status 1, one line "lac: ..." naming the path and the reason (when stderr
# can take it), the files of the earlier run byte-identical, foreign files
# kept, no temporary left.  Uses $B, writes only under
# $B/cases-bad-output/; POSIX sh.

B=${B:-build}
RO="$B/cases-bad-output"
RO_LAC="$B/lac"
rm -rf "$RO"
mkdir -p "$RO"

ro_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
ro_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
# The files of directory $1, with a checksum each.
ro_sums () { (cd "$1" && ls -A | sort && cksum * 2>/dev/null); }
ro_left () { ls -A "$(dirname "$1")" | grep -E 'lac-(new|old)-'; }

RO_SCENE=tests/bad/box-msh.scene
"$RO_LAC" run $RO_SCENE --out "$RO/keep" --quiet > "$RO/keep.out" 2> "$RO/keep.err"
echo "mine" > "$RO/keep/notes.txt"
ro_sums "$RO/keep" > "$RO/keep.sums"

# ro_case NAME WORDS: after the command just run (exit status in $rc, its
# stderr in $RO/NAME.err): status 1, every WORD ('|'-separated, none: no
# message expected) in the message, $RO/keep as it was, no temporary.
ro_case () {
  name=$1; words=$2
  msg=""
  if [ "$rc" -ne 1 ]; then
    msg="exit status $rc, expected 1"
  else
    old_ifs=$IFS; IFS='|'
    for w in $words; do
      grep -qF -- "$w" "$RO/$name.err" || msg="message lacks '$w'"
    done
    IFS=$old_ifs
  fi
  if [ -z "$msg" ] && ! ro_sums "$RO/keep" | cmp -s - "$RO/keep.sums"; then
    msg="the earlier files in $RO/keep changed"
  fi
  [ -z "$msg" ] && [ -n "$(ro_left "$RO/keep")" ] && msg="temporaries left: $(ro_left "$RO/keep")"
  if [ -z "$msg" ]; then ro_ok "bad-output-$name"; else ro_fail "bad-output-$name" "$msg: $(head -2 "$RO/$name.err")"; fi
}

RO_NEW="--set material.steel.E=2000 --out $RO/keep"

# ---- stdout and stderr ---------------------------------------------------
"$RO_LAC" run $RO_SCENE $RO_NEW --quiet > /dev/full 2> "$RO/full.err"
rc=$?
ro_case full "cannot write the summary to stdout (No space left on device)|nothing was published"

# A pipe whose reader has gone (it exits, lac starts 0.5 s later), with
# SIGPIPE's default action as in a terminal: an error, not a death.
( sleep 0.5; env --default-signal=PIPE "$RO_LAC" run $RO_SCENE $RO_NEW --quiet 2> "$RO/pipe.err"
  echo $? > "$RO/pipe.rc" ) | true
rc=$(cat "$RO/pipe.rc")
ro_case pipe "cannot write the summary to stdout (Broken pipe)|nothing was published"

# The same pipe after lac infsup and lac render --list (what they print is
# the whole result): an error, not a death.
( sleep 0.5; env --default-signal=PIPE "$RO_LAC" infsup chapters/08-experiments/taylor2d.scene --quiet 2> "$RO/pipe-infsup.err"
  echo $? > "$RO/pipe-infsup.rc" ) | true
rc=$(cat "$RO/pipe-infsup.rc")
ro_case pipe-infsup "cannot write to stdout: Broken pipe"
( sleep 0.5; env --default-signal=PIPE "$RO_LAC" render "$RO/keep" --list 2> "$RO/pipe-render.err"
  echo $? > "$RO/pipe-render.rc" ) | true
rc=$(cat "$RO/pipe-render.rc")
ro_case pipe-render "cannot write to stdout: Broken pipe"

"$RO_LAC" run $RO_SCENE $RO_NEW --quiet >&- 2> "$RO/closed.err"
rc=$?
ro_case closed "stdout is closed"

"$RO_LAC" run $RO_SCENE $RO_NEW > /dev/null 2> /dev/full
rc=$?
: > "$RO/stderr-full.err"
ro_case stderr-full ""

# ---- the output directory ------------------------------------------------
echo x > "$RO/afile"
ln -s afile "$RO/link-file"
"$RO_LAC" run $RO_SCENE --out "$RO/afile" --quiet > /dev/null 2> "$RO/file.err"
rc=$?
ro_case file "afile' exists and is a regular file, not a directory"
"$RO_LAC" run $RO_SCENE --out "$RO/afile/sub" --quiet > /dev/null 2> "$RO/under-file.err"
rc=$?
ro_case under-file "afile' is not a directory"
"$RO_LAC" run $RO_SCENE --out "$RO/link-file" --quiet > /dev/null 2> "$RO/link-file.err"
rc=$?
ro_case link-file "link-file' is a symbolic link to 'afile', which is a regular file"

# A link to a directory stands for it: the files go there, the link stays.
mkdir "$RO/real"
ln -s real "$RO/link-dir"
"$RO_LAC" run $RO_SCENE --out "$RO/link-dir" --quiet > /dev/null 2> "$RO/link-dir.err"
rc=$?
if [ $rc -eq 0 ] && [ -L "$RO/link-dir" ] && [ -f "$RO/real/summary.txt" ]; then
  ro_ok bad-output-link-dir
else
  ro_fail bad-output-link-dir "exit $rc: $(head -1 "$RO/link-dir.err")"
fi

# Root writes into a read-only directory: the run succeeds, and the
# directory is still read-only afterwards (the new one takes its mode).
cp -rp "$RO/keep" "$RO/ro-root"
chmod 555 "$RO/ro-root"
"$RO_LAC" run $RO_SCENE --out "$RO/ro-root" --quiet > /dev/null 2> "$RO/ro-root.err"
rc=$?
mode=$(stat -c %a "$RO/ro-root")
if [ "$(id -u)" -ne 0 ]; then
  ro_case ro-root "ro-root' is not writable (Permission denied)"
elif [ $rc -eq 0 ] && [ "$mode" = 555 ] && [ -f "$RO/ro-root/notes.txt" ]; then
  ro_ok bad-output-ro-mode
else
  ro_fail bad-output-ro-mode "exit $rc, mode $mode: $(head -1 "$RO/ro-root.err")"
fi
chmod 755 "$RO/ro-root"

# A directory its user cannot write, inside one the user can: refused, the
# directory and its files as they were (the same inode: not replaced).
# Root may write anywhere, so as root the case runs as nobody (setpriv).
ro_as () { "$@"; }
ro_who=$(id -u)
if [ "$ro_who" -eq 0 ]; then
  if command -v setpriv > /dev/null && getent passwd nobody > /dev/null \
     && setpriv --reuid=nobody --regid=nogroup --clear-groups "$RO_LAC" --version > /dev/null 2>&1; then
    ro_as () { setpriv --reuid=nobody --regid=nogroup --clear-groups "$@"; }
    ro_who=nobody
  else
    ro_who=""
  fi
fi
if [ -z "$ro_who" ]; then
  echo "SKIP case bad-output-read-only (root, and no setpriv or user nobody to run lac as)"
else
  RU="$RO/user"
  mkdir -p "$RU"
  [ "$ro_who" = nobody ] && chown nobody "$RU"
  ro_as "$RO_LAC" run $RO_SCENE --out "$RU/out" --quiet > /dev/null 2> "$RO/user.err"
  ro_as sh -c 'echo mine > "$0/notes.txt"; mkdir "$0/pics"; chmod 555 "$0/pics"' "$RU/out"
  cp -rp "$RU/out" "$RU/sub"
  ro_as chmod 555 "$RU/out"
  ro_sums "$RU/out" > "$RO/user.sums"
  inode=$(stat -c %i "$RU/out")
  ro_as "$RO_LAC" run $RO_SCENE $RO_NEW --out "$RU/out" --quiet > /dev/null 2> "$RO/read-only.err"
  rc=$?
  if [ $rc -eq 1 ] && grep -qF "out' is not writable (Permission denied)" "$RO/read-only.err" \
     && ro_sums "$RU/out" | cmp -s - "$RO/user.sums" && [ "$(stat -c %i "$RU/out")" = "$inode" ] \
     && [ -z "$(ro_left "$RU/out")" ]; then
    ro_ok bad-output-read-only
  else
    ro_fail bad-output-read-only "exit $rc, inode $inode -> $(stat -c %i "$RU/out"): $(head -1 "$RO/read-only.err")"
  fi
  # A writable directory with a foreign subdirectory the user cannot
  # write: it could not be moved into the new directory, so nothing is
  # published.
  ro_sums "$RU/sub" > "$RO/sub.sums"
  ro_as "$RO_LAC" run $RO_SCENE $RO_NEW --out "$RU/sub" --quiet > /dev/null 2> "$RO/foreign.err"
  rc=$?
  if [ $rc -eq 1 ] && grep -qF "subdirectory 'pics' is not writable" "$RO/foreign.err" \
     && ro_sums "$RU/sub" | cmp -s - "$RO/sub.sums" && [ -z "$(ro_left "$RU/sub")" ]; then
    ro_ok bad-output-foreign-dir
  else
    ro_fail bad-output-foreign-dir "exit $rc: $(head -1 "$RO/foreign.err")"
  fi
  chmod -R u+w "$RU" 2> /dev/null
fi
