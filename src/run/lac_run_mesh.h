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
 * LAC_STRATEGY_AUTO: the scene's), the scene's solver. */
int lac_run_mesh (const lac_scene *sc, lac_model model, int strategy,
                  double max_memory, lac_mesh **mesh, char *progress,
                  size_t size);

#endif /* LAC_RUN_MESH_H */
