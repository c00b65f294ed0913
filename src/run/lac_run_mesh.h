/* lac_run_mesh.h -- stage 1 of a run: the mesh                     [LAC §2]
 *
 * In:  the scene (its [mesh] and the groups its sections name), the model.
 * Out: the mesh, read or meshed through gmsh (io/lac_mesh_gmsh.h) and
 *      checked against the scene: its dimension is the model's, its cells
 *      are the scene's element, r >= 0 in axisymmetry, every group a
 *      section names exists with the right dimension.  Errors name the
 *      scene line.
 */
#ifndef LAC_RUN_MESH_H
#define LAC_RUN_MESH_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "io/lac_scene.h"

/* *mesh (owned by the caller, lac_mesh_free); a progress line in
 * progress[size].  max_memory: bytes the mesh may need (0: the default of
 * io/lac_mesh_opts.h), checked against a .geo's estimate made for the
 * scene's cells and the way the run will solve: strategy (lac_strategy_kind,
 * LAC_STRATEGY_AUTO: the scene's), the scene's solver; with auto, a mesh
 * whose Cholesky factor is estimated not to fit is made if it fits with
 * petsc (lac built with PETSc), and on N > 1 MPI processes the estimate
 * is petsc's.  infsup_solve (lac infsup; 0 for a run): the
 * LAC_MESH_SOLVE_INFSUP... whose memory is estimated instead. */
int lac_run_mesh (const lac_scene *sc, lac_model model, int strategy,
                  int infsup_solve, double max_memory, lac_mesh **mesh,
                  char *progress, size_t size);

/* 1 if the run leaves the choice of the solve to the strategy auto:
 * none asked for (strategy 0, the scene's auto), small strain, and with
 * contact, or without contact and without [scene] solver. */
int lac_run_mesh_auto (const lac_scene *sc, int strategy);
/* 1 if the run on mesh m is estimated to fit in max_memory bytes (0: the
 * default of io/lac_mesh_opts.h) with a sparse Cholesky factor
 * (lac_gmsh_run_bytes, the estimate a .geo is checked with before gmsh
 * meshes it); 0 if not: the strategy auto then takes petsc
 * (solve/lac_strategy.h, lac_strategy_context). */
int lac_run_mesh_factor_fits (const lac_scene *sc, const lac_mesh *m,
                              double max_memory);
/* The bytes of that estimate for the mesh made, solved as `solve`
 * (lac_mesh_solve), plus `extra`. */
double lac_run_mesh_bytes (const lac_scene *sc, const lac_mesh *m, int solve,
                           double extra);
/* LAC_SUCCESS if lac_run_mesh_bytes fits in max_memory (0: the default),
 * else LAC_EINVAL with a message naming the scene, the nodes, `what`
 * (more of the size, e.g. "and 1089 multipliers", may be ""), the bytes
 * and the solve.  For lac infsup, whose solve (the dense or the sparse
 * path) is known once the multipliers are, also on a mesh read from a
 * .msh file, which has no estimate before it is read. */
int lac_run_mesh_check_solve (const lac_scene *sc, const lac_mesh *m,
                              int solve, double extra, const char *what,
                              double max_memory);

#endif /* LAC_RUN_MESH_H */
