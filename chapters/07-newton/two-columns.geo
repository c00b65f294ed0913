// two-columns.geo -- two columns over a base, one touching, one 5 mm above
//
// The base [0, 40] x [0, 10] (nb = 4 * 2^level cells across: facets of
// 10 / 2^level mm); column A [4, 10] x [10, 30] stands on it, column B
// [24, 30] x [15, 35] stands 5 mm above it (nc = 3 * 2^level cells across:
// facets of 2 / 2^level mm).  From level 2 on, every facet near column B
// is shorter than its gap, so a pairing within one facet size does not see
// column B at all (chapter 07, no silent penetration).
//
// Physical groups: base, columns (surfaces); base_bottom, base_top,
// columns_bottom (the two bottoms), a_bottom, b_bottom (each bottom
// alone: one contact pair per column, two-columns-pairs.scene),
// columns_top (the two tops), a_corner, b_corner (the top-left corner of
// each column).
If (!Exists(level))
  level = 0;
EndIf
nb = 4 * 2^level;
nc = 3 * 2^level;
nh = 2 * 2^level;

Point(1) = {0, 0, 0};    Point(2) = {40, 0, 0};
Point(3) = {40, 10, 0};  Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {4, 10, 0};   Point(6) = {10, 10, 0};
Point(7) = {10, 30, 0};  Point(8) = {4, 30, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Point(9) = {24, 15, 0};  Point(10) = {30, 15, 0};
Point(11) = {30, 35, 0}; Point(12) = {24, 35, 0};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 12}; Line(12) = {12, 9};
Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(3) = {3};

Transfinite Curve{1, 3} = nb + 1;
Transfinite Curve{2, 4} = nh + 1;
Transfinite Curve{5, 7, 9, 11} = nc + 1;
Transfinite Curve{6, 8, 10, 12} = 3 * nc + 1;
Transfinite Surface{1, 2, 3};

Physical Surface("base") = {1};
Physical Surface("columns") = {2, 3};
Physical Curve("base_bottom") = {1};
Physical Curve("base_top") = {3};
Physical Curve("columns_bottom") = {5, 9};
Physical Curve("a_bottom") = {5};
Physical Curve("b_bottom") = {9};
Physical Curve("columns_top") = {7, 11};
Physical Point("a_corner") = {8};
Physical Point("b_corner") = {12};
