// stacked2d.geo -- three stacked 50 mm blocks, two non-matching interfaces
//
// The Taylor patch test of chapter 08 with a third block: lower, middle
// and upper blocks meshed independently, with 4, 3 and 5 cells per side
// at level 0 (4 + 3*level, 3 + 2*level, 5 + 3*level), so that neither
// interface has matching nodes.  The middle block is t mm high (the
// scene's [mesh] numbers = t=5): below 50 mm it has 1 + level cells
// across, thinner than one facet of its neighbours.
//
// Physical groups: lower, middle, upper (surfaces); lower_bottom (y = 0);
// lower_left, middle_left, upper_left (x = 0); lower_top, middle_bottom
// (y = 50, the first interface); middle_top, upper_bottom (y = 50 + t,
// the second); upper_top (y = 100 + t, the pressure).
If (!Exists(level))
  level = 0;
EndIf
If (!Exists(t))
  t = 50;
EndIf
L = 50;
n1 = 4 + 3 * level;
n2 = 3 + 2 * level;
n3 = 5 + 3 * level;
m2 = t < L ? 1 + level : n2;
Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};  Point(4) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {0, L, 0};  Point(6) = {L, L, 0};
Point(7) = {L, L+t, 0}; Point(8) = {0, L+t, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Point(9) = {0, L+t, 0};  Point(10) = {L, L+t, 0};
Point(11) = {L, 2*L+t, 0}; Point(12) = {0, 2*L+t, 0};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 12}; Line(12) = {12, 9};
Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(3) = {3};
Transfinite Curve{1, 2, 3, 4} = n1 + 1;
Transfinite Curve{5, 7} = n2 + 1;
Transfinite Curve{6, 8} = m2 + 1;
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
