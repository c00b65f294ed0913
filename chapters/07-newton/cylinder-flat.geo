// cylinder-flat.geo -- half a cylinder pressed on a rigid flat (2D)
//
// The quarter disk x >= 0, x^2 + (y - R)^2 <= R^2, y <= R of radius R =
// 10 mm, touching the flat y = 0 at the origin; symmetric about x = 0.
// Mesh size R / (4 * 2^level) along the arc near the contact, coarser
// away from it; quadrilaterals (recombined).
// Physical groups: body (surface), axis (x = 0), top (y = R), arc (the
// contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
h = R / (4 * 2^level);
Point(1) = {0, R, 0};
Point(2) = {0, 0, 0};
Point(3) = {R, R, 0};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
MeshSize{ PointsOf{ Surface{1}; } } = 4 * h;
MeshSize{ 2 } = h / 4;
Mesh.RecombineAll = 1;
Physical Surface("body") = {1};
Physical Curve("axis") = {1};
Physical Curve("arc") = {2};
Physical Curve("top") = {3};
