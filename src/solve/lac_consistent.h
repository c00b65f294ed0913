/* lac_consistent.h -- the consistent Newton step of the large-deformation
 *                     loop                        [LAC §4.5, Alg. 1; §5.4]
 *
 * An iteration of solve/lac_nonlinear.h solves, for the statuses of the
 * moment (A: active), the saddle system of the frozen geometry
 *
 *   [ K_T    -C_A ] [ dU       ]   [ r ]        r = t F - F_int(U)
 *   [ C_A^T    0  ] [ lambda_A ] = [ d_A ]      d = the mean gaps d(U)
 *
 * with a strategy of solve/lac_strategy.h (a Cholesky factorization of
 * K_T and the Schur complement of the multipliers, or another).  The
 * exact Newton step of the same residual (contact/lac_contact_tangent.h:
 * H = d(C lambda)/dU at the last multipliers, B = -d(d)/dU) solves
 *
 *   [ K_T - H  -C_A ] [ dU       ]   [ r ]
 *   [ B_A^T      0  ] [ lambda_A ] = [ d_A ]                          (**)
 *
 * which is not symmetric: a Cholesky factorization does not apply.  So
 * (**) is solved by flexible GMRES (linalg/lac_gmres.h) preconditioned by
 * the frozen system: each iteration is one solve of the strategy with
 * its factors (no new factorization), and since H and B - C are small
 * beside K_T and C when |lambda| is small beside the stiffness, a few
 * iterations are enough.  The frozen solution is the start; the gap rows
 * are scaled by ||K|| / ||C|| so that both kinds of rows count in the
 * Euclidean norm; Dirichlet rows are those of K_T as the Dirichlet data
 * left them (lac_dirichlet_apply) and the correction is zero there.
 *
 * Accuracy: the step is accurate to eta times the norm of the right-hand
 * side of (**) (an inexact Newton method: eta of the order of the Newton
 * residual keeps the convergence quadratic).  If GMRES does not get
 * there in maxit iterations the best step found is kept (and reported).
 *
 * The strategy's factorization may be older than K_T (lac_strategy_reset:
 * the factor of an earlier iteration kept): it is only the preconditioner,
 * the step is the exact one all the same, in a few more iterations.
 *
 * Ownership: everything in lac_consistent is borrowed.
 */
#ifndef LAC_CONSISTENT_H
#define LAC_CONSISTENT_H

#include <stddef.h>
#include "contact/lac_contact_tangent.h"
#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

/* GMRES's restart length: the Krylov basis kept before a restart. */
#define LAC_CONSISTENT_RESTART 30

typedef struct lac_consistent
{
  const lac_contact_system *sys;  /* the frozen system (K, C with the
                                     Dirichlet rows, F = r, G = d_A with the
                                     Dirichlet values moved in)            */
  lac_strategy *strategy;         /* set (or reset) on sys: its solve
                                     preconditions                         */
  const lac_contact_tangent *T;   /* H and B                                */
  const char *fixed;              /* n: Dirichlet dofs                      */
  const double *d;                /* k: the mean gaps d(U) (no Dirichlet
                                     value moved in)                       */
  const char *active;             /* k: the statuses of the solve           */
  double eta;                     /* relative accuracy asked (> 0)          */
  int maxit;                      /* GMRES iterations (0: 60)               */
} lac_consistent;

typedef struct lac_consistent_info
{
  int iterations;                 /* GMRES iterations (preconditioner
                                     solves)                               */
  double residual;                /* of (**), relative to its right-hand
                                     side, at the end                      */
  double start;                   /* the same for the frozen solution       */
} lac_consistent_info;

/* On entry dU, lambda (n, k) are the frozen system's solution (dU with
 * the Dirichlet increments), on return the step of (**); lambda_i = 0
 * where inactive.  LAC_ENOMEM or the strategy's error. */
int lac_consistent_solve (const lac_consistent *cs, double *dU,
                          double *lambda, lac_consistent_info *info);

#endif /* LAC_CONSISTENT_H */
