// transfinite-computed.geo -- box.geo with counts its script computes
// beyond 32-bit integers (6e9 and 3e9 nodes per curve): gmsh 4.8 made
// each count 2, and a mesh of 4 nodes was solved without a word; lac
// evaluates the counts and refuses them with their line
// (tests/cases-bad.sh).  With level = 0, nx = 6e9 and ny = 3e9.
// Physical groups: body (surface), left (x = 0), right (x = 2).
If (!Exists(level))
  level = 0;
EndIf
nx = 6e9 * 2^level;
ny = nx / 2;
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
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Physical Surface("body") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
