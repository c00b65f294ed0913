/* t014: flexible GMRES (linalg/lac_gmres.h) on a non-symmetric system
 *
 * A = the 1D convection-diffusion matrix tridiag(-1 - c, 2, -1 + c) of
 * order n (non-symmetric for c != 0), b = A x_exact with a known x_exact:
 *   1. without a preconditioner, restarted every 10 iterations: converges
 *      to rtol = 1e-10 and x matches x_exact;
 *   2. with the exact inverse (a Thomas solve of A) as the
 *      preconditioner: one iteration;
 *   3. with maxit too small: LAC_EMAXITER with the residual in the message.
 */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "linalg/lac_gmres.h"
#include "base/lac_status.h"

#define N 200
#define CONV 0.4

static int
matvec (void *ctx, const double *x, double *y)
{
  (void) ctx;
  for (int i = 0; i < N; i++)
    y[i] = 2 * x[i] - (i > 0 ? (1 + CONV) * x[i - 1] : 0)
           - (i + 1 < N ? (1 - CONV) * x[i + 1] : 0);
  return LAC_SUCCESS;
}

/* z = A^{-1} v by the Thomas algorithm (the exact inverse). */
static int
thomas (void *ctx, const double *v, double *z)
{
  double c[N], d[N];
  (void) ctx;
  for (int i = 0; i < N; i++)
    {
      double lo = i > 0 ? -(1 + CONV) : 0, up = -(1 - CONV);
      double den = 2 - (i > 0 ? lo * c[i - 1] : 0);
      c[i] = up / den;
      d[i] = (v[i] - (i > 0 ? lo * d[i - 1] : 0)) / den;
    }
  for (int i = N - 1; i >= 0; i--)
    z[i] = d[i] - (i + 1 < N ? c[i] * z[i + 1] : 0);
  return LAC_SUCCESS;
}

int
main (void)
{
  double xe[N], b[N], x[N], err = 0;
  lac_gmres_info info;
  lac_init ();
  for (int i = 0; i < N; i++)
    xe[i] = sin (0.1 * i) + 0.01 * i;
  matvec (NULL, xe, b);
  for (int i = 0; i < N; i++)
    x[i] = 0;
  check_status (lac_gmres (N, matvec, NULL, NULL, b, x, 1e-10, 10, 5000,
                           &info), LAC_SUCCESS, "unpreconditioned");
  for (int i = 0; i < N; i++)
    err = fmax (err, fabs (x[i] - xe[i]));
  check_true (info.residual <= 1e-10, "residual %.2e", info.residual);
  check_true (err <= 1e-6, "error %.2e after %d iterations", err,
              info.iterations);
  for (int i = 0; i < N; i++)
    x[i] = 0;
  check_status (lac_gmres (N, matvec, thomas, NULL, b, x, 1e-12, 30, 100,
                           &info), LAC_SUCCESS, "preconditioned");
  check_int (info.iterations, 1, "iterations with the exact inverse");
  err = 0;
  for (int i = 0; i < N; i++)
    err = fmax (err, fabs (x[i] - xe[i]));
  check_true (err <= 1e-10, "error %.2e with the exact inverse", err);
  for (int i = 0; i < N; i++)
    x[i] = 0;
  check_status (lac_gmres (N, matvec, NULL, NULL, b, x, 1e-12, 5, 5, &info),
                LAC_EMAXITER, "5 iterations only");
  check_message ("GMRES: residual", "the message");
  lac_finalize ();
  return check_summary ();
}
