// manufactured3d.geo -- the unit cube of the 3D manufactured solution
//                                                               [LAC §5.3]
// Structured (transfinite), n = 2 * 2^level cells per edge (n = 2, 4, 8,
// 16, ... for level 0, 1, 2, 3, ...): hexahedra with recombination, or
// tetrahedra without (gmsh cuts each small cube into 6 tetrahedra).
// Physical groups: body; bottom (z = 0, the contact face over the rigid
// foundation), x0, x1, y0, y1 (the sides), top (z = 1).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
n = 2 * 2^level;

Box(1) = {0, 0, 0, 1, 1, 1};
f() = Abs(Boundary{ Volume{1}; });
Transfinite Curve{ Unique(Abs(Boundary{ Surface{f()}; })) } = n + 1;
Transfinite Surface{f()};
Transfinite Volume{1};

// OCC box faces come as x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
Physical Volume("body") = {1};
Physical Surface("x0") = {f(0)};
Physical Surface("x1") = {f(1)};
Physical Surface("y0") = {f(2)};
Physical Surface("y1") = {f(3)};
Physical Surface("bottom") = {f(4)};
Physical Surface("top") = {f(5)};
