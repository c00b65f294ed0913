/* lac_infsup_lanczos.h -- the sparse path of the inf-sup estimate
 *                                                        [LAC (10)]
 *
 * The smallest eigenpair of S mu = lambda M mu, S = C^T A^{-1} C, without
 * forming S: shift-invert Lanczos on S^{-1} M (lac_infsup_lanczos.c, where
 * the method is described).  lac_infsup_estimate (lac_infsup.h) chooses
 * this path for large k, then normalizes the eigenvector.
 */
#ifndef LAC_INFSUP_LANCZOS_H
#define LAC_INFSUP_LANCZOS_H

#include "contact/lac_infsup_types.h"
#include "linalg/lac_linalg.h"

/* Fills r->lambda_min, lambda_2 (the next Ritz value), lambda_max (NAN),
 * mu (the Ritz vector, not normalized), residual (the Ritz bound) and
 * iterations; r->k = C->ncol and r->mu (k entries) are the caller's.
 * o->tol and o->maxit bound the iteration.  LAC_EINVAL (maxit = 0),
 * LAC_ESING (C = 0, or S singular), LAC_EMAXITER, LAC_EDEP, LAC_ENOMEM. */
int lac_infsup_sparse (const lac_csc *A, const lac_csc *C, const lac_csc *M,
                       const lac_infsup_opts *o, lac_infsup *r);

#endif /* LAC_INFSUP_LANCZOS_H */
