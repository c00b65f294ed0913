/* lac_frames.h -- nodal frames: the dofs of some nodes in a rotated basis,
 *                 for rollers on inclined and curved faces   [LAC (4), (8)]
 *
 * A roller on a face whose outward normal n is not a coordinate axis (an
 * inclined plane, a cylinder, a cone) imposes u.n = g at its nodes: a
 * combination of the x, y (, z) components, which no single dof carries.
 * lac eliminates fixed dofs from K and from C (lac_dirichlet_apply,
 * lac_contact_apply_dirichlet), so such a node gets a frame: its dofs
 * become the components along orthonormal axes R = [q_1 .. q_dim] (the
 * columns of R) with q_1 = n, and the roller is the ordinary fixed dof
 * q_1 . u = g.  With T the block diagonal matrix of the frames (R_a at a
 * node with a frame, I elsewhere), u = T u~ and
 *
 *   K u = F   becomes   (T^T K T) u~ = T^T F,    C~ = T^T C,
 *
 * T orthogonal: T^T K T is symmetric positive definite exactly when K is,
 * so every strategy (Cholesky, Schur, the augmented and split solves)
 * applies unchanged, and the constraint is exact.  (A penalty would not be
 * exact; Lagrange multipliers would make K indefinite.)  After the solve
 * u = T u~.
 *
 * Several conditions at one node are their intersection: a roller and a
 * symmetry plane, two rollers at a corner, a roller and a clamp.  The
 * directions d_j they fix, in the order given, are made orthonormal
 * (Gram-Schmidt, lac_frames_basis): the first r axes of the frame span
 * them and are fixed, the other dim - r axes are free.  A direction within
 * LAC_FRAMES_DEPENDENT (the sine of an angle) of the span of the earlier
 * ones fixes nothing new: its value must agree with theirs, or the
 * conditions contradict each other.
 *
 * Nodal normals (lac_frames_normals): the outward unit normal of the face
 * at a node, the normalized sum of the unit normals at that node of the
 * group's facets that contain it (curved facets evaluated at the node
 * itself); on a flat face every facet gives the same normal.
 *
 * Ownership: lac_frames_alloc / lac_frames_free; rotate_rows replaces the
 * caller's matrix (the old one freed).
 */
#ifndef LAC_FRAMES_H
#define LAC_FRAMES_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "linalg/lac_linalg.h"

/* Directions closer than this (the sine of the angle between a direction
 * and the span of the earlier ones) fix nothing new. */
#define LAC_FRAMES_DEPENDENT 1e-6

typedef struct lac_frames
{
  int dim;
  size_t nnodes;
  size_t n, cap;        /* frames set, room                                */
  long *of;             /* owned, nnodes: frame of node a, -1: the axes     */
  double *R;            /* owned, 9 cap: R[9 f + 3 i + j] = component i of
                           axis j of frame f (row-major 3 x 3)             */
} lac_frames;

/* construct / destroy */
lac_frames *lac_frames_alloc (int dim, size_t nnodes);
void lac_frames_free (lac_frames *f);                /* NULL allowed */
/* Node a's frame: R row-major 3 x 3, its first dim columns orthonormal
 * (checked to 1e-12: LAC_EINVAL otherwise).  Setting it again replaces it. */
int lac_frames_set (lac_frames *f, size_t a, const double *R);

/* query */
/* Node a's frame (9 values), NULL if it has none (or f is NULL). */
const double *lac_frames_of (const lac_frames *f, size_t a);
/* The global direction of dof q of a dim-dimensional mesh (3 values):
 * axis q % dim of its node's frame, or the coordinate axis (f NULL: every
 * node). */
void lac_frames_axis (const lac_frames *f, int dim, size_t q, double *e);

/* rotate (f NULL: nothing to do) */
void lac_frames_to_local (const lac_frames *f, double *v);   /* v <- T^T v */
void lac_frames_to_global (const lac_frames *f, double *v);  /* v <- T v   */
/* K <- T^T K T in place.  The pattern must hold the full dim x dim block
 * of every node pair it touches at a node with a frame (a stiffness
 * assembled cell by cell does): LAC_ESANITY otherwise. */
int lac_frames_rotate_matrix (const lac_frames *f, lac_csc *K);
/* *A <- T^T *A (rows of dofs; any pattern, any number of columns): a new
 * matrix replaces *A. */
int lac_frames_rotate_rows (const lac_frames *f, lac_csc **A);

/* The frame of the n conditions d_j . u = v_j at one node (d: 3 n values,
 * each d_j a unit vector; v: n values).  Out: R (9, row-major; the first
 * *rank columns span the d_j), w (3: q_k . u = w_k for k < *rank, which
 * satisfies every condition), indep (n flags: d_j added an axis).
 * Returns LAC_SUCCESS, or LAC_EINVAL with *bad = j, the first dependent
 * condition whose value contradicts the earlier ones, and *with = the
 * first earlier condition not orthogonal to it. */
int lac_frames_basis (int dim, size_t n, const double *d, const double *v,
                      double *R, double *w, char *indep, int *rank,
                      size_t *bad, size_t *with);

/* The outward unit normal of facet group g at each of its nodes:
 * n[3 k .. 3 k + 2] at node g->node[k].  LAC_EINVAL (not a facet group),
 * LAC_ESING (the normals of the facets at a node cancel: the message
 * names the node). */
int lac_frames_normals (const lac_mesh *m, const lac_group *g, double *n);

#endif /* LAC_FRAMES_H */
