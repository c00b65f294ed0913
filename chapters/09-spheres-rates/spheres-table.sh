#!/bin/sh
# spheres-table.sh -- the counterpart of the paper's Tables 3 and 4.
# Runs the self-included spheres (spheres-axi.scene, spheres3d.scene) for
# each quadratic element type and level, slave = the inner body's R = 30
# surface, and prints the DOFs, the maximum relative errors of lambda and
# of sigma_rr on the slave and master bodies, the wall time of the run, and
# the paper's values (Tables
# 3-4, as ratios).  Then the finest level again with slave and master
# swapped (slave = the outer body).
#   sh chapters/09-spheres-rates/spheres-table.sh [build-dir [max-3d-level]]
# The finest 3D levels (level 2: 85k-130k DOFs) take 10-60 s each.
B=${1:-build}
L3=${2:-2}
D=chapters/09-spheres-rates
SWAP="--set contact.interface.slave=outer_contact --set contact.interface.master=inner_contact"

now () { date +%s.%N; }

# row SCENE ELEMENT LEVEL SIDE PAPER_LAMBDA PAPER_SLAVE PAPER_MASTER [--set ...]
row () {
  scene=$1 e=$2 l=$3 side=$4 pl=$5 ps=$6 pm=$7
  shift 7
  t0=$(now)
  out=$("$B/lac" run "$D/$scene.scene" --set element="$e" --set level="$l" "$@" \
        --quiet --no-output)
  t1=$(now)
  echo "$out" | awk -v e="$e" -v l="$l" -v side="$side" -v t="$(echo "$t1 - $t0" | bc)" \
    -v pl="$pl" -v ps="$ps" -v pm="$pm" -F' = ' '
    { v[$1] = $2 }
    END { printf "%-6s %5s %-6s %7s %10.3e %10.3e %10.3e %7.1f   %-8s %-8s %s\n", e, l, side,
          v["dofs"], v["max_rel_err_lambda"], v["max_rel_err_sigma_rr_slave"],
          v["max_rel_err_sigma_rr_master"], t, pl, ps, pm }'
}

printf '%-6s %5s %-6s %7s %10s %10s %10s %7s   %-8s %-8s %s\n' element level slave dofs \
  err_lambda err_rr_slv err_rr_mst time_s paper_l paper_s paper_m
for l in 0 1 2 3 4; do row spheres-axi tri6 "$l" inner 2e-4 1.52e-2 4.3e-3; done
for l in 0 1 2 3 4; do row spheres-axi quad8 "$l" inner 1.82e-6 1.9e-3 3.7e-3; done
l=0
while [ "$l" -le "$L3" ]; do row spheres3d tet10 "$l" inner 5e-3 1.37e-2 7.6e-3; l=$((l+1)); done
l=0
while [ "$l" -le "$L3" ]; do row spheres3d hex20 "$l" inner 1.61e-2 3.57e-2 2.33e-2; l=$((l+1)); done
l=0
while [ "$l" -le "$L3" ]; do row spheres3d hex27 "$l" inner 1.46e-2 2.4e-2 2.58e-2; l=$((l+1)); done
# shellcheck disable=SC2086
{
  row spheres-axi tri6 4 outer 2e-4 1.52e-2 4.3e-3 $SWAP
  row spheres-axi quad8 4 outer 1.82e-6 1.9e-3 3.7e-3 $SWAP
  row spheres3d tet10 "$L3" outer 5e-3 1.37e-2 7.6e-3 $SWAP
  row spheres3d hex20 "$L3" outer 1.61e-2 3.57e-2 2.33e-2 $SWAP
  row spheres3d hex27 "$L3" outer 1.46e-2 2.4e-2 2.58e-2 $SWAP
}
