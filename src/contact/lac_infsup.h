/* lac_infsup.h -- a numerical estimate of the inf-sup constant beta_h
 *                                        [LAC (10), Thm. 2, App. A]
 *
 * The discrete inf-sup condition [LAC (10)]
 *
 *   inf_{mu in X^h} sup_{v in V^h} b(mu, v) / (||mu||_{W'} ||v||) >= beta_h
 *
 * is, for the piecewise constant multipliers of the LAC method, a matrix
 * statement.  With b(mu, v) = mu^T C^T v (C is ndof x k, lac_newton.h),
 * ||v||^2 = v^T A v (A: a Gram matrix of the displacement space V^h) and
 * ||mu||^2 = mu^T M mu (M: a discrete norm of the multiplier space X^h),
 * the supremum over v is attained at v = A^{-1} C mu, so
 *
 *   beta_h^2 = min_mu (mu^T S mu) / (mu^T M mu),   S = C^T A^{-1} C  (k x k),
 *
 * the smallest eigenvalue of the generalized symmetric-definite problem
 * S mu = beta^2 M mu; its eigenvector is the least stable multiplier
 * pattern.  (Chapelle and Bathe's numerical inf-sup test, 1993, for
 * saddle-point problems.)
 *
 * THE NORMS USED (the estimate depends on them; it is a diagnostic of how
 * beta_h behaves with h and epsilon, not the constant of the proofs):
 *
 *   A = the H1 Gram matrix (default, lac_infsup_gram_h1):  per component,
 *       sum over the cells of int (N_a N_b / ell^2 + grad N_a . grad N_b),
 *       i.e. v^T A v = sum_l (|v|_{1,Omega^l}^2 + ell^-2 ||v||_{0,Omega^l}^2),
 *       the norm of V in [LAC (8)-(10)] made independent of the unit of
 *       length by ell, the diameter of the bounding box of the mesh
 *       (with ell = 1 in mm units the L2 part would dominate on every
 *       mesh coarser than 1 mm, and beta_h would grow with refinement
 *       until h ~ 1 mm: a units artefact); then beta_h is a pure number.
 *       The Dirichlet dofs are eliminated (row and column zeroed, diagonal
 *       kept: the fixed unknowns decouple and, C having zero rows there,
 *       do not enter S).  It is positive definite for every mesh, also
 *       when a body is held by the contact alone.
 *       Axisymmetric: weight 2 pi r and the hoop term u_r^2 / r^2, the H1
 *       norm of the 3D field of revolution.
 *   or A = the energy matrix K of the run (LAC_INFSUP_NORM_ENERGY): the
 *       norm a(v, v)^{1/2}, equivalent to the H1 norm by Korn's inequality
 *       only when every body is fixed against rigid motions; a body held
 *       by contact alone makes K singular and the estimate is refused
 *       (LAC_ESING).  Hence H1 is the default.
 *   M = diag(h_i |T^m_i cap Gamma_C|) (lac_infsup_norm_lac), h_i the
 *       diameter of macro-element T^m_i (node-to-segment multipliers: the
 *       node's tributary measure w_i and h_i = w_i in 2D, sqrt(w_i) in 3D;
 *       axisymmetric w_i include 2 pi r): mu^T M mu = sum_i h_i
 *       ||mu||^2_{0, T^m_i cap Gamma_C}, the h-weighted L2 norm, the usual
 *       computable stand-in for the H^{-1/2} (W') norm of a piecewise
 *       constant: by an inverse inequality h^{1/2} ||mu||_0 <= C ||mu||_{-1/2}
 *       on quasi-uniform meshes, so beta_h in this norm is bounded below
 *       whenever it is in the W' norm, and the two agree for the oscillating
 *       patterns that decide the infimum.
 *
 * The estimator takes any (A, C, M): other multiplier spaces (P0 on the raw
 * trace mesh, node-to-segment) only need their own C and M.
 *
 * TWO COMPUTATIONAL PATHS (same answer, checked against each other to
 * 1e-6 by t851):
 *
 *   dense   (k up to a few thousand) factor A once (CHOLMOD), solve
 *           A X = C for blocks of LAC_INFSUP_BLOCK columns
 *           (lac_solver_solve_many), S = C^T X (k x k, symmetrized), then
 *           all eigenpairs of (S, M) with GSL's gsl_eigen_gensymmv on copies
 *           (it overwrites its inputs and returns them unsorted), sorted
 *           ascending; O(k) solves and O(k^3) flops.
 *   sparse  (large k) never forms S: O(k m) memory for m Lanczos steps
 *           instead of O(k^2 + n b).  The smallest eigenvalue of (S, M) is
 *           the largest, theta = 1/beta^2, of T = S^{-1} M, which is
 *           self-adjoint in the M inner product: Lanczos with full
 *           reorthogonalization on T (shift-and-invert at 0, ARPACK's mode
 *           3).  S^{-1} r is one solve with the saddle-point matrix
 *               [ A    s C ] [ w ]   [ 0 ]
 *               [ s C^T  0 ] [ y ] = [-r ],   S^{-1} r = s^2 y,
 *           factored once by UMFPACK (s = max|A| / max|C| balances the
 *           blocks).  Stopping test: the Ritz residual |b_j y_j| <= tol
 *           theta, which bounds the relative error of beta^2 by tol.
 *           Why not Lanczos or LOBPCG on S itself: the pencil's condition
 *           number grows like 1/h, and the smallest eigenvalues form a
 *           cluster (the checkerboard pattern under a smooth envelope;
 *           lambda_2 / lambda_1 - 1 = 0.3 % for k = 64 in 2D), so they
 *           converge slowly without inversion; inverted, the cluster is
 *           at the top of a spectrum that decays to 0.  It still takes
 *           more steps as k grows and the cluster tightens: measured on
 *           the Taylor blocks 25 steps (k = 64, 3D hex8), 50 (k = 256, 3D),
 *           60 (k = 64, 2D quad4), 88 (k = 100, 2D quad8).  Up to k ~ 1000
 *           the dense path is faster (k CHOLMOD solves against the UMFPACK
 *           factor and solves of the larger indefinite matrix: 4 s against
 *           10 s for k = 256, n = 68 000, hex8; 2.5 s against 26 s for
 *           k = 100, n = 170 000, quad8), hence the AUTO threshold; the
 *           sparse path is for the k where a k x k matrix and O(k^3) flops
 *           no longer fit.
 *
 * If C has dependent columns (two multipliers that no displacement tells
 * apart), S is singular and beta_h = 0: the dense path returns
 * lambda_min ~ 0, the sparse path LAC_ESING with a message.
 *
 * Files.  lac_infsup.c: the driver lac_infsup_estimate and the dense path;
 * lac_infsup_lanczos.[ch]: the sparse path; lac_infsup_gram.c: the
 * matrices A and M (declared here); lac_infsup_types.h: the options and
 * the result, which the driver and the sparse path share.
 *
 * Ownership: inputs are borrowed; lac_infsup_estimate returns a result
 * owned by the caller (lac_infsup_free); lac_infsup_gram_h1 and
 * lac_infsup_norm_lac return CSC matrices freed with lac_csc_free.
 *
 * References: M. Abbas, G. Drouet, P. Hild, The Local Average Contact (LAC)
 * method, 2018, (10), Theorems 1-2, Appendix A; D. Chapelle, K. J. Bathe,
 * The inf-sup test, Computers & Structures 47 (1993) 537-545; Y. Saad,
 * Numerical Methods for Large Eigenvalue Problems, 2nd ed. (SIAM 2011),
 * ch. 6 (Lanczos) and 8 (shift-and-invert).
 */
#ifndef LAC_INFSUP_H
#define LAC_INFSUP_H

#include <stddef.h>
#include "contact/lac_contact.h"
#include "contact/lac_infsup_types.h"
#include "linalg/lac_linalg.h"
#include "contact/lac_macromesh.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

typedef enum
{
  LAC_INFSUP_NORM_H1 = 0,   /* A = H1 Gram matrix (default)                 */
  LAC_INFSUP_NORM_ENERGY    /* A = the stiffness K                          */
} lac_infsup_norm;

#define LAC_INFSUP_DENSE_KMAX 1000  /* AUTO: largest k for the dense path    */
#define LAC_INFSUP_BLOCK 32         /* dense: right-hand sides per solve    */

/* construct / destroy */
void lac_infsup_opts_init (lac_infsup_opts *o);
void lac_infsup_free (lac_infsup *r);                /* NULL allowed */

/* compute */

/* beta_h of [LAC (10)] for the pencil (C^T A^{-1} C, M).
 *   [in]  A     n x n symmetric positive definite (borrowed)
 *   [in]  C     n x k (borrowed), k >= 1
 *   [in]  M     k x k symmetric positive definite (borrowed; diagonal for
 *               the LAC norm, any SPD matrix otherwise)
 *   [in]  opts  NULL for the defaults
 *   [out] out   the result (lac_infsup_free)
 *   returns LAC_SUCCESS, LAC_EBADLEN (sizes), LAC_EINVAL, LAC_ESING (A not
 *   positive definite; sparse path: S singular), LAC_EMAXITER (Lanczos did
 *   not reach tol in maxit steps), LAC_EDEP (GSL), LAC_ENOMEM */
int lac_infsup_estimate (const lac_csc *A, const lac_csc *C,
                         const lac_csc *M, const lac_infsup_opts *opts,
                         lac_infsup **out);

/* The H1 Gram matrix of the displacement space (see the file header),
 * dof = dim*node + component; fixed[dof] != 0 marks the Dirichlet dofs to
 * eliminate (fixed may be NULL: none); ell > 0 the length scale of the L2
 * part (ell <= 0: the diameter of the mesh's bounding box).  LAC_ESING for
 * an inverted cell. */
int lac_infsup_gram_h1 (const lac_mesh *mesh, lac_model model,
                        const char *fixed, double ell, lac_csc **A);

/* The dofs eliminated from a stiffness by lac_dirichlet_apply: columns
 * whose off-diagonal entries are all zero.  fixed: n bytes, set to 0/1;
 * returns their number. */
size_t lac_infsup_fixed_dofs (const lac_csc *K, char *fixed);

/* The LAC multiplier norm M = diag(h_i |T^m_i cap Gamma_C|), h_i the
 * diameter of macro-element c->macro[i] (largest distance between two
 * nodes of its sub-facets); h (k values, may be NULL) receives the h_i. */
int lac_infsup_norm_lac (const lac_mesh *mesh, const lac_macro *Mm,
                         const lac_contact *c, double *h, lac_csc **M);

/* query */

/* Diameter of macro-element m: the largest distance between two nodes of
 * its sub-facets. */
double lac_infsup_macro_diameter (const lac_mesh *mesh, const lac_macro *Mm,
                                  size_t m);

/* "dense" | "sparse" | "auto" */
const char *lac_infsup_path_name (lac_infsup_path p);

#endif /* LAC_INFSUP_H */
