// turned-cube.geo -- a cube turned in space, for rollers over an edge and
//                    a vertex (tests/cases-loads.sh)
//
// The cube [0, L]^3 (L = 10, n = 3 * 2^level cells an edge, transfinite)
// turned about the origin by 30 degrees about z, then by 20 degrees about
// x: no face is normal to an axis.  Its faces x = 0, y = 0 and z = 0
// (before turning) meet at the origin: the group "held" holds all three,
// so that a roller on it has three edges and a vertex.
//
// Physical groups: body (volume); x0, x1, y0, y1, z0, z1 (the faces, named
// before turning); held (x0, y0, z0).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
L = 10;
n = 3 * 2^level;
Box(1) = {0, 0, 0, L, L, L};
Rotate {{0, 0, 1}, {0, 0, 0}, 30 * Pi / 180} { Volume{1}; }
Rotate {{1, 0, 0}, {0, 0, 0}, 20 * Pi / 180} { Volume{1}; }
Transfinite Curve{:} = n + 1;
Transfinite Surface{:};
Transfinite Volume{1};
// OCC box faces come as x = 0, x = L, y = 0, y = L, z = 0, z = L.
Physical Volume("body") = {1};
Physical Surface("x0") = {1};
Physical Surface("x1") = {2};
Physical Surface("y0") = {3};
Physical Surface("y1") = {4};
Physical Surface("z0") = {5};
Physical Surface("z1") = {6};
Physical Surface("held") = {1, 3, 5};
