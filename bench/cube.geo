// cube.geo -- the block of bench_elasticity.c as a scene mesh: the unit
// cube [0,1]^3 with n cells per edge (gmsh -setnumber n 69, or the
// scene's [mesh] numbers = n=69), structured (transfinite): hexahedra with
// the scene's element hex8, tetrahedra otherwise.  n = 69: 70^3 nodes,
// 1,029,000 dofs with hex8, the cube whose Cholesky factor needs 20.5 GB.
//
// Physical groups: block (the volume), bottom (z = 0), top (z = 1), x0
// (x = 0) and y0 (y = 0).
SetFactory("OpenCASCADE");
If (!Exists(n))
  n = 4;
EndIf
Box(1) = {0, 0, 0, 1, 1, 1};
s() = Abs(Boundary{ Volume{1}; });
Transfinite Curve{ Unique(Abs(Boundary{ Surface{s()}; })) } = n + 1;
Transfinite Surface{s()};
Transfinite Volume{1};
// OCC box faces come as x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
Physical Volume("block") = {1};
Physical Surface("bottom") = {s(4)};
Physical Surface("top") = {s(5)};
Physical Surface("x0") = {s(0)};
Physical Surface("y0") = {s(2)};
