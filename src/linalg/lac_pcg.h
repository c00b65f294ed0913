/* lac_pcg.h -- preconditioned conjugate gradients on a small SPD system
 *
 * Solves A x = b for a symmetric positive definite A given only by its
 * action y = A x, with a preconditioner z = M^{-1} r (Hestenes-Stiefel,
 * in the form of Saad, Iterative Methods for Sparse Linear Systems, 2nd
 * ed., Algorithm 9.1).  lac uses it for the contact multipliers: A is a
 * Schur complement C_A^T K^{-1} C_A whose every product costs one solve
 * with a factor of K (solve/lac_strategy.h), so the number of iterations
 * is the price, and it is reported.
 *
 * The start x is given (a warm start: the multipliers of the previous
 * active-set iteration); it stops when the recursively updated residual
 * satisfies ||r||_2 <= rtol ||b||_2, or after maxit iterations
 * (LAC_EMAXITER, message with the residual reached).  A breakdown (p^T A p
 * <= 0: A not positive definite) is LAC_ESING.
 *
 * Ownership: the caller's arrays are borrowed; the work space is
 * allocated and freed inside.
 */
#ifndef LAC_PCG_H
#define LAC_PCG_H

#include <stddef.h>

/* y = A x (or z = M^{-1} r); returns a status. */
typedef int (*lac_linop) (void *ctx, const double *x, double *y);

typedef struct lac_pcg_info
{
  int iterations;       /* products with A                               */
  double residual;      /* ||r||_2 / ||b||_2 at the end (recursive r)     */
} lac_pcg_info;

/* x = A^{-1} b to rtol, from the start x; M NULL: no preconditioner. */
int lac_pcg (size_t n, lac_linop A, lac_linop M, void *ctx, const double *b,
             double *x, double rtol, int maxit, lac_pcg_info *info);

#endif /* LAC_PCG_H */
