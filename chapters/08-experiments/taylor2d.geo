// taylor2d.geo -- Taylor patch test, two 50 mm squares          [LAC §5.1]
//
// Two squares meshed independently (no shared nodes): the lower one with
// nl = 4 + 3*level cells per side, the upper one with nu = 3 + 2*level, so
// the interface meshes do not match, their nodes coincide only at the ends
// (nl and nu have no common divisor) and the mesh-size ratio is >= 4/3.
// Given a number n ([mesh] numbers = n:500), the squares have n and n - 1
// cells per side instead, whatever the level (bench/crossover.sh).
// Structured (transfinite): triangles, or quadrangles with recombination.
//
// Physical groups: lower, upper (surfaces); lower_bottom (y = 0),
// lower_left, upper_left (x = 0), lower_top, upper_bottom (y = 50, the
// contact interface), upper_top (y = 100, the pressure).
If (!Exists(level))
  level = 0;
EndIf
L = 50;
nl = 4 + 3 * level;
nu = 3 + 2 * level;
If (Exists(n))
  nl = n;
  nu = n - 1;
EndIf

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
Physical Curve("lower_left") = {4};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_left") = {8};
Physical Curve("upper_top") = {7};
