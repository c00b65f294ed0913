// compound.geo -- three concentric rings, a sector of them       (chapter 16)
//
// Rings a < r < b, b < r < c and c < r < d, drawn with the same radii b and
// c at their interfaces (the interferences are the scene's), cut to the
// sector 0 <= theta <= angle (degrees, the number `angle`, 60 by default).
// Each ring is meshed on its own, so that neither interface matches:
// around the sector 8, 6 and 7 cells times 2^level, across 2 * 2^level.
//
// Physical groups: ring1, ring2, ring3 (surfaces); ring1_out, ring2_in
// (r = b), ring2_out, ring3_in (r = c); bore (r = a), rim (r = d); cut0
// (theta = 0, the three rings), cut1 (theta = angle, the three rings).
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(angle))
  angle = 60;
EndIf
a = 10; b = 20; c = 30; d = 40;
t = angle * Pi / 180;
nr = 2 * 2^level;

// ring 1: a < r < b, 8 * 2^level cells around
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};  Point(3) = {b, 0, 0};
Point(4) = {b * Cos(t), b * Sin(t), 0};
Point(5) = {a * Cos(t), a * Sin(t), 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nr + 1;
Transfinite Curve{2, 4} = 8 * 2^level + 1;
Transfinite Surface{1};

// ring 2: b < r < c, 6 * 2^level cells around
Point(11) = {0, 0, 0};
Point(12) = {b, 0, 0};  Point(13) = {c, 0, 0};
Point(14) = {c * Cos(t), c * Sin(t), 0};
Point(15) = {b * Cos(t), b * Sin(t), 0};
Line(11) = {12, 13};
Circle(12) = {13, 11, 14};
Line(13) = {14, 15};
Circle(14) = {15, 11, 12};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve{11, 13} = nr + 1;
Transfinite Curve{12, 14} = 6 * 2^level + 1;
Transfinite Surface{2};

// ring 3: c < r < d, 7 * 2^level cells around
Point(21) = {0, 0, 0};
Point(22) = {c, 0, 0};  Point(23) = {d, 0, 0};
Point(24) = {d * Cos(t), d * Sin(t), 0};
Point(25) = {c * Cos(t), c * Sin(t), 0};
Line(21) = {22, 23};
Circle(22) = {23, 21, 24};
Line(23) = {24, 25};
Circle(24) = {25, 21, 22};
Curve Loop(3) = {21, 22, 23, 24};
Plane Surface(3) = {3};
Transfinite Curve{21, 23} = nr + 1;
Transfinite Curve{22, 24} = 7 * 2^level + 1;
Transfinite Surface{3};

Physical Surface("ring1") = {1};
Physical Surface("ring2") = {2};
Physical Surface("ring3") = {3};
Physical Curve("bore") = {4};
Physical Curve("ring1_out") = {2};
Physical Curve("ring2_in") = {14};
Physical Curve("ring2_out") = {12};
Physical Curve("ring3_in") = {24};
Physical Curve("rim") = {22};
Physical Curve("cut0") = {1, 11, 21};
Physical Curve("cut1") = {3, 13, 23};
