#!/bin/sh
# fuzz/campaign.sh -- a long fuzzing campaign in chunks     (fuzz/README.md)
#
#   sh fuzz/campaign.sh OUT FUZZ_BUILD BUILD HARNESS=EXECUTIONS ...
#
# Runs each harness (built by make fuzz) in chunks of at most FUZZ_CHUNK
# seconds (600) until it has executed EXECUTIONS inputs, each chunk through
# fuzz/run.sh (the corpus grows from chunk to chunk).  With FUZZ_LOCK set
# to a file, each chunk runs under `flock FUZZ_LOCK`, so that other long
# jobs of a shared machine can run between two chunks.  Writes OUT: one
# line per chunk and per harness the totals (executions, crashes, wall
# seconds of fuzzing, waits for the lock excluded).  Exit status 1 if any
# chunk crashed.
OUT=${1:?output file}
F=${2:?fuzz build directory}
B=${3:?build directory}
shift 3
CHUNK=${FUZZ_CHUNK:-600}
# the sanitizer options of make fuzz, unless given
export ASAN_OPTIONS="${ASAN_OPTIONS:-alloc_dealloc_mismatch=0:detect_leaks=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0}"
bad=0
{
  echo "# sh fuzz/campaign.sh $OUT $F $B $*  (chunks of at most $CHUNK s)"
  echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(uname -srm), $(nproc) cores"
} > "$OUT"
for hr in "$@"; do
  h=${hr%%=*}; want=${hr#*=}
  done_runs=0; crashes=0; wall=0; k=0
  while [ "$done_runs" -lt "$want" ]; do
    k=$((k + 1))
    line=$(FUZZ_RUNS=$((want - done_runs)) ${FUZZ_LOCK:+flock "$FUZZ_LOCK"} \
      sh -c 't0=$(date +%s); sh fuzz/run.sh "$1" "$2" "$3" "$4"; echo " wall $(( $(date +%s) - t0 ))"' \
      sh "$F" "$CHUNK" "$B" "$h" | tr -d '\n')
    runs=$(echo "$line" | sed -n 's/.* s, \([0-9]*\) executions.*/\1/p')
    c=$(echo "$line" | sed -n 's/.*inputs, \([0-9]*\) crashes.*/\1/p')
    w=$(echo "$line" | sed -n 's/.* wall \([0-9]*\)$/\1/p')
    if [ -z "$runs" ] || [ -z "$c" ]; then
      echo "chunk $h $k: no figures: $line" >> "$OUT"; bad=1; break
    fi
    done_runs=$((done_runs + runs)); crashes=$((crashes + c)); wall=$((wall + w))
    echo "chunk $h $k: $runs executions, $c crashes, $w s" >> "$OUT"
    [ "$c" -eq 0 ] || bad=1
  done
  echo "total fuzz_$h: $done_runs executions, $crashes crashes, $wall s of fuzzing in $k chunks" >> "$OUT"
done
cat "$OUT"
[ "$bad" -eq 0 ]
