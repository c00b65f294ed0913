// Unit square for the mesh tests (t040).  `level' (given by lac_mesh_read,
// 0 when run from the command line) refines: 2^(level+1) segments a side.
DefineConstant[ level = {0, Name "level"} ];
n = 2^(level + 1);
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};       // counter-clockwise
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Physical Surface("body") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Point("origin") = {1};
Physical Point(7) = {3};            // unnamed: read as "0:7"
