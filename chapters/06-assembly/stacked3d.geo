// stacked3d.geo -- three stacked 50 mm cubes, two non-matching interfaces
//
// stacked2d.geo in 3D: 4, 3 and 5 cells per edge at level 0, the middle
// cube t mm high ([mesh] numbers = t=5: 1 + level cells across).
// Structured (transfinite): tetrahedra, or hexahedra with recombination.
//
// Physical groups: lower, middle, upper (volumes); NAME_x0, NAME_y0 the
// symmetry planes of each; lower_bottom (z = 0); lower_top and
// middle_bottom, middle_top and upper_bottom (the interfaces); upper_top.
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(t))
  t = 50;
EndIf
L = 50;
n1 = 4 + 3 * level;
n2 = 3 + 2 * level;
n3 = 5 + 3 * level;
m2 = t < L ? 1 + level : n2;
e = 1e-6;
Box(1) = {0, 0, 0, L, L, L};
Box(2) = {0, 0, L, L, L, t};
Box(3) = {0, 0, L + t, L, L, L};
c1() = Abs(Boundary{ Volume{1}; });
c2() = Abs(Boundary{ Volume{2}; });
c3() = Abs(Boundary{ Volume{3}; });
Transfinite Curve{ Unique(Abs(Boundary{ Surface{c1()}; })) } = n1 + 1;
Transfinite Curve{ Unique(Abs(Boundary{ Surface{c2()}; })) } = m2 + 1;
Transfinite Curve{ Unique(Abs(Boundary{ Surface{c2(4), c2(5)}; })) } = n2 + 1;
Transfinite Curve{ Unique(Abs(Boundary{ Surface{c3()}; })) } = n3 + 1;
Transfinite Surface{c1()};
Transfinite Surface{c2()};
Transfinite Surface{c3()};
Transfinite Volume{1};
Transfinite Volume{2};
Transfinite Volume{3};
Physical Volume("lower") = {1};
Physical Volume("middle") = {2};
Physical Volume("upper") = {3};
Physical Surface("lower_x0") = {c1(0)};
Physical Surface("lower_y0") = {c1(2)};
Physical Surface("lower_bottom") = {c1(4)};
Physical Surface("lower_top") = {c1(5)};
Physical Surface("middle_x0") = {c2(0)};
Physical Surface("middle_y0") = {c2(2)};
Physical Surface("middle_bottom") = {c2(4)};
Physical Surface("middle_top") = {c2(5)};
Physical Surface("upper_x0") = {c3(0)};
Physical Surface("upper_y0") = {c3(2)};
Physical Surface("upper_bottom") = {c3(4)};
Physical Surface("upper_top") = {c3(5)};
