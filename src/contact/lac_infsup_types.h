/* lac_infsup_types.h -- options and result of the inf-sup estimate
 *                                                        [LAC (10)]
 *
 * Header only.  What the driver lac_infsup_estimate (lac_infsup.h: the
 * mathematics, the norms, the two paths) and its sparse path
 * (lac_infsup_lanczos.h) share: the choice of path, the options, and the
 * result, whose eigenvector the driver normalizes for both paths.
 *
 * Ownership: the result owns mu (lac_infsup_free, lac_infsup.h).
 */
#ifndef LAC_INFSUP_TYPES_H
#define LAC_INFSUP_TYPES_H

#include <stddef.h>

typedef enum
{
  LAC_INFSUP_AUTO = 0,   /* dense if k <= LAC_INFSUP_DENSE_KMAX, else sparse */
  LAC_INFSUP_DENSE,
  LAC_INFSUP_SPARSE
} lac_infsup_path;

typedef struct lac_infsup_opts
{
  lac_infsup_path path;  /* AUTO                                            */
  double tol;            /* sparse: relative Ritz residual (1e-10)          */
  size_t maxit;          /* sparse: Lanczos steps at most (500)             */
} lac_infsup_opts;

typedef struct lac_infsup
{
  size_t n, k;          /* dofs (rows of C), multipliers (columns of C)     */
  lac_infsup_path path; /* the path used (DENSE or SPARSE)                  */
  double beta;          /* beta_h = sqrt(max(lambda_min, 0))     [LAC (10)] */
  double lambda_min;    /* smallest eigenvalue of S mu = lambda M mu        */
  double lambda_2;      /* the next one (dense; sparse: the next Ritz value,
                           NAN if not available)                            */
  double lambda_max;    /* largest (dense only; NAN for sparse)             */
  double *mu;           /* owned, k: its eigenvector, mu^T M mu = 1,
                           mu[imax] > 0                                     */
  size_t imax;          /* argmax_i |mu_i| (the first within 1e-6 of the
                           largest): the least stable multiplier            */
  size_t iterations;    /* sparse: Lanczos steps; dense: 0                  */
  double residual;      /* ||S mu - lambda M mu||_2 / (lambda ||M mu||_2)
                           (dense: computed with S; sparse: the Ritz bound) */
} lac_infsup;

#endif /* LAC_INFSUP_TYPES_H */
