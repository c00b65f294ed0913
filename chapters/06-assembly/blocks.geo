// blocks.geo -- five bodies, six contact pairs, crosspoints
//
// A slab A (x 30..150, y 0..30) and a wall W (x 0..30, y 30..130), both
// clamped; block B (50 mm) in the corner between them, block C (50 mm
// wide, 40 mm high) beside B on the slab, block D (50 x 30 mm) on B
// against the wall.
// Each body is meshed on its own (structured quadrangles, cells per side
// times 1 + level), with sizes chosen so that no interface has matching
// nodes.  B's bottom-left corner is a crosspoint: its bottom and its left
// face are the slave surfaces of two pairs, pressed by A and by W.
//
// Physical groups: A, W, B, C, D (surfaces); NAME_bottom, NAME_right,
// NAME_top, NAME_left of each (W has W_bottom, W_left, W_right; A has
// A_bottom and A_top).
If (!Exists(level))
  level = 0;
EndIf
k = level + 1;
// name, x0, y0, width, height, cells in x, cells in y
// A slab, W wall, B block in the corner, C block beside it, D block on B
bx[] = {30, 0, 30, 80, 30};
by[] = {0, 30, 30, 30, 80};
bw[] = {120, 30, 50, 50, 50};
bh[] = {30, 100, 50, 40, 30};
nx[] = {13, 3, 4, 5, 5};
ny[] = {3, 11, 4, 4, 3};
For b In {0 : 4}
  p = 4 * b;
  Point(p + 1) = {bx[b], by[b], 0};
  Point(p + 2) = {bx[b] + bw[b], by[b], 0};
  Point(p + 3) = {bx[b] + bw[b], by[b] + bh[b], 0};
  Point(p + 4) = {bx[b], by[b] + bh[b], 0};
  Line(p + 1) = {p + 1, p + 2};    // bottom
  Line(p + 2) = {p + 2, p + 3};    // right
  Line(p + 3) = {p + 3, p + 4};    // top
  Line(p + 4) = {p + 4, p + 1};    // left
  Curve Loop(b + 1) = {p + 1, p + 2, p + 3, p + 4};
  Plane Surface(b + 1) = {b + 1};
  Transfinite Curve{p + 1, p + 3} = k * nx[b] + 1;
  Transfinite Curve{p + 2, p + 4} = k * ny[b] + 1;
  Transfinite Surface{b + 1};
EndFor
Physical Surface("A") = {1};
Physical Surface("W") = {2};
Physical Surface("B") = {3};
Physical Surface("C") = {4};
Physical Surface("D") = {5};
Physical Curve("A_bottom") = {1};
Physical Curve("A_top") = {3};
Physical Curve("W_bottom") = {5};
Physical Curve("W_left") = {8};
Physical Curve("W_right") = {6};
Physical Curve("B_bottom") = {9};
Physical Curve("B_right") = {10};
Physical Curve("B_top") = {11};
Physical Curve("B_left") = {12};
Physical Curve("C_bottom") = {13};
Physical Curve("C_right") = {14};
Physical Curve("C_top") = {15};
Physical Curve("C_left") = {16};
Physical Curve("D_bottom") = {17};
Physical Curve("D_right") = {18};
Physical Curve("D_top") = {19};
Physical Curve("D_left") = {20};
