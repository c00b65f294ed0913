/* lac_newton.h -- generalized Newton / active-set method      [LAC §4.5, Alg. 1]
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
 * paper's blocks [LAC (16)-(17)]; with C^M entering with a minus sign
 * because n^M = -n^S.  The complementarity function of [LAC (18)],
 * written with this convention, is
 *
 *   A_i(U, lambda) = lambda_i - min(0, lambda_i + rho_i d_i) = 0,
 *
 * so macro-element i is ACTIVE (in contact) iff lambda_i + rho_i d_i < 0,
 * and then d_i = 0; otherwise lambda_i = 0.  rho_i > 0 only scales the test
 * (it changes the path, not the solution).
 *
 * A linear scene (K constant) is solved by the primal-dual active set
 * iteration: for a fixed active set the saddle-point system
 *
 *   [ K      -C_A ] [ U        ]   [  F   ]
 *   [ -C_A^T   0  ] [ lambda_A ] = [ -G_A ],   lambda_I = 0,
 *
 * is solved exactly, then the statuses are updated; it stops when no
 * status changes.  The saddle-point matrix is scaled symmetrically
 * (diag(K)^-1/2 on the displacements, the largest scaled entry of each
 * column of C on the multipliers) before it is factorized, so that partly
 * covered macro-elements and contrasts of stiffness do not spoil its
 * conditioning.  Back ends: `umfpack` and `dense` factorize the full
 * saddle system (inactive multipliers get the identity row of [LAC Alg. 1,
 * line 17]); `cholmod` factorizes K once and solves the active set on the
 * Schur complement S_A = C_A^T K^{-1} C_A (dense, k x k), reusing the
 * factor of K across iterations.
 *
 * Usage (INITIALIZE / ITERATE / TEST, the loop belongs to the caller):
 *   lac_newton *s = lac_newton_alloc (kind, n, k);
 *   lac_newton_set (s, &sys);
 *   do { lac_newton_iterate (s); st = lac_newton_test (s); } while (st == LAC_CONTINUE);
 *   lac_newton_free (s);
 * or simply lac_newton_solve (s, &sys, maxit).
 *
 * Ownership: the system's arrays are borrowed and must live until the last
 * call on the workspace; the workspace owns U, lambda and the history.
 */
#ifndef LAC_NEWTON_H
#define LAC_NEWTON_H

#include <stddef.h>
#include "linalg/lac_linalg.h"

typedef struct lac_contact_system
{
  const lac_csc *K;    /* borrowed, n x n, Dirichlet applied (SPD)        */
  const double *F;     /* borrowed, n                                     */
  const lac_csc *C;    /* borrowed, n x k, rows of fixed dofs are zero     */
  const double *G;     /* borrowed, k, mean gaps (fixed dofs moved in);
                          values that are zero up to roundoff must be 0   */
  const double *rho;   /* borrowed, k, scaling of the status test; NULL: 1 */
} lac_contact_system;

typedef struct lac_newton_record
{
  int iter;            /* 1, 2, ...                                         */
  size_t nactive;      /* size of the active set used in this iteration     */
  size_t nchanged;     /* statuses changed by the update after it           */
  double residual;     /* normwise backward error of the equilibrium:
                          ||K U - C lambda - F|| / (||K|| ||U|| + ||C||
                          ||lambda|| + ||F||), infinity norms              */
  double ncp;          /* max_i |A_i(U, lambda)| / max |lambda| (or 1)       */
  double max_penetration; /* max_i (-d_i / |C(:,i)|_1), scale of a length    */
} lac_newton_record;

typedef struct lac_newton
{
  lac_solver_kind kind;
  size_t n, k;
  double *U;           /* owned, n                                         */
  double *lambda;      /* owned, k                                         */
  double *d;           /* owned, k: mean gaps d = G - C^T U                 */
  char *active;        /* owned, k: current status (1 = contact)           */
  size_t nhist, caphist;
  lac_newton_record *hist;  /* owned, nhist records                        */
  /* internals */
  const lac_contact_system *sys;
  lac_solver *solver;  /* owned: K (cholmod) or the saddle matrix          */
  lac_solver *shared;  /* borrowed, NULL: a cholmod solver that factors K
                          with lac_solver_refactor instead of `solver`   */
  lac_csc *Ct;         /* owned: C^T (rows of C^T = multipliers)            */
  double *work;        /* owned, scratch                                   */
  size_t changed;      /* statuses changed by the last update               */
  double normK, normC; /* ||K||_inf, ||C||_inf (for the backward error)   */
  double time_setup;   /* seconds in lac_newton_set (cholmod: factor, S)  */
  double time_solve;   /* seconds in the solves of all iterations          */
  int restarted;       /* 1: the first solve was singular with the initial
                          statuses and was redone with all active          */
  int factored_K;
} lac_newton;

lac_newton *lac_newton_alloc (lac_solver_kind kind, size_t n, size_t k);
void lac_newton_free (lac_newton *s);

/* Factor K with `so` (a cholmod solver the caller owns and keeps between
 * calls) by lac_solver_refactor: a Newton loop on a fixed mesh calls
 * lac_newton_set with a new K_T of the same pattern at every iteration,
 * and the ordering and symbolic analysis are then made once.  Only the
 * Schur path (kind cholmod) uses it. */
void lac_newton_share_solver (lac_newton *s, lac_solver *so);
/* Step 0 of [LAC Alg. 1]: borrow the system, lambda = 0, status active iff
 * G_i <= 0 (closed or penetrating at the start), factorize K (cholmod). */
int lac_newton_set (lac_newton *s, const lac_contact_system *sys);
/* One iteration: solve the saddle system for the current active set,
 * update U, lambda, d and the statuses; append a history record.  If the
 * very first system is singular with some multipliers inactive (a body
 * held by contact alone, starting with open gaps), it is solved again with
 * every multiplier active (s->restarted = 1). */
int lac_newton_iterate (lac_newton *s);
/* LAC_SUCCESS when the last iteration changed no status and the
 * residuals are below tol; LAC_CONTINUE otherwise. */
int lac_newton_test (const lac_newton *s, double tol);
/* The whole loop; LAC_EMAXITER (with a message) if maxit is reached. */
int lac_newton_solve (lac_newton *s, const lac_contact_system *sys,
                      int maxit, double tol);
size_t lac_newton_nactive (const lac_newton *s);

#endif /* LAC_NEWTON_H */
