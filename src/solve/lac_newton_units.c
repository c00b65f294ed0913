/* lac_newton_units.c -- the units of a column of the loop of Algorithm 1
 *                       (see lac_newton_internal.h)      [LAC (18), Alg. 1]
 *
 * The status rule compares lambda_i + rho_i d_i with 0: lambda_i is a
 * force per area and d_i a mean gap times a measure, so rho_i carries
 * E / (h_i |T^m cap Gamma_C|) to make the two of one unit; a mean gap at
 * the level of rounding of the terms it was computed from counts as 0.
 * Shared by the loop (lac_newton.c) and its friction steps
 * (lac_newton_friction.c).
 */
#include <math.h>
#include "solve/lac_newton_internal.h"

#include "solve/lac_contact_model.h"

/* |T^m cap Gamma_C| of column i (1 where the model gives none). */
double
lac_newton_area (const lac_newton *s, size_t i)
{
  return s->pt.area ? s->pt.area[i] : 1.0;
}

/* rho_i = E / (h_i |T^m cap Gamma_C|) (lac_contact_model.h), unless the
 * options or the model give it. */
double
lac_newton_rho (const lac_newton *s, size_t i)
{
  double a = lac_newton_area (s, i) * lac_model_h (&s->pt, i, s->model.dim);
  if (s->opts.rho > 0)
    return s->opts.rho;
  if (s->pt.rho)
    return s->pt.rho[i];
  return a > 0 ? s->model.E / a : 1.0;
}

/* The scale of what d_i was computed from, |d_i| + sum |C_ri U_r|: d_i
 * is zero when it is below 1e-12 of it (lac_snap, base/lac_vec.h; the
 * mean gaps of the model were snapped at their assembly already, with
 * the scale of the coordinates). */
double
lac_newton_gap_scale (const lac_newton *s, size_t i)
{
  const lac_csc *C = s->pt.C;
  double sc = fabs (s->pt.d[i]);
  for (int q = C->p[i]; q < C->p[i + 1]; q++)
    sc += fabs (C->x[q] * s->U[C->i[q]]);
  return sc;
}
