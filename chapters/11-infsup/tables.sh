#!/bin/sh
# tables.sh -- the two inf-sup tables of chapter 11          [LAC (10), App. A]
#
#   sh chapters/11-infsup/tables.sh [build-dir]      (from the repository root)
#
# Table 1: beta_h against h, geometrically conforming (Gamma_C is the whole
#          common face of the Taylor blocks, non-matching meshes): levels
#          0..3 of taylor2d (quad4) and taylor3d (hex8), plus finer 2D levels.
# Table 2: beta_h against the coverage delta of one macro-element in the
#          non-conforming case (narrow2d: the master ends inside a slave
#          macro-element, kept with epsilon = 1e-9), at two mesh levels, next
#          to its criterion phibar sqrt(delta) of [LAC Def. 1].
# Every number comes from `lac infsup` (H1 norm, dense path).  LAC=path
# selects another lac executable.
B=${1:-build}
LAC=${LAC:-$B/lac}
here=$(dirname "$0")
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# infsup SCENE ARGS... -> "k ndof h_max beta_h lambda_2 criterion_min"
# (lambda_2: - with a single multiplier, which has no second eigenvalue)
infsup () {
  "$LAC" infsup "$@" --quiet | awk -F' = ' '
    { v[$1] = $2 }
    END { split (v["criterion_min"], c, " ");
          printf "%s %s %s %s %s %s\n", v["multipliers"], v["ndof"], v["h_max"],
                 v["beta_h"], v["lambda_2"] == "" ? "-" : v["lambda_2"], c[1] }'
}

echo "Table 1. Geometrically conforming: beta_h against h (Taylor blocks)"
printf '%-9s %5s %5s %7s %8s %9s %12s\n' scene level k ndof h_max beta_h sqrt_lam2
for s in taylor2d:0 taylor2d:1 taylor2d:2 taylor2d:3 taylor2d:6 taylor2d:9 \
         taylor2d:12 taylor3d:0 taylor3d:1 taylor3d:2 taylor3d:3; do
  scene=${s%%:*}; l=${s##*:}
  infsup "$here/../08-experiments/$scene.scene" --set level="$l" |
    awk -v s="$scene" -v l="$l" '{ printf "%-9s %5s %5s %7s %8.3f %9.5f %12s\n",
                                   s, l, $1, $2, $3, $4,
                                   $5 == "-" ? "-" : sprintf ("%.5f", sqrt ($5)) }'
done

echo
echo "Table 2. Non-conforming: beta_h against the coverage delta of the cut"
echo "macro-element (narrow2d, quad4: criterion = delta^{3/2} for delta <= 1/2)"
printf '%5s %10s %5s %11s %9s %12s %13s\n' level delta k criterion beta_h \
       beta/crit "beta/sqrt(d)"
cp "$here/narrow2d.scene" "$tmp/"
for l in 0 2; do
  for d in 1 0.5 0.25 0.125 0.0625 0.03125 0.015625 0.0078125 0.00390625; do
    sed "s/^delta = .*/delta = $d;/" "$here/narrow2d.geo" > "$tmp/narrow2d.geo"
    infsup "$tmp/narrow2d.scene" --set level="$l" |
      awk -v l="$l" -v d="$d" '{ printf "%5s %10.6g %5s %11.4e %9.5f %12.4g %13.5f\n",
                                 l, d, $1, $6, $4, $4 / $6, $4 / sqrt (d) }'
  done
done
