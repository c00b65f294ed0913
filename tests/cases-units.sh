# tests/cases-units.sh -- the same scenes in mm and MPa and in m and Pa
# (sourced by tests/run.sh)                         [LAC (17), Alg. 1]
#
# Nothing in lac may depend on the unit system: the scenes below run
# twice, as they are (mm, MPa, N) and in SI units (every length x 1e-3:
# the numbers of a scaled copy of the .geo, or the nodes of a .msh, the
# imposed displacements and bounds; every modulus and pressure x 1e6),
# through every strategy that applies: linear (the 2D and 3D Taylor
# patch tests, the axisymmetric spheres, the cylinder on a block of
# chapter 07) and with large deformation (the cylinder on the block,
# Saint Venant-Kirchhoff, through the strategies of [scene] solver =
# dense, cholmod, umfpack).  Checked, with the results of the SI run
# brought back to mm and MPa:
#   - the same active-set and Newton iteration counts, and every other
#     integer and word of summary.txt;
#   - every result to 1e-10 relative: the lengths, stresses, pressures,
#     forces, areas and works of summary.txt (not the errors against the
#     exact solutions, at rounding level in the patch tests); U, the
#     coordinates, the stresses of nodes.csv and lambda of contact.csv
#     (each against the largest of its kind), the statuses exactly;
#   - petsc: the same, to 1e-8 (its conjugate gradients stop at a
#     relative residual of 1e-10, and the rounding that is the only
#     difference between the two runs, amplified by GAMG and the
#     conjugate gradients, moves lambda by about 1e-9 and the stresses by
#     up to 1e-8, the Krylov counts, not compared, by a few); and with
#     every length x 2^-10 and every modulus x 2^20 (exact in binary, no
#     rounding between the runs), U and the stresses bitwise (chapter
#     11).
# Skipped without PETSc for petsc (cases-petsc.sh checks that message).
# Same conventions as tests/cases.sh ($B, pass, fail).  About 15 s.

B=${B:-build}
C="$B/cases-units"
LAC="$B/lac"
rm -rf "$C"
mkdir -p "$C"

units_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
units_fail () { fail=$((fail+1)); echo "FAIL case $1"; echo "     $2"; }
UNITS_ENV="ASAN_OPTIONS=${ASAN_OPTIONS:-}${LAC_MPI_ASAN:-}"
D7=chapters/07-newton
D8=chapters/08-experiments
D9=chapters/09-spheres-rates

# units_geo NAME SOURCE 'SED SCRIPT': the scaled copy $C/NAME.geo of a
# .geo; fails if the script changed nothing.
units_geo () {
  sed "$3" "$2" > "$C/$1.geo"
  if cmp -s "$2" "$C/$1.geo"; then
    units_fail "units-geo-$1" "$3 changed nothing in $2"
  fi
}
units_geo taylor2d "$D8/taylor2d.geo" 's/^L = 50;/L = 0.05;/'
units_geo taylor3d "$D8/taylor3d.geo" 's/^L = 50;/L = 0.05;/'
units_geo cylinder "$D7/cylinder-block.geo" 's/^R = 10;/R = 0.01;/'

# units_msh NAME GEO LEVEL: $C/NAME-mm.msh, the mesh gmsh (the command)
# makes of GEO with lac's options for quad8 (src/io/lac_mesh_gmsh_session.c),
# and its copies with the coordinates x 1e-3 (NAME-m.msh) and x 2^-10
# (NAME-p2.msh, exact).
units_msh () {
  if command -v gmsh > /dev/null 2>&1 \
     && gmsh -2 -order 2 -setnumber level "$3" -format msh22 -string \
          "Mesh.RecombineAll = 1; Mesh.RecombinationAlgorithm = 1; Mesh.SecondOrderIncomplete = 1; Mesh.Algorithm = 6;" \
          "$2" -o "$C/$1-mm.msh" > "$C/gmsh-$1.log" 2>&1; then
    for f in m:1e-3 p2:0.0009765625; do
      awk -v s="${f#*:}" '/^\$Nodes/ { on = 1; print; getline; print; next }
        /^\$EndNodes/ { on = 0 }
        on { printf "%s %.17g %.17g %.17g\n", $1, $2 * s, $3 * s, $4 * s; next }
        { print }' "$C/$1-mm.msh" > "$C/$1-${f%%:*}.msh"
    done
  else
    units_fail "units-mesh-$1" "gmsh (the command) could not mesh $2: $(tail -1 "$C/gmsh-$1.log" 2> /dev/null)"
  fi
}
# The spheres' arcs: gmsh meshes a scaled copy of their .geo with nodes
# that move by 1e-10 of the radius (its geometric tolerances are
# lengths): both runs read one mesh.
units_msh spheres "$D9/spheres-axi.geo" 1
units_msh cylinder "$D7/cylinder-block.geo" 3

# the SI overrides of each scene (after --set mesh.file=...)
SI_TAYLOR="--set material.all.E=2e9 --set load.top.pressure=25e6 --set exact.p=25e6 --set exact.E=2e9"
SI_SPHERES="--set material.inner.E=2e9 --set material.outer.E=2e9 --set load.pressure.pressure=25e6 --set exact.a=0.02 --set exact.b=0.04 --set exact.p=25e6 --set exact.E=2e9"
SI_CYLINDER="--set material.steel.E=2e11 --set dirichlet.top.uy=-2e-4 --set contact.interface.gap_bound=5e-4"

# units_compare NAME D RTOL: the SI results of $C/NAME-m against the mm
# ones of $C/NAME-mm; D = 2 (plane strain) or 3 (axisymmetric, 3D): the
# dimension of a volume, D - 1 that of a contact area.
units_compare () {
  uc_mm="$C/$1-mm" uc_m="$C/$1-m"
  uc_msg=$(awk -v D="$2" -v R="$3" -v L=1e-3 -v S=1e6 '
    function abs(x) { return x < 0 ? -x : x }
    # the factor from mm, MPa to m, Pa of a summary key (0: not compared)
    function fac(k) {
      if (k ~ /^(h|max_u|u_r_(inner|outer)(_exact)?|monitor_u[xyz]|monitor_extreme)$/) return L
      if (k ~ /^(max_von_mises|lambda_min|lambda_max|max_contact_pressure)$/) return S
      if (k == "contact_force") return S * L ^ (D - 1)
      if (k == "contact_area") return L ^ (D - 1)
      if (k == "load_work") return S * L ^ D
      return 0
    }
    # the factor of a column of nodes.csv or contact.csv (0: not
    # compared), and its group: the columns of a group are measured
    # against the largest value of the group (a stress component that is
    # zero but for rounding against the largest stress)
    function col(c) {
      if (c ~ /^(x|y|z)$/) { grp = "coordinates"; return L }
      if (c ~ /^u_[a-z]$/) { grp = "U"; return L }
      if (c ~ /^(s_..|von_mises)$/) { grp = "stresses"; return S }
      if (c == "lambda") { grp = "lambda"; return S }
      return 0
    }
    FNR == 1 { file++ }
    file == 1 || file == 2 { split ($0, kv, " = "); v[file, kv[1]] = kv[2]; keys[kv[1]] = 1; next }
    FNR == 1 { split ($0, h, ","); which = FILENAME; sub (/.*\//, "", which); next }
    {
      n = split ($0, a, ",")
      for (c = 1; c <= n; c++) {
        key = which SUBSEP c
        if (file % 2 == 1) { ref[key, FNR] = a[c]; continue }
        f = col(h[c]); r = ref[key, FNR]; g = which SUBSEP grp
        if (h[c] == "active" || h[c] == "node" || h[c] == "macro") {
          if (a[c] != r) bad = bad sprintf(" %s row %d %s: %s against %s;", which, FNR, h[c], a[c], r)
          continue
        }
        if (f == 0 || a[c] == "") continue
        d = abs(a[c] - f * r); m = abs(f * r)
        if (d > dmax[g]) dmax[g] = d
        if (m > vmax[g]) vmax[g] = m
        seen[g] = 1
      }
    }
    END {
      for (k in keys) {
        x = v[1, k]; y = v[2, k]
        if (x ~ /^-?[0-9]+$/ || x !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) {
          if (k != "solver_iterations" && k != "solver_residual" && x != y)
            bad = bad sprintf(" %s = %s against %s;", k, y, x)
          continue
        }
        f = fac(k)
        if (f != 0 && abs(y - f * x) > R * abs(f * x))
          bad = bad sprintf(" %s = %s against %s (%.1e);", k, y, x, abs(y - f * x) / abs(f * x))
      }
      for (wc in seen)
        if (dmax[wc] > R * vmax[wc]) {
          split (wc, p, SUBSEP)
          bad = bad sprintf(" %s %s: %.1e of its largest value;", p[1], p[2], dmax[wc] / vmax[wc])
        }
      printf "%s", bad
    }' "$uc_mm/summary.txt" "$uc_m/summary.txt" \
       "$uc_mm/nodes.csv" "$uc_m/nodes.csv" \
       $( [ -f "$uc_mm/contact.csv" ] && echo "$uc_mm/contact.csv $uc_m/contact.csv" ))
  if [ -z "$uc_msg" ]; then units_ok "units-$1"; else units_fail "units-$1" "$uc_msg"; fi
}

# units_case NAME D SCENE MESH 'SI overrides' ARGS...: both runs,
# compared; MESH: the scaled copy $C/MESH.geo of the scene's .geo, or
# msh:NAME for the meshes $C/NAME-mm.msh and $C/NAME-m.msh.
units_case () {
  un=$1 ud=$2 us=$3 ug=$4 usi=$5 urt=1e-10
  shift 5
  case $un in *-petsc) urt=1e-8 ;; esac
  case $ug in
    msh:*) umm="--set mesh.file=$(pwd)/$C/${ug#msh:}-mm.msh"
           um="$(pwd)/$C/${ug#msh:}-m.msh" ;;
    *) umm= um="$(pwd)/$C/$ug.geo" ;;
  esac
  # shellcheck disable=SC2086
  if env "$UNITS_ENV" "$LAC" run "$us" "$@" $umm --quiet --out "$C/$un-mm" \
       > /dev/null 2> "$C/$un-mm.err" \
     && env "$UNITS_ENV" "$LAC" run "$us" "$@" --set mesh.file="$um" \
       $usi --quiet --out "$C/$un-m" > /dev/null 2> "$C/$un-m.err"; then
    units_compare "$un" "$ud" "$urt"
  else
    units_fail "units-$un" "lac run failed: $(tail -qn 1 "$C/$un-mm.err" "$C/$un-m.err" | tr '\n' ' ')"
  fi
}

env "$UNITS_ENV" "$LAC" run "$D8/taylor2d.scene" --strategy petsc --quiet \
  --no-output > "$C/avail.out" 2> "$C/avail.err"
UNITS_PETSC=petsc
grep -q "built without PETSc" "$C/avail.err" && UNITS_PETSC=

# linear: every strategy that applies (the upper body of the patch tests
# is held by contact alone: no schur; every body of the others is held:
# no split)
for s in dense saddle augmented split $UNITS_PETSC; do
  units_case "taylor2d-quad8-$s" 2 "$D8/taylor2d.scene" taylor2d "$SI_TAYLOR" \
    --set element=quad8 --strategy "$s"
  units_case "taylor3d-hex8-$s" 3 "$D8/taylor3d.scene" taylor3d "$SI_TAYLOR" \
    --strategy "$s"
done
for s in dense schur augmented saddle $UNITS_PETSC; do
  units_case "spheres-axi-$s" 3 "$D9/spheres-axi.scene" msh:spheres "$SI_SPHERES" \
    --set element=quad8 --set level=1 --strategy "$s"
  lv=3                           # dense: 3295 unknowns would take 20 s
  [ "$s" = dense ] && lv=2
  units_case "cylinder-block-$s" 2 "$D7/cylinder-block.scene" cylinder "$SI_CYLINDER" \
    --set level=$lv --strategy "$s"
done

# large deformation: the strategies of [scene] solver
for s in dense cholmod umfpack; do
  units_case "cylinder-block-large-$s" 2 "$D7/cylinder-block.scene" cylinder "$SI_CYLINDER" \
    --set level=1 --set scene.large_deformation=yes --solver "$s"
done

# petsc with every length x 2^-10 and every modulus x 2^20 (exact in
# binary): the same floating-point operations, so U and the stresses of
# solution.vtu are bitwise those of the mm run, scaled (tests/vtu.py).
if [ -n "$UNITS_PETSC" ] && [ -f "$C/cylinder-p2.msh" ] \
   && command -v python3 > /dev/null 2>&1; then
  if env "$UNITS_ENV" "$LAC" run "$D7/cylinder-block.scene" --strategy petsc \
       --set mesh.file="$(pwd)/$C/cylinder-mm.msh" --quiet --out "$C/pow2-mm" \
       > /dev/null 2> "$C/pow2-mm.err" \
     && env "$UNITS_ENV" "$LAC" run "$D7/cylinder-block.scene" --strategy petsc \
       --set mesh.file="$(pwd)/$C/cylinder-p2.msh" --set material.steel.E=209715200000 \
       --set dirichlet.top.uy=-0.0001953125 --set contact.interface.gap_bound=0.00048828125 \
       --quiet --out "$C/pow2-p2" > /dev/null 2> "$C/pow2-p2.err"; then
    if msg=$(python3 - "$C/pow2-mm/solution.vtu" "$C/pow2-p2/solution.vtu" 2>&1 <<'EOF'
import sys
sys.path.insert(0, "tests")
from vtu import read
a, b = read(sys.argv[1])[1], read(sys.argv[2])[1]
for name, f in (("displacement", 2.0 ** -10), ("von_mises", 2.0 ** 20)):
    bad = sum(1 for x, y in zip(a[name], b[name]) if x * f != y)
    assert len(a[name]) == len(b[name]) and bad == 0, "%s: %d values differ" % (name, bad)
EOF
    ); then units_ok units-petsc-pow2; else units_fail units-petsc-pow2 "$(echo "$msg" | tail -1)"; fi
  else
    units_fail units-petsc-pow2 "lac run failed: $(tail -qn 1 "$C/pow2-mm.err" "$C/pow2-p2.err" | tr '\n' ' ')"
  fi
fi
