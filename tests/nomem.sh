#!/bin/sh
# tests/nomem.sh -- out of memory at every allocation of a whole run
#                                              (chapter 01, bad-input.md, 9)
#
#   sh tests/nomem.sh BUILD_DIR [STRIDE] [FIRST] SCENE [--set ...]
#
# Runs the scene with nothing failing (BUILD_DIR/tests/nomem_lac: `lac
# run` with the allocation counter of base/lac_mem.h), which counts the N
# allocations of lac's process, then again for k = 0 .. N with
# allocation k and all after it failing (in gmsh's child too, which
# inherits the counter): every k below FIRST (500), and every STRIDE-th (1)
# from there on.  Each failed run must end with exit status 1 and one
# line on stderr that says "out of memory" -- never a signal -- and leave
# the files of the first run in its --out directory byte-identical, with
# no temporary beside them; a run that succeeds must print the same
# summary as the first.  Prints the figures; exit status 1 on any other
# outcome.  Writes under BUILD_DIR/nomem/.  NOMEM_LAC=nomem_lac_malloc:
# every malloc of lac's process counts, not only lac's own.
B=${1:?build directory}
STRIDE=${2:-1}
FIRST=${3:-500}
shift 3
W="$B/nomem"
LAC="$B/tests/${NOMEM_LAC:-nomem_lac}"
rm -rf "$W"
mkdir -p "$W"
sums () { (cd "$W/out" && ls -A | sort && cksum * 2>/dev/null); }

# twice: a run into a directory of earlier results allocates more
if ! "$LAC" run "$@" --out "$W/out" --quiet > /dev/null 2> "$W/ref.err" \
   || ! LAC_NOMEM_COUNT="$W/count" "$LAC" run "$@" --out "$W/out" --quiet \
     > "$W/ref.out" 2> "$W/ref.err"; then
  echo "nomem: the run without failures failed: $(tail -1 "$W/ref.err")"
  exit 1
fi
n=$(cat "$W/count")
sums > "$W/ref.sums"
runs=0; nomem=0; ok=0; child=0; bad=0; k=0
while [ "$k" -le "$n" ]; do
  LAC_NOMEM_AT=$k "$LAC" run "$@" --out "$W/out" --quiet > "$W/k.out" 2> "$W/k.err"
  rc=$?
  runs=$((runs + 1))
  why=""
  if [ "$rc" -gt 128 ]; then
    why="killed by signal $((rc - 128))"
  elif [ "$rc" -eq 0 ]; then
    cmp -s "$W/k.out" "$W/ref.out" && ok=$((ok + 1)) || why="another summary"
  elif [ "$rc" -ne 1 ]; then
    why="exit status $rc"
  elif [ "$(wc -l < "$W/k.err")" -ne 1 ] || ! grep -q '^lac: .*out of memory' "$W/k.err"; then
    why="not one line saying out of memory"
  else
    nomem=$((nomem + 1))
    grep -q 'gmsh\|mesh' "$W/k.err" && child=$((child + 1))
  fi
  if [ -z "$why" ] && [ "$rc" -ne 0 ] && ! sums | cmp -s - "$W/ref.sums"; then
    why="the earlier files changed"
  fi
  if [ -z "$why" ] && ls -A "$W" | grep -q '^\.out\.lac-'; then
    why="temporaries left: $(ls -A "$W" | grep '^\.out\.lac-' | head -1)"
  fi
  if [ -n "$why" ]; then
    bad=$((bad + 1))
    echo "nomem: allocation $k: $why: $(head -2 "$W/k.err")"
  fi
  [ "$rc" -eq 0 ] && sums > "$W/ref.sums"   # a finished run rewrote them
  if [ "$k" -lt "$FIRST" ]; then k=$((k + 1)); else k=$((k + STRIDE)); fi
done
echo "nomem: $n allocations, $runs runs: $nomem out of memory with exit status 1 ($child while reading the mesh), $ok finished with the same summary, $bad other"
[ "$bad" -eq 0 ]
