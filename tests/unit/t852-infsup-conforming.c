/* t852: beta_h stays bounded below as h -> 0 in the geometrically
 *       conforming case                         [LAC (10), Thm. 1, App. A]
 *
 * Taylor-like stacked blocks (t85-infsup-blocks.h), Gamma_C = the whole
 * common face, non-matching meshes, four levels each:
 *   2D quad4, upper 6 * 2^l cells (k = 3, 6, 12, 24 macro-elements of two
 *     segments), lower 8 * 2^l + 1:
 *     beta_h = 0.81197, 0.69742, 0.66322, 0.65469;
 *   3D hex8, the levels of taylor3d.geo (upper 3 + 2l, lower 4 + 3l cells
 *     per edge; k = 9, 25, 49, 81 faces cut into 4 pyramids):
 *     beta_h = 0.38799, 0.30648, 0.29274, 0.28850
 * (H1 norm with ell = mesh diameter, M = diag(h_i |T^m_i|)).  Checked:
 * beta(level 3) / beta(level 0) > 0.5 (0.806 and 0.744), the last change
 * is less than a fifth of the first (the sequence settles: a bound from
 * below independent of h, as [LAC Thm. 1] uses), beta_h(level 3) above
 * 0.6 (2D) and 0.25 (3D), the numbers above to 1e-4, and the multiplier
 * norm: h_i = 100 / n (2D pairs) and 50 sqrt(2) / n (3D faces),
 * M_ii = h_i |T^m_i|.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "t85-infsup-blocks.h"

static void
sequence (lac_elem_type type, const size_t *nlo, const size_t *nup,
          const double *want, double floor)
{
  const char *tn = lac_refelem_get (type)->name;
  double beta[4] = { 0 };
  for (int l = 0; l < 4; l++)
    {
      blocks b;
      int st = blocks_build (&b, type, nlo[l], nup[l], 50.0, LAC_EPSILON_DEFAULT);
      check_status (st, LAC_SUCCESS, "%s level %d: build", tn, l);
      lac_infsup *r = st ? NULL : blocks_infsup (&b, LAC_INFSUP_AUTO);
      check_true (r != NULL, "%s level %d: estimate: %s", tn, l,
                  lac_error_message ());
      if (r)
        {
          size_t k = r->k;
          double H = b.dim == 2 ? 100.0 / (double) nup[l]
                     : 50.0 * sqrt (2.0) / (double) nup[l];
          beta[l] = r->beta;
          check_abs (beta[l], want[l], 1e-4, "%s level %d: beta_h", tn, l);
          check_int ((long) k, (long) (b.dim == 2 ? nup[l] / 2
                                       : nup[l] * nup[l]), "%s level %d: k",
                     tn, l);
          for (size_t i = 0; i < k; i++)
            {
              check_rel (b.h[i], H, 1e-12, "%s level %d: h_%zu", tn, l, i);
              check_rel (b.Mn->x[i], H * b.c->area[i], 1e-14,
                         "%s level %d: M_%zu", tn, l, i);
            }
          if (getenv ("LAC_TEST_VERBOSE"))
            printf ("%s level %d: ndof=%zu k=%zu h=%.4f beta=%.5f\n", tn, l,
                    r->n, k, H, r->beta);
        }
      lac_infsup_free (r);
      blocks_free (&b);
    }
  check_true (beta[3] / beta[0] > 0.5, "%s: beta(3)/beta(0) = %.3f > 0.5",
              tn, beta[3] / beta[0]);
  check_true (fabs (beta[3] - beta[2]) < 0.2 * fabs (beta[1] - beta[0]),
              "%s: the sequence settles", tn);
  check_true (beta[3] > floor, "%s: beta(3) = %.4f > %.2f", tn, beta[3], floor);
}

int
main (void)
{
  lac_init ();
  const size_t lo2[4] = { 9, 17, 33, 65 }, up2[4] = { 6, 12, 24, 48 };
  const double b2[4] = { 0.81197, 0.69742, 0.66322, 0.65469 };
  sequence (LAC_QUAD4, lo2, up2, b2, 0.6);
  const size_t lo3[4] = { 4, 7, 10, 13 }, up3[4] = { 3, 5, 7, 9 };
  const double b3[4] = { 0.38799, 0.30648, 0.29274, 0.28850 };
  sequence (LAC_HEX8, lo3, up3, b3, 0.25);
  lac_finalize ();
  return check_summary ();
}
