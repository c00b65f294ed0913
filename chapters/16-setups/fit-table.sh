#!/bin/sh
# fit-table.sh -- the interference against the chords (chapter 16, section 5)
#
# The shrink fit of chapters/08-experiments/shrink-fit.scene (delta = 0.01)
# at levels 0-3, quad8 and quad4, its tolerance lifted so that every run
# goes through: the ratio r = interference_gap = max_i |g_i| / delta of
# the mean gaps g_i that the chords alone make, and quad4's lambda_min
# against -p = -0.2576 (Lame).
#   sh chapters/16-setups/fit-table.sh [build-dir]
B=${1:-build}
S=chapters/08-experiments/shrink-fit.scene
# cell E L KEY: one summary value of the run of element E at level L
cell () {
  "$B/lac" run $S --set element="$1" --set level="$2" \
    --set contact.fit.interference_tolerance=1e9 --quiet --no-output |
    awk -F' = ' -v k="$3" '$1 == k { printf "%.2g", $2 }'
}
echo "| the shrink fit, δ = 0.01 | level 0 | level 1 | level 2 | level 3 |"
echo "|---|---:|---:|---:|---:|"
for row in "quad8 interference_gap quad8 (tri6, quad9 alike): \$r\$" \
           "quad4 interference_gap quad4 (tri3 alike): \$r\$" \
           "quad4 lambda_min quad4: \$\\lambda_{\\min}\$ against \$-p = -0.2576\$"; do
  set -- $row
  e=$1 k=$2; shift 2
  printf '| %s |' "$*"
  for l in 0 1 2 3; do printf ' %s |' "$(cell "$e" "$l" "$k")"; done
  echo
done
