// interior-curve.geo -- a 2 x 1 block of two conforming squares: one body,
// with the curve between them as a physical group "mid" (inside the body).
// A load or a contact surface on "mid" is refused (tests/cases-bad.sh,
// interior-load.scene).
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {2, 0, 0, 0.5};
Point(4) = {2, 1, 0, 0.5};
Point(5) = {1, 1, 0, 0.5};
Point(6) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Physical Surface("body") = {1, 2};
Physical Curve("left") = {6};
Physical Curve("right") = {3};
Physical Curve("mid") = {7};
