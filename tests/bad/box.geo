// box.geo -- a 2 x 1 rectangle for the command-line tests (tests/cases.sh)
//
// Physical groups: body (surface), left (x = 0), right (x = 2),
// bottom (y = 0), top (y = 1), corner (the point (0,0)).
// Refinement: `level` doubles the cells per direction.
If (!Exists(level))
  level = 0;
EndIf
n = 2 * 2^level;
Point(1) = {0, 0, 0, 1};
Point(2) = {2, 0, 0, 1};
Point(3) = {2, 1, 0, 1};
Point(4) = {0, 1, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * n + 1;
Transfinite Curve{2, 4} = n + 1;
Transfinite Surface{1};
Physical Surface("body") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Point("corner") = {1};
