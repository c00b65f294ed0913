/* lac_mesh_gmsh_estimate.h -- how large a .geo mesh will be, before it
 * is made                                                        [LAC §2]
 *
 * `level = 12` asks a .geo of lac's chapters for 2^12 times more cells per
 * edge than level 0: billions of nodes, which gmsh would try to build until
 * it ran out of memory.  Meshing only the curves costs little (the number
 * of 1D nodes grows like 2^level, not 2^(d*level)), and the 1D mesh obeys
 * every transfinite and extrusion constraint of the .geo.  From it,
 * lac_gmsh_estimate counts the nodes of each surface (2D) or volume (3D):
 * exactly for structured quadrilaterals and hexahedra (transfinite blocks,
 * extrusions in layers: the product of the curves' node counts), by the
 * Delaunay bound (measure / h^d, h the curves' mesh size) for the other
 * triangles and tetrahedra; then the memory a run of lac needs for them, by how it
 * will solve (lac_mesh_solve: a Cholesky or LU factor with its fill, a
 * dense matrix, or an iterative solve: the matrix, a multigrid hierarchy
 * and a few vectors; or, for lac infsup, the factors of its eigenvalue
 * problem) and by the cells (dofs per node, nonzeros per row).
 * Against the meshes gmsh makes: within 5 % for the structured blocks of
 * the chapters (the ring on block, the 3D Taylor patch test, the
 * spheres), within 1.5 for Delaunay tetrahedra once refined; the memory
 * within a factor of about 1.5 of what lac run measures.  The formulas
 * are in lac_mesh_gmsh_estimate.c.
 */
#ifndef LAC_MESH_GMSH_ESTIMATE_H
#define LAC_MESH_GMSH_ESTIMATE_H

#include "io/lac_mesh_gmsh_reader.h"

/* Mesh the curves of the model (dimension dim) and estimate the nodes and
 * the bytes of a run on the mesh of dimension dim; 0 and 0 when the
 * model has no curves to count on. */
int lac_gmsh_estimate (lac_gmsh_reader *R, int dim, double *nodes,
                       double *bytes);

/* Bytes a run of lac needs on a mesh of `nodes` nodes of dimension dim,
 * with o->element's cells (or o->recombine, o->order, o->serendipity)
 * solved as o->solve says. */
double lac_gmsh_run_bytes (double nodes, int dim, const lac_mesh_opts *o);

/* How a solve (lac_mesh_solve) is named in the messages, e.g. "a sparse
 * Cholesky factor". */
const char *lac_gmsh_solve_name (int solve);

/* lac_gmsh_estimate, and an error (LAC_EINVAL, naming the file, level,
 * size, the nodes, the memory and how the run solves) when the bytes
 * exceed R->opts->max_memory.  A size factor below 1 is reached in steps
 * from 1 (halving it, so that no 1D mesh is made much larger than one
 * already within the limit); a curve with fewer segments at a smaller
 * factor is an error too: gmsh's count of segments overflowed (size =
 * 1e-10 gave 1 segment a curve and fewer cells than size = 1).  With
 * R->opts->else_iterative, bytes over the limit are estimated again for
 * an iterative solve, and the error (naming it) only if they still
 * exceed it. */
int lac_gmsh_estimate_check (lac_gmsh_reader *R, int dim);

#endif /* LAC_MESH_GMSH_ESTIMATE_H */
