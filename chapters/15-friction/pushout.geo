// pushout.geo -- a shaft in a hub, axisymmetric (r, z): the push-out of a
//                shrink fit
//
// The shaft 0 <= r <= a = 10 mm, 0 <= z <= 40 mm; the hub a <= r <= b =
// 20 mm, 10 <= z <= 30 mm, meshed apart (non-matching: 3 and 2 cells per
// 5 mm along the fit at level 0).
If (!Exists(level))
  level = 0;
EndIf
a = 10; b = 20; L = 40; z0 = 10; z1 = 30;
ns = 12 * 2^level;  nh = 8 * 2^level;  nr = 4 * 2^level;

Point(1) = {0, 0, 0};  Point(2) = {a, 0, 0};
Point(3) = {a, z0, 0}; Point(4) = {a, z1, 0};
Point(5) = {a, L, 0};  Point(6) = {0, L, 0};
Point(7) = {0, z1, 0}; Point(8) = {0, z0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 1};
Line(9) = {3, 8}; Line(10) = {4, 7};
Curve Loop(1) = {1, 2, 9, 8};  Plane Surface(1) = {1};
Curve Loop(2) = {-9, 3, 10, 7}; Plane Surface(2) = {2};
Curve Loop(3) = {-10, 4, 5, 6}; Plane Surface(3) = {3};
Transfinite Curve{1, 9, 10, 5} = nr + 1;
Transfinite Curve{2, 8, 4, 6} = ns / 2 + 1;
Transfinite Curve{3, 7} = ns + 1;
Transfinite Surface{1, 2, 3};

Point(11) = {a, z0, 0}; Point(12) = {b, z0, 0};
Point(13) = {b, z1, 0}; Point(14) = {a, z1, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(4) = {11, 12, 13, 14}; Plane Surface(4) = {4};
Transfinite Curve{11, 13} = nr + 1;
Transfinite Curve{12, 14} = nh + 1;
Transfinite Surface{4};

Physical Surface("shaft") = {1, 2, 3};
Physical Surface("hub") = {4};
Physical Curve("shaft_fit") = {3};
Physical Curve("shaft_top") = {5};
Physical Curve("hub_bore") = {14};
Physical Curve("hub_bottom") = {11};
