// turned-square.geo -- a square turned by an angle, for rollers over a
//                      corner (tests/cases-loads.sh)
//
// The square [0, L] x [0, L] (L = 10, n = 4 * 2^level cells a side)
// turned about the origin by `angle` degrees (30 by default).  Its left
// and bottom sides meet at the origin at a right angle: the group "held"
// holds both, so that a roller on it has a corner.
//
// Physical groups: body (surface); bottom (y = 0 before turning), right,
// top, left; held (left and bottom).
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(angle))
  angle = 30;
EndIf
L = 10;
n = 4 * 2^level;
c = Cos(angle * Pi / 180);
s = Sin(angle * Pi / 180);
Point(1) = {0, 0, 0};
Point(2) = {L*c, L*s, 0};
Point(3) = {L*c - L*s, L*s + L*c, 0};
Point(4) = {-L*s, L*c, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Physical Surface("body") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("held") = {1, 4};
