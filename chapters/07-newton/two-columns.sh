#!/bin/sh
# two-columns.sh -- no silent penetration: the two columns at levels 0-3
#
#   sh chapters/07-newton/two-columns.sh [BUILD]
#
# Runs two-columns.scene at levels 0 to 3 and prints, per level, the
# length of a slave facet, the multipliers (one per paired, admissible
# macro-element of the two column bottoms), how many times the loop paired
# again (pairing_widened), the contact force and its error against the
# uniaxial value -E / (1 - nu^2) * 6 * (6 + 1) / 20 (the base is stiff,
# not rigid: about 3e-4).
B=${1:-build}
here=$(dirname "$0")
printf '%5s %8s %11s %8s %14s %10s\n' level facet multipliers widened contact_force "error(%)"
for L in 0 1 2 3; do
  "$B/lac" run "$here/two-columns.scene" --set level="$L" --quiet --no-output |
    awk -v L="$L" -F' = ' '{ v[$1] = $2 }
      END { want = -2000 / (1 - 0.09) * 6 * 7 / 20
            printf "%5d %8.4f %11d %8d %14.6f %10.4f\n", L, 2 / 2 ^ L,
                   v["multipliers"], v["pairing_widened"] + 0,
                   v["contact_force"], 100 * (v["contact_force"] - want) / want }'
done
