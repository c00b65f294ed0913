// taylor3d.geo -- Taylor patch test, two 50 mm cubes            [LAC §5.1]
//
// Two cubes meshed independently (no shared nodes): the lower one with
// nl = 4 + 3*level cells per edge, the upper one with nu = 3 + 2*level, so
// the interface meshes do not match, their nodes coincide only on the cube
// edges and the mesh-size ratio is >= 4/3.  Given a number n (the scene's
// [mesh] numbers = n:28, or gmsh -setnumber n 28), the cubes have n and
// n - 1 cells per edge instead, whatever the level: the sizes of the
// benchmarks (n = 10, 20, 28, 35: about 7k, 52k, 139k and 269k dofs with
// hex8).  Structured (transfinite): tetrahedra (6 per small cube), or
// hexahedra with recombination.
//
// Physical groups: lower, upper (volumes); lower_bottom (z = 0);
// lower_x0, upper_x0 (x = 0) and lower_y0, upper_y0 (y = 0), the symmetry
// planes; lower_top, upper_bottom (z = 50, the contact interface);
// upper_top (z = 100, the pressure).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
L = 50;
nl = 4 + 3 * level;
nu = 3 + 2 * level;
If (Exists(n))
  nl = n;
  nu = n - 1;
EndIf

Box(1) = {0, 0, 0, L, L, L};
Box(2) = {0, 0, L, L, L, L};

lc() = Abs(Boundary{ Volume{1}; });
uc() = Abs(Boundary{ Volume{2}; });
Transfinite Curve{ Unique(Abs(Boundary{ Surface{lc()}; })) } = nl + 1;
Transfinite Curve{ Unique(Abs(Boundary{ Surface{uc()}; })) } = nu + 1;
Transfinite Surface{lc()};
Transfinite Surface{uc()};
Transfinite Volume{1};
Transfinite Volume{2};

// OCC box faces come as x = 0, x = L, y = 0, y = L, z = 0, z = L.
Physical Volume("lower") = {1};
Physical Volume("upper") = {2};
Physical Surface("lower_x0") = {lc(0)};
Physical Surface("lower_y0") = {lc(2)};
Physical Surface("lower_bottom") = {lc(4)};
Physical Surface("lower_top") = {lc(5)};
Physical Surface("upper_x0") = {uc(0)};
Physical Surface("upper_y0") = {uc(2)};
Physical Surface("upper_bottom") = {uc(4)};
Physical Surface("upper_top") = {uc(5)};
