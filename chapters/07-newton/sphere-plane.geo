// sphere-plane.geo -- a quarter of a ball pressed on a rigid plane (3D)
//
// The part x >= 0, y >= 0, z <= R of the ball of radius R = 10 mm centred
// at (0, 0, R): it touches the plane z = 0 at the origin.  Mesh size
// h = R / (16 * 2^level) within R / 5 of the contact point, growing to
// min(8 h, R / 4) at a distance R;
// tetrahedra.
// Physical groups: body (volume), symx (x = 0), symy (y = 0), top (z = R),
// sphere (the curved side, where the contact is).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
h = R / (16 * 2^level);
H = 8 * h;
If (H > R / 4)
  H = R / 4;
EndIf
Sphere(1) = {0, 0, R, R};
Box(2) = {0, 0, 0, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6 * R;
sx[] = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
sy[] = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
st[] = Surface In BoundingBox{-e, -e, R - e, R + e, R + e, R + e};
all[] = Boundary{ Volume{3}; };
ss[] = {};
For i In {0 : #all[] - 1}
  s = Abs(all[i]);
  If (s != sx[0] && s != sy[0] && s != st[0])
    ss[] += s;
  EndIf
EndFor
MeshSize{ PointsOf{ Volume{3}; } } = H;
p0[] = Point In BoundingBox{-e, -e, -e, e, e, e};
Field[1] = Distance;
Field[1].PointsList = {p0[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = R / 5;
Field[2].DistMax = R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Physical Volume("body") = {3};
Physical Surface("symx") = {sx[]};
Physical Surface("symy") = {sy[]};
Physical Surface("top") = {st[]};
Physical Surface("sphere") = {ss[]};
