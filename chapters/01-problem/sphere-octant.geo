// sphere-octant.geo -- one eighth of the thick sphere a <= r <= b   [LAC §5.2]
//
// The octant x, y, z >= 0 of the spherical shell, cut into three
// hexahedral blocks (a "cubed sphere" octant): the spherical triangle of
// the octant is split into three quadrilaterals meeting at its centre
// (1,1,1)/sqrt(3), each swept radially from r = a to r = b.  Every block is
// transfinite, so the mesh is structured: hexahedra with Mesh.RecombineAll
// (lac_mesh_opts.recombine), tetrahedra otherwise; with order 2 the
// mid-nodes lie on the spheres (curved quadratic geometry).  All arcs are
// great circles and every radial face lies in a plane through the centre.
//
// Physical groups:  body (volume), inner (r = a, pressure), outer (r = b),
// symx (x = 0: u_x = 0), symy (y = 0: u_y = 0), symz (z = 0: u_z = 0).
// Refinement: `level` (lac_mesh_opts.level, default 0) doubles the cells.
//
// Tetrahedra: gmsh fills a transfinite volume with 6 tetrahedra per
// hexahedron in a fixed pattern and does not check that the triangles of
// the faces follow it; the Left/Right orientations of the symmetry faces
// below are the ones that match (else the symmetry triangles are faces of no
// tetrahedron, and lac_mesh_read refuses the mesh).

If (!Exists(level))
  level = 0;
EndIf
a = 20;                     // inner radius (mm)
b = 40;                     // outer radius (mm)
nr = 2 * 2^level;           // cells across the thickness
nt = 2 * 2^level;           // cells along each side of a block

Point(1) = {0, 0, 0, 1};    // centre
// Points on the sphere of radius R, tags 10*k + 1..7 for k = 1 (a), 2 (b):
// Px, Py, Pz, Mxy, Myz, Mzx (edge midpoints), C (centre of the octant).
For k In {1:2}
  R = (k == 1) ? a : b;
  s = R / Sqrt(2);
  t = R / Sqrt(3);
  Point(10*k + 1) = {R, 0, 0, 1};
  Point(10*k + 2) = {0, R, 0, 1};
  Point(10*k + 3) = {0, 0, R, 1};
  Point(10*k + 4) = {s, s, 0, 1};
  Point(10*k + 5) = {0, s, s, 1};
  Point(10*k + 6) = {s, 0, s, 1};
  Point(10*k + 7) = {t, t, t, 1};
  // great-circle arcs, tags 10*k + 1..9
  Circle(10*k + 1) = {10*k + 1, 1, 10*k + 4};   // Px  - Mxy   (z = 0)
  Circle(10*k + 2) = {10*k + 4, 1, 10*k + 2};   // Mxy - Py    (z = 0)
  Circle(10*k + 3) = {10*k + 2, 1, 10*k + 5};   // Py  - Myz   (x = 0)
  Circle(10*k + 4) = {10*k + 5, 1, 10*k + 3};   // Myz - Pz    (x = 0)
  Circle(10*k + 5) = {10*k + 3, 1, 10*k + 6};   // Pz  - Mzx   (y = 0)
  Circle(10*k + 6) = {10*k + 6, 1, 10*k + 1};   // Mzx - Px    (y = 0)
  Circle(10*k + 7) = {10*k + 4, 1, 10*k + 7};   // Mxy - C
  Circle(10*k + 8) = {10*k + 5, 1, 10*k + 7};   // Myz - C
  Circle(10*k + 9) = {10*k + 6, 1, 10*k + 7};   // Mzx - C
  // the three spherical quadrilaterals, tags 10*k + 1..3
  Curve Loop(10*k + 1) = {10*k + 1, 10*k + 7, -(10*k + 9), 10*k + 6};
  Surface(10*k + 1) = {10*k + 1} In Sphere {1};   // around Px
  Curve Loop(10*k + 2) = {10*k + 3, 10*k + 8, -(10*k + 7), 10*k + 2};
  Surface(10*k + 2) = {10*k + 2} In Sphere {1};   // around Py
  Curve Loop(10*k + 3) = {10*k + 5, 10*k + 9, -(10*k + 8), 10*k + 4};
  Surface(10*k + 3) = {10*k + 3} In Sphere {1};   // around Pz
EndFor

// Radial lines from the inner to the outer point, tags 31..37.
For j In {1:7}
  Line(30 + j) = {10 + j, 20 + j};
EndFor

// Radial plane faces, one per arc j (tags 41..49): inner arc, radial line,
// outer arc reversed, radial line reversed.
arc0[] = {1, 4, 2, 5, 3, 6, 4, 5, 6};  // start point index of arc j
arc1[] = {4, 2, 5, 3, 6, 1, 7, 7, 7};  // end point index of arc j
For j In {1:9}
  Curve Loop(40 + j) = {10 + j, 30 + arc1[j-1], -(20 + j), -(30 + arc0[j-1])};
  Plane Surface(40 + j) = {40 + j};
EndFor

// Three blocks: around Px (inner 11, outer 21, sides on arcs 1, 7, 9, 6),
// around Py (12, 22; arcs 3, 8, 7, 2), around Pz (13, 23; arcs 5, 9, 8, 4).
Surface Loop(1) = {11, 21, 41, 47, 49, 46};
Volume(1) = {1};
Surface Loop(2) = {12, 22, 43, 48, 47, 42};
Volume(2) = {2};
Surface Loop(3) = {13, 23, 45, 49, 48, 44};
Volume(3) = {3};

Transfinite Curve{11:19, 21:29} = nt + 1;
Transfinite Curve{31:37} = nr + 1;
Transfinite Surface{11:13, 21:23, 47:49};
Transfinite Surface{41, 43, 45} Left;    // triangles as the volume's
Transfinite Surface{42, 44, 46} Right;   // tetrahedra cut the hexahedra
Transfinite Volume{1:3};

Physical Volume("body") = {1, 2, 3};
Physical Surface("inner") = {11, 12, 13};
Physical Surface("outer") = {21, 22, 23};
Physical Surface("symz") = {41, 42};
Physical Surface("symx") = {43, 44};
Physical Surface("symy") = {45, 46};
