// sphere-axi.geo -- thick sphere a <= r <= b, axisymmetric model   [LAC §5.2]
//
// The meridian section of the shell: a quarter annulus in the (r, z) half
// plane, r = x >= 0, z = y >= 0 (the lower half follows by the symmetry
// z -> -z, imposed as u_z = 0 on the equator).  Built-in kernel, structured
// (transfinite) so that the same file gives triangles or, with
// Mesh.RecombineAll (lac_mesh_opts.recombine), quadrangles; with order 2 the
// mid-nodes of the arcs lie on the circles (curved quadratic geometry).
//
// Physical groups:  body (surface), inner (r = a, the pressure p acts here),
// outer (r = b), axis (r = 0: u_r = 0), equator (z = 0: u_z = 0).
// Refinement: `level` (set by lac_mesh_opts.level, default 0) doubles the
// number of cells per direction.

If (!Exists(level))
  level = 0;
EndIf
a = 20;                     // inner radius (mm)
b = 40;                     // outer radius (mm)
nr = 2 * 2^level;           // cells across the thickness
nt = 4 * 2^level;           // cells along a quarter circle

Point(1) = {0, 0, 0, 1};    // centre
Point(2) = {a, 0, 0, 1};
Point(3) = {b, 0, 0, 1};
Point(4) = {0, b, 0, 1};
Point(5) = {0, a, 0, 1};

Line(1) = {2, 3};           // equator z = 0
Circle(2) = {3, 1, 4};      // outer arc
Line(3) = {4, 5};           // axis r = 0
Circle(4) = {5, 1, 2};      // inner arc

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = nr + 1;
Transfinite Curve{2, 4} = nt + 1;
Transfinite Surface{1};

Physical Surface("body") = {1};
Physical Curve("inner") = {4};
Physical Curve("outer") = {2};
Physical Curve("axis") = {3};
Physical Curve("equator") = {1};
