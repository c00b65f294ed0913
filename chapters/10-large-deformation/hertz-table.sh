#!/bin/sh
# hertz-table.sh -- the Hertz tables of the book, as Markdown
#
#   sh chapters/10-large-deformation/hertz-table.sh [2d|3d] [BUILD]
#
# Runs hertz.sh (this folder) and writes its rows as the tables of
# chapter 14, section 5 (make doc-snapshots compares them with the book):
#   2d  the cylinder on a rigid flat and on an elastic block, quad8 and
#       tri6, levels 0-4: dofs, the peak pressure and the half-width a_h
#       with their errors against Hertz (percent), |F - P|/P;
#   3d  the sphere on a rigid flat (tet10, hex20, levels 0-3) and on an
#       elastic block (levels 0-2): dofs, active-set iterations, the errors
#       of the peak pressure, of a_h and of the radius a_A of the active
#       area (percent), |F - P|/P and the wall time of the run (which
#       depends on the machine; about 3 minutes for all on 2 cores).
# Errors below 1e-10 of the force are shown as "< 1e-10".
D=${1:-2d}
B=${2:-build}
here=$(dirname "$0")
case $D in
  2d) rows=$(B="$B" sh "$here/hertz.sh") || exit 1 ;;
  3d) rows=$(B="$B" sh "$here/hertz.sh" "sph-rigid:tet10 sph-rigid:hex20" "0 1 2 3") || exit 1
      more=$(B="$B" sh "$here/hertz.sh" "sph-block:tet10 sph-block:hex20" "0 1 2") || exit 1
      rows=$(printf '%s\n%s\n' "$rows" "$more" | awk 'NR == 1 || $1 != "case"') ;;
  *) echo "hertz-table.sh: 2d or 3d, not '$D'" >&2; exit 2 ;;
esac
# hertz.sh's columns: case level dofs p_max err a_h err a_A |F-P|/P t it
printf '%s\n' "$rows" | awk -v d="$D" '
  function pc(x,   s) { s = sprintf ("%+.3g", x); sub (/^-/, "−", s); return s }
  function f(x) { return x < 1e-10 ? "< 1e-10" : sprintf ("%.1e", x) }
  function name(c,   n, e) { split (c, n, ":"); e = n[2]
    return (n[1] ~ /rigid/ ? "rigid flat" : "block") ", " e }
  NR == 1 { if (d == "2d") print "| case | level | dofs | $p_{max}$ (MPa) | err (%) | $a_h$ (mm) | err (%) | $\\lvert F-P\\rvert/P$ |\n|---|---|---|---|---|---|---|---|"
            else print "| case | level | dofs | it | $p_{max}$ err | $a_h$ err | $a_A$ err | $\\lvert F-P\\rvert/P$ | $t$ (s) |\n|---|---|---|---|---|---|---|---|---|"
            next }
  { c = ($1 == last) ? "" : name($1); last = $1
    if (d == "2d") printf "| %s | %d | %d | %.2f | %s | %.6f | %s | %s |\n", c, $2, $3, $4, pc($5), $6, pc($7), f($9)
    else printf "| %s | %d | %d | %d | %s | %s | %s | %s | %.1f |\n", c, $2, $3, $11, pc($5), pc($7), pc($8), f($9), $10 }'
