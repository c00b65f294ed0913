/* lac_mesh_gmsh_estimate.h -- how large a .geo mesh will be, before it
 * is made                                                        [LAC §2]
 *
 * `level = 12` asks a .geo of lac's chapters for 2^12 times more cells per
 * edge than level 0: billions of nodes, which gmsh would try to build until
 * it ran out of memory.  Meshing only the curves costs little (the number
 * of 1D nodes grows like 2^level, not 2^(d*level)) and tells the mesh
 * size h: the mean length of the curve segments.  From the measure of the
 * bounding box of each surface (2D) or volume (3D), h and the element
 * order, lac_gmsh_estimate gives the nodes to expect and the memory a
 * run of lac needs for them (measured with lac run on tri6 and hex meshes:
 * about 4 kB per node in 2D, 1.2 kB x nodes^(4/3) in 3D, twice that for
 * quadratic 3D cells, where the Cholesky factor dominates).  On the
 * scenes of the chapters at levels 0 to 2 the nodes are within 0.35 to 6
 * times those gmsh makes: low for coarse meshes (the boundary nodes are
 * not counted), near 1 for the structured ones as they grow, high for
 * curved shells (whose bounding box is much larger than the shell).  It
 * tells 10^5 from 10^9, which is what the limit needs.
 */
#ifndef LAC_MESH_GMSH_ESTIMATE_H
#define LAC_MESH_GMSH_ESTIMATE_H

#include "io/lac_mesh_gmsh_reader.h"

/* Mesh the curves of the model (dimension dim) and estimate the nodes and
 * the bytes of a run on the mesh of dimension dim; 0 and 0 when the
 * model has no curves to measure h on. */
int lac_gmsh_estimate (lac_gmsh_reader *R, int dim, double *nodes,
                       double *bytes);

/* lac_gmsh_estimate, and an error (LAC_EINVAL, naming level, size, the
 * nodes and the memory) when the bytes exceed R->opts->max_memory. */
int lac_gmsh_estimate_check (lac_gmsh_reader *R, int dim);

#endif /* LAC_MESH_GMSH_ESTIMATE_H */
