// ring-rollers.geo -- a ring whose outer circle is cut into quarters, for
//                     rollers on arcs (tests/cases-loads.sh)
//
// The ring a = 10 < r < b = 20 about the origin, four transfinite blocks
// (one per quadrant: n = 6 * 2^level cells around each, 2 * 2^level
// across), quadrangles.
//
// Physical groups: ring (surface); inner (r = a), inner1 (its first
// quadrant); outer (r = b) and outer1 .. outer4 (its quadrants, counter-
// clockwise from the x axis).
If (!Exists(level))
  level = 0;
EndIf
a = 10; b = 20;
n = 6 * 2^level;
nr = 2 * 2^level;
Point(1) = {0, 0, 0};
For k In {0 : 3}
  t = k * Pi / 2;
  Point(2 + k) = {a * Cos(t), a * Sin(t), 0};
  Point(6 + k) = {b * Cos(t), b * Sin(t), 0};
EndFor
For k In {0 : 3}
  Circle(1 + k) = {2 + k, 1, 2 + (k + 1) % 4};
  Circle(5 + k) = {6 + k, 1, 6 + (k + 1) % 4};
  Line(9 + k) = {2 + k, 6 + k};
EndFor
For k In {0 : 3}
  Curve Loop(1 + k) = {9 + k, 5 + k, -(9 + (k + 1) % 4), -(1 + k)};
  Plane Surface(1 + k) = {1 + k};
EndFor
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = n + 1;
Transfinite Curve{9, 10, 11, 12} = nr + 1;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};
Physical Surface("ring") = {1, 2, 3, 4};
Physical Curve("inner") = {1, 2, 3, 4};
Physical Curve("inner1") = {1};
Physical Curve("outer") = {5, 6, 7, 8};
Physical Curve("outer1") = {5};
Physical Curve("outer2") = {6};
Physical Curve("outer3") = {7};
Physical Curve("outer4") = {8};
