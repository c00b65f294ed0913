/* lac_gmres.c -- flexible GMRES with restarts (see lac_gmres.h)
 *
 *   r = b - A x, beta = ||r||, v_1 = r / beta, g = beta e_1
 *   for j = 1 .. m:  z_j = M^{-1} v_j,  w = A z_j,
 *                    h_ij = w . v_i, w -= h_ij v_i  (i <= j, modified
 *                    Gram-Schmidt),  h_{j+1,j} = ||w||,  v_{j+1} = w / h,
 *                    rotate column j, |g_{j+1}| = the residual
 *   x += Z y with H y = g (the j x j upper triangle); restart from x.
 */
#include "linalg/lac_gmres.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* r = b - A x; returns ||r|| through *nr. */
static int
residual (size_t n, lac_linop A, void *ctx, const double *b, const double *x,
          double *r, double *nr)
{
  int status = A (ctx, x, r);
  for (size_t i = 0; !status && i < n; i++)
    r[i] = b[i] - r[i];
  *nr = sqrt (lac_vec_dot (n, r, r));
  return status;
}

/* Apply the rotations 0..j-1 to column j of H, then make rotation j zero
 * its subdiagonal; g follows. */
static void
rotate (int j, double *hj, double *cs, double *sn, double *g)
{
  for (int i = 0; i < j; i++)
    {
      double t = cs[i] * hj[i] + sn[i] * hj[i + 1];
      hj[i + 1] = -sn[i] * hj[i] + cs[i] * hj[i + 1];
      hj[i] = t;
    }
  double d = hypot (hj[j], hj[j + 1]);
  cs[j] = d > 0 ? hj[j] / d : 1.0;
  sn[j] = d > 0 ? hj[j + 1] / d : 0.0;
  hj[j] = d;
  hj[j + 1] = 0;
  g[j + 1] = -sn[j] * g[j];
  g[j] *= cs[j];
}

/* x += Z y, H y = g (upper triangle of order k; column j of H at
 * H + j (m + 1)). */
static void
update (size_t n, int k, int m, const double *H, double *g, double *const *Z,
        double *x)
{
  for (int i = k - 1; i >= 0; i--)
    {
      for (int j = i + 1; j < k; j++)
        g[i] -= H[j * (m + 1) + i] * g[j];
      g[i] /= H[i * (m + 1) + i];
    }
  for (int j = 0; j < k; j++)
    for (size_t q = 0; q < n; q++)
      x[q] += g[j] * Z[j][q];
}

/* One cycle of at most m iterations from v_0 = r / beta. */
static int
cycle (size_t n, lac_linop A, lac_linop M, void *ctx, double beta,
       double target, int m, double *const *V, double *const *Z, double *H,
       double *wk, double *x, int *its, int maxit, double *res)
{
  double *cs = wk, *sn = wk + m, *g = wk + 2 * m;
  int j, status = LAC_SUCCESS;
  memset (g, 0, (size_t) (m + 1) * sizeof *g);
  g[0] = beta;
  for (j = 0; j < m && *its < maxit && !status; j++)
    {
      double *hj = H + j * (m + 1);
      if (M)
        status = M (ctx, V[j], Z[j]);
      else
        memcpy (Z[j], V[j], n * sizeof *Z[j]);
      if (!status)
        status = A (ctx, Z[j], V[j + 1]);
      if (status)
        break;
      (*its)++;
      for (int i = 0; i <= j; i++)
        {
          hj[i] = lac_vec_dot (n, V[j + 1], V[i]);
          for (size_t q = 0; q < n; q++)
            V[j + 1][q] -= hj[i] * V[i][q];
        }
      double hn = sqrt (lac_vec_dot (n, V[j + 1], V[j + 1]));
      hj[j + 1] = hn;
      for (size_t q = 0; hn > 0 && q < n; q++)
        V[j + 1][q] /= hn;
      rotate (j, hj, cs, sn, g);
      *res = fabs (g[j + 1]);
      if (*res <= target || hn == 0)              /* hn = 0: x is exact */
        {
          j++;
          break;
        }
    }
  if (!status)
    update (n, j, m, H, g, Z, x);
  return status;
}

int
lac_gmres (size_t n, lac_linop A, lac_linop M, void *ctx, const double *b,
           double *x, double rtol, int m, int maxit, lac_gmres_info *info)
{
  m = m > 0 ? m : 30;
  double *work = lac_malloc (((size_t) (2 * m + 1) * n
                              + (size_t) ((m + 1) * (m + 4))) * sizeof *work);
  double **V = lac_malloc ((size_t) (2 * m + 1) * sizeof *V);
  int status = work && V ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "GMRES work space, %d vectors of %zu",
                             2 * m + 1, n);
  double nb = sqrt (lac_vec_dot (n, b, b)), beta = 0, res = 0;
  int its = 0;
  for (int i = 0; !status && i < 2 * m + 1; i++)
    V[i] = work + (size_t) i * n;
  double *H = work + (size_t) (2 * m + 1) * n, *wk = H + m * (m + 1);
  double target = rtol * nb;
  while (!status)
    {
      if ((status = residual (n, A, ctx, b, x, V[0], &beta)))
        break;
      res = beta;
      if (beta <= target || its >= maxit)
        break;
      for (size_t q = 0; q < n; q++)
        V[0][q] /= beta;
      status = cycle (n, A, M, ctx, beta, target, m, V, V + m + 1, H, wk, x,
                      &its, maxit, &res);
    }
  if (info)
    {
      info->iterations = its;
      info->residual = nb > 0 ? res / nb : res;
    }
  lac_free (work);
  lac_free (V);
  if (!status && res > target)
    LAC_ERROR (LAC_EMAXITER, "GMRES: residual %.3e of ||b|| after %d "
               "iterations (asked %.1e)", nb > 0 ? res / nb : res, its, rtol);
  return status;
}
