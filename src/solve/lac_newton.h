/* lac_newton.h -- generalized Newton / active-set method      [LAC §4.5, Alg. 1]
 *
 * The sign convention and the saddle-point system (*) of one active set
 * are written once, in solve/lac_system.h; the status rule (the
 * complementarity function A_i = lambda_i - min(0, lambda_i + rho_i d_i))
 * in solve/lac_complementarity.h; how (*) is solved in
 * solve/lac_strategy.h.
 *
 * A linear scene (K constant) is solved by the primal-dual active set
 * iteration (a semismooth Newton method on A(U, lambda) = 0): for the
 * current statuses, (*) is solved exactly (warm-started from the previous
 * iterate), then the statuses are updated by the rule; it stops when no
 * status changes and the residuals are below tol.
 *
 * Start [LAC Alg. 1, lines 2-8]: active iff G_i <= 0 (closed or
 * penetrating at the start), or the statuses given to lac_newton_set (the
 * previous load step's).  If these statuses do not hold a body held by
 * contact alone (lac_system_check_held: its stiffness alone is singular),
 * the iteration starts instead from the multipliers of the smallest
 * initial gaps, 1, 2, 4, ... of them until they hold every body
 * (restarted = 1, held_start = their number; every multiplier if fewer
 * do not hold): the first solve presses the bodies on these, and the
 * first-contact rule below picks the zone among the elements it makes
 * penetrate.  (Starting from every multiplier active, the rule released
 * the elements in tension a ring at a time: 19/22/24 iterations for
 * chapter 10's sphere on a rigid flat, tet10 levels 0/1/2, against 3/5/5
 * from this start.)
 *
 * First contact: when the first solve had no active multiplier (bodies
 * apart at the start), or only those of the held start, only the
 * elements switched on that penetrate by at least
 * LAC_NEWTON_FIRST_CONTACT times the deepest penetration are switched on
 * (Hertz: the contact radius of a pressed paraboloid is where the overlap
 * is half the deepest); the rule switches on the others at the next
 * iteration if they belong to the contact.  The solution is the same; the
 * overlap of a curved body, wider than its contact zone, is not taken
 * whole and released half an excess per iteration.
 *
 * Safeguard against cycling: the statuses of every iteration are
 * remembered (a checksum); when the rule would return to statuses already
 * tried, only the most violated half of its changes is made (the
 * largest |A_i|, at least one), which breaks the cycle.
 *
 * Usage (INITIALIZE / ITERATE / TEST, the loop belongs to the caller):
 *   lac_newton *s = lac_newton_alloc (strategy, n, k);
 *   lac_newton_set (s, &sys, NULL);
 *   do { lac_newton_iterate (s); report s->hist[s->nhist - 1];
 *        st = lac_newton_test (s, tol); } while (st == LAC_CONTINUE);
 *   lac_newton_free (s);
 * or simply lac_newton_solve (s, &sys, maxit, tol).
 *
 * Ownership: the system's arrays are borrowed and must live until the last
 * call on the workspace; the workspace owns U, lambda, the statuses, the
 * strategy and the history.
 */
#ifndef LAC_NEWTON_H
#define LAC_NEWTON_H

#include <stddef.h>
#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

/* Fraction of the deepest penetration switched on at the first contact. */
#define LAC_NEWTON_FIRST_CONTACT 0.5
/* The same after a held start: the first solve pressed the bodies on a
 * few elements, its penetrations are those of a load concentrated there,
 * not of a rigid approach; the zone is grown from its deepest elements
 * instead (measured on chapter 10's sphere on a rigid flat, tet10 levels
 * 0/1/2: 7/10/- active-set iterations with 0.5, 4/6/8 with 0.9, 3/5/5
 * with 0.95, 7/6/5 with 0.99). */
#define LAC_NEWTON_HELD_CONTACT 0.95

typedef struct lac_newton_record
{
  int iter;            /* 1, 2, ...                                         */
  size_t nactive;      /* size of the active set used in this iteration     */
  size_t nchanged;     /* statuses changed by the update after it           */
  double residual;     /* normwise backward error of (*) (lac_system.h)    */
  double ncp;          /* max_i |A_i(U, lambda)| / max |lambda| (or 1)       */
  double max_penetration; /* max_i (-d_i / |C(:,i)|_1), scale of a length    */
  int cg_iterations;   /* conjugate-gradient iterations of this solve       */
  int krylov_iterations; /* petsc: Krylov iterations of its first solve     */
  double krylov_residual; /* petsc: that solve's true relative residual    */
  int factorizations;  /* numeric factorizations of this solve              */
  int damped;          /* 1: the cycle safeguard limited the changes        */
  double seconds;      /* wall time of the iteration                       */
} lac_newton_record;

typedef struct lac_newton
{
  lac_strategy_kind kind;  /* the strategy asked for (concrete)             */
  size_t n, k;
  double *U;           /* owned, n                                         */
  double *lambda;      /* owned, k                                         */
  double *d;           /* owned, k: mean gaps d = G - C^T U                 */
  char *active;        /* owned, k: current status (1 = contact)           */
  size_t nhist, caphist;
  lac_newton_record *hist;  /* owned, nhist records                        */
  lac_strategy *strategy;   /* owned: solves (*) for the statuses          */
  int restarted;       /* 1: the initial statuses did not hold a body      */
  size_t held_start;   /* then: multipliers of the smallest gaps switched on */
  /* internals */
  const lac_contact_system *sys;
  size_t changed;      /* statuses changed by the last update               */
  double normC;        /* ||C||_inf (penetration scale)                   */
  unsigned long long *seen;  /* owned, nhist + 1: checksums of the statuses */
  double *work;        /* owned, 3 k                                       */
} lac_newton;

/* kind: a concrete strategy (lac_strategy_choose). */
lac_newton *lac_newton_alloc (lac_strategy_kind kind, size_t n, size_t k);
void lac_newton_free (lac_newton *s);

/* Step 0 of [LAC Alg. 1]: borrow the system, U = 0, lambda = 0, the
 * statuses active0 (k flags) or, if NULL, active iff G_i <= 0; set up the
 * strategy (a factorization for schur). */
int lac_newton_set (lac_newton *s, const lac_contact_system *sys,
                    const char *active0);
/* One iteration: solve (*) for the current statuses, update U, lambda, d
 * and the statuses; append a history record. */
int lac_newton_iterate (lac_newton *s);
/* LAC_SUCCESS when the last iteration changed no status and the
 * residuals are below tol; LAC_CONTINUE otherwise. */
int lac_newton_test (const lac_newton *s, double tol);
/* The whole loop; LAC_EMAXITER (with a message naming the status changes
 * of the last iteration) if maxit is reached. */
int lac_newton_solve (lac_newton *s, const lac_contact_system *sys,
                      int maxit, double tol);
/* The LAC_EMAXITER message of lac_newton_solve, for a caller's loop. */
int lac_newton_maxiter_error (const lac_newton *s, int maxit);
size_t lac_newton_nactive (const lac_newton *s);

#endif /* LAC_NEWTON_H */
