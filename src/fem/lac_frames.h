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
 * The conditions of rollers (lac_frames_pieces): at a node, the facets of
 * the rollers' groups that hold it are split into the smooth pieces of the
 * face there, by the corner rule of fem/lac_mesh.h (two facets whose unit
 * normals at the node are within LAC_MESH_CORNER_DEG are one piece, and so
 * is a chain of such facets).  Each piece is one condition along its
 * normal, the normalized sum of its facets' unit normals at the node
 * (curved facets evaluated at the node itself): one on a flat face or a
 * smooth curved one, whatever the number of groups that meet there; two
 * at a node of an edge between two faces, three at a vertex of three.
 *
 * What the rigid-motion check sees (fem/lac_rigid.h).  A roller on a
 * curved face lets the face slide along itself (a ring on a roller on its
 * circle turns about the centre), but its polygon's normals differ from
 * the smooth face's: by O(h^2 / R^2) inside a piece of an even mesh, by
 * half the turn across one facet, O(h / R), where a piece ends (the end
 * nodes of a partial arc have the normal of their last chord, and a
 * rotation about the arc's centre crosses it).  So the nodes carry, with
 * their frames, what the check needs to ask about the smooth face:
 *   - the axes it counts: a roller's condition where its piece ends
 *     (lac_face_pieces.end) and the face is curved there (tilt > 0) is
 *     left out, its axis the last of the node's frame;
 *   - the node's tilt, the sum of the squares of its counted rollers'
 *     tilts: a piece's tilt is the sine of the largest angle between its
 *     normal and those of the pieces of its facets at their other nodes,
 *     how much the face turns within one facet (0 on a flat face); the
 *     check frees a motion that the rollers hold no better than normals
 *     tilted by that much could.
 *
 * Ownership: lac_frames_alloc / lac_frames_free; rotate_rows replaces the
 * caller's matrix (the old one freed); lac_face_pieces owns its arrays
 * (lac_face_pieces_clear).
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
  double *tilt;         /* owned, nnodes, or NULL (all 0): the tilt of
                           node a (see above)                              */
  int *counted;         /* owned with tilt: the rigid-motion check counts
                           node a's first counted[a] axes (see above)      */
} lac_frames;

/* The smooth pieces of some facet groups' faces at their nodes (see
 * above). */
typedef struct lac_face_pieces
{
  size_t nnodes, n;     /* mesh nodes, pieces                              */
  size_t *ptr;          /* owned, nnodes + 1: the pieces at node a are
                           ptr[a] .. ptr[a + 1] - 1, in the order of their
                           first group, then of their first facet          */
  double *normal;       /* owned, 3 n: outward unit normals                */
  double *tilt;         /* owned, n: sines (0 up to LAC_FRAMES_DEPENDENT:
                           a flat face, to rounding)                       */
  char *end;            /* owned, n: 1 if the piece ends at the node (its
                           facets do not surround it: the end of an arc,
                           the rim of a partial cylinder)                  */
  size_t *gptr;         /* owned, n + 1: the groups with a facet in piece
                           p are grp[gptr[p] .. gptr[p + 1] - 1]           */
  size_t *grp;          /* owned: indices in the caller's list, increasing */
  size_t failed;        /* after an error: the group it names              */
} lac_face_pieces;

/* construct / destroy */
lac_frames *lac_frames_alloc (int dim, size_t nnodes);
void lac_frames_free (lac_frames *f);                /* NULL allowed */
/* Node a's frame: R row-major 3 x 3, its first dim columns orthonormal
 * (checked to 1e-12: LAC_EINVAL otherwise).  Setting it again replaces it. */
int lac_frames_set (lac_frames *f, size_t a, const double *R);
/* What the rigid-motion check sees of node a (see above): its tilt
 * (>= 0) and the number of its axes it counts.  LAC_ENOMEM. */
int lac_frames_set_check (lac_frames *f, size_t a, double tilt,
                          int counted);

/* query */
/* Node a's frame (9 values), NULL if it has none (or f is NULL). */
const double *lac_frames_of (const lac_frames *f, size_t a);
/* Node a's tilt, 0 if none was set (or f is NULL). */
double lac_frames_tilt (const lac_frames *f, size_t a);
/* The number of node a's axes the rigid-motion check counts: all (3) if
 * none was set. */
int lac_frames_counted (const lac_frames *f, size_t a);
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

/* The smooth pieces of the faces of the ng facet groups g[0 .. ng) at
 * every node of m (see above; the groups in the order given).  LAC_EINVAL
 * (a group that is not a facet group), LAC_ESING (a degenerate facet:
 * the message names the group and the node), LAC_ENOMEM; out->failed is
 * the group the error names. */
int lac_frames_pieces (const lac_mesh *m, size_t ng,
                       const lac_group *const *g, lac_face_pieces *out);
void lac_face_pieces_clear (lac_face_pieces *p);

#endif /* LAC_FRAMES_H */
