// sliver2d.geo -- hard case: the master ends 1e-8 h into a slave element
//                                          (tests/hard/sliver2d.scene)
//
// chapters/11-infsup/narrow2d.geo with delta = 5e-9: the upper (slave)
// block [0, 50] x [50, 100] has 4 * 2^level quad4 cells per side (h = 12.5
// at level 0), its macro-elements (pairs of segments) H = 25 / 2^level;
// the lower (master) block [0, Lm] x [0, 50], Lm = 25 + delta * H, covers
// the macro-element [25, 25 + H] on the fraction delta = 5e-9 of its
// length, i.e. 1e-8 h of its first segment.  Criterion phibar sqrt(delta)
// = delta^{3/2} = 3.5e-13.
//
// Physical groups: lower, upper (surfaces); lower_bottom, lower_left,
// lower_top (y = 50, master), upper_bottom (y = 50, slave), upper_left,
// upper_top.
If (!Exists(level))
  level = 0;
EndIf
delta = 5e-9;
nu = 4 * 2^level;
nl = 3 * 2^level;
H = 25 / 2^level;
Lm = 25 + delta * H;
L = 50;

Point(1) = {0, 0, 0};  Point(2) = {Lm, 0, 0};
Point(3) = {Lm, L, 0}; Point(4) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {0, L, 0};  Point(6) = {L, L, 0};
Point(7) = {L, 2*L, 0}; Point(8) = {0, 2*L, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Transfinite Curve{1, 2, 3, 4} = nl + 1;
Transfinite Curve{5, 6, 7, 8} = nu + 1;
Transfinite Surface{1};
Transfinite Surface{2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_left") = {4};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_left") = {8};
Physical Curve("upper_top") = {7};
