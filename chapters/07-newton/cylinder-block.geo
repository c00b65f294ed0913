// cylinder-block.geo -- half a cylinder pressed on an elastic block (2D)
//
// The quarter disk of cylinder-flat.geo (radius R = 10 mm, touching y = 0
// at the origin) above the block 0 <= x <= 2R, -R <= y <= 0; symmetric
// about x = 0.  The two bodies are meshed independently (no shared node
// on y = 0): the disk with size R / (4 * 2^level) near the contact, the
// block with sizes 1.5 times that near the contact, so that the nodes do
// not match; quadrilaterals (recombined).
// Physical groups: disk, block (surfaces), disk_axis, block_axis (x = 0),
// top (y = R), bottom (y = -R), arc (the contact side of the disk), face
// (y = 0, the contact side of the block).
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
Point(11) = {0, -R, 0};
Point(12) = {2 * R, -R, 0};
Point(13) = {2 * R, 0, 0};
Point(14) = {0, 0, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
MeshSize{ PointsOf{ Surface{1}; } } = 4 * h;
MeshSize{ 2 } = h / 4;
MeshSize{ PointsOf{ Surface{2}; } } = 6 * h;
MeshSize{ 14 } = 1.5 * h / 4;
Mesh.RecombineAll = 1;
Physical Surface("disk") = {1};
Physical Surface("block") = {2};
Physical Curve("disk_axis") = {1};
Physical Curve("arc") = {2};
Physical Curve("top") = {3};
Physical Curve("bottom") = {11};
Physical Curve("face") = {13};
Physical Curve("block_axis") = {14};
