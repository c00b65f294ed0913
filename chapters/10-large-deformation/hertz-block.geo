// hertz-block.geo -- the elastic flat of the 2D Hertz test
//
// The block 0 <= x <= R, -R <= y <= 0 (R = 10 mm = 50 a0, a0 = 0.2 mm
// the Hertz half-width of the scenes), symmetric about x = 0, its top
// y = 0 touching the cylinder of hertz-cylinder.geo at the origin.  Mesh
// size h / 1.3 near the contact (h that of hertz-cylinder.geo), so that
// the nodes of the two bodies do not match and the block, the slave,
// is the finer; the same growth to R / 8.
// Physical groups: block (surface), block_axis (x = 0), bottom (y = -R),
// face (y = 0, the contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
a0 = 0.2;
h = a0 / (2 * 2^level) / 1.3;
H = R / 8;
Rectangle(1) = {0, -R, 0, R, R};
e = 1e-6 * R;
face[] = Curve In BoundingBox{-e, -e, -e, R + e, e, e};
bottom[] = Curve In BoundingBox{-e, -R - e, -e, R + e, -R + e, e};
axis[] = Curve In BoundingBox{-e, -R - e, -e, e, e, e};
p0[] = Point In BoundingBox{-e, -e, -e, e, e, e};
Field[1] = Distance;
Field[1].PointsList = {p0[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 2 * a0;
Field[2].DistMax = 2 * a0 + 4 * H;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Surface("block") = {1};
Physical Curve("block_axis") = {axis[]};
Physical Curve("bottom") = {bottom[]};
Physical Curve("face") = {face[]};
