// A square in the plane z = 1: 2D cells off the plane z = 0 (rejected).
Point(1) = {0, 0, 1};
Point(2) = {1, 0, 1};
Point(3) = {1, 1, 1};
Point(4) = {0, 1, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
