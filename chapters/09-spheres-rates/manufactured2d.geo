// manufactured2d.geo -- the unit square of the 2D manufactured solution
//                                                               [LAC §5.3]
// Structured (transfinite), n = 4 * 2^level cells per side: triangles, or
// quadrangles with recombination.  Physical groups: body; bottom (y = 0,
// the contact side over the rigid foundation), left, right, top.
If (!Exists(level))
  level = 0;
EndIf
n = 4 * 2^level;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
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
