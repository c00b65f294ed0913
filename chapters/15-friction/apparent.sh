#!/bin/sh
# apparent.sh -- the apparent slip of a curved slave, and of a load step
#
#   sh chapters/15-friction/apparent.sh [BUILD] [LEVELS] [LOADS]
#
# cattaneo2d.scene under the normal force P alone (Q = 0), for each P of
# LOADS (N/mm, default 7; the mesh's fine zone a0 scaled as Hertz's a):
# the largest tangential traction of a macro-element in contact, over mu
# p0 (Hertz's largest pressure times mu), with the flat face of the block
# as the slave (the default) and P in one load step, then in 16, and with
# the cylinder's arc as the slave and P in 16 steps.  For two elastically
# similar half-spaces it is zero whatever the path.  The finite bodies
# depart from half-spaces by terms of the order of a / R: their surfaces
# slide against each other as P grows, by little (chapter 15, section 5).
# In one step the contact zone sticks from the unloaded shape, so its
# edges resist all of that sliding; in 16 the zone grows with P.  The
# arc's tangent turns by x/R across the contact, and the normal approach
# shows as a slip along it, which the sticking macro-elements resist.
B=${1:-build}
LEVELS=${2:-"1 2 3"}
LOADS=${3:-7}
here=$(dirname "$0")
OUT=$B/apparent
mkdir -p "$OUT" || exit 1
for P in $LOADS; do
  A0=$(awk -v p="$P" 'BEGIN { printf "%.10g", 0.03 * sqrt(p / 7) }')
  echo "P = $P N/mm"
  printf '%5s %14s %14s %14s\n' level "flat, 1 step" "flat, 16" "curved, 16"
  for L in $LEVELS; do
    printf '%5d' "$L"
    for case in face:arc:1 face:arc:16 arc:face:16; do
      s=${case%%:*}; r=${case#*:}; m=${r%%:*}; n=${r#*:}; d="$OUT/$s-$n-$L-$P"
      if "$B/lac" run "$here/cattaneo2d.scene" --set level="$L" \
           --set "load.pull.point_force=0 0" --set "load.press.total_force=0 -$P" \
           --set "mesh.numbers=a0=$A0" --set steps.n="$n" \
           --set steps.end=1 --set contact.interface.slave="$s" \
           --set contact.interface.master="$m" --quiet --out "$d" \
           > /dev/null 2> "$d.err"; then
        awk -F, -v P="$P" 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
          $(c["multiplier"]) != "" && $(c["status"]) != "inactive" {
            t = $(c["lambda_t"]); t = t < 0 ? -t : t; if (t > m) m = t }
          END { Es = 200000 / (2 * (1 - 0.09)); a = sqrt (4 * P * 10 / (3.141592653589793 * Es))
                printf " %14.4f", m / (0.3 * 2 * P / (3.141592653589793 * a)) }' \
          "$d/contact.csv"
      else printf ' %14s' failed
      fi
    done
    printf '\n'
  done
done
