/* t851: the two paths of the inf-sup estimate agree        [LAC (10)]
 *
 * Taylor-like stacked blocks built in code (t85-infsup-blocks.h), medium
 * sizes; beta_h by the dense path (S = C^T A^-1 C formed, GSL gensymmv)
 * and by the sparse path (shift-invert Lanczos on S^-1 M with the
 * saddle-point factor) must agree to 1e-6 (relative), and their
 * eigenvectors to 1e-6 in the M inner product (|<mu_d, mu_s>_M| = 1):
 *   2D quad8, 40 / 30 cells:   k = 30, ndof ~ 1.6e4, lambda_2/lambda_1 = 1.018;
 *   3D hex8, 10 / 7 cells:     k = 49, ndof ~ 5.7e3, lambda_2/lambda_1 = 1.15;
 *   2D quad4 non-conforming, 12 / 16 cells, master [0, 25.78125] (it covers
 *   1/8 of the slave macro-element [25, 31.25]; epsilon 1e-9): k = 5, the
 *   eigenvector largest on the cut macro-element.
 * Measured (dense): beta = 0.66357, 0.29274, 0.40500 (LAC_TEST_VERBOSE=1); Lanczos
 * steps 30 (= k), 25 (of k = 49), 5.
 * Also: the Lanczos residual reported is below its tolerance 1e-10, and
 * AUTO picks the dense path at these sizes.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "t85-infsup-blocks.h"

static void
compare (lac_elem_type type, size_t nlo, size_t nup, double Lm)
{
  const char *tn = lac_refelem_get (type)->name;
  blocks b;
  int st = blocks_build (&b, type, nlo, nup, Lm, 1e-9);
  check_status (st, LAC_SUCCESS, "%s %zu/%zu build", tn, nlo, nup);
  if (st)
    {
      blocks_free (&b);
      return;
    }
  lac_infsup *d = blocks_infsup (&b, LAC_INFSUP_DENSE);
  check_true (d != NULL, "%s dense: %s", tn, lac_error_message ());
  lac_infsup *s = blocks_infsup (&b, LAC_INFSUP_SPARSE);
  check_true (s != NULL, "%s sparse: %s", tn, lac_error_message ());
  lac_infsup *a = blocks_infsup (&b, LAC_INFSUP_AUTO);
  if (d && s && a)
    {
      size_t k = d->k;
      double *Mmu = calloc (k, sizeof *Mmu), ip = 0;
      check_rel (s->beta, d->beta, 1e-6, "%s k=%zu: sparse beta = dense beta",
                 tn, k);
      check_rel (s->lambda_min, d->lambda_min, 1e-6, "%s: lambda_min", tn);
      lac_csc_matvec (b.Mn, s->mu, Mmu);
      for (size_t i = 0; i < k; i++)
        ip += d->mu[i] * Mmu[i];
      check_rel (fabs (ip), 1.0, 1e-6, "%s: |<mu_dense, mu_sparse>_M| = 1", tn);
      check_int ((long) s->imax, (long) d->imax, "%s: the same least stable "
                 "multiplier (ties broken alike)", tn);
      if (Lm < 50)                     /* the cut macro-element is the least stable */
        for (size_t i = 0; i < k; i++)
          if (b.c->covered[b.c->macro[i]] < 0.99 * b.c->meas[b.c->macro[i]])
            check_int ((long) d->imax, (long) i, "%s: mu largest on the cut "
                       "macro-element", tn);
      check_true (s->residual <= 1e-10, "%s: Lanczos residual %.2e", tn,
                  s->residual);
      check_true (d->residual <= 1e-10, "%s: dense residual %.2e", tn,
                  d->residual);
      check_int ((long) a->path, LAC_INFSUP_DENSE, "%s: AUTO = dense", tn);
      check_rel (a->beta, d->beta, 1e-14, "%s: AUTO = dense", tn);
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%s %zu/%zu Lm=%g: ndof=%zu k=%zu beta dense=%.10f sparse="
                "%.10f (%zu steps) lambda2/lambda1=%.4f imax=%zu\n", tn, nlo,
                nup, Lm, d->n, k, d->beta, s->beta, s->iterations,
                d->lambda_2 / d->lambda_min, d->imax);
      free (Mmu);
    }
  lac_infsup_free (a);
  lac_infsup_free (s);
  lac_infsup_free (d);
  blocks_free (&b);
}

int
main (void)
{
  lac_init ();
  compare (LAC_QUAD8, 40, 30, 50.0);
  compare (LAC_HEX8, 10, 7, 50.0);
  compare (LAC_QUAD4, 12, 16, 25.78125);
  lac_finalize ();
  return check_summary ();
}
