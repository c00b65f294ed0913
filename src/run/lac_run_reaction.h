/* lac_run_reaction.h -- the reaction force of every Dirichlet section
 *                                                  [LAC (4), (8), (17)]
 *
 * Part of stage 6 (post).  At equilibrium K u - C lambda = F on the free
 * dofs (solve/lac_system.h: K U - C lambda = F); at a fixed dof the
 * difference is the force the support exerts on the body.  Node by node,
 *
 *   r_a = (f_int(u) - F - C lambda)_a,   f_int = K u (linear), F_int(u)
 *                                        (large deformation, fem/lac_hyper.h)
 *
 * with K and C before any Dirichlet elimination and in the axes (the
 * stiffness of the cells around the fixed nodes is assembled again for
 * it, and C from the pairs, all of them side by side: only when a fixed
 * node lies on a contact surface).  r_a lies in the span of the
 * directions fixed at the node (the free components balance, to the
 * solver's precision); it is split
 * among the conditions there (run/lac_run_roller.h lists them: a
 * direction d_j and a section each), r_a = sum_j mu_j d_j over the
 * directions that fix something new in the order of the sections
 * (fem/lac_frames.h: two rollers at a corner get their own multipliers
 * mu_j, not projections; a direction fixed twice counts for the first
 * section only), and
 *
 *   R_g = sum over the nodes of g of mu_j d_j        (a vector)
 *
 * for every [dirichlet] section g: "reaction.NAME = Rx Ry [Rz]" in the
 * summary (axisymmetric: Rr Rz, the forces on the whole surface of
 * revolution: the 2 pi r of the integrals; Rr sums radial nodal forces,
 * not a resultant).  Sum over the sections plus the loads plus the
 * contact forces on the fixed nodes: zero.
 *
 * A rigid plate (run/lac_run_plate.h) moves as one: a condition at any
 * node of its group holds the whole plate.  So the residuals of its
 * nodes are summed at its plate node, r_P = sum over the group of
 * (f_int - F)_a (the plate's equilibrium, which the solve made zero along
 * its free components), and split among the conditions of all the
 * group's nodes, in the order of the sections.
 */
#ifndef LAC_RUN_REACTION_H
#define LAC_RUN_REACTION_H

#include "contact/lac_contact_set.h"
#include "io/lac_scene.h"
#include "run/lac_run_material.h"
#include "run/lac_run_plate.h"
#include "run/lac_summary.h"

typedef struct lac_run_reaction_in
{
  const lac_scene *sc;
  lac_model model;
  const lac_mesh *mesh;
  const lac_run_material *mat;
  int large;                       /* 1: F_int(u) of fem/lac_hyper.h      */
  const double *F;                 /* ndof: the load (at t = 1)           */
  const double *u;                 /* ndof: the displacement, in the axes */
  const lac_contact_set *set;      /* the contact pairs (their options of
                                      the last pairing), or NULL          */
  const double *lambda;            /* per slot of the set, or NULL        */
  const char *on_contact;          /* nnodes flags, or NULL               */
  const lac_run_ties *ties;        /* the rigid plates (linear), or NULL  */
} lac_run_reaction_in;

/* "reaction.NAME" lines for the [dirichlet] sections, in their order. */
int lac_run_reactions (const lac_run_reaction_in *in, lac_summary *sum);

#endif /* LAC_RUN_REACTION_H */
