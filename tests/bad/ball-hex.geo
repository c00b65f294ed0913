// ball-hex.geo -- a ball meshed in hexahedra the naive way (tests/cases-bad.sh)
//
// gmsh's all-hex subdivision (Mesh.SubdivisionAlgorithm = 2: every
// tetrahedron cut into four hexahedra) of a ball of radius 1: cells near
// the sphere are tangled (det J changes sign inside them, with hex8 as
// with hex20).  lac must refuse the mesh and say how to mesh a ball in
// hexahedra instead.
// Physical groups: ball (volume), surface (the sphere).
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.MeshSizeMin = 0.5;
Mesh.MeshSizeMax = 0.5;
Mesh.SubdivisionAlgorithm = 2;
Physical Volume("ball") = {1};
Physical Surface("surface") = {Abs(Boundary{ Volume{1}; })};
