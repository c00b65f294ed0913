/* lac_tangential.h -- the tangential averages of Coulomb friction on the
 *                     macro-elements        [LAC (16)-(18), with t for n]
 *
 * Friction adds to the normal multiplier of every admissible macro-element
 * T^m a tangential one, constant on T^m like the normal one (P0), paired
 * with the mean of the tangential jump over T^m cap Gamma_C.  Its columns
 * are the paper's (16) with the tangent vectors t_b in place of n^S: for
 * multiplier i and every integration point of the pairing (slave point x_s,
 * master point x_m, weight w, 2 pi r in the axisymmetric model),
 *
 *   Ct(dof(a, c), i ntan + b) += w phi^S_a(x_s) t_b,c     (slave)
 *   Ct(dof(a, c), i ntan + b) -= w phi^M_a(x_m) t_b,c     (master)
 *
 * so that (Ct^T U)_{i,b} = int_{T^m cap Gamma_C} [u] . t_b, [u] = u^S -
 * u^M, the mean tangential jump (times the measure, like C^T U).  Against
 * a rigid obstacle the master part is absent.
 *
 * The tangent frame, at every point, from the unit normal nu used by the
 * normal column (n^S, or the obstacle's -n^O):
 *   2D and axisymmetric (ntan = 1):  t = (-nu_y, nu_x), nu turned by +90
 *     degrees: on a slave face whose outward normal is -y, t = +x;
 *   3D (ntan = 2): a frame fixed per macro-element, carried to every
 *     point: e_m, the coordinate axis least aligned with the mean normal
 *     of T^m (x before y before z), t_1 = the unit projection of e_m on
 *     the tangent plane of the point, t_2 = nu x t_1 (t_1, t_2, nu a
 *     right-handed frame): on a slave face of normal -z, t_1 = x and
 *     t_2 = -y.
 * The frame turns with nu: on a curved slave the tangent at the edge of
 * the contact zone differs from the one at its centre by x/R, so that a
 * normal approach also moves the mean tangential jump (chapter 15
 * measures this "apparent slip").  A frame per point, not per
 * macro-element, keeps the traction lambda_n n + lambda_t t of the two
 * multipliers a traction that is normal and tangential everywhere, as
 * the normal multiplier of LAC is.
 */
#ifndef LAC_TANGENTIAL_H
#define LAC_TANGENTIAL_H

#include "contact/lac_contact_types.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_pairing.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

/* Ct, sfix (zero) and mu (= mu for all) of the k multipliers of c (built
 * by lac_contact_build from the same M, P and master), ntan = dim - 1.
 * LAC_EINVAL (mu not finite or < 0), LAC_ENOMEM. */
int lac_tangential_build (lac_contact *c, const lac_mesh *mesh,
                          lac_model model, const lac_macro *M,
                          const lac_pairing *P,
                          const lac_pairing_facets *master, double mu);

/* The tangent frame at a point of unit normal nu (dim 2 or 3): t (ntan x
 * 3, row after row); ref: the reference axis e_m in 3D (unused in 2D). */
void lac_tangential_frame (int dim, const double *nu, const double *ref,
                           double *t);
/* e_m of a macro-element whose normals sum to nbar: the coordinate axis
 * least aligned with it, x before y before z where they tie (within
 * 1e-8 of |nbar|: a face normal to z has t_1 = x, t_2 = y). */
void lac_tangential_reference (const double *nbar, double *ref);

#endif /* LAC_TANGENTIAL_H */
