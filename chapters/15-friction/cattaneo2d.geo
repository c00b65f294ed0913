// cattaneo2d.geo -- a cylinder on a block, the whole width: Cattaneo-Mindlin
//
// The half cylinder of radius R = 10 mm (centre (0, R), the arc touching
// y = 0 at the origin; a 2R x R/2 block on its flat side, whose top y =
// 1.5 R carries the loads) on the block -2R <= x <=
// 2R, -2R <= y <= 0, meshed apart (non-matching), each refined near the
// origin to h = a0 / 2^level over |x| <= 2 a0, |y| <= a0 (a0 = 0.03 mm,
// about the half-width of the contact; [mesh] numbers = "a0=..." for another load),
// the size growing by half the distance beyond, up to R / 3.  Groups: cylinder, block (surfaces); arc
// (the cylinder's contact side), top (its top face) and corner (its end
// x = R), face (the block's top), bottom (the block's bottom).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
R = 10;
If (!Exists(a0))
  a0 = 0.03;
EndIf
h = a0 / 2 / 2^level;             // halved by the subdivision
H = R / 3;
e = 1e-6 * R;

// the cylinder: the lower half disk of centre (0, R) under a 2R x R/2
// block, whose top face carries the loads (a rigid plate that does not
// touch the contact arc)
Disk(1) = {0, R, 0, R, R};
Rectangle(2) = {-R - 1, R, 0, 2 * R + 2, R + 1};
BooleanDifference(5) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Rectangle(6) = {-R, R, 0, 2 * R, R / 2};
cyl[] = BooleanFragments{ Surface{5}; Delete; }{ Surface{6}; Delete; };
// the block
Rectangle(4) = {-2 * R, -2 * R, 0, 4 * R, 2 * R};

arc[] = Curve In BoundingBox{-R - e, -e, -e, R + e, R + e, e};
arc[] -= {Curve In BoundingBox{-R - e, R - e, -e, R + e, R + e, e}};
top[] = Curve In BoundingBox{-R - e, 1.5 * R - e, -e, R + e, 1.5 * R + e, e};
face[] = Curve In BoundingBox{-2 * R - e, -e, -e, 2 * R + e, e, e};
bottom[] = Curve In BoundingBox{-2 * R - e, -2 * R - e, -e, 2 * R + e,
                                -2 * R + e, e};
corner[] = Point In BoundingBox{R - e, 1.5 * R - e, -e, R + e, 1.5 * R + e,
                                e};

// the size: h in the ellipse x^2 / 4 + y^2 < a0^2 around the contact,
// then growing by half the (elliptic) distance, up to H
Field[1] = MathEval;
Field[1].F = Sprintf("min(%g, max(%g, %g + 0.5 * (Sqrt(x * x / 4 + y * y) - %g)))",
                     H, h, h, a0);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.SubdivisionAlgorithm = 1;    // every cell split into quadrangles
                                  // (the recombination leaves triangles)

Physical Surface("cylinder") = {cyl[]};
Physical Surface("block") = {4};
Physical Curve("arc") = {arc[]};
Physical Curve("top") = {top[]};
Physical Curve("face") = {face[]};
Physical Curve("bottom") = {bottom[]};
Physical Point("corner") = {corner[]};
