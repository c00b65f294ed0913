/* lac_complementarity.c -- the status rule (see lac_complementarity.h)
 *                                        [LAC (18), Alg. 1, lines 26-33]
 */
#include "solve/lac_complementarity.h"

#include <math.h>
#include "base/lac_vec.h"

double
lac_complementarity_lmax (size_t k, const double *lambda)
{
  double m = 0;
  for (size_t i = 0; i < k; i++)
    m = fmax (m, fabs (lambda[i]));
  return m;
}

/* lambda + rho d with the values at the level of rounding set to 0. */
static double
test_value (double lambda, double d, double rho, double lmax, double dscale)
{
  return lac_snap (lambda, lmax)
         + rho * lac_snap (d, dscale);
}

int
lac_complementarity_active (double lambda, double d, double rho, double lmax,
                            double dscale)
{
  return test_value (lambda, d, rho, lmax, dscale) < 0;   /* [Alg. 1, l. 28] */
}

double
lac_complementarity_residual (double lambda, double d, double rho,
                              double lmax, double dscale)
{
  double a = test_value (lambda, d, rho, lmax, dscale);
  double lam = lac_snap (lambda, lmax);
  return fabs (lam - (a < 0 ? a : 0.0));          /* lambda - min(0, .) */
}
