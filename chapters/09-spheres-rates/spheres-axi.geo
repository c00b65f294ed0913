// spheres-axi.geo -- self-included spheres, axisymmetric model   [LAC §5.2]
//
// The meridian section (r = x >= 0, z = y >= 0) of two nested thick shells:
// the inner body Omega^1, 20 <= R <= 30, and the outer body Omega^2,
// 30 <= R <= 40 (R the distance to the centre).  Each is a structured
// (transfinite) quarter annulus, meshed independently: no shared point,
// curve or node at R = 30.  With k = 2^level, the inner body has
// n1 = 3k + 2 cells along its quarter circles and the outer one n2 = 4k + 3
// (5 and 7 at level 0, then 8 and 11, 14 and 19, 26 and 35, 50 and 67):
// n1 and n2 have no common divisor (4(3k+2) - 3(4k+3) = -1), so the
// interface nodes coincide only on the axis and the equator, and the
// mesh-size ratio n2/n1 is between 4/3 and 7/5; the inner body (the slave
// of spheres-axi.scene) is the coarser one at the interface.  Across the
// thickness: m1 = ceil(3k/2) cells in the inner body, where sigma_RR ~ 1/R^3
// is steepest, and m2 = k in the outer one (2 and 1, 3 and 2, 6 and 4, 12
// and 8, 24 and 16).  The same file gives triangles, or quadrangles with
// recombination; with order 2 the mid-nodes of the arcs lie on the circles
// (curved quadratic geometry, exact arc midpoints).
//
// Physical groups:
//   inner_body, outer_body   (surfaces)
//   pressure        R = 20, the inner pressure p
//   inner_contact   R = 30, boundary of the inner body
//   outer_contact   R = 30, boundary of the outer body
//   outer_free      R = 40
//   inner_axis, outer_axis         r = 0  (u_r = 0)
//   inner_equator, outer_equator   z = 0  (u_z = 0)
// The multipliers may live on either contact curve (the scene's slave).

If (!Exists(level))
  level = 0;
EndIf
a = 20;                      // inner radius of Omega^1 (mm)
c = 30;                      // contact radius
b = 40;                      // outer radius of Omega^2
k = 2^level;
n1 = 3 * k + 2;              // cells along a quarter circle, inner body
n2 = 4 * k + 3;              // cells along a quarter circle, outer body
m1 = Ceil(1.5 * k);          // cells across the thickness, inner body
m2 = k;                      // cells across the thickness, outer body

Point(1) = {0, 0, 0, 1};     // centre (shared only as an arc centre)

// Inner body Omega^1
Point(11) = {a, 0, 0, 1};
Point(12) = {c, 0, 0, 1};
Point(13) = {0, c, 0, 1};
Point(14) = {0, a, 0, 1};
Line(11) = {11, 12};         // equator
Circle(12) = {12, 1, 13};    // R = 30
Line(13) = {13, 14};         // axis
Circle(14) = {14, 1, 11};    // R = 20
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};

// Outer body Omega^2: its own points at R = 30 (not shared with Omega^1)
Point(21) = {c, 0, 0, 1};
Point(22) = {b, 0, 0, 1};
Point(23) = {0, b, 0, 1};
Point(24) = {0, c, 0, 1};
Line(21) = {21, 22};         // equator
Circle(22) = {22, 1, 23};    // R = 40
Line(23) = {23, 24};         // axis
Circle(24) = {24, 1, 21};    // R = 30
Curve Loop(21) = {21, 22, 23, 24};
Plane Surface(21) = {21};

Transfinite Curve{11, 13} = m1 + 1;
Transfinite Curve{12, 14} = n1 + 1;
Transfinite Curve{21, 23} = m2 + 1;
Transfinite Curve{22, 24} = n2 + 1;
Transfinite Surface{11};
Transfinite Surface{21};

Physical Surface("inner_body") = {11};
Physical Surface("outer_body") = {21};
Physical Curve("pressure") = {14};
Physical Curve("inner_contact") = {12};
Physical Curve("outer_contact") = {24};
Physical Curve("outer_free") = {22};
Physical Curve("inner_axis") = {13};
Physical Curve("outer_axis") = {23};
Physical Curve("inner_equator") = {11};
Physical Curve("outer_equator") = {21};
