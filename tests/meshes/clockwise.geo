// Unit square whose curve loop turns clockwise: gmsh 4.8 makes every
// triangle clockwise (det J < 0).  t040 flips or rejects them.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {-4, -3, -2, -1};   // clockwise
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3;
Physical Surface("body") = {1};
Physical Curve("bottom") = {1};
Physical Curve("left") = {4};
