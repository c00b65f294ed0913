// grazing2d.geo -- a block [0,50] x [50,100] for the grazing hard case
//                                        (tests/hard/grazing2d.scene)
// n = 10 * 2^level cells per side, structured.  Physical groups: block
// (surface), bottom (y = 50, the slave), top, left (x = 0).
If (!Exists(level))
  level = 0;
EndIf
n = 10 * 2^level;
Point(1) = {0, 50, 0};  Point(2) = {50, 50, 0};
Point(3) = {50, 100, 0}; Point(4) = {0, 100, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Physical Surface("block") = {1};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
