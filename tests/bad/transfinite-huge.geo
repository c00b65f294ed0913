// transfinite-huge.geo -- box.geo with counts of 3e9 nodes on its curves:
// gmsh 4.8 makes each such count 2, and a mesh of 4 nodes was solved
// without a word; lac refuses the count with its line (tests/cases-bad.sh).
// Physical groups: body (surface), left (x = 0), right (x = 2).
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
/* Transfinite Curve{1, 3} = 5; (a comment: not read) */
Transfinite Curve{1, 2, 3, 4} = 3e9 Using Progression 1;
Transfinite Surface{1};
Physical Surface("body") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
