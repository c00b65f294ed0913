#!/bin/sh
# memory-table.sh -- the estimate of a mesh against what gmsh and the run make
#
#   sh chapters/01-problem/memory-table.sh [BUILD]
#
# The table of bad-input.md, section "Too large": for each mesh, the
# nodes and the memory that lac run estimates before meshing (the line
# --max-memory prints: below 100M every run is refused, with its
# estimate), the nodes gmsh made (the mesh line of the run) and the peak
# memory of the whole run (/usr/bin/time's maximum resident set; with
# mpirun, the sum over the processes).  The peaks depend on the machine
# and the libraries.  The whole table takes about an hour on 2 cores and
# 8 GB (the ring at level 1, the Taylor test of 1M dofs on 2 processes);
# ROWS picks some of "taylor8 tets ring taylor55 spheres3d spheresaxi".
B=${1:-build}
LAC=$B/lac
ROWS=${ROWS:-"taylor8 tets ring taylor55 spheres3d spheresaxi"}
T3=chapters/08-experiments/taylor3d.scene
W=$B/memory-table
mkdir -p "$W" || exit 1

# est SCENE ARGS...: "NODES GB" as the estimate says them
est () {
  "$LAC" run "$@" --max-memory 100M --quiet --no-output 2>&1 |
    sed -n 's/.*an estimated \([0-9.e+]*\) nodes, which need about \([0-9.e+]*\) GB.*/\1 \2/p'
}
# real NP SCENE ARGS...: "NODES PEAK_KB" of the run on NP processes
real () {
  np=$1; shift
  if [ "$np" = 1 ]; then
    /usr/bin/time -f 'peak %M' -o "$W/time" "$LAC" run "$@" --no-output > /dev/null 2> "$W/err"
  else
    mpi=mpirun; [ "$(id -u)" = 0 ] && mpi="mpirun --allow-run-as-root --oversubscribe"
    $mpi -n "$np" sh -c '/usr/bin/time -f "peak %M" -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' \
      "$W/time" "$LAC" run "$@" --no-output > /dev/null 2> "$W/err"
    cat "$W/time".* > "$W/time"; rm -f "$W/time".*
  fi || { echo "memory-table.sh: lac run $*: $(grep '^lac:' "$W/err" | tail -1)" >&2; exit 1; }
  n=$(sed -n 's/.*\] mesh *\([0-9]*\) nodes.*/\1/p' "$W/err" | head -1)
  echo "$n $(awk '$1 == "peak" { s += $2 } END { print s }' "$W/time")"
}
# row LABEL NP "ARGS1" ["ARGS2" ...]: one row, the cells of the variants
# joined by " / "
row () {
  label=$1 np=$2; shift 2
  en= rn= em= pk=
  for a in "$@"; do
    # shellcheck disable=SC2086
    set -f; e=$(est $a); r=$(real "$np" $a) || exit 1; set +f
    en="$en${en:+ / }$(echo "$e" | awk '{ x = sprintf ("%.1e", $1); sub (/e\+0*/, "e", x); print x }')"
    em="$em${em:+ / }$(echo "$e" | awk '{ printf "%.1f GB", $2 }')"
    rn="$rn${rn:+ / }$(echo "$r" | awk '{ n = $1; s = ""; if (n >= 10000) { while (n >= 1000) { s = sprintf (",%03d", n % 1000) s; n = int (n / 1000) } } print n s }')"
    pk="$pk${pk:+ / }$(echo "$r" | awk '{ printf "%.1f GB", $2 / 1048576 }')"
  done
  [ "$np" = 1 ] || pk="$pk ($np processes)"
  echo "| $label | $en | $rn | $em | $pk |"
}

echo '| mesh | estimated nodes | gmsh'"'"'s nodes | estimated memory | measured peak |'
echo '|---|---:|---:|---:|---:|'
for r in $ROWS; do
  case $r in
    taylor8) row '`taylor3d.geo`, n = 8, hex8 / hex20 / hex27' 1 \
               "$T3 --set mesh.numbers=n=8 --set element=hex8" \
               "$T3 --set mesh.numbers=n=8 --set element=hex20" \
               "$T3 --set mesh.numbers=n=8 --set element=hex27" ;;
    tets) row '`tests/bad/cylinder-tets.geo` level 1 (Delaunay), tet4 / tet10' 1 \
            "tests/bad/cylinder-tets.scene --set level=1 --set element=tet4" \
            "tests/bad/cylinder-tets.scene --set level=1 --set element=tet10" ;;
    ring) row 'ring on block level 1, hex20' 1 \
            "chapters/10-large-deformation/ring.scene --set level=1" ;;
    taylor55) row '`taylor3d.geo` n = 55, hex8, petsc' 2 \
                "$T3 --set mesh.numbers=n=55 --set element=hex8 --strategy petsc" ;;
    spheres3d) row '3D spheres level 2, tet10 / hex20' 1 \
                 "chapters/09-spheres-rates/spheres3d.scene --set level=2 --set element=tet10" \
                 "chapters/09-spheres-rates/spheres3d.scene --set level=2 --set element=hex20" ;;
    spheresaxi) row 'axisymmetric spheres level 2, tri6' 1 \
                  "chapters/09-spheres-rates/spheres-axi.scene --set level=2 --set element=tri6" ;;
    *) echo "memory-table.sh: unknown row '$r'" >&2; exit 2 ;;
  esac
done
