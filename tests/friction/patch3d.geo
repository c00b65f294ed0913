// patch3d.geo -- the frictional patch test in 3D: two 50 mm cubes
//
// taylor3d.geo's two cubes (nl = 4 + 3 level and nu = 3 + 2 level cells
// per edge: non-matching interface meshes), every face of both in a group,
// and three corners of the lower cube as points.
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
L = 50;
nl = 4 + 3 * level;
nu = 3 + 2 * level;

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

e = 1e-6;
Physical Volume("lower") = {1};
Physical Volume("upper") = {2};
Physical Surface("lower_x0") = {lc(0)};
Physical Surface("lower_x1") = {lc(1)};
Physical Surface("lower_y0") = {lc(2)};
Physical Surface("lower_y1") = {lc(3)};
Physical Surface("lower_bottom") = {lc(4)};
Physical Surface("lower_top") = {lc(5)};
Physical Surface("upper_x0") = {uc(0)};
Physical Surface("upper_x1") = {uc(1)};
Physical Surface("upper_y0") = {uc(2)};
Physical Surface("upper_y1") = {uc(3)};
Physical Surface("upper_bottom") = {uc(4)};
Physical Surface("upper_top") = {uc(5)};
Physical Point("p000") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("p100") = Point In BoundingBox{L - e, -e, -e, L + e, e, e};
Physical Point("p010") = Point In BoundingBox{-e, L - e, -e, e, L + e, e};
