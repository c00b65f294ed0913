#!/bin/sh
# Run every test program given on the command line (and tests/cases*.sh,
# the command-line, scene and golden cases); print one line per failure and the
# summary line "N passed, N failed".  Exit status 1 if anything failed.
pass=0; fail=0
for t in "$@"; do
  # under make test-asan, the programs that start MPI (the petsc strategy,
  # the distributed assembly) unwind in full
  case $t in *petsc*|*-dist) a="$ASAN_OPTIONS${LAC_MPI_ASAN:-}" ;; *) a="$ASAN_OPTIONS" ;; esac
  if out=$(ASAN_OPTIONS="$a" "./$t" 2>&1); then pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   $t"
  else fail=$((fail+1)); echo "FAIL $t"; echo "$out" | tail -20 | sed 's/^/     /'; fi
done
for cases in tests/cases*.sh; do
  [ -f "$cases" ] && . "./$cases"
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
