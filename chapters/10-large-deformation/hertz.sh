#!/bin/sh
# hertz.sh -- Hertz contact: convergence table and pressure profiles
#
#   sh chapters/10-large-deformation/hertz.sh [CASES [LEVELS]]
#
# Runs the Hertz scenes of this chapter at each of LEVELS ("0 1 2 3 4")
# for each case of CASES (default: the four 2D cases
# "cyl-rigid:quad8 cyl-rigid:tri6 cyl-block:quad8 cyl-block:tri6"; in 3D
# sph-rigid (the sphere on a rigid flat) and sph-block (on an elastic
# block), each :tet10 or :hex20; the finer 3D levels take up to a minute)
# and prints one row per run: dofs, the peak pressure
# max_contact_pressure against Hertz's p0, the half-width (radius in 3D)
# a_h against Hertz's a, the contact force against the load, the time,
# the iterations.
# a_h comes from the second moment of the computed pressure over the
# active macro-elements (contact.csv: centroid, measure, lambda), which
# for Hertz's distribution is m2/m0 = a^2/4 in 2D and 2 a^2/5 in 3D, so
# a_h = 2 sqrt(m2/m0) or sqrt(5 m2 / (2 m0)); each macro-element counts
# with its centroid plus its own second moment about it (2D: L^2/12 of
# its length L; 3D: A/6 of its area A, that of a square).  a_A(%) is the
# error of the radius (2D: half-width) of the active area contact_area
# instead, which moves by whole macro-elements.  The time t is
# the wall-clock time of the run, it the active-set iterations
# (chapters/10-large-deformation/hertz-table.sh makes the tables of
# chapter 14 from these rows); LAC_ARGS adds options to every run
# (LAC_ARGS="--strategy schur --timings").  Hertz (E* the
# combined modulus 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)):
#   2D, P per unit length: a = sqrt(4 P R / (pi E*)),  p0 = 2 P / (pi a);
#   3D:                    a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2).
# The finest run of each case leaves OUT/CASE-LEVEL/profile.dat: the
# position x (2D) or r (3D), lambda and the exact p0 sqrt(1 - x^2/a^2),
# for the figure (figures/make-figures.sh).  OUT = out/hertz, B = build.
set -e
B=${B:-build}
OUT=${OUT:-out/hertz}
CASES=${1:-"cyl-rigid:quad8 cyl-rigid:tri6 cyl-block:quad8 cyl-block:tri6"}
LEVELS=${2:-"0 1 2 3 4"}
D8=chapters/10-large-deformation
mkdir -p "$OUT"
printf '%-16s %5s %8s %12s %9s %10s %9s %9s %9s %6s %3s\n' case level dofs p_max "err(%)" a_h "err(%)" "a_A(%)" "|F-P|/P" "t(s)" it
for c in $CASES; do
  name=${c%%:*}; el=${c#*:}
  case $name in
    cyl-rigid) scene=hertz-cylinder; dim=2; P=700; Es=219780.21978021978; q=2; mesh= ;;
    cyl-block) scene=hertz-cylinder-block; dim=2; P=700; Es=109890.10989010989; q=2; mesh= ;;
    sph-rigid) scene=hertz-sphere; dim=3; P=3600; Es=219780.21978021978; q=4
               mesh=hertz-sphere.geo; [ "$el" = tet10 ] || mesh=hertz-sphere-hex.geo ;;
    sph-block) scene=hertz-sphere-block; dim=3; P=3600; Es=109890.10989010989; q=4
               mesh="hertz-sphere.geo hertz-flat.geo"
               [ "$el" = tet10 ] || mesh="hertz-sphere-hex.geo hertz-flat-hex.geo" ;;
    *) echo "hertz.sh: unknown case '$name'" >&2; exit 1 ;;
  esac
  for L in $LEVELS; do
    d="$OUT/$name-$el-$L"
    t0=$(date +%s.%N)
    if [ -n "$mesh" ]; then
      "$B/lac" run "$D8/$scene.scene" --set element="$el" --set level="$L" \
        --set mesh.file="$mesh" --out "$d" --quiet $LAC_ARGS > "$d.out"
    else
      "$B/lac" run "$D8/$scene.scene" --set element="$el" --set level="$L" \
        --out "$d" --quiet $LAC_ARGS > "$d.out"
    fi
    t1=$(date +%s.%N)
    awk -F, -v dim="$dim" -v P="$P" -v Es="$Es" -v q="$q" -v name="$name:$el" \
        -v L="$L" -v t="$(echo "$t0 $t1" | awk '{ print $2 - $1 }')" \
        -v sum="$d.out" -v prof="$d/profile.dat" '
      BEGIN { pi = atan2(0, -1); R = 10
        if (dim == 2) { a = sqrt(4 * P * R / (pi * Es)); p0 = 2 * P / (pi * a) }
        else { a = (3 * P * R / (4 * Es)) ^ (1 / 3); p0 = 3 * P / (2 * pi * a * a) }
        while ((getline line < sum) > 0) { split(line, kv, " = "); v[kv[1]] = kv[2] } }
      NR == 1 { for (k = 1; k <= NF; k++) col[$k] = k; next }
      $col["active"] == 1 { x = $col["x"]; y = $col["y"]; m = $col["measure"]; l = -$col["lambda"]
        r2 = dim == 2 ? x * x + m * m / 12 : x * x + y * y + m / 6
        m0 += l * m; m2 += l * m * r2 }
      $col["lambda"] != "" { r = dim == 2 ? x = $col["x"] : sqrt($col["x"] ^ 2 + $col["y"] ^ 2)
        e = r < a ? p0 * sqrt(1 - r * r / (a * a)) : 0
        printf "%.8g %.8g %.8g\n", r, -$col["lambda"], e > prof }
      END { ah = dim == 2 ? 2 * sqrt(m2 / m0) : sqrt(2.5 * m2 / m0)
        aA = dim == 2 ? v["contact_area"] * q / 2 : sqrt(v["contact_area"] * q / pi)
        F = -v["contact_force"] * q; pm = v["max_contact_pressure"]
        printf "%-16s %5d %8d %12.5f %9.4f %10.6f %9.4f %9.4f %9.1e %6.1f %3d\n", name, L, v["dofs"], pm,
          100 * (pm / p0 - 1), ah, 100 * (ah / a - 1), 100 * (aA / a - 1), (F > P ? F - P : P - F) / P, t,
          v["newton_iterations"] }' "$d/contact.csv"
  done
done

# FIG=file.png: the pressure of the finest level of the first two cases
# against position, with Hertz's exact profile (gnuplot, pngcairo).
if [ -n "$FIG" ]; then
  Lmax=$(echo $LEVELS | awk '{ print $NF }')
  set -- $CASES
  {
    echo 'set terminal pngcairo size 1500,620 font "DejaVu Sans,13" enhanced'
    echo "set output '$FIG'"
    echo 'set multiplot layout 1,2'
    echo 'set xlabel "x (mm)"; set ylabel "contact pressure -{/Symbol l} (MPa)"; set key top right'
    for c in "$1" "$2"; do
      name=${c%%:*}; el=${c#*:}
      case $name in
        cyl-rigid) Es=219780.21978021978; t="cylinder on a rigid flat" ;;
        *) Es=109890.10989010989; t="cylinder on an elastic block" ;;
      esac
      echo "Es = $Es; a = sqrt(4 * 700 * 10 / (pi * Es)); p0 = 2 * 700 / (pi * a)"
      echo "set title \"$t, $el level $Lmax (P = 700 N/mm, R = 10 mm)\""
      echo "set xrange [0:1.4 * a]; set samples 400"
      echo "p(x) = abs(x) < a ? p0 * sqrt(1 - x * x / (a * a)) : 0"
      echo "plot '$OUT/$name-$el-$Lmax/profile.dat' using 1:2 with points pt 7 ps 0.8 title 'LAC, one value per macro-element', p(x) with lines lw 2 title 'Hertz'"
    done
    echo 'unset multiplot'
  } > "$OUT/hertz.gp"
  gnuplot "$OUT/hertz.gp"
fi
