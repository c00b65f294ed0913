// hertz-sphere.geo -- the sphere of the 3D Hertz test, tetrahedra
//
// The body of hertz-sphere-hex.geo: the part of the ball of radius R =
// 10 mm centred at (0, 0, R) inside the box [0, L]^3, L = R / 2, touching
// z = 0 at the origin (a quarter model, symmetric about x = 0 and y = 0).
// Mesh size h = a0 / (3 * 1.5^level) within a0 = 0.5 mm (the order of the
// Hertz radius) of the origin, growing linearly (by a third of the
// distance) to L / 4; tetrahedra.
// Physical groups: sphere_body (volume), sphere_x0 (x = 0), sphere_y0
// (y = 0), top (z = L), sphere (the contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
L = R / 2;
a0 = 0.5;
h = a0 / (3 * 1.5^level);
H = L / 4;
Sphere(1) = {0, 0, R, R};
Rotate {{1, 0, 0}, {0, 0, R}, Pi / 2} { Volume{1}; }
Box(2) = {0, 0, 0, L, L, L};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6 * R;
fa() = Abs(Boundary{ Volume{3}; });
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
p0[] = Point In BoundingBox{-e, -e, -e, e, e, e};
Field[1] = Distance;
Field[1].PointsList = {p0[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = a0;
Field[2].DistMax = a0 + 3 * H;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Volume("sphere_body") = {3};
Physical Surface("sphere_x0") = {sx[]};
Physical Surface("sphere_y0") = {sy[]};
Physical Surface("top") = {st[]};
Physical Surface("sphere") = {ss[]};
