// hertz-sphere-hex.geo -- the sphere of the 3D Hertz test, hexahedra
//
// The body is the part of the ball of radius R = 10 mm centred at
// (0, 0, R) inside the box [0, L] x [0, L] x [0, L], L = R / 2: a quarter
// model (symmetric about x = 0 and y = 0) whose bottom is the sphere,
// touching z = 0 at the origin, and whose top z = L carries the load.
// Topologically a hexahedron (six faces, four corners each), so the mesh
// is structured (transfinite): n = 6 + 3 * level cells along every edge,
// in a geometric progression from h0 = a0 / (3 * 1.5^level) at the
// origin's side (a0 = 0.5 mm, the order of the Hertz radius of the
// scenes) to the far side; hexahedra with the scene's hex20 or hex27.
// Why not a whole ball: gmsh's all-hex meshes of a ball (subdivision of
// tetrahedra) are tangled near the surface, and a transfinite ball needs
// several blocks (a "cubed sphere", spheres3d.geo); the contact sees only
// the sphere near the pole.  The sphere is turned so that OpenCASCADE's
// poles and seam (where its parametrization is singular) lie outside the
// box.  Tetrahedra of the same body: hertz-sphere.geo.
// Physical groups: sphere_body (volume), sphere_x0 (x = 0), sphere_y0
// (y = 0), top (z = L), sphere (the contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
L = R / 2;
a0 = 0.5;
n = 6 + 3 * level;
h0 = a0 / (3 * 1.5^level);
// the ratio r of the progression: h0 (r^n - 1) / (r - 1) = L (bisection)
rlo = 1;
rhi = 3;
For it In {1:80}
  r = 0.5 * (rlo + rhi);
  If (h0 * (r^n - 1) / (r - 1) > L)
    rhi = r;
  Else
    rlo = r;
  EndIf
EndFor
Sphere(1) = {0, 0, R, R};
Rotate {{1, 0, 0}, {0, 0, R}, Pi / 2} { Volume{1}; }
Box(2) = {0, 0, 0, L, L, L};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6 * R;
// every edge runs along x, y or z: finest at its end nearer the origin
cu() = Abs(Boundary{ Surface{ Abs(Boundary{ Volume{3}; }) }; });
cu() = Unique(cu());
For j In {0 : #cu() - 1}
  pe() = PointsOf{ Curve{cu(j)}; };
  P0[] = Point{pe(0)};
  P1[] = Point{pe(1)};
  k = 0;
  If (Fabs(P1[1] - P0[1]) > Fabs(P1[k] - P0[k]))
    k = 1;
  EndIf
  If (Fabs(P1[2] - P0[2]) > Fabs(P1[k] - P0[k]))
    k = 2;
  EndIf
  If (P0[k] < P1[k])
    Transfinite Curve{cu(j)} = n + 1 Using Progression r;
  Else
    Transfinite Curve{cu(j)} = n + 1 Using Progression 1 / r;
  EndIf
EndFor
fa() = Abs(Boundary{ Volume{3}; });
Transfinite Surface{fa()};
Transfinite Volume{3};
sx[] = Surface In BoundingBox{-e, -e, -e, e, L + e, L + e};
sy[] = Surface In BoundingBox{-e, -e, -e, L + e, e, L + e};
st[] = Surface In BoundingBox{-e, -e, L - e, L + e, L + e, L + e};
ss[] = {};
For i In {0 : #fa() - 1}
  bb[] = BoundingBox Surface{fa(i)};
  If (bb[5] - bb[2] > e && bb[3] - bb[0] > e && bb[4] - bb[1] > e)
    ss[] += fa(i);
  EndIf
EndFor
Physical Volume("sphere_body") = {3};
Physical Surface("sphere_x0") = {sx[]};
Physical Surface("sphere_y0") = {sy[]};
Physical Surface("top") = {st[]};
Physical Surface("sphere") = {ss[]};
