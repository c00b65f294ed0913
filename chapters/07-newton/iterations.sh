#!/bin/sh
# iterations.sh -- active-set iterations of this chapter's curved scenes
#
#   sh chapters/07-newton/iterations.sh [BUILD]
#
# The cylinder on a rigid flat and on an elastic block (levels 4-6) and
# the tet10 ball on a rigid plane (levels 0-2): unknowns, multipliers,
# active ones at the end, iterations (solves) of Algorithm 1 with the
# rules of section 5 ([contact] rules = all, the default) and without
# them (rules = none: the paper's algorithm alone).  About two minutes on
# two cores.
B=${1:-build}
here=$(dirname "$0")
printf '%-15s %5s %7s %6s %6s %10s %6s\n' scene level dofs mult active \
  iterations bare
for c in cylinder-flat:flat:4 cylinder-flat:flat:5 cylinder-flat:flat:6 \
         cylinder-block:interface:4 cylinder-block:interface:5 \
         cylinder-block:interface:6 sphere-plane:plane:0 \
         sphere-plane:plane:1 sphere-plane:plane:2; do
  s=${c%%:*}; L=${c##*:}; p=${c#*:}; p=${p%%:*}
  bare=$("$B/lac" run "$here/$s.scene" --set level="$L" \
           --set "contact.$p.rules=none" --quiet --no-output |
         sed -n 's/^newton_iterations = //p')
  "$B/lac" run "$here/$s.scene" --set level="$L" --quiet --no-output |
    awk -v s="$s" -v L="$L" -v bare="$bare" -F' = ' '{ v[$1] = $2 }
      END { printf "%-15s %5d %7d %6d %6d %10d %6d\n", s, L, v["dofs"],
                   v["multipliers"], v["active"], v["newton_iterations"],
                   bare }'
done
