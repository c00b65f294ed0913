/* lac_run_multipliers.h -- the contact multipliers after the solve
 *                                               [LAC (16)-(18); §5.1-5.2]
 *
 * Part of stage 6 (post) of a linear run with contact: where each
 * multiplier sits (the centroid of T^m cap Gamma_C, or the collocation
 * point of node-to-segment), the mean of the exact contact pressure
 * n.sigma.n there when the scene has an [exact] solution, and the errors
 * of the summary: max |lambda_h - lambda| / max |lambda|, the L2 norm of
 * lambda - lambda_h on Gamma_C (lambda_h = 0 on the non-admissible
 * macro-elements), the nodal stresses against the exact ones (and
 * sigma_rr on each body of a radial solution).  Axisymmetric measures
 * carry 2 pi r, as the LAC terms do.
 */
#ifndef LAC_RUN_MULTIPLIERS_H
#define LAC_RUN_MULTIPLIERS_H

#include "fem/lac_exact.h"
#include "run/lac_run_setup.h"
#include "run/lac_run_system.h"
#include "run/lac_summary.h"
#include "solve/lac_newton.h"

typedef struct lac_run_multipliers
{
  double *x;            /* owned, 3 k: where multiplier i sits            */
  double *exact;        /* owned, k: mean exact n.sigma.n there (0: none) */
} lac_run_multipliers;

/* The positions, exact values and the summary lines of the multipliers;
 * sigma: the nodal stresses (ns per node) of stage 6. */
int lac_run_multipliers_post (lac_model model, const lac_mesh *m,
                              const lac_run_setup *setup,
                              const lac_contact *c, const lac_newton *nw,
                              const lac_exact *e, const double *sigma,
                              lac_run_multipliers *mu, lac_summary *sum);
void lac_run_multipliers_clear (lac_run_multipliers *mu);

#endif /* LAC_RUN_MULTIPLIERS_H */
