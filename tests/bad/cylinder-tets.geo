// cylinder-tets.geo -- an unstructured tetrahedral cylinder for the size
// estimate of a .geo (tests/cases-bad.sh): no transfinite constraint and
// not a topological hexahedron (3 faces, 3 curves), so gmsh's Delaunay
// mesher decides the nodes and lac's estimate is the Delaunay bound
// (src/io/lac_mesh_gmsh_estimate.c).  OpenCASCADE kernel (the measure of
// the volume is exact); radius 0.5, height 1, mesh size 0.25 / 2^level.
//
// Physical groups: body (volume), side, top (z = 1), bottom (z = 0).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
h = 0.25 / 2^level;
Cylinder(1) = {0, 0, 0, 0, 0, 1, 0.5};
MeshSize{ PointsOf{ Volume{1}; } } = h;
f() = Abs(Boundary{ Volume{1}; });
Physical Volume("body") = {1};
Physical Surface("side") = {f(0)};
Physical Surface("top") = {f(1)};
Physical Surface("bottom") = {f(2)};
