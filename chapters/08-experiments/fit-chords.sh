#!/bin/sh
# fit-chords.sh -- the interference of the shrink fit against the chords
#
#   sh chapters/08-experiments/fit-chords.sh [BUILD]
#
# shrink-fit.scene (delta = 0.01) at levels 0-3 with quad8 and quad4
# cells, the tolerance raised so that every run finishes: the summary's
# interference_gap r (the largest mean gap of a macro-element without
# delta, over delta), and for quad4 lambda_min against the exact -p.
B=${1:-build}
here=$(dirname "$0")
OUT=$B/fit-chords
mkdir -p "$OUT" || exit 1
val () {   # val ELEMENT LEVEL KEY
  sed -n "s/^$3 = //p" "$OUT/$1-$2.out"
}
for e in quad8 quad4; do
  for L in 0 1 2 3; do
    "$B/lac" run "$here/shrink-fit.scene" --set element=$e --set level=$L \
      --set contact.fit.interference_tolerance=1e9 --quiet --no-output \
      > "$OUT/$e-$L.out" 2> "$OUT/$e-$L.err" \
      || { echo "failed: $e level $L: $(tail -1 "$OUT/$e-$L.err")"; exit 1; }
  done
done
echo "| the shrink fit, δ = 0.01 | level 0 | level 1 | level 2 | level 3 |"
echo "|---|---:|---:|---:|---:|"
printf '| quad8 (tri6, quad9 alike): $r$ |'
for L in 0 1 2 3; do printf ' %.1e |' "$(val quad8 $L interference_gap)"; done
printf '\n| quad4 (tri3 alike): $r$ |'
for L in 0 1 2 3; do printf ' %.3g |' "$(val quad4 $L interference_gap)"; done
printf '\n| quad4: $\\lambda_{\\min}$ against $-p = -0.2576$ |'
for L in 0 1 2 3; do printf ' %.3g |' "$(val quad4 $L lambda_min)"; done
printf '\n'
