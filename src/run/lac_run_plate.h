/* lac_run_plate.h -- a total force through a rigid plate
 *
 * Part of stage 4 (assemble) of a linear run.  A [load] with
 * `total_force` and `plate = yes` loads its boundary group through a rigid
 * plate glued to it: the nodes of the group move together, by one unknown
 * translation u_P (the plate does not rotate), and the plate's resultant is
 * the given force.  The constraint u_a = u_P for every node a of the group
 * is eliminated by master-dof condensation: one node of the group (the one
 * with the most Dirichlet components, else the first) is the plate; every
 * entry K_ij of the stiffness and F_i of the loads of a dof of another
 * node of the group is added to the same component of the plate node's
 * dof (K <- P^T K P, F <- P^T F, P the 0/1 matrix that copies u_P to the
 * group), so that the plate node's equation is the equilibrium of the whole
 * plate.  The other dofs keep only their diagonal and are fixed (their
 * rows and columns are empty after the condensation); after the solve
 * they take the plate's displacement.  A component that a [dirichlet]
 * fixes at some node of the group is fixed for the whole plate (a
 * symmetry plane through it).  The group may not touch a contact surface.
 * The plate forbids the rotations of its body: the rigid-motion check of
 * stage 4 knows it (lac_run_plate_motions).
 *
 * Ownership: the ties are owned by the struct (lac_run_plate_clear).
 */
#ifndef LAC_RUN_PLATE_H
#define LAC_RUN_PLATE_H

#include <stddef.h>
#include "fem/lac_assembly.h"
#include "fem/lac_rigid.h"
#include "io/lac_scene.h"
#include "linalg/lac_linalg.h"
#include "run/lac_run_setup.h"

typedef struct lac_run_ties
{
  size_t n;
  size_t *dof;          /* owned, n: a tied dof                          */
  size_t *to;           /* owned, n: the plate dof it follows            */
  size_t nplates;
} lac_run_ties;

/* Condense every plate of the scene: T (the stiffness triplets), F, the
 * Dirichlet list (the tied dofs and the plate's fixed components added). */
int lac_run_plate_tie (const lac_scene *sc, const lac_mesh *m,
                       const lac_run_setup *setup, lac_triplet *T, double *F,
                       lac_dirichlet *dir, lac_run_ties *ties);
/* The rigid motions the plates forbid, taken from the bodies' free
 * motions (fem/lac_rigid.h, made before the plates are tied): a plate
 * moves its nodes by one translation, so a free motion of a body is kept
 * only as far as it moves every plate's nodes in the body alike (a body
 * held in x by a roller at one node and in y by contact, with a plate on
 * its top: its rotation is no free motion).  The modes of each body with
 * a plate are made again, and so are their words (B->body[b].desc). */
int lac_run_plate_motions (const lac_scene *sc, const lac_mesh *m,
                           lac_bodies *B);
/* u of every tied dof = u of its plate dof. */
void lac_run_plate_untie (const lac_run_ties *ties, double *u);
void lac_run_plate_clear (lac_run_ties *ties);

#endif /* LAC_RUN_PLATE_H */
