// hertz-cylinder.geo -- half a cylinder for the 2D Hertz test
//
// The quarter disk x >= 0, x^2 + (y - R)^2 <= R^2, y <= R of radius R =
// 10 mm, touching y = 0 at the origin; symmetric about x = 0.  The Hertz
// half-width of the scenes is a0 = 0.2 mm = R / 50: the mesh size is
// h = a0 / (2 * 2^level) within 2 a0 of the contact point, growing
// linearly (by a quarter of the distance) to R / 8.  Triangles, or
// quadrangles when the scene's element asks for them.
// Physical groups: cylinder (surface), axis (x = 0), top (y = R), arc
// (the contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
a0 = 0.2;
h = a0 / (2 * 2^level);
H = R / 8;
Point(1) = {0, R, 0};
Point(2) = {0, 0, 0};
Point(3) = {R, R, 0};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {2};
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
Physical Surface("cylinder") = {1};
Physical Curve("axis") = {1};
Physical Curve("arc") = {2};
Physical Curve("top") = {3};
