/* lac_active.h -- the active multipliers of an augmented solve of (*)
 *                                                 [LAC (17), Alg. 1 l. 21]
 *
 * The strategies that add C_A W_A C_A^T to K (solve/lac_augmented.h,
 * solve/lac_split.h) solve for the active multipliers lambda_A by a Krylov
 * method, from the given lambda, with the weights
 *
 *   W_i = omega / s_i,   s_i = c_i^T diag(K)^{-1} c_i   (lac_system.h),
 *
 * on the active ones, 0 on the others.  lac_active holds what they share:
 * the scales s, the weights of the current factor and the statuses it was
 * made for (a factor is made again only when they change), the list of
 * the active columns, and the right-hand side and unknown of the
 * iteration.  Index a < na is the a-th active multiplier, idx[a] its
 * column of C.
 *
 * Ownership: the arrays are owned (lac_active_init ... lac_active_clear).
 */
#ifndef LAC_ACTIVE_H
#define LAC_ACTIVE_H

#include <stddef.h>
#include "linalg/lac_linalg.h"

typedef struct lac_active
{
  double omega;        /* W_i = omega / s_i                              */
  size_t k;            /* multipliers                                    */
  double *s;           /* owned, k: the scales s_i                       */
  double *w;           /* owned, k: W_i of the factor, 0 if inactive     */
  char *factored_for;  /* owned, k: the statuses of the factor           */
  int have_factor;     /* w and factored_for are those of a factor       */
  size_t na, *idx;     /* owned, k: the active columns                   */
  double *b, *lamA;    /* owned, k: right-hand side, unknown (na used)   */
} lac_active;

/* Arrays for k multipliers (those held before are freed), no factor;
 * omega is kept.  LAC_SUCCESS or LAC_ENOMEM (message set). */
int lac_active_init (lac_active *act, size_t k);
void lac_active_clear (lac_active *act);     /* the arrays; omega is kept */
/* Does `active` need a new factor (none yet, or other statuses than
 * factored_for)?  If so w = W for these statuses, and 1 is returned;
 * lac_active_factored records them once the factor is made. */
int lac_active_weights (lac_active *act, const char *active);
void lac_active_factored (lac_active *act, const char *active);
/* na, idx and the start lamA from the statuses and lambda (k). */
void lac_active_gather (lac_active *act, const char *active,
                        const double *lambda);
/* x += C_A v (v: na values). */
void lac_active_add_C (const lac_active *act, const lac_csc *C, const double *v,
                       double *x);
/* q = C_A^T U (na values). */
void lac_active_Ct (const lac_active *act, const lac_csc *C, const double *U,
                    double *q);
/* b = g_A - C_A^T U: the right-hand side of the iteration. */
void lac_active_rhs (lac_active *act, const lac_csc *C, const double *g,
                     const double *U);
/* lambda (k) = lamA on the active multipliers, 0 on the others. */
void lac_active_scatter (const lac_active *act, double *lambda);

#endif /* LAC_ACTIVE_H */
