// disk-plate.geo -- a quarter disk with a flat top, on a block
//                                          (tests/unit/t705-run-plates.c)
//
// The quarter disk of chapters/07-newton/cylinder-block.geo (radius 10,
// touching y = 0 at the origin) cut flat at y = 8, its arc ending at
// (9.17, 6) below a short vertical side, so that its top is apart from
// its contact surface (a rigid plate may not touch one); the block
// 0 <= x <= 20, -10 <= y <= 0 below.  Meshed independently, quadrangles.
// Physical groups: disk, block (surfaces); disk_axis, block_axis (x = 0),
// arc (the disk's contact side), face (y = 0, the block's), top (y = 8),
// topcorner (the point (9.17, 8)), bottom (y = -10).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
h = R / (4 * 2^level);
s = Sqrt(R*R - 4*4);
Point(1) = {0, 8, 0};
Point(2) = {0, 0, 0};
Point(3) = {s, 6, 0};
Point(4) = {0, R, 0};
Point(5) = {s, 8, 0};
Line(1) = {1, 2};
Circle(2) = {2, 4, 3};
Line(4) = {3, 5};
Line(3) = {5, 1};
Curve Loop(1) = {1, 2, 4, 3};
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
Physical Point("topcorner") = {5};
Physical Curve("bottom") = {11};
Physical Curve("face") = {13};
Physical Curve("block_axis") = {14};
