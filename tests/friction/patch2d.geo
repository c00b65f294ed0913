// patch2d.geo -- the frictional patch test in 2D: two 50 mm squares
//
// taylor2d.geo's two squares (nl = 4 + 3 level and nu = 3 + 2 level cells
// per side: non-matching interface meshes) with every side of both in a
// group of its own and the corners (0, 0) and (50, 0) as points.
If (!Exists(level))
  level = 0;
EndIf
L = 50;
nl = 4 + 3 * level;
nu = 3 + 2 * level;

Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};  Point(4) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {0, L, 0};  Point(6) = {L, L, 0};
Point(7) = {L, 2*L, 0}; Point(8) = {0, 2*L, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Transfinite Curve{1, 2, 3, 4} = nl + 1;
Transfinite Curve{5, 6, 7, 8} = nu + 1;
Transfinite Surface{1};
Transfinite Surface{2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_right") = {2};
Physical Curve("lower_top") = {3};
Physical Curve("lower_left") = {4};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_right") = {6};
Physical Curve("upper_top") = {7};
Physical Curve("upper_left") = {8};
Physical Point("origin") = {1};
Physical Point("right_foot") = {2};
