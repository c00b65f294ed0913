// beam.geo -- a 10 x 1 plane-strain beam for the load cases
// (tests/cases-loads.sh).  Physical groups: body (surface), left
// (x = 0), right (x = 10), top (y = 1); points tip (10, 1) and ends (the
// two left corners: a point group of two points).
h = 0.25;
Point(1) = {0, 0, 0, h};
Point(2) = {10, 0, 0, h};
Point(3) = {10, 1, 0, h};
Point(4) = {0, 1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("body") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Point("tip") = {3};
Physical Point("ends") = {1, 4};
