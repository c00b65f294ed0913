/* lac_infsup_internal.h -- internal: shared by the lac_infsup*.c files
 *
 * Not part of the public interface: the two computational paths of
 * lac_infsup_estimate (lac_infsup.h) and the normalization they share.
 * Both fill r->lambda_min, lambda_2, lambda_max, mu (normalized), imax,
 * residual, iterations and path; the driver sets beta.
 */
#ifndef LAC_INFSUP_INTERNAL_H
#define LAC_INFSUP_INTERNAL_H

#include "contact/lac_infsup.h"

/* Dense path: sA holds the CHOLMOD factor of A (lac_infsup.c). */
int lac_infsup_dense (lac_solver *sA, const lac_csc *C, const lac_csc *M,
                      lac_infsup *r);

/* Sparse path: shift-invert Lanczos (lac_infsup_lanczos.c). */
int lac_infsup_sparse (const lac_csc *A, const lac_csc *C, const lac_csc *M,
                       const lac_infsup_opts *o, lac_infsup *r);

/* mu^T M mu = 1, largest entry positive, imax set; work: k doubles. */
void lac_infsup_normalize (const lac_csc *M, lac_infsup *r, double *work);

#endif /* LAC_INFSUP_INTERNAL_H */
