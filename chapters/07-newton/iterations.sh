#!/bin/sh
# iterations.sh -- active-set iterations of this chapter's curved scenes
#
#   sh chapters/07-newton/iterations.sh [BUILD]
#
# The cylinder on a rigid flat and on an elastic block (levels 4-6) and
# the tet10 ball on a rigid plane (levels 0-2): unknowns, multipliers,
# active ones at the end, iterations (solves) of Algorithm 1.  About a
# minute on two cores.
B=${1:-build}
here=$(dirname "$0")
printf '%-15s %5s %7s %6s %6s %10s\n' scene level dofs mult active iterations
for c in cylinder-flat:4 cylinder-flat:5 cylinder-flat:6 \
         cylinder-block:4 cylinder-block:5 cylinder-block:6 \
         sphere-plane:0 sphere-plane:1 sphere-plane:2; do
  s=${c%%:*}; L=${c##*:}
  "$B/lac" run "$here/$s.scene" --set level="$L" --quiet --no-output |
    awk -v s="$s" -v L="$L" -F' = ' '{ v[$1] = $2 }
      END { printf "%-15s %5d %7d %6d %6d %10d\n", s, L, v["dofs"],
                   v["multipliers"], v["active"], v["newton_iterations"] }'
done
