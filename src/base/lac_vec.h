/* lac_vec.h -- small vector geometry: dot and cross products, lengths;
 *             the rounding rule (lac_snap)
 *
 * Header only: static inline functions on plain arrays of doubles, for the
 * geometry kernels (pairing, projection, refinement templates), the
 * Lanczos vectors of the inf-sup estimate and the Krylov vectors of
 * linalg/lac_pcg.c and lac_gmres.c.  Each sums in index order, as
 * the loops it replaces did, so results are the same to the last bit.
 */
#ifndef LAC_VEC_H
#define LAC_VEC_H

#include <math.h>
#include <stddef.h>

/* a . b over n components. */
static inline double
lac_vec_dot (size_t n, const double *a, const double *b)
{
  double s = 0;
  for (size_t i = 0; i < n; i++)
    s += a[i] * b[i];
  return s;
}

/* c = a x b (3 components; c must not alias a or b). */
static inline void
lac_vec_cross (const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* |a| over n components. */
static inline double
lac_vec_norm (size_t n, const double *a)
{
  return sqrt (lac_vec_dot (n, a, a));
}

/* |a - b| over n components. */
static inline double
lac_vec_dist (size_t n, const double *a, const double *b)
{
  double s = 0;
  for (size_t i = 0; i < n; i++)
    s += (a[i] - b[i]) * (a[i] - b[i]);
  return sqrt (s);
}

/* The rounding rule of lac, written once: x counts as 0 when |x| <=
 * LAC_ROUNDING times the scale of what it was computed from (a mean gap
 * at its assembly: the size of its macro-element times its area; a gap or
 * a multiplier in the status rule of Algorithm 1: the terms it sums). */
#define LAC_ROUNDING 1e-12

static inline double
lac_snap (double x, double scale)
{
  return fabs (x) <= LAC_ROUNDING * scale ? 0.0 : x;
}

#endif /* LAC_VEC_H */
