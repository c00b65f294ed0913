#!/bin/sh
# rates.sh -- the counterpart of the paper's Tables 5 and 6 [LAC §5.3].
# Solves the manufactured problems (manufactured2d.scene, manufactured3d.scene)
# on successive mesh levels for each element type and prints, per level,
#   h        the largest cell diameter        dofs
#   err_u    ||u - u_h||_{0,Omega}           err_lam  ||lambda - lambda_h||_{0,Gamma_C}
#   e_avg    ||P0 lambda - lambda_h||_{0,Gamma_C}, P0 lambda the mean of the exact
#            pressure on each macro-element (contact.csv: lambda_exact)
#   e_P0     ||lambda - P0 lambda||_{0,Gamma_C}, the best a multiplier constant
#            per macro-element can do: err_lam^2 = e_avg^2 + e_P0^2 exactly
#   act      active multipliers / multipliers
# then one summary row per element: the rates (slopes of log err against
# log h) fitted by least squares over all levels ("fit") and from the last
# two levels ("last"), next to the paper's numerical column ("paper").
#
#   sh chapters/09-spheres-rates/rates.sh [build-dir] [element ...]
#
# Environment: LEVELS="1 2 3" replaces the levels of every element;
# EXTRA="--set ..." is appended to every `lac run` (e.g. the 3D variant
# holding x = 0: EXTRA="--set dirichlet.hold.group=x0 --set load.face1.group=top").
B=${1:-build}
[ $# -gt 0 ] && shift
ELEMENTS=${*:-"tri3 tri6 quad4 quad8 tet4 tet10 hex8 hex20 hex27"}
D=chapters/09-spheres-rates
T=$(mktemp -d "${TMPDIR:-/tmp}/lac-rates.XXXXXX") || exit 1
trap 'rm -rf "$T"' EXIT INT TERM

# element -> scene, levels, the paper's rates (u, lambda; Tables 5-6)
info () {
  case $1 in
    tri3)  echo "manufactured2d|1 2 3 4 5|1.99|1.01" ;;
    tri6)  echo "manufactured2d|1 2 3 4 5|2.99|1.04" ;;
    quad4) echo "manufactured2d|1 2 3 4 5|2.00|1.01" ;;
    quad8) echo "manufactured2d|1 2 3 4 5|2.96|1.08" ;;
    tet4)  echo "manufactured3d|1 2 3 4|1.99|1.51" ;;
    tet10) echo "manufactured3d|0 1 2 3|2.99|1.99" ;;
    hex8)  echo "manufactured3d|1 2 3 4|1.98|1.93" ;;
    hex20) echo "manufactured3d|0 1 2 3|2.54|1.04" ;;
    hex27) echo "manufactured3d|0 1 2 3|2.97|1.01" ;;
    *) return 1 ;;
  esac
}

printf '%-7s %2s %10s %7s %11s %11s %11s %11s %9s\n' \
  element lv h dofs err_u err_lam e_avg e_P0 act
for e in $ELEMENTS; do
  i=$(info "$e") || { echo "rates.sh: unknown element '$e'" >&2; exit 1; }
  scene=${i%%|*}; i=${i#*|}
  levels=${LEVELS:-${i%%|*}}; i=${i#*|}
  : > "$T/$e.dat"
  for l in $levels; do
    o="$T/$e-$l"
    # shellcheck disable=SC2086
    if ! "$B/lac" run "$D/$scene.scene" --set element="$e" --set level="$l" \
         --set output.vtu=no --out "$o" $EXTRA --quiet > "$o.sum" 2> "$o.err"; then
      echo "rates.sh: $e level $l: $(tail -1 "$o.err")" >&2
      exit 1
    fi
    # per level: h dofs err_u err_lam e_avg e_P0 active multipliers
    awk -F, -v sum="$o.sum" '
      BEGIN { while ((getline line < sum) > 0) { split(line, kv, " = "); v[kv[1]] = kv[2] } }
      NR > 1 && $9 >= 0 { s += $6 * ($10 - $11)^2 }    # covered part x (lambda_h - mean)^2
      END { l = v["l2_err_lambda"]; p = l * l - s; p = p > 0 ? sqrt(p) : 0
            print v["h"], v["dofs"], v["l2_err_u"], l, sqrt(s), p, v["active"], v["multipliers"] }' \
      "$o/contact.csv" > "$o.row"
    awk -v e="$e" -v l="$l" '{ printf "%-7s %2d %10.4e %7d %11.4e %11.4e %11.4e %11.4e %9s\n",
                               e, l, $1, $2, $3, $4, $5, $6, $7 "/" $8 }' "$o.row"
    cat "$o.row" >> "$T/$e.dat"
    rm -rf "$o"
  done
  echo "$e ${i%%|*} ${i#*|}" >> "$T/summary.in"
done

# rates: least-squares slope of log err against log h, and the last pair
echo
printf '%-7s | %-17s | %-17s | %-11s | %s\n' "" "rate u" "rate lambda" "rate e_avg" "rate e_P0"
printf '%-7s | %5s %5s %5s | %5s %5s %5s | %5s %5s | %5s %5s\n' \
  element fit last paper fit last paper fit last fit last
while read -r e pu pl; do
  awk -v e="$e" -v pu="$pu" -v pl="$pl" '
    function fit(c,   i, sx, sy, sxx, sxy, x, y) {
      sx = sy = sxx = sxy = 0
      for (i = 1; i <= n; i++) { x = log(h[i]); y = log(v[i, c]); sx += x; sy += y; sxx += x * x; sxy += x * y }
      return (n * sxy - sx * sy) / (n * sxx - sx * sx)
    }
    function last(c) { return log(v[n, c] / v[n - 1, c]) / log(h[n] / h[n - 1]) }
    { n++; h[n] = $1; for (c = 3; c <= 6; c++) v[n, c] = $c }
    END { if (n < 2) exit
          printf "%-7s | %5.2f %5.2f %5.2f | %5.2f %5.2f %5.2f | %5.2f %5.2f | %5.2f %5.2f\n",
                 e, fit(3), last(3), pu, fit(4), last(4), pl, fit(5), last(5), fit(6), last(6) }' "$T/$e.dat"
done < "$T/summary.in"
