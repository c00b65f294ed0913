// hertz-flat.geo -- the elastic flat of the 3D Hertz test, tetrahedra
//
// The body of hertz-flat-hex.geo: the block [0, B] x [0, B] x [-B, 0],
// B = R = 10 mm, symmetric about x = 0 and y = 0, its top z = 0 touching
// the sphere of hertz-sphere.geo at the origin.  Mesh size h / 1.3 within
// a0 = 0.5 mm of the origin (h that of hertz-sphere.geo), so that the
// nodes of the two bodies do not match and the block, the slave, is the
// finer; growing by a third of the distance to B / 4 (the block is twice
// as large as the sphere's box); tetrahedra.
// Physical groups: block (volume), block_x0 (x = 0), block_y0 (y = 0),
// bottom (z = -B), face (z = 0, the contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
B = 10;
a0 = 0.5;
h = a0 / (3 * 1.5^level) / 1.3;
H = B / 4;
Box(1) = {0, 0, -B, B, B, B};
e = 1e-6 * B;
sx[] = Surface In BoundingBox{-e, -e, -B - e, e, B + e, e};
sy[] = Surface In BoundingBox{-e, -e, -B - e, B + e, e, e};
sb[] = Surface In BoundingBox{-e, -e, -B - e, B + e, B + e, -B + e};
sf[] = Surface In BoundingBox{-e, -e, -e, B + e, B + e, e};
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
Physical Volume("block") = {1};
Physical Surface("block_x0") = {sx[]};
Physical Surface("block_y0") = {sy[]};
Physical Surface("bottom") = {sb[]};
Physical Surface("face") = {sf[]};
