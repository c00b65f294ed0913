# tests/cases-doc-snapshots.sh -- the book's snapshots rerun (sourced by
# tests/run.sh)
#
# tests/doc-snapshots.sh reruns the command behind each snapshot of the
# book (a table or a log excerpt marked <!-- snapshot[...]: COMMAND ... -->)
# and compares what it prints with the book.  make test runs the cheap
# tier (the snapshots without `long` or `bench`, about a minute on 2
# cores); make doc-snapshots runs the others too (README.md, "Other
# targets").  The cases:
#   doc-snapshot FILE:LINE  one per cheap snapshot: the book shows what its
#                  command prints now;
#   doc-snapshots-edit      on a copy of a chapter whose snapshot table has
#                  one number changed by hand, the checker fails (and
#                  passes on the unchanged copy);
#   doc-snapshots-code      the checker fails when the command prints one
#                  number otherwise (as when the code changes a result the
#                  table shows: its output given with --output);
#   doc-snapshots-tolerance on a snapshot of its own: a value marked
#                  machine= (a column, or numbers in seconds) may differ,
#                  a float within rtol, an integer not at all;
#   doc-snapshots-update    --update makes the edited copy what the command
#                  prints, with the checksum of tests/cases-doc.sh renewed.
# Same conventions as tests/cases.sh ($B, pass, fail).

B=${B:-build}
DS="$B/cases-doc-snapshots"
rm -rf "$DS"
mkdir -p "$DS"
ds_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
ds_fail () { fail=$((fail+1)); echo "FAIL case $1"; printf '%s\n' "$2" | head -20 | sed 's/^/     /'; }
# ds_check ARGS...: the checker in a folder of its own (make test may run
# beside make doc-snapshots)
ds_check () { B="$B" DOC_SNAP_DIR="$DS/w" sh tests/doc-snapshots.sh "$@"; }

# ---- the cheap tier --------------------------------------------------------
ds_check --list > "$DS/list" 2>&1
ds_check --tier cheap --keep "$DS/out" > "$DS/cheap.log" 2>&1
st=$?
n=0
while IFS= read -r l; do
  case $l in
    "ok       "*) n=$((n+1)); at=${l#ok       }; ds_ok "doc-snapshot ${at%% *}" ;;
    DIFFERS*|FAILS*) n=$((n+1)); at=$(printf '%s' "$l" | awk '{ print $2 }')
                     ds_fail "doc-snapshot $at" "$(sed -n "\#^[A-Z]* *${at%%:*}:${at##*:}[ :]#,\#^[a-zA-Z]#p" "$DS/cheap.log" | sed '$d')" ;;
  esac
done < "$DS/cheap.log"
if [ "$n" -lt 5 ] || ! tail -1 "$DS/cheap.log" | grep -q '^doc-snapshots: '; then
  ds_fail doc-snapshots-cheap "only $n cheap snapshots checked (status $st): $(tail -3 "$DS/cheap.log")"
fi

# ---- a number changed by hand, or by the code -------------------------------
# the first cheap snapshot that passed and shows an integer: its file, its
# line and its command's output (N.out of --keep: N its rank in the list)
pick=$(awk '{ n++ } $1 == "cheap" { print n, $2 }' "$DS/list" | while read -r k at; do
  f=${at%:*}; ln=${at##*:}
  grep -q "^ok       $at " "$DS/cheap.log" && [ -f "$DS/out/$k.out" ] || continue
  awk -v n="$ln" 'NR > n + 2 && /^(```|$)/ { exit } NR > n + 2 && /(^|[ |])[0-9]+([ |]|$)/ { f = 1; exit } END { exit !f }' "$f" &&
    { echo "$k $f $ln"; break; }
done)
# bump FROM: the first integer of a line of the block (its first two lines,
# a header, skipped) that starts after line FROM, plus one
bump () {
  awk -v from="$1" 'NR <= from + 2 || done { print; next }
    /^```/ && NR > from + 2 { done = 1; print; next }
    { if (match ($0, /(^|[ |])[0-9]+([ |]|$)/)) {
        s = substr ($0, RSTART, RLENGTH); d = s; gsub (/[^0-9]/, "", d)
        sub (/[0-9]+/, d + 1, s); $0 = substr ($0, 1, RSTART - 1) s substr ($0, RSTART + RLENGTH); done = 1 }
      print }'
}
if [ -z "$pick" ]; then
  ds_fail doc-snapshots-edit "no cheap snapshot with an integer passed: $(tail -1 "$DS/cheap.log")"
else
  set -- $pick; k=$1; f=$2; ln=$3
  cp "$f" "$DS/same.md"
  bump "$ln" < "$f" > "$DS/edited.md"
  ds_check --output "$DS/out/$k.out" "$DS/same.md:$ln" > "$DS/same.log" 2>&1; s0=$?
  ds_check --output "$DS/out/$k.out" "$DS/edited.md:$ln" > "$DS/edited.log" 2>&1; s1=$?
  if cmp -s "$f" "$DS/edited.md"; then
    ds_fail doc-snapshots-edit "$f:$ln: no number to change"
  elif [ $s0 = 0 ] && [ $s1 = 1 ] && grep -q "^DIFFERS  $DS/edited.md:$ln " "$DS/edited.log"; then
    ds_ok doc-snapshots-edit
  else
    ds_fail doc-snapshots-edit "$f:$ln: unchanged copy status $s0 (want 0), edited status $s1 (want 1):
$(diff "$f" "$DS/edited.md")
$(cat "$DS/same.log" "$DS/edited.log")"
  fi
  # the command prints one number otherwise
  { head -2 "$DS/out/$k.out"; tail -n +3 "$DS/out/$k.out" | bump -2; } > "$DS/changed.out"
  ds_check --output "$DS/changed.out" "$DS/same.md:$ln" > "$DS/changed.log" 2>&1; s2=$?
  if ! cmp -s "$DS/out/$k.out" "$DS/changed.out" && [ $s2 = 1 ] && grep -q "^DIFFERS" "$DS/changed.log"; then
    ds_ok doc-snapshots-code
  else
    ds_fail doc-snapshots-code "status $s2 (want 1): $(diff "$DS/out/$k.out" "$DS/changed.out"; cat "$DS/changed.log")"
  fi
  # --update: the edited copy regenerated from the output, then it passes,
  # its block is the output and the marker's checksum that of the block
  ds_check --update --output "$DS/out/$k.out" "$DS/edited.md:$ln" > "$DS/update.log" 2>&1; s3=$?
  ds_check --output "$DS/out/$k.out" "$DS/edited.md:$ln" > "$DS/update2.log" 2>&1; s4=$?
  awk -v n="$ln" 'NR == n + 1 && /^```/ { f = 1; next } NR > n && f && /^```/ { exit }
    NR > n && !f && !/^\|/ { exit } NR > n { print }' "$DS/edited.md" > "$DS/block"
  sha=$(sha256sum < "$DS/block" | cut -c1-12)
  if [ $s3 = 0 ] && [ $s4 = 0 ] && grep -q "^updated  $DS/edited.md:$ln" "$DS/update.log" &&
     cmp -s "$DS/block" "$DS/out/$k.out" && sed -n "${ln}p" "$DS/edited.md" | grep -q "; sha $sha -->\$"; then
    ds_ok doc-snapshots-update
  else
    ds_fail doc-snapshots-update "statuses $s3 $s4 (want 0 0), block sha $sha, marker: $(sed -n "${ln}p" "$DS/edited.md")
$(cat "$DS/update.log" "$DS/update2.log"; diff "$DS/block" "$DS/out/$k.out")"
  fi
fi

# ---- tolerances and machine-bound values -------------------------------------
# a snapshot of its own: column 3 and the numbers in seconds are the
# machine's; 2.5 a float (rtol 1e-6), 7 an integer
cat > "$DS/tol.md" <<'EOF'
<!-- snapshot[machine=3+s]: sh tests/doc-snapshots.sh --list @ 0000000, none; sha 000000000000 -->
```
run n time value note
a 7 1.25 2.5 took 0.31 s (0.40 s)
```
EOF
printf 'run n time value note\na 7 9.75 2.5000001 took 12.5 s (13.0 s)\n' > "$DS/tol-ok.out"
printf 'run n time value note\na 8 1.25 2.5 took 0.31 s (0.40 s)\n' > "$DS/tol-int.out"
printf 'run n time value note\na 7 1.25 2.5001 took 0.31 s (0.40 s)\n' > "$DS/tol-float.out"
printf 'run n time value note\na 7 1.25 2.5 took 0.31 min (0.40 s)\n' > "$DS/tol-word.out"
msg=""
for c in ok:0 int:1 float:1 word:1; do
  ds_check --output "$DS/tol-${c%:*}.out" "$DS/tol.md" > "$DS/tol-${c%:*}.log" 2>&1
  st=$?
  [ $st = "${c#*:}" ] || msg="$msg
output tol-${c%:*}: status $st (want ${c#*:}): $(cat "$DS/tol-${c%:*}.log")"
done
if [ -z "$msg" ]; then ds_ok doc-snapshots-tolerance
else ds_fail doc-snapshots-tolerance "$msg"; fi
