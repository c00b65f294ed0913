// strips.geo -- two stacked strips of squares for the memory estimates of
// `lac infsup` (tests/cases-bad.sh, tests/bad/strips.scene)
//
// A lower strip of nx x ny unit squares and an upper one of (nx - 1) x ny
// squares of side nx / (nx - 1), both transfinite (the size estimate is
// then exact): (nx + 1)(ny + 1) + nx (ny + 1) nodes, and about nx - 1
// multipliers on the upper strip's bottom.
//
// Physical groups: lower, upper (surfaces); lower_bottom, lower_top,
// upper_bottom (the contact pair), upper_top; lower_left, upper_left.
If (!Exists(nx))
  nx = 10;
EndIf
If (!Exists(ny))
  ny = 1;
EndIf
Point(1) = {0, 0, 0};  Point(2) = {nx, 0, 0};
Point(3) = {nx, ny, 0}; Point(4) = {0, ny, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {0, ny, 0};  Point(6) = {nx, ny, 0};
Point(7) = {nx, 2 * ny, 0}; Point(8) = {0, 2 * ny, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4, 6, 8} = ny + 1;
Transfinite Curve{5, 7} = nx;
Transfinite Surface{1};
Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("lower_left") = {4};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_top") = {7};
Physical Curve("upper_left") = {8};
