/* lac_run_roller.h -- the Dirichlet conditions node by node, and the
 *                     frames of the conditions along a normal (rollers)
 *                                                        [LAC (4), (8)]
 *
 * Part of stage 4 (assemble) of a linear run.  A [dirichlet] section with
 * `normal = g` imposes u.n = g at every node of its facet group, n the
 * outward unit normal of the face at the node: a roller for g = 0, on any
 * face, plane or curved.  At a corner or an edge of the face (where it
 * turns by more than the corner rule's angle, fem/lac_mesh.h) the node
 * gets one condition per smooth piece of the face, each along the mean of
 * the unit normals of its facets there (fem/lac_frames.h,
 * lac_frames_pieces); the facets of all the `normal` sections are split
 * together, so that two sections that meet along a smooth face give their
 * common node one condition (with one value, or an error naming both).
 *
 * Every condition of the scene at a node is a direction d and a value v,
 * d . u = v: ux = v is (e_x, v), clamp three (or two) of them, exact the
 * components of the exact solution, normal (n, g) per piece.
 * lac_run_conditions lists them node by node, in the order of the
 * sections (a piece two sections share: with the first).
 *
 * lac_run_rollers gives each node of a `normal` group a frame made from
 * ALL the conditions at the node (fem/lac_frames.h, lac_frames_basis: the
 * intersection of the conditions; a direction fixed twice with two values
 * is an error naming both sections) and rewrites the Dirichlet data
 * there: the fixed dofs of such a node are the first axes of its frame,
 * with the values that satisfy every condition; dir->frames holds the
 * frames, and the tilts of the rollers' pieces for the rigid-motion check
 * (fem/lac_rigid.h: what a roller on a curved face lets slide).  A node of a rigid plate ([load] plate = yes) may not have a
 * frame (an error naming both sections).  The linear run (stage 4) and
 * the large-deformation run (run/lac_run_nonlinear.c, which keeps a
 * ramp flag per entry) call it alike.
 *
 * Ownership: lac_run_conditions owns its arrays (lac_run_conditions_clear).
 */
#ifndef LAC_RUN_ROLLER_H
#define LAC_RUN_ROLLER_H

#include <stddef.h>
#include "fem/lac_assembly.h"
#include "fem/lac_mesh.h"
#include "io/lac_scene.h"

/* One condition d . u = v of section sec (an index of sc->dirichlet). */
typedef struct lac_run_condition
{
  size_t sec;
  double d[3];          /* a unit vector                                   */
  double v;
  double tilt;          /* a roller: its piece's tilt and whether the    */
  char end;             /* piece ends at the node (fem/lac_frames.h); 0
                           for the others                                 */
} lac_run_condition;

typedef struct lac_run_conditions
{
  size_t nnodes;
  size_t *ptr;              /* owned, nnodes + 1: the conditions of node a
                               are c[ptr[a] .. ptr[a + 1])                 */
  lac_run_condition *c;     /* owned                                       */
} lac_run_conditions;

/* The conditions of the scene at the nodes flagged in `want` (nnodes
 * flags; NULL: every node), in the order of the sections; the normals of
 * the `normal` groups from the mesh (refined: stage 2 is done). */
int lac_run_conditions_build (const lac_scene *sc, lac_model model,
                              const lac_mesh *m, const char *want,
                              lac_run_conditions *out);
void lac_run_conditions_clear (lac_run_conditions *cs);

/* The frames of the nodes of the `normal` groups, in dir (see above).
 * Nothing to do without such a section. */
int lac_run_rollers (const lac_scene *sc, lac_model model, const lac_mesh *m,
                     lac_dirichlet *dir);

#endif /* LAC_RUN_ROLLER_H */
