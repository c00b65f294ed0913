/* lac_pcg.c -- preconditioned conjugate gradients (see lac_pcg.h)
 *
 *   r = b - A x,  z = M^{-1} r,  p = z
 *   repeat:  q = A p,  alpha = (r.z) / (p.q),  x += alpha p,  r -= alpha q
 *            stop if ||r|| <= rtol ||b||
 *            z = M^{-1} r,  beta = (r.z)_new / (r.z)_old,  p = z + beta p
 */
#include "linalg/lac_pcg.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

static int
precondition (lac_linop M, void *ctx, size_t n, const double *r, double *z)
{
  if (M)
    return M (ctx, r, z);
  memcpy (z, r, n * sizeof *z);
  return LAC_SUCCESS;
}

int
lac_pcg (size_t n, lac_linop A, lac_linop M, void *ctx, const double *b,
         double *x, double rtol, int maxit, lac_pcg_info *info)
{
  double *w = lac_malloc ((4 * n + 1) * sizeof *w);
  double *r = w, *z = w + n, *p = w + 2 * n, *q = w + 3 * n;
  double nb = sqrt (lac_vec_dot (n, b, b)), nr = 0, rz;
  int status, it = 0;
  if (!w)
    LAC_ERROR (LAC_ENOMEM, "conjugate gradients, n = %zu", n);
  if (nb == 0)                                          /* x = 0 exactly */
    {
      memset (x, 0, n * sizeof *x);
      if (info)
        info->iterations = 0, info->residual = 0;
      lac_free (w);
      return LAC_SUCCESS;
    }
  status = A (ctx, x, q);                               /* r = b - A x */
  for (size_t i = 0; !status && i < n; i++)
    r[i] = b[i] - q[i];
  if (!status)
    status = precondition (M, ctx, n, r, z);
  memcpy (p, z, n * sizeof *p);
  rz = lac_vec_dot (n, r, z);
  nr = sqrt (lac_vec_dot (n, r, r));
  while (!status && nr > rtol * nb && it < maxit)
    {
      double pq, alpha, rz_new;
      if ((status = A (ctx, p, q)))                     /* q = A p */
        break;
      it++;
      pq = lac_vec_dot (n, p, q);
      if (!(pq > 0))
        {
          status = LAC_ERRMSG (LAC_ESING, "conjugate gradients broke down "
                               "at iteration %d (p.Ap = %.3g): the operator "
                               "is not positive definite", it, pq);
          break;
        }
      alpha = rz / pq;
      for (size_t i = 0; i < n; i++)
        {
          x[i] += alpha * p[i];
          r[i] -= alpha * q[i];
        }
      nr = sqrt (lac_vec_dot (n, r, r));
      if (nr <= rtol * nb || (status = precondition (M, ctx, n, r, z)))
        break;
      rz_new = lac_vec_dot (n, r, z);
      for (size_t i = 0; i < n; i++)
        p[i] = z[i] + rz_new / rz * p[i];
      rz = rz_new;
    }
  if (info)
    {
      info->iterations = it;
      info->residual = nb > 0 ? nr / nb : nr;
    }
  lac_free (w);
  if (!status && nr > rtol * nb)
    LAC_ERROR (LAC_EMAXITER, "conjugate gradients: residual %.3g after %d "
               "iterations (asked %.3g)", nb > 0 ? nr / nb : nr, it, rtol);
  return status;
}
