/* lac_run_conflict.h -- what a scene asks that contradicts itself on the
 * mesh                                                            [LAC §2]
 *
 * Checked once the mesh is read (stage 1, run/lac_run_mesh.c), each as an
 * error that names both places:
 *
 *   - two [dirichlet] sections that impose different values on one
 *     displacement component of one node (two sections on one group, or
 *     a node in two groups): the later section used to win without a
 *     word.  Equal values are fine; so is a component fixed by one
 *     section and left free by the other;
 *   - a surface load (pressure, traction, total_force, exact traction)
 *     on a facet that two cells share: a load inside a body, which the
 *     assembly would apply as if on the boundary (a contact surface there
 *     is refused already, contact/lac_macromesh.c); the same for a
 *     condition along the outward normal (normal = VALUE), which has no
 *     outward normal there.
 * A condition along the normal contradicts the others at a node only
 * through its direction, known once the mesh is refined: stage 4 checks
 * it (run/lac_run_roller.h).
 */
#ifndef LAC_RUN_CONFLICT_H
#define LAC_RUN_CONFLICT_H

#include "fem/lac_material.h"
#include "fem/lac_mesh.h"
#include "io/lac_scene.h"

/* LAC_SUCCESS, or LAC_EINVAL with a message naming the scene lines, the
 * node or the facet; LAC_ENOMEM. */
int lac_run_conflicts (const lac_scene *sc, lac_model model,
                       const lac_mesh *m);

#endif /* LAC_RUN_CONFLICT_H */
