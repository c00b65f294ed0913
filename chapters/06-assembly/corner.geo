// corner.geo -- a block in the inner corner of an L-shaped body
//
// The union is a 100 mm square (dim = 2) or a 100 x 100 x 50 mm box
// (dim = 3, [mesh] numbers = dim=3): the L-shaped body is three 50 mm
// squares (cubes) with shared nodes, 4 + 3*level cells per side; the
// block fills the upper right quarter with 5 + 3*level cells, so that the
// meshes do not match.  The block's slave surface block_inner is its left
// and bottom faces, one group that turns 90 degrees at the block's corner.
//
// Physical groups: L, block; L_left (x = 0), L_bottom (y = 0), L_right
// (x = 100), L_top (y = 100), L_inner (the two inner faces of the L),
// L_z0 (3D: z = 0); block_inner, block_right, block_top, block_z0.
SetFactory("OpenCASCADE");
If (!Exists(dim))
  dim = 2;
EndIf
If (!Exists(level))
  level = 0;
EndIf
L = 50;
n1 = 4 + 3 * level;
n2 = 5 + 3 * level;
e = 1e-3;
If (dim == 2)
  Rectangle(1) = {0, 0, 0, L, L};
  Rectangle(2) = {L, 0, 0, L, L};
  Rectangle(3) = {0, L, 0, L, L};
  BooleanFragments{ Surface{1, 2, 3}; Delete; }{}
  Rectangle(4) = {L, L, 0, L, L};
  Transfinite Curve{ Unique(Abs(Boundary{ Surface{1, 2, 3}; })) } = n1 + 1;
  Transfinite Curve{ Unique(Abs(Boundary{ Surface{4}; })) } = n2 + 1;
  Transfinite Surface{1, 2, 3, 4};
  Physical Surface("L") = {1, 2, 3};
  Physical Surface("block") = {4};
  Physical Curve("L_left") = Curve In BoundingBox{-e, -e, -e, e, 2*L+e, e};
  Physical Curve("L_bottom") = Curve In BoundingBox{-e, -e, -e, 2*L+e, e, e};
  Physical Curve("L_right") = Curve In BoundingBox{2*L-e, -e, -e, 2*L+e, L+e, e};
  Physical Curve("L_top") = Curve In BoundingBox{-e, 2*L-e, -e, L+e, 2*L+e, e};
  inner() = Curve In BoundingBox{L-e, L-e, -e, 2*L+e, 2*L+e, e};
  b() = Abs(Boundary{ Surface{4}; });
  li() = {};
  For k In {0 : #inner() - 1}
    If (inner(k) != b(0) && inner(k) != b(1) && inner(k) != b(2) && inner(k) != b(3))
      li() += inner(k);
    EndIf
  EndFor
  Physical Curve("L_inner") = li();
  Physical Curve("block_inner") = {b(0), b(3)};
  Physical Curve("block_right") = {b(1)};
  Physical Curve("block_top") = {b(2)};
EndIf
If (dim == 3)
  Box(1) = {0, 0, 0, L, L, L};
  Box(2) = {L, 0, 0, L, L, L};
  Box(3) = {0, L, 0, L, L, L};
  BooleanFragments{ Volume{1, 2, 3}; Delete; }{}
  Box(4) = {L, L, 0, L, L, L};
  Transfinite Curve{ Unique(Abs(Boundary{ Surface{ Abs(Boundary{ Volume{1, 2, 3}; }) }; })) } = n1 + 1;
  Transfinite Curve{ Unique(Abs(Boundary{ Surface{ Abs(Boundary{ Volume{4}; }) }; })) } = n2 + 1;
  Transfinite Surface{ Abs(Boundary{ Volume{1, 2, 3, 4}; }) };
  Transfinite Volume{1, 2, 3, 4};
  b() = Abs(Boundary{ Volume{4}; });
  Physical Volume("L") = {1, 2, 3};
  Physical Volume("block") = {4};
  Physical Surface("L_left") = Surface In BoundingBox{-e, -e, -e, e, 2*L+e, L+e};
  Physical Surface("L_bottom") = Surface In BoundingBox{-e, -e, -e, 2*L+e, e, L+e};
  Physical Surface("L_right") = Surface In BoundingBox{2*L-e, -e, -e, 2*L+e, L+e, L+e};
  Physical Surface("L_top") = Surface In BoundingBox{-e, 2*L-e, -e, L+e, 2*L+e, L+e};
  z0() = Surface In BoundingBox{-e, -e, -e, 2*L+e, 2*L+e, e};
  inner() = Surface In BoundingBox{L-e, L-e, -e, 2*L+e, 2*L+e, L+e};
  li() = {};
  For k In {0 : #inner() - 1}
    If (inner(k) != b(0) && inner(k) != b(1) && inner(k) != b(2) && inner(k) != b(3) && inner(k) != b(4) && inner(k) != b(5))
      li() += inner(k);
    EndIf
  EndFor
  lz() = {};
  For k In {0 : #z0() - 1}
    If (z0(k) != b(4))
      lz() += z0(k);
    EndIf
  EndFor
  Physical Surface("L_inner") = li();
  Physical Surface("L_z0") = lz();
  Physical Surface("block_inner") = {b(0), b(2)};
  Physical Surface("block_right") = {b(1)};
  Physical Surface("block_top") = {b(3)};
  Physical Surface("block_z0") = {b(4)};
EndIf
