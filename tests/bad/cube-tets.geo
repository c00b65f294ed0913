// cube-tets.geo -- an unstructured tetrahedral cube for the size estimate
// of a .geo (tests/cases-bad.sh): no transfinite constraint, so gmsh's
// Delaunay mesher decides the nodes and lac's estimate is the Delaunay
// bound (src/io/lac_mesh_gmsh_estimate.c).  Built-in kernel (the measure
// of the volume is its bounding box's), mesh size 0.25 / 2^level.
//
// Physical groups: body (volume), bottom (z = 0), top (z = 1).
If (!Exists(level))
  level = 0;
EndIf
h = 0.25 / 2^level;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {0, 1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
v[] = Extrude {0, 0, 1} { Surface{1}; };
Physical Volume("body") = {v[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {v[0]};
