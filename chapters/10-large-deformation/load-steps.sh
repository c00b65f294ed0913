#!/bin/sh
# load-steps.sh -- the coarse ring with few and with many load steps
#
#   sh chapters/10-large-deformation/load-steps.sh [BUILD]
#
# Exercise 4: the hex8 ring of ring.scene, the rigid approach then 6 and
# then 60 load steps; per run the load steps, the Newton iterations (all,
# most in a step), the load steps cut and the final u_z of ring_mid.
# Under a minute on 2 cores.
B=${1:-build}
here=$(dirname "$0")
printf '%10s %7s %9s %5s %15s\n' load_steps newton max/step cuts "u_z (mm)"
for n in 6 60; do
  "$B/lac" run "$here/ring.scene" --set element=hex8 --set steps.n=$n \
    --quiet --no-output |
    awk -F' = ' '{ v[$1] = $2 }
      END { printf "%10d %7d %9d %5d %15.10f\n", v["load_steps"], v["newton_iterations"],
                   v["max_iterations_per_step"], v["cut_steps"], v["monitor_uz"] }'
done
