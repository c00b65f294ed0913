/* t110-quadrature-exact.c -- every quadrature rule is exact to its degree.
 *
 * For every shape and every degree d = 0..lac_quad_max_degree: the rule
 * states degree >= d, its weights are positive and sum to the reference
 * measure (1e-13), its points lie in the reference element, and it
 * integrates every monomial x^a y^b z^c with a+b+c <= its stated degree to
 * 1e-13 relative to int |x^a y^b z^c|, against the closed forms
 *   line/quad/hex  prod_k m(a_k),  m(a) = 2/(a+1) (a even), 0 (a odd)
 *   tri            a! b! / (a+b+2)!
 *   tet            a! b! c! / (a+b+c+3)!
 *   pyramid        m(a) m(b) c! (a+b+2)! / (a+b+c+3)!
 * (the pyramid by the collapsed map x = xi(1-z), y = eta(1-z), whose
 * Jacobian is (1-z)^2).  The rule sizes of the symmetric simplex rules are
 * checked (1, 3, 6, 7, 12, 16 and 1, 4, 8, 14 points), bad degrees are
 * refused, and the degree-2 pyramid rule integrates the mass and stiffness
 * products of the rational pyr5 basis like the degree-31 rule (1e-13).
 * The cache's tables (lac_quad_cache_table): for every cell type and
 * degrees 0..20, the rule of lac_quad_cache_get with the values of
 * lac_refelem_eval at its points, bit for bit, and the same table again
 * on a second call.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

#define DMAX 41

static double M[DMAX + 1][DMAX + 1][DMAX + 1];

/* B(p, q) = (p-1)! (q-1)! / (p+q-1)! for integers p, q >= 1. */
static double
beta_int (int p, int q)
{
  double r = 1.0 / p;
  for (int i = 1; i < q; i++)
    r *= (double) i / (p + i);
  return r;
}

/* int_{-1}^{1} x^a dx, and of |x^a|. */
static double
m1 (int a, int absval)
{
  return (a % 2 && !absval) ? 0 : 2.0 / (a + 1);
}

/* Closed-form integral of x^a y^b z^c over the reference domain. */
static double
exact (lac_shape s, int a, int b, int c, int absval)
{
  switch (s)
    {
    case LAC_SHAPE_LINE: return m1 (a, absval);
    case LAC_SHAPE_QUAD: return m1 (a, absval) * m1 (b, absval);
    case LAC_SHAPE_HEX: return m1 (a, absval) * m1 (b, absval) * m1 (c, absval);
    case LAC_SHAPE_TRI: return beta_int (a + 1, b + 2) / (b + 1);
    case LAC_SHAPE_TET:
      return beta_int (b + 1, c + 2) / (c + 1) * beta_int (a + 1, b + c + 3);
    case LAC_SHAPE_PYR:
      return m1 (a, absval) * m1 (b, absval) * beta_int (c + 1, a + b + 3);
    }
  return NAN;
}

static const lac_elem_type shape_elem[] = {
  [LAC_SHAPE_LINE] = LAC_SEG2, [LAC_SHAPE_TRI] = LAC_TRI3,
  [LAC_SHAPE_QUAD] = LAC_QUAD4, [LAC_SHAPE_TET] = LAC_TET4,
  [LAC_SHAPE_HEX] = LAC_HEX8, [LAC_SHAPE_PYR] = LAC_PYR5
};

static const char *shape_name[] = { "line", "tri", "quad", "tet", "hex", "pyr" };

/* Points inside, positive weights summing to the measure. */
static void
check_points (const lac_quad *q)
{
  const lac_refelem *re = lac_refelem_get (shape_elem[q->shape]);
  double sum = 0;
  int inside = 1, positive = 1;
  for (int p = 0; p < q->n; p++)
    {
      sum += q->w[p];
      positive &= q->w[p] > 0;
      inside &= lac_refelem_contains (re, q->xi + p * q->dim, 1e-14);
    }
  check_rel (sum, lac_quad_ref_measure (q->shape), 1e-13, "%s deg %d: sum w",
             shape_name[q->shape], q->degree);
  check_true (positive, "%s deg %d: positive weights", shape_name[q->shape],
              q->degree);
  check_true (inside, "%s deg %d: points inside", shape_name[q->shape],
              q->degree);
}

/* All monomials of total degree <= q->degree. */
static void
check_monomials (const lac_quad *q)
{
  int D = q->degree, dim = q->dim;
  int bmax = dim > 1 ? D : 0, cmax = dim > 2 ? D : 0;
  double px[DMAX + 1], py[DMAX + 1], pz[DMAX + 1];
  for (int a = 0; a <= D; a++)
    for (int b = 0; b <= D; b++)
      for (int c = 0; c <= D; c++)
        M[a][b][c] = 0;
  for (int p = 0; p < q->n; p++)
    {
      const double *x = q->xi + p * dim;
      px[0] = py[0] = pz[0] = 1;
      for (int k = 1; k <= D; k++)
        {
          px[k] = px[k - 1] * x[0];
          py[k] = dim > 1 ? py[k - 1] * x[1] : 0;
          pz[k] = dim > 2 ? pz[k - 1] * x[2] : 0;
        }
      for (int a = 0; a <= D; a++)
        for (int b = 0; b <= D - a && b <= bmax; b++)
          {
            double wab = q->w[p] * px[a] * py[b];
            for (int c = 0; c <= D - a - b && c <= cmax; c++)
              M[a][b][c] += wab * pz[c];
          }
    }
  int nbad = 0;
  for (int a = 0; a <= D; a++)
    for (int b = 0; b <= D - a && b <= bmax; b++)
      for (int c = 0; c <= D - a - b && c <= cmax; c++)
        {
          double e = exact (q->shape, a, b, c, 0);
          double s = exact (q->shape, a, b, c, 1);
          if (fabs (M[a][b][c] - e) > 1e-13 * s && nbad++ < 5)
            check_abs (M[a][b][c], e, 1e-13 * s, "%s deg %d: x^%d y^%d z^%d",
                       shape_name[q->shape], D, a, b, c);
        }
  check_int (nbad, 0, "%s deg %d: inexact monomials", shape_name[q->shape], D);
}

static void
check_shape (lac_shape s)
{
  int maxdeg = lac_quad_max_degree (s), last = -1;
  check_true (maxdeg >= 21, "%s: max degree %d >= 21", shape_name[s], maxdeg);
  for (int d = 0; d <= maxdeg; d++)
    {
      lac_quad *q = lac_quad_alloc (s, d);
      check_true (q != NULL, "%s: rule of degree %d", shape_name[s], d);
      if (q == NULL)
        continue;
      check_true (q->degree >= d && q->shape == s, "%s: degree %d >= %d",
                  shape_name[s], q->degree, d);
      check_points (q);
      if (q->degree != last)         /* each distinct rule once */
        check_monomials (q);
      last = q->degree;
      lac_quad_free (q);
    }
  check_true (lac_quad_alloc (s, -1) == NULL, "%s: degree -1 refused",
              shape_name[s]);
  check_true (lac_quad_alloc (s, maxdeg + 1) == NULL, "%s: degree max+1",
              shape_name[s]);
  check_message ("out of range", "%s: message", shape_name[s]);
}

static void
check_sizes (lac_shape s, const int *npts, int nd)
{
  for (int d = 1; d <= nd; d++)
    {
      lac_quad *q = lac_quad_alloc (s, d);
      check_int (q->n, npts[d - 1], "%s degree %d: points", shape_name[s], d);
      lac_quad_free (q);
    }
}

/* int N_a N_b and int grad N_a . grad N_b on the pyramid: rule 2 == rule 31. */
static void
check_pyramid_basis (void)
{
  const lac_refelem *re = lac_refelem_get (LAC_PYR5);
  double mass[2][25] = { { 0 } }, stiff[2][25] = { { 0 } };
  int degs[2] = { 2, 31 };
  for (int r = 0; r < 2; r++)
    {
      lac_quad *q = lac_quad_alloc (LAC_SHAPE_PYR, degs[r]);
      for (int p = 0; p < q->n; p++)
        {
          double N[5], dN[15];
          lac_refelem_eval (re, q->xi + 3 * p, N, dN);
          for (int a = 0; a < 5; a++)
            for (int b = 0; b < 5; b++)
              {
                mass[r][5 * a + b] += q->w[p] * N[a] * N[b];
                for (int k = 0; k < 3; k++)
                  stiff[r][5 * a + b] += q->w[p] * dN[3 * a + k] * dN[3 * b + k];
              }
        }
      lac_quad_free (q);
    }
  for (int i = 0; i < 25; i++)
    {
      check_abs (mass[0][i], mass[1][i], 1e-13, "pyr5 mass %d", i);
      check_abs (stiff[0][i], stiff[1][i], 1e-13, "pyr5 stiffness %d", i);
    }
  check_rel (mass[1][24], 2.0 / 15, 1e-13, "pyr5 int N_4^2 = 2/15");
}

static void
check_tables (void)
{
  lac_quad_cache qc;
  double N[LAC_MAX_NODES], dN[LAC_MAX_NODES * 3];
  memset (&qc, 0, sizeof qc);
  for (int e = 0; e < LAC_NELEM_TYPES; e++)
    {
      const lac_refelem *re = lac_refelem_get ((lac_elem_type) e);
      int ok = 1;
      for (int d = 0; d <= 20 && ok; d++)
        {
          const lac_quad_table *t = lac_quad_cache_table (&qc, re, d);
          const lac_quad *q = lac_quad_cache_get (&qc, re->shape, d);
          ok = t && t->q == q && lac_quad_cache_table (&qc, re, d) == t;
          for (int p = 0; ok && p < q->n; p++)
            {
              size_t nen = (size_t) re->nnodes, dim = (size_t) re->dim;
              lac_refelem_eval (re, q->xi + (size_t) p * dim, N, dN);
              ok = !memcmp (N, t->N + (size_t) p * nen, nen * sizeof *N)
                   && !memcmp (dN, t->dN + (size_t) p * nen * dim,
                               nen * dim * sizeof *dN);
            }
        }
      check_true (ok, "%s: the cache's tables", re->name);
    }
  lac_quad_cache_free (&qc);
}

int
main (void)
{
  static const int tri_n[] = { 1, 3, 6, 6, 7, 12, 16, 16 };
  static const int tet_n[] = { 1, 4, 8, 14, 14 };
  lac_init ();
  for (int s = LAC_SHAPE_LINE; s <= LAC_SHAPE_PYR; s++)
    check_shape ((lac_shape) s);
  check_sizes (LAC_SHAPE_TRI, tri_n, 8);
  check_sizes (LAC_SHAPE_TET, tet_n, 5);
  static const int hex_n[] = { 1, 8, 8, 27, 27 };
  check_sizes (LAC_SHAPE_HEX, hex_n, 5);
  check_pyramid_basis ();
  check_tables ();
  check_rel (lac_quad_ref_measure (LAC_SHAPE_PYR), 4.0 / 3, 1e-15, "|pyr|");
  lac_quad_free (NULL);
  lac_finalize ();
  return check_summary ();
}
