// Unit cube, transfinite: tetrahedra by default, hexahedra when surfaces
// are recombined (lac_mesh_opts.recombine).  2^(level+1) cells an edge.
SetFactory("OpenCASCADE");
DefineConstant[ level = {0, Name "level"} ];
n = 2^(level + 1);
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve{:} = n + 1;
Transfinite Surface{:};
Transfinite Volume{1};
Physical Volume("body") = {1};
Physical Surface("xmin") = {1};
Physical Surface("xmax") = {2};
Physical Surface("ymin") = {3};
Physical Surface("ymax") = {4};
Physical Surface("zmin") = {5};
Physical Surface("zmax") = {6};
Physical Curve("edge") = {1};
