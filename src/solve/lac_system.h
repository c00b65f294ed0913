/* lac_system.h -- the LAC system of one active set and its residuals
 *                                                 [LAC (17), (18), Alg. 1]
 *
 * THE SIGN CONVENTION (written once, used everywhere in lac):
 *
 *   lambda_i <= 0          the contact pressure of macro-element i
 *                          (compression is negative, lambda = sigma_N [LAC (6)])
 *   (C^T U)_i              = int_{T^m_i cap Gamma_C} [u_N] dGamma, the mean
 *                          normal jump, [u_N] = (u^S - u^M) . n^S, positive
 *                          when the slave moves into the master
 *   G_i                    = int_{T^m_i cap Gamma_C} g0 dGamma, the mean
 *                          initial gap, positive when open        [LAC (18)]
 *   d_i = G_i - (C^T U)_i  the mean gap after deformation, >= 0 when there
 *                          is no (mean) interpenetration
 *
 *   equilibrium      K U - C lambda = F                      [LAC (8), (17)]
 *   contact          d >= 0,  lambda <= 0,  lambda_i d_i = 0  [LAC (18)]
 *
 * C has one column per admissible macro-element: C(:,i) = C^S - C^M in the
 * paper's blocks [LAC (16)-(17)], with C^M entering with a minus sign
 * because n^M = -n^S.  For a fixed active set A (the statuses, 1 = in
 * contact) Algorithm 1 solves, at its line 21, the saddle-point system
 *
 *   [ K      -C_A ] [ U        ]   [  F   ]
 *   [ -C_A^T   0  ] [ lambda_A ] = [ -G_A ],   lambda_I = 0.          (*)
 *
 * The system also carries what the strategies need to know about K
 * (solve/lac_strategy.h): N, a basis of the rigid motions that the
 * Dirichlet conditions leave free (bodies held by contact alone), each
 * with a description for the messages.  K is positive definite iff N is
 * empty; K + C_A W C_A^T is iff C_A^T N has full column rank, i.e. the
 * active multipliers hold every such body.
 *
 * Ownership: everything in lac_contact_system is borrowed.
 */
#ifndef LAC_SYSTEM_H
#define LAC_SYSTEM_H

#include <stddef.h>
#include "linalg/lac_linalg.h"

struct lac_dist_source;        /* fem/lac_assembly_dist.h */
struct lac_post_request;       /* fem/lac_post_dist.h */

/* K without its entries: what the residuals need of it when no process
 * holds it whole (the petsc strategy, whose processes hold its rows:
 * solve/lac_petsc.h).  mult: y = K x (n); norm: ||K||_inf, known once K
 * was assembled (an error before); both collective calls or answers of
 * the processes. */
typedef struct lac_stiffness_op
{
  size_t n;
  void *self;
  int (*mult) (void *self, const double *x, double *y);
  int (*norm) (void *self, double *value);
} lac_stiffness_op;

typedef struct lac_contact_system
{
  const lac_csc *K;    /* borrowed, n x n, Dirichlet applied (symmetric);
                          NULL: Kop                                       */
  const double *F;     /* borrowed, n                                     */
  const lac_csc *C;    /* borrowed, n x k, rows of fixed dofs are zero     */
  const double *G;     /* borrowed, k, mean gaps (fixed dofs moved in);
                          values that are zero up to roundoff must be 0   */
  const double *rho;   /* borrowed, k, scaling of the status test; NULL:
                          E / (h_i |T^i cap Gamma_C|) (solve/lac_newton.h) */
  size_t nfree;        /* free rigid motions (0: every body held)         */
  const double *N;     /* borrowed, n x nfree, column after column        */
  const char *const *N_what;  /* borrowed, nfree: "body 'upper':
                          translation along z", or NULL                    */
  const lac_stiffness_op *Kop; /* borrowed; used when K is NULL          */
} lac_contact_system;

/* The equations of the multipliers for a contact law other than the
 * frictionless one (Coulomb friction, solve/lac_friction.h), in place of
 * the statuses of (*).  The columns of C come q at a time, one group per
 * macro-element (q = 1 + ntan: the normal column, then the tangential
 * ones); row j of group g = j / q reads, over the columns of its group,
 *
 *   sum_a P[j q + a] (-c_{g q + a}^T U) + sum_a Q[j q + a] lambda_{g q + a}
 *     = r[j],
 *
 * so that the system of one iteration is
 *
 *   [ K        -C ] [ U      ]   [ F ]
 *   [ -P C^T    Q ] [ lambda ] = [ r ]      (P, Q block diagonal).
 *
 * The frictionless law is q = 1, P = 1, Q = 0, r = -G on the active
 * multipliers and P = 0, Q = 1, r = 0 on the others: (*) itself.  The
 * system is not symmetric where P differs from Q's pattern (the slip of
 * friction): only the strategies with a solve_rows operation solve it.
 * Ownership: borrowed. */
typedef struct lac_contact_rows
{
  int q;                 /* columns (multiplier components) per group     */
  const double *P, *Q;   /* k q each: row j's q coefficients at j q       */
  const double *r;       /* k: the right-hand sides                       */
  const char *free;      /* k: 1 if lambda_j is an unknown; 0 where row j
                            is lambda_j = 0 (then lambda_j = 0)           */
} lac_contact_rows;

/* What the Cholesky-based solvers of (*) did (solve/lac_schur.h,
 * solve/lac_augmented.h). */
typedef struct lac_solve_counts
{
  int factorizations;  /* numeric factorizations                         */
  int analyses;        /* orderings and symbolic analyses                */
  int solves;          /* forward and back substitutions                 */
  int iterations;      /* conjugate-gradient iterations, all solves      */
  double rcond;        /* condition estimate of the last factorization   */
  double time_factor;  /* seconds in analyses and factorizations         */
  double flops;        /* floating-point operations of the numeric
                          factorizations, summed (the analyses' counts)  */
  int last_iterations; /* Krylov iterations of the last solve            */
  double last_residual; /* its relative residual ||b - A x|| / ||b||      */
  int processes;       /* MPI processes that solve (0: one, no MPI)      */
} lac_solve_counts;

/* The operations of one way of solving (*): a strategy's type
 * (solve/lac_strategy.h; one file each).  w: the workspace alloc made;
 * the system is borrowed from set (or reset) until the next one or free.
 * NULL marks an optional operation. */
typedef struct lac_strategy_ops
{
  void *(*alloc) (void);                 /* NULL, a message, if it fails */
  void (*free) (void *w);
  /* Borrow the system; factorize what depends on K alone, or nothing. */
  int (*set) (void *w, const lac_contact_system *sys);
  /* Optional: another C, the factorization of the last set's K kept. */
  int (*reset) (void *w, const lac_contact_system *sys);
  /* Optional: other right-hand sides F, G (sys: as many dofs and
   * columns), the factorization and the C of the last set or reset kept
   * with everything made of them: the solves are those of the older
   * system, a preconditioner of the new one. */
  int (*keep) (void *w, const lac_contact_system *sys);
  /* U, lambda of (*) for the statuses `active` (k = 0 too: K U = F),
   * right-hand sides f, g (NULL: F, G); U, lambda: start on entry,
   * solution on return (lambda_i = 0 where inactive); rtol: of an inner
   * Krylov method. */
  int (*solve) (void *w, const char *active, const double *f,
                const double *g, double rtol, double *U, double *lambda);
  void (*get_counts) (const void *w, lac_solve_counts *c);
  /* Optional: 1 if the last error was a Cholesky factorization (not
   * positive definite), what triggers the fallback. */
  int (*factor_failed) (const void *w);
  /* Optional: what solves, e.g. "projected cg + gamg on K_W, 2
   * processes" (else the type's name). */
  const char *(*method) (const void *w);
  /* Optional: nodal coordinates (dof = dim * node + comp), before set. */
  void (*set_coordinates) (void *w, int dim, const double *x);
  /* Optional: the cells K was assembled from (fem/lac_assembly_dist.h),
   * before set: a type that assembles K itself may use them. */
  void (*set_mesh) (void *w, const struct lac_dist_source *src);
  /* Optional: y = K x and ||K||_inf with the K of the last set, from
   * the type's own copy (the residuals of a system whose K is NULL:
   * Kop); own_k: 1 if the type assembles that copy for these n dofs from
   * set_mesh's cells, so that the caller's K may be NULL. */
  int (*kmul) (void *w, const double *x, double *y);
  int (*knorm) (const void *w, double *norm);
  int (*own_k) (const void *w, size_t n);
  /* Optional, with own_k: the stresses and errors of the solution from
   * the cells, on the processes that hold them (fem/lac_post_dist.h). */
  int (*post) (void *w, struct lac_post_request *p);
  /* Optional: U, lambda of the system of a contact law's equations R
   * (lac_contact_rows), right-hand sides f and r (NULL: F and R->r);
   * lambda_j = 0 where R->free[j] is 0.  Without it the type solves only
   * the frictionless law. */
  int (*solve_rows) (void *w, const lac_contact_rows *R, const double *f,
                     const double *r, double *U, double *lambda);
} lac_strategy_ops;

/* Residuals of (U, lambda) for the active set `active` (NULL: all):
 *   r = F - K U + C_A lambda_A   (n),   g = G_A - C_A^T U   (k; 0 on I).
 * *berr: the normwise backward error of (*) in infinity norms,
 *   max(||r||, ||g||) / (||K|| ||U|| + ||C|| ||lambda|| + ||F|| + ||G||),
 * whatever the units and the contrast of the stiffnesses.  An error only
 * from Kop's product. */
int lac_system_residual (const lac_contact_system *sys, const char *active,
                         const double *U, const double *lambda,
                         double *r, double *g, double *berr);
/* The residuals of (U, lambda) for the equations R of a contact law:
 *   res_f = F - K U + C lambda (n),
 *   res_r_j = r_j - (P (-C^T U) + Q lambda)_j (k; 0 where R->free is 0),
 * and the normwise backward error as for lac_system_residual (with r in
 * place of G). */
int lac_system_rows_residual (const lac_contact_system *sys,
                              const lac_contact_rows *R, const double *U,
                              const double *lambda, double *res_f,
                              double *res_r, double *berr);
/* n, K's order (K or Kop). */
size_t lac_system_n (const lac_contact_system *sys);
/* y = K x (K or Kop). */
int lac_system_k_mult (const lac_contact_system *sys, const double *x,
                       double *y);
/* ||K||_inf (max row sum; K symmetric: lac_csc_diag_norm1).  An error
 * only from Kop's norm. */
int lac_system_norm_k (const lac_contact_system *sys, double *normK);
/* ||C||_inf (max row sum). */
int lac_system_norm_c (const lac_contact_system *sys, double *normC);
/* d = G - C^T U (k). */
void lac_system_gaps (const lac_contact_system *sys, const double *U,
                      double *d);
/* Do the active multipliers hold the bodies held by contact alone?
 * LAC_SUCCESS if C_A^T N has full column rank; otherwise LAC_ESING with a
 * message naming the free motion (N_what) that no active multiplier
 * touches, and the number of active multipliers. */
int lac_system_check_held (const lac_contact_system *sys, const char *active);
/* The scale of each multiplier seen from K's diagonal,
 *   s_i = c_i^T diag(K)^{-1} c_i   (k; partly covered macro-elements
 * have small columns), which sets W_i = omega / s_i of the augmented
 * strategies; work: n doubles (diag(K)^{-1} on return).  K, not Kop
 * (the petsc strategy takes the same sums on its processes). */
void lac_system_column_scales (const lac_contact_system *sys, double *work,
                               double *s);
/* A numeric factorization of A with `chol` (lac_solver_refactor: the
 * analysis kept while the pattern is), counted in c: factorizations,
 * analyses, the two solves of the condition estimate, its time, rcond
 * and flops. */
int lac_solve_counts_factor (lac_solve_counts *c, lac_solver *chol,
                             const lac_csc *A);
/* The same counts for a factorization made elsewhere (two at once,
 * solve/lac_split.c), without its time. */
void lac_solve_counts_factored (lac_solve_counts *c, const lac_solver *chol);
/* After a Krylov solve for the na active multipliers that returned
 * `status`: its iterations and final relative residual counted in c.
 * Returns status, with LAC_EMAXITER and LAC_ESING (a breakdown) turned
 * into LAC_ESING and a message: the multipliers are not determined, the
 * contact constraints are linearly dependent [LAC (10)]. */
int lac_solve_counts_krylov (lac_solve_counts *c, int status, int iterations,
                             double residual, size_t na);

#endif /* LAC_SYSTEM_H */
