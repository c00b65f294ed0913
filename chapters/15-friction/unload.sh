#!/bin/sh
# unload.sh -- Cattaneo-Mindlin loaded and unloaded (Mindlin-Deresiewicz)
#
#   sh chapters/15-friction/unload.sh [BUILD] [LEVEL]
#
# cattaneo2d.scene at LEVEL (default 1) in 12 load steps: P from t = 0 to
# 1, Q from 0 to 0.6 mu P at t = 2, back to 0 at t = 3.  Prints per step
# of Q the load factor, Q / (mu P), the displacement u_x of the point
# where Q acts and the active-set iterations; then the largest tangential
# traction left at Q = 0, over mu p0, and its closed form: unloaded from
# Q*, the fit slips back in c' < |x| < a, c' = a sqrt(1 - Q* / (2 mu P)),
# where q = -mu p, largest at |x| = c': mu p0 sqrt(Q* / (2 mu P)).
B=${1:-build}
L=${2:-1}
here=$(dirname "$0")
d=$B/unload
mkdir -p "$d" || exit 1
"$B/lac" run "$here/cattaneo2d.scene" --set level="$L" --set steps.n=12 \
  --set steps.end=3 --set "load.pull.curve=0 0 1 0 2 1 3 0" \
  --set steps.monitor=corner --quiet --out "$d" > /dev/null 2> "$d.err" \
  || { echo "failed: $(tail -1 "$d.err")"; exit 1; }
printf '%6s %9s %14s %11s\n' t "Q / muP" "u_x (mm)" iterations
awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  $(c["load_factor"]) >= 1 { t = $(c["load_factor"])
    f = t <= 1 ? 0 : t <= 2 ? t - 1 : 3 - t
    printf "%6.2f %9.2f %14.6e %11d\n", t, 0.6 * f, $(c["monitor_ux"]),
           $(c["iterations"]) }' "$d/curve.csv"
awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  $(c["multiplier"]) != "" { t = $(c["lambda_t"]); t = t < 0 ? -t : t
                             if (t > m) m = t }
  END { Es = 200000 / (2 * (1 - 0.09)); a = sqrt (4 * 7 * 10 / (3.141592653589793 * Es))
        printf "at Q = 0, the largest |lambda_t| / (mu p0): %.4f", m / (0.3 * 2 * 7 / (3.141592653589793 * a))
        printf " (Mindlin-Deresiewicz: sqrt(Q* / (2 mu P)) = %.4f)\n", sqrt (0.3) }' "$d/contact.csv"
