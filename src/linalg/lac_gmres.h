/* lac_gmres.h -- flexible GMRES with restarts for a non-symmetric system
 *
 * Solves A x = b for a general A given only by its action y = A x, with a
 * right preconditioner z = M^{-1} v that may change from one application
 * to the next (FGMRES: Saad, Iterative Methods for Sparse Linear Systems,
 * 2nd ed., Algorithm 9.6; Givens rotations keep the least-squares
 * residual at hand).  lac uses it for the consistent Newton step of the
 * large-deformation loop: A is the exact tangent, M^{-1} the solve of the
 * frozen-geometry system by a direct factorization (solve/lac_strategy.h),
 * so that A M^{-1} is close to the identity and a few iterations suffice;
 * every iteration costs one solve with the factors, no factorization.
 *
 * The start x is given; it stops when the least-squares residual
 * satisfies ||b - A x||_2 <= rtol ||b||_2 (the true residual is checked at
 * every restart), or after maxit products with A (LAC_EMAXITER, message
 * with the residual reached).
 *
 * Ownership: the caller's arrays are borrowed; the work space ((2 m + 1)
 * vectors) is allocated and freed inside.
 */
#ifndef LAC_GMRES_H
#define LAC_GMRES_H

#include <stddef.h>
#include "linalg/lac_pcg.h"

typedef struct lac_gmres_info
{
  int iterations;       /* products with A (and applications of M^{-1})  */
  double residual;      /* ||b - A x||_2 / ||b||_2 at the end             */
} lac_gmres_info;

/* x = A^{-1} b to rtol, from the start x, restarted every m iterations
 * (m <= 0: 30); M NULL: no preconditioner. */
int lac_gmres (size_t n, lac_linop A, lac_linop M, void *ctx, const double *b,
               double *x, double rtol, int m, int maxit, lac_gmres_info *info);

#endif /* LAC_GMRES_H */
