// stacked2d-rotated.geo -- chapters/06-assembly/stacked2d.geo turned by an
//                          angle (tests/cases-pairs.sh, rollers and pairs)
//
// The three stacked 50 mm blocks of stacked2d.geo (4 + 3*level,
// 3 + 2*level, 5 + 3*level cells per side: neither interface has matching
// nodes) turned about the origin by `angle` degrees (30 by default), so
// that the two interfaces, the pressed top and the faces held by rollers
// are all inclined.  Same physical groups as stacked2d.geo.
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(angle))
  angle = 30;
EndIf
L = 50;
n1 = 4 + 3 * level;
n2 = 3 + 2 * level;
n3 = 5 + 3 * level;
c = Cos(angle * Pi / 180);
s = Sin(angle * Pi / 180);
// block k (0, 1, 2) is the square [0, L] x [k L, (k + 1) L] turned
For k In {0 : 2}
  p = 4 * k;
  Point(p + 1) = {-k*L*s, k*L*c, 0};
  Point(p + 2) = {L*c - k*L*s, L*s + k*L*c, 0};
  Point(p + 3) = {L*c - (k+1)*L*s, L*s + (k+1)*L*c, 0};
  Point(p + 4) = {-(k+1)*L*s, (k+1)*L*c, 0};
  Line(p + 1) = {p + 1, p + 2}; Line(p + 2) = {p + 2, p + 3};
  Line(p + 3) = {p + 3, p + 4}; Line(p + 4) = {p + 4, p + 1};
  Curve Loop(k + 1) = {p + 1, p + 2, p + 3, p + 4};
  Plane Surface(k + 1) = {k + 1};
EndFor
Transfinite Curve{1, 2, 3, 4} = n1 + 1;
Transfinite Curve{5, 6, 7, 8} = n2 + 1;
Transfinite Curve{9, 10, 11, 12} = n3 + 1;
Transfinite Surface{1};
Transfinite Surface{2};
Transfinite Surface{3};
Physical Surface("lower") = {1};
Physical Surface("middle") = {2};
Physical Surface("upper") = {3};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_left") = {4};
Physical Curve("lower_top") = {3};
Physical Curve("middle_bottom") = {5};
Physical Curve("middle_left") = {8};
Physical Curve("middle_top") = {7};
Physical Curve("upper_bottom") = {9};
Physical Curve("upper_left") = {12};
Physical Curve("upper_top") = {11};
