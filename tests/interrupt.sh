#!/bin/sh
# tests/interrupt.sh -- SIGINT and SIGTERM at random moments of runs with
# large output: the output directory always holds the complete files of
# one run, and no temporary is left anywhere.      (chapter 01, bad-input.md)
#
#   sh tests/interrupt.sh [BUILD_DIR] [N] [LEVEL] [SEED] [FROM]
#
# tests/bad/box.scene at `level` LEVEL (default 6: 131,841 nodes, 61 MB of
# files) is run N times (default 20) into one directory, alternately with
# E = 1000 and E = 2000, and each run gets SIGINT or SIGTERM (alternately)
# after a random delay between FROM (default 0) and 1.1 times the time of
# a whole run (FROM = 0.7 aims at the output stage).
# After each: the directory must hold exactly the files of the earlier run
# (interrupted) or exactly those of the run (finished), byte for byte, as
# two reference runs made them; no .lac-new-*, .lac-old-* or .tmp file may
# be left.  Prints one line per run and a tally; exit status 1 on failure.
# Used with N = 3 by tests/cases-bad.sh; the full 20 runs take 2 minutes
# (run under the machine's lock for long jobs).

B=${1:-build}
N=${2:-20}
L=${3:-6}
SEED=${4:-$$}
FROM=${5:-0}
W="$B/interrupt"
LAC="$B/lac"
rm -rf "$W"
mkdir -p "$W"

sums () { (cd "$1" && ls -A | sort && cksum * 2> /dev/null); }
leftovers () { (cd "$W" && ls -A | grep -E 'lac-(new|old)-' ; ls -A "$W/out" 2> /dev/null | grep -E '^\..*(tmp|lac-)') ; }

run_ref () {
  "$LAC" run tests/bad/box.scene --set level="$L" --set material.steel.E="$1" \
    --out "$W/ref$1" --quiet > /dev/null 2> "$W/ref$1.err" || {
    echo "interrupt: the reference run E = $1 failed: $(tail -1 "$W/ref$1.err")"; exit 1; }
  sums "$W/ref$1" > "$W/ref$1.sums"
}

t0=$(date +%s.%N)
run_ref 1000
t1=$(date +%s.%N)
run_ref 2000
T=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
cp -p "$W/ref1000/"* "$W/out" 2> /dev/null || { mkdir -p "$W/out"; cp -p "$W/ref1000/"* "$W/out"; }
state=1000
bad=0; kept=0; done_=0; in_output=0
i=1
while [ "$i" -le "$N" ]; do
  if [ "$state" = 1000 ]; then E=2000; else E=1000; fi
  if [ $((i % 2)) -eq 1 ]; then sig=INT; else sig=TERM; fi
  delay=$(awk -v s="$SEED" -v i="$i" -v t="$T" -v f="$FROM" 'BEGIN { srand (s); for (k = 0; k < i; k++) r = rand (); printf "%.3f", (f + r * (1.1 - f)) * t }')
  # (a shell script starts background jobs with SIGINT ignored: env gives
  # lac the default action, as in a terminal)
  env --default-signal=INT,TERM "$LAC" run tests/bad/box.scene --set level="$L" \
    --set material.steel.E="$E" --out "$W/out" --quiet > /dev/null 2> "$W/run$i.err" &
  pid=$!
  sleep "$delay"
  kill -s "$sig" "$pid" 2> /dev/null
  wait "$pid"
  rc=$?
  sums "$W/out" > "$W/now.sums"
  if cmp -s "$W/now.sums" "$W/ref$state.sums"; then
    what="earlier results kept"; kept=$((kept + 1))
  elif cmp -s "$W/now.sums" "$W/ref$E.sums"; then
    what="run finished, its results"; done_=$((done_ + 1)); state=$E
  else
    what="MIXED OR INCOMPLETE"; bad=$((bad + 1))
  fi
  grep -q 'interrupted by signal' "$W/run$i.err" && in_output=$((in_output + 1)) \
    && what="$what (stopped in the output stage)"
  left=$(leftovers)
  if [ -n "$left" ]; then
    what="$what; TEMPORARIES LEFT: $left"; bad=$((bad + 1))
  fi
  printf 'run %2d: SIG%-4s after %6.3f s, exit %3d: %s\n' "$i" "$sig" "$delay" "$rc" "$what"
  i=$((i + 1))
done
echo "interrupt: $N runs (a whole run: $T s): $kept kept the earlier results ($in_output stopped in the output stage), $done_ finished, $bad failures"
[ "$bad" -eq 0 ]
