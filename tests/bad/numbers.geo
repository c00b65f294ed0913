// numbers.geo -- box.geo with its cells per direction from the number n
// ([mesh] numbers = n=N): the counts a .geo computes from a number given
// by the scene (tests/cases-bad.sh, numbers-nan.scene).
If (!Exists(n))
  n = 2;
EndIf
Point(1) = {0, 0, 0, 1};
Point(2) = {2, 0, 0, 1};
Point(3) = {2, 1, 0, 1};
Point(4) = {0, 1, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * n + 1;
Transfinite Curve{2, 4} = n + 1;
Transfinite Surface{1};
Physical Surface("body") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
