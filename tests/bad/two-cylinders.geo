// two-cylinders.geo -- two equal half cylinders touching at the origin
//                                    (tests/bad/cylinders-sliding.scene)
//
// The lower half disk, centre (0, -R), its arc upwards; the upper one,
// centre (0, R), its arc downwards; R = 10, meshed independently (finer
// near the origin: the two meshes do not match), quadrangles.
// Physical groups: lower, upper (surfaces); lower_arc, upper_arc,
// bottom (y = -R), top (y = R).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
h = R / (4 * 2^level);
// lower half disk, centre (0,-R), its arc on top touching the origin
Point(1) = {-R, -R, 0}; Point(2) = {R, -R, 0}; Point(3) = {0, -R, 0}; Point(4) = {0, 0, 0};
Circle(1) = {2, 3, 4}; Circle(2) = {4, 3, 1}; Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
// upper half disk, centre (0,R)
Point(11) = {R, R, 0}; Point(12) = {-R, R, 0}; Point(13) = {0, R, 0}; Point(14) = {0, 0, 0};
Circle(11) = {12, 13, 14}; Circle(12) = {14, 13, 11}; Line(13) = {11, 12};
Curve Loop(2) = {11, 12, 13}; Plane Surface(2) = {2};
MeshSize{ PointsOf{ Surface{1, 2}; } } = 4 * h;
MeshSize{ 4 } = h / 4;
MeshSize{ 14 } = 1.5 * h / 4;
Mesh.RecombineAll = 1;
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_arc") = {1, 2};
Physical Curve("upper_arc") = {11, 12};
Physical Curve("bottom") = {3};
Physical Curve("top") = {13};
