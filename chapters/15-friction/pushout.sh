#!/bin/sh
# pushout.sh -- the push-out of a shrink fit, pulled further and further
#
#   sh chapters/15-friction/pushout.sh [BUILD]
#
# pushout.scene with the shaft's top moved by d along z (each run from
# the unpulled fit, in one step): the macro-elements of the fit that stick
# and that slip, the axial friction force over mu times the normal force,
# and the active-set iterations.  The fit slips from its ends inwards;
# once every macro-element slips the ratio is 1, to rounding.
B=${1:-build}
here=$(dirname "$0")
OUT=$B/pushout
mkdir -p "$OUT" || exit 1
printf '%8s %6s %6s %14s %11s\n' d stick slip "F_z / (mu N)" iterations
for d in 0.0005 0.001 0.002 0.005 0.01 0.02; do
  if "$B/lac" run "$here/pushout.scene" --set dirichlet.pull.uz=$d --quiet \
       --no-output > "$OUT/$d.out" 2> "$OUT/$d.err"; then
    awk -v d=$d '/^contact_normal_force =/ { n = $3 } /^friction_force =/ { f = $4 }
      /^stick_macro_elements =/ { s = $3 } /^slip_macro_elements =/ { p = $3 }
      /^newton_iterations =/ { it = $3 }
      END { printf "%8s %6d %6d %14.10f %11d\n", d, s, p, f / (0.2 * n), it }' \
      "$OUT/$d.out"
  else printf '%8s failed: %s\n' "$d" "$(tail -1 "$OUT/$d.err")"
  fi
done
