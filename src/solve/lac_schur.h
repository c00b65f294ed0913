/* lac_schur.h -- the multipliers of one active set through the Schur
 *                complement of K                  [LAC (17), Alg. 1 l. 21]
 *
 * Strategy (a) of solve/lac_strategy.h, for bodies all held by their
 * Dirichlet conditions (K symmetric positive definite):
 *
 *   K = L L^T (CHOLMOD), once per matrix;
 *   S(:, i) = C^T K^{-1} c_i for every multiplier i that is active, the
 *     first time it is (blocks of LAC_SCHUR_BLOCK right-hand sides), kept:
 *     a later active set only adds the columns of its new members;
 *   S_AA lambda_A = g_A - C_A^T K^{-1} f    (dense Cholesky, k_A x k_A);
 *   U = K^{-1} (f + C_A lambda_A).
 *
 * A linear scene factorizes K once and pays for each column of S once,
 * whatever the number of active-set iterations; a large-deformation step
 * (a new K every iteration) pays for the active columns at every
 * iteration.  Chapter 07 compares it with the augmented strategy (b).
 *
 * Ownership: the system is borrowed from lac_schur_set until the next set
 * or lac_schur_free.
 */
#ifndef LAC_SCHUR_H
#define LAC_SCHUR_H

#include "solve/lac_system.h"

#define LAC_SCHUR_BLOCK 64

typedef struct lac_schur lac_schur;     /* opaque */

lac_schur *lac_schur_alloc (void);
void lac_schur_free (lac_schur *s);      /* NULL allowed */
/* Borrow the system, factorize K (the analysis kept for a K of the same
 * pattern), forget the columns of S. */
int lac_schur_set (lac_schur *s, const lac_contact_system *sys);
/* Borrow a system with the same K as the last set's (or a K whose old
 * factorization will do, as a preconditioner) and another C: keep the
 * factorization, forget the columns of S. */
int lac_schur_reset (lac_schur *s, const lac_contact_system *sys);
/* U, lambda of (*) for the statuses `active`, right-hand sides f, g
 * (NULL: F, G); lambda_i = 0 where inactive. */
int lac_schur_solve (lac_schur *s, const char *active, const double *f,
                     const double *g, double *U, double *lambda);
void lac_schur_get_counts (const lac_schur *s, lac_solve_counts *c);

#endif /* LAC_SCHUR_H */
