/* lac_contact.h -- the LAC contact data: admissibility, C and mean gaps
 *                                          [LAC Def. 1, (16)-(18), §4.3]
 *
 * Given the macro-mesh T^M of the slave surface (lac_macromesh.h) and its
 * pairing with the master surface (lac_pairing.h, slave list = the
 * sub-facets of T^M in order), this module
 *
 *   1. measures, for every macro-element T^m, the covered fraction
 *        delta_m = |T^m cap Gamma_C| / |T^m|
 *      and the mean of its interior basis function over T^m cap Gamma_C,
 *        phibar_m = (1/|T^m cap Gamma_C|) int_{T^m cap Gamma_C} phi_{m*+1},
 *      and keeps T^m iff   phibar_m sqrt(delta_m) >= epsilon   [LAC Def. 1];
 *   2. gives one multiplier to every admissible macro-element and assembles
 *        C(:,i) = int_{T^m cap Gamma_C} (phi^S n^S  -  phi^M n^S) dGamma
 *      (the blocks C^S and C^M of [LAC (16)-(17)], with n^M = -n^S) and
 *        G_i    = int_{T^m cap Gamma_C} g0 dGamma                [LAC (18)]
 *      with g0 the initial normal gap (> 0 open).
 * The sign convention is the one of lac_newton.h.  Axisymmetric integrals
 * carry the weight 2 pi r, in the measures of Definition 1 too (they are
 * the measures of the surfaces of revolution).
 *
 * The default epsilon, LAC_EPSILON_DEFAULT = 1e-2, is below phibar of a
 * fully covered macro-element of every type lac builds (the smallest is
 * the hex20 six-hexahedra cut), so fully covered macro-elements are always
 * admissible [LAC Def. 1, remark after it]; a test checks it.
 *
 * Files.  lac_contact.c: lac_contact_build, which runs the two items, and
 * the other functions below; lac_admissibility.[ch]: item 1;
 * lac_assembly_lac.[ch]: item 2; lac_contact_types.h: the struct lac_contact
 * that they fill; lac_contact_facet.[ch]: the map of one facet at a point,
 * which they evaluate; lac_nts.c: lac_contact_build_nts.
 *
 * Ownership: lac_contact_alloc/lac_contact_free; the struct owns its arrays
 * and refers to the mesh, macro-mesh and pairing by indices only.
 */
#ifndef LAC_CONTACT_H
#define LAC_CONTACT_H

#include <stddef.h>
#include "linalg/lac_linalg.h"
#include "contact/lac_contact_facet.h"
#include "contact/lac_contact_types.h"
#include "contact/lac_macromesh.h"
#include "fem/lac_frames.h"
#include "fem/lac_material.h"
#include "contact/lac_pairing.h"

#define LAC_EPSILON_DEFAULT 1e-2

/* Items 1 and 2 above.  The pairing's slave list must be the sub-facets of
 * M in order (cell = M->cell, face = M->face); master facets are given by
 * `master` (of the same mesh), or master is NULL for a rigid obstacle
 * (lac_obstacle.h: no master part in C).  epsilon in (0, 1].
 * Errors: LAC_EINVAL (epsilon out of range, list mismatch), LAC_EADMISS
 * (no admissible macro-element at all: the message gives the largest
 * criterion found), LAC_ENOMEM. */
int lac_contact_build (const lac_mesh *mesh, lac_model model,
                       const lac_macro *M, const lac_pairing *P,
                       const lac_pairing_facets *master, double epsilon,
                       lac_contact **out);
void lac_contact_free (lac_contact *c);   /* NULL allowed */
/* Zeroed arrays for nmacro macro-elements (C, xpt, npt NULL). */
lac_contact *lac_contact_alloc (size_t nmacro);

/* The node-to-segment (2D) / node-to-face (3D) method, for comparison
 * [LAC §1]: one multiplier per slave node a whose projection along the
 * nodal normal n_a (average of the adjacent facet normals) lands on a
 * master facet; the constraint is collocated there:
 *   C(:,i) = w_a (e_a - sum_b phi^M_b(xi) e_b) n_a,  G_i = w_a g_a,
 * with w_a the node's share of the slave surface (|T|/nnodes of each
 * adjacent facet: lumped, so quadratic vertices get a positive weight) and
 * g_a the distance to the master along n_a.  The master candidates of a
 * node are the masters paired with its facets (P).  The "macro-elements"
 * of the result are the slave nodes (nmacro = their number; inode = node).
 * LAC_EADMISS if no node projects onto the master. */
int lac_contact_build_nts (const lac_mesh *mesh, lac_model model,
                           const lac_macro *M, const lac_pairing *P,
                           const lac_pairing_facets *master,
                           lac_contact **out);

/* Dirichlet data on contact dofs: G_i -= C(dof,i) value for every fixed
 * dof, then the row of C is zeroed (the fixed value moves into the gap);
 * with friction, sfix_j += Ct(dof,j) value and the row of Ct is zeroed. */
int lac_contact_apply_dirichlet (lac_contact *c, size_t n, const size_t *dof,
                                 const double *val);

/* The rows of C (and Ct, with friction) turned to the nodal frames of
 * rollers: T^T C (fem/lac_frames.h; f NULL: nothing to do). */
int lac_contact_to_frames (lac_contact *c, const lac_frames *f);

/* An interference fit drawn with matching surfaces (a shrink fit): the
 * gap of every point is g0 - delta (delta > 0 an overlap, < 0 a
 * clearance added), so that the mean gaps become
 *   G_i = int_{T^m cap Gamma_C} (g0 - delta) = G_i - delta area_i
 * (area_i 2 pi r weighted, as G_i); c->offset = delta, which the
 * derivatives of large deformations read (lac_contact_tangent.h).  Setting
 * it again replaces the former delta.  Call it before
 * lac_contact_apply_dirichlet or after, as the Dirichlet part of G does
 * not depend on it.  LAC_EINVAL if delta is not finite. */
int lac_contact_set_offset (lac_contact *c, double delta);

/* The multiplier of the macro-element owning slave sub-facet j (-1: none). */
long lac_contact_mult_of_subfacet (const lac_contact *c, const lac_macro *M,
                                   size_t j);

#endif /* LAC_CONTACT_H */
