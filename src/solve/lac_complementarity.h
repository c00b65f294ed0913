/* lac_complementarity.h -- the status rule of the generalized Newton method
 *                                        [LAC (18), Alg. 1, lines 26-33]
 *
 * The conditions d_i >= 0, lambda_i <= 0, lambda_i d_i = 0 of macro-element
 * i (the signs of solve/lac_system.h) are the one equation
 *
 *   A_i(U, lambda) = lambda_i - min(0, lambda_i + rho_i d_i) = 0,  rho_i > 0,
 *
 * and Newton's method on it makes i ACTIVE (in contact: d_i = 0 is the
 * next equation) iff lambda_i + rho_i d_i < 0, INACTIVE (lambda_i = 0)
 * otherwise.  rho_i scales the test, it does not change the solution.
 * Values at the level of rounding count as zero: |lambda_i| <= 1e-12
 * max |lambda| and |d_i| <= 1e-12 times the scale of the gap (|G_i| +
 * sum |C_ri U_r|, what d_i was computed from), so that a contact that
 * is exactly closed (the Taylor patch test) does not flicker.
 *
 * The rounding rule is lac_snap (base/lac_vec.h), the one of the mean gaps
 * at their assembly (contact/lac_assembly_lac.c); the loop of Algorithm 1
 * (solve/lac_newton.c) uses it for the first statuses too (d_i <= 0
 * [Alg. 1, lines 2-8]).
 */
#ifndef LAC_COMPLEMENTARITY_H
#define LAC_COMPLEMENTARITY_H

#include <stddef.h>

/* 1 if macro-element i is active: lambda + rho d < 0 after the rounding
 * rule (lmax = max |lambda| over all, dscale = the scale of this gap). */
int lac_complementarity_active (double lambda, double d, double rho,
                                double lmax, double dscale);
/* |A_i(U, lambda)| with the same rounding rule. */
double lac_complementarity_residual (double lambda, double d, double rho,
                                     double lmax, double dscale);
/* max |lambda_i| over k values. */
double lac_complementarity_lmax (size_t k, const double *lambda);

#endif /* LAC_COMPLEMENTARITY_H */
