#!/bin/sh
# fuzz/run.sh -- the campaign of `make fuzz`              (fuzz/README.md)
#
#   sh fuzz/run.sh FUZZ_BUILD SECONDS BUILD [HARNESS...]
#
# Seeds (made again each time, added to the corpora kept in
# FUZZ_BUILD/corpus/NAME between campaigns):
#   scene  every scene of chapters/ and tests/bad/, and box.scene with
#          --set overrides appended (fuzz_scene.c's input format);
#   mesh   every .msh of tests/meshes/ and tests/bad/ (byte 0 in front: the
#          line check) and the streams the child sends for them and for
#          the .geo of tests/meshes/ (byte 1 in front: BUILD/tools/make_seeds);
#   gmsh   the .msh files as they are;
#   numbers numbers of every kind (byte 0), [mesh] numbers (byte 1), --set
#          lines (byte 2) and the .geo scripts of the project (byte 3).
# Each harness runs SECONDS (libFuzzer's -max_total_time), one process;
# FUZZ_RUNS (environment), if set, stops it after that many executions.
# Prints per harness the executions, the corpus size and the crashes
# (libFuzzer's crash-, leak-, oom- and timeout- files; its slow-unit- files,
# inputs slower than 10 s on a busy machine, are not); the inputs are in
# FUZZ_BUILD/crashes/.  Exit status 1 if any.
F=${1:?fuzz build directory}
S=${2:-60}
B=${3:-build}
shift 3
H=${*:-scene mesh gmsh numbers}
mkdir -p "$F/corpus" "$F/crashes" "$F/seeds"

seeds_scene () {
  d="$F/seeds/scene"; rm -rf "$d"; mkdir -p "$d"; k=0
  for f in chapters/*/*.scene tests/bad/*.scene; do
    cp "$f" "$d/s$k"; k=$((k + 1))
  done
  for s in "level=2" "material.steel.E=3000
load.pull.traction=1 2" "element=quad8
mesh.numbers=n=3" "output.vtu=no
scene.solver=dense"; do
    { cat tests/bad/box.scene; printf '\n\f\n%s\n' "$s"; } > "$d/s$k"; k=$((k + 1))
  done
}

seeds_mesh () {
  d="$F/seeds/mesh"; rm -rf "$d"; mkdir -p "$d"; k=0
  for f in tests/meshes/*.msh tests/bad/*.msh; do
    { printf '\0'; cat "$f"; } > "$d/m$k"; k=$((k + 1))
  done
  "$B/tools/make_seeds" "$d" tests/meshes/*.msh tests/meshes/square.geo \
    tests/meshes/box.geo tests/bad/box.msh > /dev/null
}

seeds_gmsh () {
  d="$F/seeds/gmsh"; rm -rf "$d"; mkdir -p "$d"; k=0
  for f in tests/meshes/*.msh tests/bad/*.msh; do
    cp "$f" "$d/g$k"; k=$((k + 1))
  done
}

seeds_numbers () {
  d="$F/seeds/numbers"; rm -rf "$d"; mkdir -p "$d"; k=0
  for s in 12 -0.25 2.1e5 .5 1e308 1e400 4.9e-324 nan 0x10 " 12" 3e9 \
           2147483647 1e-31 0.4999999999999999; do
    printf '\0%s' "$s" > "$d/n$k"; k=$((k + 1))
  done
  for s in "n=28" "n=28, m=3.5" "n=nan" "level=3" "a=1 a=2"; do
    printf '\1%s' "$s" > "$d/n$k"; k=$((k + 1))
  done
  for s in "material.steel.E=3000" "load.pull.traction=1e400 0" \
           "mesh.numbers=n=3" "level=12" "mesh.size=1e-29" \
           "dirichlet.left.ux=0.5"; do
    printf '\2%s' "$s" > "$d/n$k"; k=$((k + 1))
  done
  for f in chapters/*/*.geo tests/bad/*.geo tests/meshes/*.geo; do
    { printf '\3'; cat "$f"; } > "$d/n$k"; k=$((k + 1))
  done
}

# gmsh's child process is a fork of the fuzzer and keeps its allocation
# hook: a malloc larger than -rss_limit_mb in gmsh would be reported by
# the child as an out-of-memory "crash" of the fuzzer.  There the memory
# limit of the child (io/lac_mesh_child.h) is what counts: no hook.
extra () { [ "$1" = gmsh ] && echo "-malloc_limit_mb=1000000"; }

bad=0
for h in $H; do
  "seeds_$h"
  mkdir -p "$F/corpus/$h"
  before=$(ls "$F/crashes" | grep -cE "^$h-(crash|leak|oom|timeout)-")
  "$F/bin/fuzz_$h" -max_total_time="$S" ${FUZZ_RUNS:+-runs=$FUZZ_RUNS} $(extra "$h") \
    -timeout=60 -rss_limit_mb=4096 \
    -artifact_prefix="$F/crashes/$h-" -print_final_stats=1 \
    "$F/corpus/$h" "$F/seeds/$h" > "$F/fuzz_$h.log" 2>&1
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$F/fuzz_$h.log")
  after=$(ls "$F/crashes" | grep -cE "^$h-(crash|leak|oom|timeout)-")
  corpus=$(ls "$F/corpus/$h" | wc -l)
  echo "fuzz_$h: ${S} s, ${runs:-?} executions, corpus $corpus inputs, $((after - before)) crashes (exit $rc; log $F/fuzz_$h.log)"
  [ "$rc" -ne 0 ] || [ "$after" -gt "$before" ] && bad=1
done
[ "$bad" -eq 0 ]
