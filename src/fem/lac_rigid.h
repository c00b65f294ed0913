/* lac_rigid.h -- bodies and the rigid motions their Dirichlet conditions
 *                leave free                                        [LAC §2]
 *
 * A body is a connected component of the mesh (nodes joined through
 * cells).  The rigid motions of a model (plane strain: two translations
 * and the rotation about z; axisymmetric: the translation along the axis;
 * 3D: three translations and three rotations) strain nothing, so the
 * stiffness of a body is singular unless its fixed dofs stop every one of
 * them.  Here, for every body, the rigid modes are restricted to its fixed
 * dofs and the Gram matrix G of these restrictions is diagonalised (GSL):
 * its null space is the set of motions the Dirichlet conditions leave
 * free, each described in words ("rotation about (0, 0)", "translation
 * along z").
 *
 * Rollers on curved faces (fem/lac_frames.h).  A roller lets its face
 * slide along itself, but the check sees the facets' normals, which hold
 * such a slide weakly (a ring on a roller on a quarter of its circle,
 * through the chords at the ends of the arc).  So it asks about the smooth
 * face: the axes of rollers where a curved piece ends are not counted in
 * G, and the counted rollers' tilts t (how much the face turns within one
 * facet) give H = sum t^2 M_a, M_a the Gram matrix of the modes at their
 * node a (the squared length of a motion there).  An eigenvector c of G is
 * free if its eigenvalue is below 1e-10 of the largest, or below c^T H c:
 * held no better than normals off the smooth face's by one facet's turn
 * could hold it.  H = 0 without curved rollers.
 *
 * Used twice by a run: a body that touches no contact surface must have
 * none (its stiffness would be singular: an error naming it and its free
 * motion); the free motions of bodies on a contact surface, held by
 * contact alone, go to the contact solves as the basis N of
 * solve/lac_system.h, which is how the strategies know, before anything
 * is factorized, that K is singular and what the active multipliers must
 * hold.
 *
 * Ownership: lac_bodies_find allocates *out, freed by lac_bodies_free; the
 * arrays of lac_bodies_free_motions are the caller's (lac_free, and
 * lac_free of each string).
 */
#ifndef LAC_RIGID_H
#define LAC_RIGID_H

#include <stddef.h>
#include "fem/lac_frames.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

#define LAC_RIGID_DESC 200

typedef struct lac_body
{
  size_t cell0;           /* a cell of the body                            */
  int group;              /* the body's physical group (index), -1: none   */
  double ctr[3], size;    /* centre and size: the frame of its modes       */
  int nfree;              /* rigid motions left free by its fixed dofs     */
  int slide;              /* 1: some of them move rollers on curved faces
                             (see above)                                   */
  double mode[6][6];      /* free motion j: coefficients mode[j][0..nm) of
                             the model's rigid modes in that frame         */
  char desc[LAC_RIGID_DESC];  /* "translation along z; rotation about x"   */
} lac_body;

typedef struct lac_bodies
{
  lac_model model;
  int nm;                 /* rigid modes of the model: 3, 1 or 6           */
  size_t n;               /* bodies                                        */
  lac_body *body;         /* owned, n                                      */
  size_t *node_body;      /* owned, nnodes: body of node a (SIZE_MAX: in
                             no cell)                                      */
} lac_bodies;

/* Bodies of m and the rigid motions that the fixed dofs (ndof flags, 1 =
 * fixed) leave free to each; a fixed dof of a node with a frame (fr, or
 * NULL: none; fem/lac_frames.h) fixes the component along its axis.
 * LAC_ENOMEM, LAC_EDEP (GSL failed). */
int lac_bodies_find (const lac_mesh *m, lac_model model, const char *fixed,
                     const lac_frames *fr, lac_bodies **out);
void lac_bodies_free (lac_bodies *b);            /* NULL allowed */
/* The name of body b: its physical group, or NULL. */
const char *lac_bodies_name (const lac_bodies *b, const lac_mesh *m,
                             size_t body);
/* The free motions of the bodies flagged in `which` (n flags; NULL: all)
 * as vectors of the ndof displacements (0 outside the body): *N =
 * ndof x *nfree, column after column; (*what)[j] = "body 'upper':
 * translation along z".  *N and *what are NULL when *nfree = 0. */
int lac_bodies_free_motions (const lac_bodies *b, const lac_mesh *m,
                             const char *which, size_t *nfree, double **N,
                             char ***what);

#endif /* LAC_RIGID_H */
