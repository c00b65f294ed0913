// quarter-ring.geo -- a quarter of a ring, for a roller over its cuts and
//                     its outer arc in one group (tests/cases-loads.sh)
//
// The quarter a = 10 < r < b = 20, 0 <= theta <= 90 degrees, one
// transfinite block (n = 6 * 2^level cells around, 3 * 2^level across),
// quadrangles.
//
// Physical groups: ring (surface); cut0 (theta = 0), cut1 (theta = 90
// degrees), outer (r = b), inner (r = a); held (cut0, outer and cut1: a
// curve with a corner at each end of the arc).
If (!Exists(level))
  level = 0;
EndIf
a = 10; b = 20;
n = 6 * 2^level; nr = 3 * 2^level;
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0};
Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{2, 4} = n + 1;
Transfinite Curve{1, 3} = nr + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("ring") = {1};
Physical Curve("cut0") = {1};
Physical Curve("cut1") = {3};
Physical Curve("outer") = {2};
Physical Curve("inner") = {4};
Physical Curve("held") = {1, 2, 3};
