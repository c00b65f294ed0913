// shrink-fit.geo -- two concentric rings, a sector of them    (chapter 16, 5)
//
// An inner ring a < r < b and an outer ring b < r < c, drawn with the same
// radius b at the interface (the interference is the scene's [contact]
// interference, not the drawing), cut to the sector 0 <= theta <= angle
// (degrees, the number `angle`, 90 by default: a quarter).  Meshed
// independently, so that the interface meshes do not match: around the
// sector the inner ring has 8*2^level cells, the outer 6*2^level; across,
// 2*2^level each.  Quadrangles with recombination, or triangles.
//
// Physical groups: inner, outer (surfaces); inner_contact, outer_contact
// (r = b of each ring); cut0 (theta = 0, both rings), cut1 (theta =
// angle, both rings); inner_free (r = a), outer_free (r = c).
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(angle))
  angle = 90;
EndIf
a = 10; b = 20; c = 30;
t = angle * Pi / 180;
ni = 8 * 2^level;
no = 6 * 2^level;
nr = 2 * 2^level;

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};          Point(3) = {b, 0, 0};
Point(4) = {a*Cos(t), a*Sin(t), 0};  Point(5) = {b*Cos(t), b*Sin(t), 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 5};
Line(3) = {5, 4};
Circle(4) = {4, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(6) = {b, 0, 0};          Point(7) = {c, 0, 0};
Point(8) = {b*Cos(t), b*Sin(t), 0};  Point(9) = {c*Cos(t), c*Sin(t), 0};
Line(5) = {6, 7};
Circle(6) = {7, 1, 9};
Line(7) = {9, 8};
Circle(8) = {8, 1, 6};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Transfinite Curve{1, 3} = nr + 1;
Transfinite Curve{2, 4} = ni + 1;
Transfinite Curve{5, 7} = nr + 1;
Transfinite Curve{6, 8} = no + 1;
Transfinite Surface{1};
Transfinite Surface{2};

Physical Surface("inner") = {1};
Physical Surface("outer") = {2};
Physical Curve("inner_contact") = {2};
Physical Curve("outer_contact") = {8};
Physical Curve("cut0") = {1, 5};
Physical Curve("cut1") = {3, 7};
Physical Curve("inner_free") = {4};
Physical Curve("outer_free") = {6};
