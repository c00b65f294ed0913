/* lac_contact_tangent.h -- the derivatives of the LAC contact terms with
 *                          respect to the displacement
 *                                          [LAC (16)-(18), §4.5, Alg. 1]
 *
 * In the large-deformation loop (solve/lac_nonlinear.h) the LAC terms are
 * computed on the current coordinates x = X + U: the force C(U) lambda
 * and the mean gaps d(U).  Their derivatives with respect to U are what
 * the "frozen geometry" of the generalized Newton method leaves out; this
 * module computes them, for the exact (consistent) Newton step.
 *
 * At an integration point of the pairing (lac_pairing.h) on slave
 * sub-facet s of macro-element T^m, with the slave point x_s(xi) = sum_a
 * phi_a(xi) x_a, its tangents a_k = dx_s/dxi_k, the un-normalized normal
 *   nu = a_1 x a_2 (3D),  (a_y, -a_x) (2D),  J = |nu|,  n = nu / J,
 * and the master point x_m(eta) = sum_b psi_b(eta) y_b = x_s + g n, the
 * physical weight is w = w^ J rho (rho = 2 pi r axisymmetric, else 1), so
 *   C(:,i) lambda_i = sum_p lambda_i w^ rho nu (phi_a on the slave dofs,
 *                                                -psi_b(eta) on the master),
 *   d_i            = sum_p w^ rho g J.
 * The derivatives hold the points (xi) and w^ fixed: the points of the
 * pairing live on the slave reference facet; moving the cuts between
 * master facets changes nothing to first order, since the integrands are
 * continuous across them (the exact rule of an affine pair makes this
 * exact; curved pairs differ by the derivative of the quadrature error).
 * With d. the variation along a change dU of the nodal positions:
 *   d.nu   = sum_a (dphi_a/dxi_1 d.x_a x a_2 + a_1 x dphi_a/dxi_2 d.x_a)
 *            (2D: the rotated d.a),  d.J = n . d.nu,
 *   d.n    = (I - n n^T) d.nu / J,
 * and eta, g from the projection x_m(eta) = x_s + g n:
 *   [t_1 .. t_{dim-1}  -n] [d.eta; d.g] = d.x_s + g d.n - sum_b psi_b d.y_b
 * (t_k = dx_m/deta_k).  Against a rigid obstacle (lac_obstacle.h) g is
 * the signed distance and the vector nu of C is replaced by -J n^O (n^O
 * the obstacle's normal at the closest point of x_s):
 *   d.g = n^O . d.x_s,   d.(-J n^O) = -d.J n^O - J (dn^O/dx) d.x_s;
 * with the obstacle's slave_normal flag (the paper's manufactured scenes)
 * g is measured along n, x_m = x_s + g n on the graph F(x) = 0:
 *   d.g = -grad F . (d.x_s + g d.n) / (grad F . n).  Then
 *   B(:,i) = -d(d_i)/dU = -sum_p w^ (d.rho g' J + rho (d.g J + g' d.J)),
 *   g' = g - delta with the interference delta of the pair (c->offset,
 *   contact/lac_contact.h: the mean gaps are int (g - delta)),
 *   H = d(C lambda)/dU:  rows of slave node a   lambda w^ phi_a d.(rho nu),
 *                        rows of master node b  -lambda w^ (psi_b d.(rho nu)
 *                                + rho nu sum_k dpsi_b/deta_k d.eta_k).
 * With the frozen geometry B = C and H = 0.  H is kept as one dense block
 * per slave sub-facet of a macro-element with lambda != 0 (its dofs: the
 * sub-facet's nodes and those of the master facets it is paired with),
 * applied without assembly; B is a sparse ndof x k matrix like C.
 *
 * Not differentiated: the edge of the contact zone (a slave facet partly
 * covered by the master: the motion of the master's boundary over it),
 * and the admissibility and the number of pairs (they change by jumps).
 *
 * Ownership: the result owns its arrays (lac_contact_tangent_free).
 */
#ifndef LAC_CONTACT_TANGENT_H
#define LAC_CONTACT_TANGENT_H

#include <stddef.h>
#include "contact/lac_contact_types.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_obstacle.h"
#include "contact/lac_pairing.h"
#include "fem/lac_frames.h"
#include "fem/lac_material.h"
#include "linalg/lac_linalg.h"

typedef struct lac_contact_tangent
{
  size_t ndof, k;
  lac_csc *B;            /* owned, ndof x k: column i = -d(d_i)/dU          */
  size_t nblock;         /* blocks of H                                     */
  size_t *bptr;          /* owned, nblock+1: dofs of block b are
                            dof[bptr[b] .. bptr[b+1])                       */
  size_t *dof;           /* owned                                           */
  size_t *vptr;          /* owned, nblock+1: its values, row-major          */
  double *val;           /* owned                                           */
} lac_contact_tangent;

/* The derivatives at the current coordinates of `mesh` (those the pairing
 * P and the contact data c were built on; lac_contact_build's arguments),
 * with the multipliers lambda (c->k values, lambda[i] of multiplier i).
 * Master facets are given by `master`, or master is NULL and `obstacle`
 * is the rigid master.  `want` (k flags, or NULL: all) says which columns
 * of B are wanted (the active multipliers'); the others are left empty.
 * LAC_EINVAL, LAC_ENOMEM, LAC_ESING (a degenerate facet or a projection
 * parallel to the master). */
int lac_contact_tangent_build (const lac_mesh *mesh, lac_model model,
                               const lac_macro *M, const lac_pairing *P,
                               const lac_pairing_facets *master,
                               const lac_obstacle *obstacle,
                               const lac_contact *c, const double *lambda,
                               const char *want, lac_contact_tangent **out);

/* Columns i0 <= i < i1 of the same alone: a tangent of i1 - i0 columns
 * (column i - i0 of B is multiplier i's; H's blocks those of these
 * columns, in the same order).  Each column is made as in the whole
 * build, so that the pieces of a cut put side by side
 * (lac_contact_tangent_cat) are the whole tangent, bit for bit: two pieces
 * can be built at the same time (solve/lac_nonlinear.c).  LAC_EINVAL if
 * the range is not within c's columns. */
int lac_contact_tangent_build_cols (const lac_mesh *mesh, lac_model model,
                                    const lac_macro *M, const lac_pairing *P,
                                    const lac_pairing_facets *master,
                                    const lac_obstacle *obstacle,
                                    const lac_contact *c,
                                    const double *lambda, const char *want,
                                    size_t i0, size_t i1,
                                    lac_contact_tangent **out);

/* The work of column i in the build (the points of the pairing on its
 * sub-facets; 0 if it is neither wanted nor lambda_i != 0): where to cut
 * the columns into pieces of equal work. */
size_t lac_contact_tangent_work (const lac_macro *M, const lac_pairing *P,
                                 const lac_contact *c, const double *lambda,
                                 const char *want, size_t i);
void lac_contact_tangent_free (lac_contact_tangent *t);    /* NULL allowed */

/* The tangents of several contact pairs as one (contact/lac_contact_set.h:
 * their columns side by side, B = [B_0 B_1 ...], the blocks of H one
 * after the other); t[p] are left as they are. */
int lac_contact_tangent_cat (lac_contact_tangent *const *t, size_t n,
                             lac_contact_tangent **out);

/* y += H x (ndof vectors). */
void lac_contact_tangent_apply (const lac_contact_tangent *t, const double *x,
                                double *y);

/* To the nodal frames f of rollers (fem/lac_frames.h; NULL: nothing to
 * do): B <- T^T B, H <- T^T H T, block by block (every block holds all
 * the components of its nodes).  LAC_ENOMEM, LAC_ESANITY. */
int lac_contact_tangent_rotate (lac_contact_tangent *t, const lac_frames *f);

#endif /* LAC_CONTACT_TANGENT_H */
