// taylor-lower.geo -- the lower square of chapter 08's taylor2d.geo alone
// (tests/cases-loads.sh: a scene with one mesh file per body).
// Physical groups: lower, lower_bottom, lower_left, lower_top.
If (!Exists(level))
  level = 0;
EndIf
L = 50;
nl = 4 + 3 * level;
Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};  Point(4) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = nl + 1;
Transfinite Surface{1};
Physical Surface("lower") = {1};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_left") = {4};
Physical Curve("lower_top") = {3};
