// taylor2d-rotated.geo -- the 2D Taylor patch test turned by an angle
//
// taylor2d.geo's two squares (lower 4 + 3*level cells per side, upper
// 3 + 2*level: the interface meshes do not match) turned about the origin
// by `angle` degrees (the number angle, 30 by default), so that no face
// is normal to a coordinate axis: the interface, the pressed top and the
// faces on rollers are inclined.  Same physical groups as taylor2d.geo.
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(angle))
  angle = 30;
EndIf
L = 50;
nl = 4 + 3 * level;
nu = 3 + 2 * level;
c = Cos(angle * Pi / 180);
s = Sin(angle * Pi / 180);

Point(1) = {0, 0, 0};            Point(2) = {L*c, L*s, 0};
Point(3) = {L*c - L*s, L*s + L*c, 0}; Point(4) = {-L*s, L*c, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {-L*s, L*c, 0};       Point(6) = {L*c - L*s, L*s + L*c, 0};
Point(7) = {L*c - 2*L*s, L*s + 2*L*c, 0}; Point(8) = {-2*L*s, 2*L*c, 0};
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
Physical Curve("lower_left") = {4};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_left") = {8};
Physical Curve("upper_top") = {7};
