// spheres3d.geo -- self-included spheres, one eighth in 3D       [LAC §5.2]
//
// The octant x, y, z >= 0 of two nested thick shells: the inner body
// Omega^1, 20 <= R <= 30, and the outer body Omega^2, 30 <= R <= 40, in
// contact at R = 30.  Each shell is cut into three blocks as in
// chapters/01-problem/sphere-octant.geo (a "cubed sphere" octant): block i
// is the part of the shell around the axis i, where x_i >= the two other
// coordinates; the blocks meet on the planes x = y, y = z, z = x.  Every
// block is transfinite (structured): hexahedra with Mesh.RecombineAll
// (lac_mesh_opts.recombine), otherwise 6 tetrahedra per hexahedron; with
// order 2 the mid-nodes lie on the spheres.  The two shells are built and
// meshed independently: no shared point, curve, surface or node at R = 30.
//
// Sizes, with k = 2^level: each block of the inner shell has t1 = 2k + 1
// cells along its spherical sides, the outer one t2 = 3k + 1 (3 and 4 at
// level 0, 5 and 7, 9 and 13, ...); t1 and t2 have no common divisor
// (3 t1 - 2 t2 = 1), so the interface nodes coincide only on the symmetry
// planes and at the centre (1,1,1) R/sqrt(3) of the octant, and the
// mesh-size ratio t2/t1 is between 4/3 and 3/2: the inner shell (the slave
// of spheres3d.scene) is the coarser one.  Across the thickness both have
// ceil(3k/2) cells (2, 3, 6, 12), so that the tetrahedra stay close to
// isotropic at level 2 (radial 1.7 mm, tangential about 2.2 mm).
//
// Why OpenCASCADE.  gmsh places the mid-node of a mesh edge on a curved
// surface at the surface's closest point to the chord's midpoint.  For the
// spheres of the built-in kernel (Surface ... In Sphere, as in
// sphere-octant.geo) that projection does not take place in gmsh 4.8.4: the
// mid-node stays at the parametric midpoint, up to 2 % of the edge off the
// geodesic midpoint on the diagonals of the triangles, and the tri6 facets
// then bulge in and out of the sphere by O(h^3) (+-3e-3 mm at level 0), in a
// pattern that differs on the two sides of the interface.  LAC enforces
// the mean gap of each macro-element exactly, so this false gap shows up
// in lambda as a checkerboard (tet10, one radial cell per shell at level
// 0: 92 % error at level 0, 39 % at level 1).  OpenCASCADE projects
// exactly: every mid-node is on its sphere and at the geodesic midpoint
// (1e-14), and on the same meshes the error falls to 4.7 % and 1.3 %.
// Each shell is the difference of two spheres, intersected with three
// pyramids (apex at the origin, one over each face x_i = L of the
// cube [0, L]^3), and the three blocks are glued (BooleanFragments) to
// each other but not to the other shell.  The spheres are first rotated so
// that their poles and seam, where the (u, v) parametrization is singular,
// lie outside the octant (poles on +-(1,-1,0)/sqrt(2), seam through
// -(1,1,1)/sqrt(3)).
//
// Entities are found by position (OpenCASCADE numbers them itself): the
// block corners by bounding boxes, the boundary faces by their bounding
// boxes.  Tetrahedra: gmsh cuts every hexahedron of a transfinite volume
// along a fixed pattern of its (i, j, k) corner order and does not check
// that the triangles of the faces follow it.  The corners of each block
// are given explicitly (P_i, the midpoint of the arc towards the axis
// i + 1, the centre C, the midpoint towards i + 2; inner sphere, then
// outer), which makes the shared faces of neighbouring blocks agree; the
// spherical faces and the symmetry face through the axis i + 2 of each
// block are then triangulated "Right" to match the tetrahedra.
//
// Physical groups:
//   inner_body, outer_body          (volumes)
//   pressure        R = 20, the inner pressure p
//   inner_contact   R = 30, boundary of the inner body
//   outer_contact   R = 30, boundary of the outer body
//   outer_free      R = 40
//   inner_x0, outer_x0   x = 0 (u_x = 0);  inner_y0, outer_y0   y = 0;
//   inner_z0, outer_z0   z = 0

SetFactory("OpenCASCADE");
If (!Exists(level))
  level = 0;
EndIf
k = 2^level;
Ra[] = {20, 30};                 // inner radius of body 1, 2 (mm)
Rb[] = {30, 40};                 // outer radius of body 1, 2
nt[] = {2 * k + 1, 3 * k + 1};   // cells along each spherical block side
nr[] = {Ceil(1.5 * k), Ceil(1.5 * k)};   // cells across the thickness

For B In {0:1}
  // the shell, its poles and seam turned away from the octant
  sp1 = newv; Sphere(sp1) = {0, 0, 0, Rb[B]};
  sp0 = newv; Sphere(sp0) = {0, 0, 0, Ra[B]};
  sh() = BooleanDifference{ Volume{sp1}; Delete; }{ Volume{sp0}; Delete; };
  Rotate {{-0.06741163453054881, 0.7915486586045049, -0.6073766480457812},
          {0, 0, 0}, 2.195122867150535} { Volume{sh()}; }
  // block i = shell ∩ pyramid over the face x_i = L of the cube [0, L]^3
  L = Rb[B] + 5;
  blk() = {};
  For i In {0:2}
    For c In {0:3}                       // base corners, cyclic
      X[] = {0, 0, 0};
      X[i] = L;
      X[(i + 1) % 3] = (c == 1 || c == 2) ? L : 0;
      X[(i + 2) % 3] = (c >= 2) ? L : 0;
      bp[c] = newp; Point(bp[c]) = {X[0], X[1], X[2]};
    EndFor
    o = newp; Point(o) = {0, 0, 0};
    For c In {0:3}
      bl[c] = newl; Line(bl[c]) = {bp[c], bp[(c + 1) % 4]};
      rl[c] = newl; Line(rl[c]) = {o, bp[c]};
    EndFor
    cl = newll; Curve Loop(cl) = {bl[0], bl[1], bl[2], bl[3]};
    fs[0] = news; Plane Surface(fs[0]) = {cl};
    For c In {0:3}
      cl = newll; Curve Loop(cl) = {rl[c], bl[c], -rl[(c + 1) % 4]};
      fs[c + 1] = news; Plane Surface(fs[c + 1]) = {cl};
    EndFor
    sl = newsl; Surface Loop(sl) = {fs[0], fs[1], fs[2], fs[3], fs[4]};
    py = newv; Volume(py) = {sl};
    blk() += BooleanIntersection{ Volume{sh()}; }{ Volume{py}; Delete; };
  EndFor
  Recursive Delete { Volume{sh()}; }
  vb() = BooleanFragments{ Volume{blk()}; Delete; }{};

  // arcs (both end points on one sphere): nt cells; radial segments: nr
  fa() = Unique(Abs(Boundary{ Volume{vb()}; }));
  cu() = Unique(Abs(Boundary{ Surface{fa()}; }));
  For j In {0:#cu()-1}
    pe() = PointsOf{ Curve{cu(j)}; };
    P0[] = Point{pe(0)};
    P1[] = Point{pe(1)};
    R0 = Sqrt(P0[0]^2 + P0[1]^2 + P0[2]^2);
    R1 = Sqrt(P1[0]^2 + P1[1]^2 + P1[2]^2);
    If (Fabs(R0 - R1) < 1e-6)
      Transfinite Curve{cu(j)} = nt[B] + 1;
    Else
      Transfinite Curve{cu(j)} = nr[B] + 1;
    EndIf
  EndFor
  Transfinite Surface{fa()};

  // corners of block i: P_i, M(i, i+1), C, M(i, i+2) on the inner sphere,
  // then on the outer one; the points of this body at those places
  pv() = PointsOf{ Volume{vb()}; };
  For i In {0:2}
    For s In {0:7}
      R = (s < 4) ? Ra[B] : Rb[B];
      q = s % 4;
      D[] = {0, 0, 0};
      D[i] = 1;
      If (q == 1)
        D[(i + 1) % 3] = 1;
      EndIf
      If (q == 2)
        D[] = {1, 1, 1};
      EndIf
      If (q == 3)
        D[(i + 2) % 3] = 1;
      EndIf
      nD = Sqrt(D[0]^2 + D[1]^2 + D[2]^2);
      X[] = {R * D[0] / nD, R * D[1] / nD, R * D[2] / nD};
      cand() = Point In BoundingBox{X[0] - 1e-3, X[1] - 1e-3, X[2] - 1e-3,
                                    X[0] + 1e-3, X[1] + 1e-3, X[2] + 1e-3};
      cn[s] = -1;
      For a In {0:#cand()-1}
        For b In {0:#pv()-1}
          If (cand(a) == pv(b))
            cn[s] = cand(a);
          EndIf
        EndFor
      EndFor
      If (cn[s] < 0)
        Error("spheres3d.geo: no corner %g of block %g of body %g",
              s, i, B + 1);
      EndIf
    EndFor
    vi = -1;                             // the block holding P_i
    For a In {0:2}
      pa() = PointsOf{ Volume{vb(a)}; };
      For b In {0:#pa()-1}
        If (pa(b) == cn[0])
          vi = vb(a);
        EndIf
      EndFor
    EndFor
    Transfinite Volume{vi} = {cn[0], cn[1], cn[2], cn[3],
                              cn[4], cn[5], cn[6], cn[7]};
  EndFor

  // boundary faces by their bounding boxes
  bf() = Abs(CombinedBoundary{ Volume{vb()}; });
  sx() = {}; sy() = {}; sz() = {}; sin() = {}; sout() = {}; flip() = {};
  Rm = 0.5 * (Ra[B] + Rb[B]);
  For j In {0:#bf()-1}
    bb() = BoundingBox Surface{bf(j)};
    If (bb(3) < 1e-3)                    // x = 0; flip the one along z
      sx() += bf(j);
      If (bb(5) > 0.85 * Rb[B])
        flip() += bf(j);
      EndIf
    ElseIf (bb(4) < 1e-3)                // y = 0; flip the one along x
      sy() += bf(j);
      If (bb(3) > 0.85 * Rb[B])
        flip() += bf(j);
      EndIf
    ElseIf (bb(5) < 1e-3)                // z = 0; flip the one along y
      sz() += bf(j);
      If (bb(4) > 0.85 * Rb[B])
        flip() += bf(j);
      EndIf
    ElseIf (bb(3) < Rm && bb(4) < Rm && bb(5) < Rm)
      sin() += bf(j);                    // R = Ra
    Else
      sout() += bf(j);                   // R = Rb
    EndIf
  EndFor
  If (#sx() != 2 || #sy() != 2 || #sz() != 2 || #sin() != 3 || #sout() != 3)
    Error("spheres3d.geo: body %g: unexpected boundary faces", B + 1);
  EndIf
  Transfinite Surface{sin(), sout(), flip()} Right;

  If (B == 0)
    Physical Volume("inner_body") = {vb()};
    Physical Surface("pressure") = {sin()};
    Physical Surface("inner_contact") = {sout()};
    Physical Surface("inner_x0") = {sx()};
    Physical Surface("inner_y0") = {sy()};
    Physical Surface("inner_z0") = {sz()};
  Else
    Physical Volume("outer_body") = {vb()};
    Physical Surface("outer_contact") = {sin()};
    Physical Surface("outer_free") = {sout()};
    Physical Surface("outer_x0") = {sx()};
    Physical Surface("outer_y0") = {sy()};
    Physical Surface("outer_z0") = {sz()};
  EndIf
EndFor
