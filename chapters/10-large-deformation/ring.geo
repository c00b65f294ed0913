// ring.geo -- ring on block, a quarter of the 3D benchmark    [LAC §5.4, Table 7]
//
// A half-ring of two 5 mm layers (inner radius 85, layer interface 90,
// outer radius 95 mm: diameters 170 / 180 / 190) above a block 250 x 50 x 50
// mm, with an initial gap of 20 mm between the bottom of the ring and the
// block.  A quarter is modelled, with two symmetry planes: x = 0 (through
// the ring's top-bottom axis) and y = 0 (the mid-depth).  Axes: x along the
// block, y across (depth), z up; block top at z = 0; ring centre at
// (0, ., 115); the half-ring's ends lie in the plane z = 115; the quarter
// ring runs from its bottom (x = 0) to its end (x = 85..95).  The ring is
// as deep as the block (the paper's Figure 9 did not survive; 50 mm).
//
// Structured hexahedra (transfinite + recombine, extruded in y); the
// element order is the scene's (hex8, hex20, hex27).  `level` 0 is the
// coarse mesh, 1 the fine one (every count doubled):
//   ring   nt = 25 cells along the quarter arc, nr = 2 per layer, ny = 5
//   block  nx = 25 along x, nz = 8 in z, ny = 5
// so the slave surface (the ring's outer face) has 25 x 5 = 125 faces at
// level 0 and 500 at level 1, the numbers Table 7's counts imply (hex27
// has 1125 = 125 x 9 elements fewer than hex20 at the coarse level:
// code_aster's 6-hexahedra cut adds 5 cells and 4 faces per slave face).
// Nodes before the macro-mesh refinement: hex8 2184 / 14586, hex27
// 14586 / 106050 (Table 7: 2085 + 1000 cut nodes = 3085 / 13998 + 4000
// = 17998 for hex8; 13998 / 102114 for hex27).
//
// Physical groups:
//   volumes   ring_inner (E = 1e5), ring_outer (E = 1e3), block (E = 300)
//   surfaces  ring_contact  the outer face of the ring (slave)
//             block_top     z = 0 (master)
//             block_bottom  z = -50 (clamped)
//             ring_end      the ring's end, z = 115 (moved down)
//             ring_x0, block_x0, ring_y0, block_y0  symmetry planes
//   points    ring_mid      the inner bottom point of the ring (0, 0, 30):
//                           "the middle of the half-ring" of Figure 10
//             ring_bottom   the outer bottom point (0, 0, 20)
If (!Exists(level))
  level = 0;
EndIf
f = 2^level;
Ri = 85; Rm = 90; Ro = 95;       // radii
gap = 20;
zc = gap + Ro;                   // ring centre height
Lb = 125; Hb = 50; D = 25;       // quarter block: half length, height, half depth
nt = 25 * f; nr = 2 * f; ny = 5 * f;
nx = 25 * f; nz = 8 * f;

// the quarter ring in the plane y = 0
Point(1) = {0, 0, zc};
Point(2) = {0, 0, zc - Ri};
Point(3) = {0, 0, zc - Rm};
Point(4) = {0, 0, zc - Ro};
Point(5) = {Ri, 0, zc};
Point(6) = {Rm, 0, zc};
Point(7) = {Ro, 0, zc};
Circle(1) = {2, 1, 5};           // inner face
Circle(2) = {3, 1, 6};           // layer interface
Circle(3) = {4, 1, 7};           // outer face (contact)
Line(4) = {2, 3};
Line(5) = {3, 4};
Line(6) = {5, 6};
Line(7) = {6, 7};
Curve Loop(1) = {4, 2, -6, -1};
Plane Surface(1) = {1};          // inner layer
Curve Loop(2) = {5, 3, -7, -2};
Plane Surface(2) = {2};          // outer layer
Transfinite Curve{1, 2, 3} = nt + 1;
Transfinite Curve{4, 5, 6, 7} = nr + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

// the quarter block in the plane y = 0
Point(11) = {0, 0, -Hb};
Point(12) = {Lb, 0, -Hb};
Point(13) = {Lb, 0, 0};
Point(14) = {0, 0, 0};
Line(11) = {11, 12};             // bottom
Line(12) = {12, 13};             // x = Lb
Line(13) = {13, 14};             // top (contact)
Line(14) = {14, 11};             // x = 0
Curve Loop(3) = {11, 12, 13, 14};
Plane Surface(3) = {3};
Transfinite Curve{11, 13} = nx + 1;
Transfinite Curve{12, 14} = nz + 1;
Transfinite Surface{3};
Recombine Surface{3};

// extrusion in y: [top, volume, one lateral face per boundary curve in
// the order of the curve loop] for each surface (the shared layer
// interface is reused)
r[] = Extrude {0, D, 0} { Surface{1, 2}; Layers{ny}; Recombine; };
b[] = Extrude {0, D, 0} { Surface{3}; Layers{ny}; Recombine; };

Physical Volume("ring_inner") = {r[1]};
Physical Volume("ring_outer") = {r[7]};
Physical Volume("block") = {b[1]};
Physical Surface("ring_contact") = {r[9]};
Physical Surface("block_top") = {b[4]};
Physical Surface("block_bottom") = {b[2]};
Physical Surface("ring_end") = {r[4], r[10]};
Physical Surface("ring_x0") = {r[2], r[8]};
Physical Surface("block_x0") = {b[5]};
Physical Surface("ring_y0") = {1, 2};
Physical Surface("block_y0") = {3};
Physical Point("ring_mid") = {2};
Physical Point("ring_bottom") = {4};
