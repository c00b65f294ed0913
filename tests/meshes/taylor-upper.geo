// taylor-upper.geo -- the upper square of chapter 08's taylor2d.geo alone
// (tests/cases-loads.sh: a scene with one mesh file per body).
// Physical groups: upper, upper_bottom, upper_left, upper_top.
If (!Exists(level))
  level = 0;
EndIf
L = 50;
nu = 3 + 2 * level;
Point(5) = {0, L, 0};  Point(6) = {L, L, 0};
Point(7) = {L, 2*L, 0}; Point(8) = {0, 2*L, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{5, 6, 7, 8} = nu + 1;
Transfinite Surface{2};
Physical Surface("upper") = {2};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_left") = {8};
Physical Curve("upper_top") = {7};
