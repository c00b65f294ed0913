#!/bin/sh
# doc-snapshots.sh -- rerun the commands behind the snapshots of the book
#
#   sh tests/doc-snapshots.sh [--tier cheap|long|bench] [--update] [--list]
#                             [--output FILE] [--keep DIR] [FILE[:LINE]...]
#
# (make doc-snapshots [UPDATE=1] [TIER=bench]; tests/cases-doc-snapshots.sh
# runs the cheap tier in make test.)  A snapshot is a table or a log
# excerpt of the book that a command prints, marked on the line right
# before its fenced block or pipe table by
#
#   <!-- snapshot[ATTRS]: COMMAND @ COMMIT, MACHINE; sha SHA -->
#
# ([ATTRS] is optional).  COMMAND runs from the top of the repository (in
# $DOC_SNAP_DIR/run, whose entries are links to the repository's, its
# build/ the build folder $B, and " /tmp/" a folder of its own) and must
# print the block: line by line, word by word, integers exactly and other
# numbers within atol + rtol |x| (tests/numcmp), blank lines at the end
# aside; its standard output only (a log excerpt says 2>&1).  A command
# "HEAD | FILTER" runs HEAD once for all the snapshots that share it.
# ATTRS, separated by commas:
#   long          a run of minutes: not in the cheap tier that make test runs
#   bench         a benchmark's record (the times of one machine, runs of
#                 hours): rerun only in the tier bench (TIER=bench)
#   machine=ITEMS values that depend on the machine (times, memory): not
#                 compared.  ITEMS joined by +, each a column (a cell of a
#                 pipe table, a blank-separated field of a block; N-M a
#                 range) or a unit (s, MB, GB: every number followed by it)
#   rtol=R atol=A numcmp's tolerances (1e-6 and 1e-9 unless given)
#   int=K         integers may differ by K (numcmp --int)
# SHA is the checksum that tests/cases-doc.sh (doc-tables) checks against
# edits by hand; COMMIT the commit of the run.
#
# Options: --tier the snapshots to rerun (cheap: those without long or
# bench; long, the default: all but bench; bench: all); --update: a
# snapshot that differs is replaced by what its command prints now
# (tests/doc-snapshot.sh: the block, COMMIT and SHA; the chapter's text
# around it is the author's to read again); --list: the snapshots and
# their tiers, nothing run; --output FILE: FILE stands for what every
# command prints (nothing is run: the tests of this script); --keep DIR:
# each command's output is also copied to DIR/N.out, N the order of the
# snapshot in the listing.  FILE[:LINE]: only the snapshots of FILE (at
# LINE); default: README.md chapters/README.md chapters/*/*.md.  The
# runs happen in $DOC_SNAP_DIR ($B/doc-snapshots by default).
# Prints a line per snapshot (ok, DIFFERS, FAILS, updated, skipped) and the
# time its command took; exit status 1 if any differs or fails (without
# --update).  Run from the top of the repository; B = build folder.
B=${B:-build}
TIER=long; UPDATE=; LIST=; GIVEN=; KEEP=
while [ $# -gt 0 ]; do
  case $1 in
    --tier) TIER=${2:?--tier needs cheap, long or bench}; shift ;;
    --update) UPDATE=1 ;;
    --list) LIST=1 ;;
    --output) GIVEN=${2:?--output needs a file}; shift ;;
    --keep) KEEP=${2:?--keep needs a folder}; shift ;;
    -*) echo "doc-snapshots: unknown option '$1'" >&2; exit 2 ;;
    *) break ;;
  esac
  shift
done
case $TIER in cheap|long|bench) ;; *) echo "doc-snapshots: --tier cheap, long or bench, not '$TIER'" >&2; exit 2 ;; esac
[ -f tests/doc-snapshot.sh ] || { echo "doc-snapshots: run from the top of the repository" >&2; exit 2; }
ROOT=$(pwd)
NUMCMP="$ROOT/$B/tests/numcmp"
[ -n "$LIST" ] || [ -x "$NUMCMP" ] || { echo "doc-snapshots: $NUMCMP is not built (make $B/tests/numcmp)" >&2; exit 2; }
W=${DOC_SNAP_DIR:-$B/doc-snapshots}
case $W in /*) ;; *) W="$ROOT/$W" ;; esac
rm -rf "$W"; mkdir -p "$W/run/tmp" "$W/cache" || exit 2
[ -z "$KEEP" ] || mkdir -p "$KEEP" || exit 2
# the sandbox: the repository's entries, build/ the build folder
for e in * .[!.]*; do
  case $e in build|out|exercises|.git|'.[!.]*'|'*') continue ;; esac
  ln -s "$ROOT/$e" "$W/run/$e"
done
ln -s "$ROOT/$B" "$W/run/build"

# the markers: "FILE<TAB>LINE<TAB>ATTRS (- if none)<TAB>COMMAND", each
# file's last first (an update changes the lines below it)
[ $# -gt 0 ] || set -- README.md chapters/README.md chapters/*/*.md
for a in "$@"; do
  f=${a%%:*}; at=; [ "$f" = "$a" ] || at=${a#*:}
  [ -f "$f" ] || { echo "doc-snapshots: no file $f" >&2; exit 2; }
  awk -v at="$at" '/^<!-- snapshot(\[[^]]*\])?: .* @ .*; sha [0-9a-f]* -->$/ {
      if (at != "" && FNR != at) next
      a = ""; c = $0; sub (/^<!-- snapshot/, "", c)
      if (c ~ /^\[/) { a = substr (c, 2, index (c, "]") - 2); c = substr (c, index (c, "]") + 1) }
      sub (/^: /, "", c); sub (/ @ [^@]*$/, "", c)
      printf "%s\t%d\t%s\t%s\n", FILENAME, FNR, (a == "" ? "-" : a), c }' "$f" | sort -t'	' -k2,2nr
done > "$W/markers"
[ -s "$W/markers" ] || { echo "doc-snapshots: no snapshot marker in $*" >&2; exit 2; }

# attr A NAME: the value of NAME= in the attributes A ("" if none), or
# "yes" for a flag
attr () {
  printf '%s\n' "$1" | tr ',' '\n' | sed 's/^ *//; s/ *$//' |
    awk -v n="$2" -F= '$1 == n { print (NF > 1 ? substr ($0, length (n) + 2) : "yes"); exit }'
}
# block FILE LINE: the lines of the block right after the marker
block () {
  awk -v n="$2" 'FNR <= n { next }
    FNR == n + 1 { if (/^```/) { fence = 1; next } if (!/^\|/) exit }
    fence && /^```/ { exit }
    !fence && !/^\|/ { exit }
    { print }' "$1"
}
# mask ITEMS: the machine-bound values of stdin replaced by ~
mask () {
  awk -v items="$1" 'BEGIN { n = split (items, it, "+")
      for (i = 1; i <= n; i++)
        if (it[i] ~ /^[0-9]+(-[0-9]+)?$/) { split (it[i], r, "-"); hi = r[2] == "" ? r[1] : r[2]
                                          for (c = r[1]; c <= hi; c++) col[c] = 1 }
        else if (it[i] != "") unit[it[i]] = 1 }
    function units (l,   u, out, e) {
      for (u in unit) { out = ""
        while (match (l, "[0-9]+([.][0-9]+)?([eE][-+]?[0-9]+)? ?" u)) {
          e = RSTART + RLENGTH
          if (substr (l, e, 1) ~ /[A-Za-z0-9_]/) { out = out substr (l, 1, e - 1); l = substr (l, e); continue }
          out = out substr (l, 1, RSTART - 1) "~" u; l = substr (l, e) }
        l = out l }
      return l }
    { l = $0
      if (l ~ /^\|/) { k = split (l, p, "|"); l = "|"
                       for (c = 2; c < k; c++) l = l ((c - 1) in col ? " ~ " : p[c]) "|" }
      else { k = split (l, p, /[ \t]+/); l = ""; c = 0
             for (j = 1; j <= k; j++) { if (p[j] == "") continue; c++; l = l (c > 1 ? " " : "") (c in col ? "~" : p[j]) } }
      print units(l) }'
}
# run COMMAND OUT ERR: COMMAND's standard output in OUT (a log excerpt
# says 2>&1 in its command), its errors in ERR; its status
run () {
  rcmd=$(printf '%s\n' "$1" | sed "s# /tmp/# $W/run/tmp/#g")
  case $rcmd in
    *" | "*) rhead=${rcmd%% | *}; rtail=${rcmd#* | } ;;
    *) rhead=$rcmd; rtail= ;;
  esac
  key=$(printf '%s' "$rhead" | cksum | tr ' ' _)
  if [ ! -f "$W/cache/$key.st" ]; then
    (cd "$W/run" && sh -c "$rhead") < /dev/null > "$W/cache/$key" 2> "$W/cache/$key.err"
    echo $? > "$W/cache/$key.st"
  fi
  rst=$(cat "$W/cache/$key.st")
  cp "$W/cache/$key.err" "$3"
  if [ -n "$rtail" ]; then
    (cd "$W/run" && sh -c "$rtail") < "$W/cache/$key" > "$2" 2>> "$3" || rst=$?
  else
    cp "$W/cache/$key" "$2"
  fi
  return "$rst"
}

nok=0; nbad=0; nskip=0; nup=0; i=0
while IFS='	' read -r f n a c; do
  i=$((i+1))
  t=cheap; [ -n "$(attr "$a" long)" ] && t=long; [ -n "$(attr "$a" bench)" ] && t=bench
  if [ -n "$LIST" ]; then printf '%-5s %s:%s  %s\n' "$t" "$f" "$n" "$c"; continue; fi
  case $TIER:$t in
    cheap:long|cheap:bench|long:bench) nskip=$((nskip+1)); printf 'skipped  %s:%s (%s)\n' "$f" "$n" "$t"; continue ;;
  esac
  block "$f" "$n" > "$W/exp"
  s0=$(date +%s)
  if [ -n "$GIVEN" ]; then cp "$GIVEN" "$W/act"; : > "$W/err"; st=0
  else run "$c" "$W/act" "$W/err"; st=$?; fi
  dt=$(( $(date +%s) - s0 ))
  [ -z "$KEEP" ] || cp "$W/act" "$KEEP/$i.out"
  # blank lines at the end of the output are not part of the block
  awk '{ l[NR] = $0 } END { n = NR; while (n > 0 && l[n] ~ /^[ \t]*$/) n--; for (i = 1; i <= n; i++) print l[i] }' \
    "$W/act" > "$W/act.t" && mv "$W/act.t" "$W/act"
  if [ "$st" -ne 0 ]; then
    nbad=$((nbad+1)); printf 'FAILS    %s:%s (%ss): %s: exit status %s\n' "$f" "$n" "$dt" "$c" "$st"
    cat "$W/act" "$W/err" | tail -5 | sed 's/^/         /'; continue
  fi
  mi=$(attr "$a" machine)
  mask "$mi" < "$W/exp" > "$W/exp.m"; mask "$mi" < "$W/act" > "$W/act.m"
  rt=$(attr "$a" rtol); az=$(attr "$a" atol); it=$(attr "$a" int)
  if d=$("$NUMCMP" --as-written --rtol "${rt:-1e-6}" --atol "${az:-1e-9}" --int "${it:-exact}" "$W/exp.m" "$W/act.m" 2>&1); then
    nok=$((nok+1)); printf 'ok       %s:%s (%ss)\n' "$f" "$n" "$dt"
  elif [ -n "$UPDATE" ]; then
    if sh tests/doc-snapshot.sh "$f" "$n" "$W/act" > /dev/null; then
      nup=$((nup+1)); printf 'updated  %s:%s (%ss): %s\n' "$f" "$n" "$dt" "$c"
    else nbad=$((nbad+1)); printf 'FAILS    %s:%s: tests/doc-snapshot.sh could not replace it\n' "$f" "$n"; fi
  else
    nbad=$((nbad+1)); printf 'DIFFERS  %s:%s (%ss): %s prints what the snapshot does not show (make doc-snapshots UPDATE=1 renews it):\n' "$f" "$n" "$dt" "$c"
    printf '%s\n' "$d" | head -12 | sed "s|$W/exp.m|the snapshot|g; s|$W/act.m|the output|g; s/^/         /"
  fi
done < "$W/markers"
[ -n "$LIST" ] && exit 0
echo "doc-snapshots: $nok ok, $nup updated, $nbad differ or fail, $nskip skipped (tier $TIER)"
[ "$nbad" -eq 0 ]
