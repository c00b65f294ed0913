// overhang.geo -- a block that overhangs the end of another
//                                           (tests/bad/nts-overhang.scene)
//
// The lower block [0, 10] x [0, 2], the upper one [8, 12] x [2, 4]: the
// right half of the upper block's bottom lies beyond the end of the lower
// block's top.  Quadrangles, 4 x 2^level cells across the upper block,
// 8 x 2^level across the lower one (the nodes do not match).
// Physical groups: lower, upper (surfaces); lower_bottom, lower_top,
// upper_bottom, upper_top.
If (!Exists(level))
  level = 0;
EndIf
n = 2^level;
Point(1) = {0, 0, 0};  Point(2) = {10, 0, 0};
Point(3) = {10, 2, 0}; Point(4) = {0, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {8, 2, 0};  Point(6) = {12, 2, 0};
Point(7) = {12, 4, 0}; Point(8) = {8, 4, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 8 * n + 1;
Transfinite Curve{2, 4} = 2 * n + 1;
Transfinite Curve{5, 7} = 5 * n + 1;
Transfinite Curve{6, 8} = 2 * n + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_top") = {7};
