#!/bin/sh
# taylor-table.sh -- the counterpart of the paper's Tables 1 and 2.
# Runs the Taylor patch test for every element type, slave and master as in
# the scene and swapped, and prints the multipliers, the maximum relative
# errors of lambda and of the stress and the active-set iterations (the
# paper's values are quoted beside this table in chapter 08, section 5).
#   sh chapters/08-experiments/taylor-table.sh [build-dir]
B=${1:-build}
printf '%-6s %-9s %-5s %12s %12s %6s\n' element slave mult err_lambda err_sigma iters
for s in taylor2d:tri3 taylor2d:quad4 taylor2d:tri6 taylor2d:quad8 taylor2d:quad9 \
         taylor3d:tet4 taylor3d:hex8 taylor3d:tet10 taylor3d:hex20 taylor3d:hex27; do
  scene=${s%%:*}; e=${s##*:}
  for swap in 0 1; do
    set -- ; side=upper
    [ $swap = 1 ] && { set -- --set contact.interface.slave=lower_top --set contact.interface.master=upper_bottom; side=lower; }
    "$B/lac" run "chapters/08-experiments/$scene.scene" --set element="$e" "$@" --quiet --no-output |
      awk -v e="$e" -v side="$side" -F' = ' '
        { v[$1] = $2 }
        END { printf "%-6s %-9s %5s %12s %12s %6s\n", e, side, v["multipliers"],
              v["max_rel_err_lambda"], v["max_rel_err_sigma"], v["newton_iterations"] }'
  done
done
