// hertz-flat-hex.geo -- the elastic flat of the 3D Hertz test, hexahedra
//
// The block [0, B] x [0, B] x [-B, 0], B = R = 10 mm (20 a0, a0 = 0.5
// mm the order of the Hertz radius of the scenes), a quarter model
// symmetric about x = 0 and y = 0, its top z = 0 touching the sphere of
// hertz-sphere-hex.geo at the origin.  Structured (transfinite): n = 8 +
// 3 * level cells along every edge, in a geometric progression from h0 /
// 1.3 at the origin's side (h0 that of hertz-sphere-hex.geo) to the far
// side, so that the nodes of the two bodies do not match and the block,
// the slave, is the finer; hexahedra with the scene's hex20 or hex27.
// Tetrahedra of the same body: hertz-flat.geo.
// Physical groups: block (volume), block_x0 (x = 0), block_y0 (y = 0),
// bottom (z = -B), face (z = 0, the contact side).
SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
B = 10;
a0 = 0.5;
n = 8 + 3 * level;
h0 = a0 / (3 * 1.5^level) / 1.3;
// the ratio r of the progression: h0 (r^n - 1) / (r - 1) = B (bisection)
rlo = 1;
rhi = 3;
For it In {1:80}
  r = 0.5 * (rlo + rhi);
  If (h0 * (r^n - 1) / (r - 1) > B)
    rhi = r;
  Else
    rlo = r;
  EndIf
EndFor
Box(1) = {0, 0, -B, B, B, B};
e = 1e-6 * B;
// every edge runs along x, y or z: finest at its end nearer the origin
cu() = Abs(Boundary{ Surface{ Abs(Boundary{ Volume{1}; }) }; });
cu() = Unique(cu());
For j In {0 : #cu() - 1}
  pe() = PointsOf{ Curve{cu(j)}; };
  P0[] = Point{pe(0)};
  P1[] = Point{pe(1)};
  k = 0;
  If (Fabs(P1[1] - P0[1]) > Fabs(P1[k] - P0[k]))
    k = 1;
  EndIf
  If (Fabs(P1[2] - P0[2]) > Fabs(P1[k] - P0[k]))
    k = 2;
  EndIf
  If (Fabs(P0[k]) < Fabs(P1[k]))
    Transfinite Curve{cu(j)} = n + 1 Using Progression r;
  Else
    Transfinite Curve{cu(j)} = n + 1 Using Progression 1 / r;
  EndIf
EndFor
fa() = Abs(Boundary{ Volume{1}; });
Transfinite Surface{fa()};
Transfinite Volume{1};
sx[] = Surface In BoundingBox{-e, -e, -B - e, e, B + e, e};
sy[] = Surface In BoundingBox{-e, -e, -B - e, B + e, e, e};
sb[] = Surface In BoundingBox{-e, -e, -B - e, B + e, B + e, -B + e};
sf[] = Surface In BoundingBox{-e, -e, -e, B + e, B + e, e};
Physical Volume("block") = {1};
Physical Surface("block_x0") = {sx[]};
Physical Surface("block_y0") = {sy[]};
Physical Surface("bottom") = {sb[]};
Physical Surface("face") = {sf[]};
