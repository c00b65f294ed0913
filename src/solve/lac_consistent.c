/* lac_consistent.c -- the consistent Newton step (see lac_consistent.h)
 *                                                 [LAC §4.5, Alg. 1; §5.4]
 *
 * The unknowns of GMRES are z = (dU, lambda) stacked (n + k); the rows of
 * the inactive multipliers are the identity (lambda_i = 0).
 */
#include "solve/lac_consistent.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_gmres.h"

#define MAXIT 60

typedef struct ctx
{
  const lac_consistent *cs;
  size_t n, k;
  double omega;              /* scale of the gap rows                     */
  double *h;                 /* n: H x                                     */
  double *w;                 /* n: scratch of the product K_T x            */
  double *f, *g;             /* n, k: right-hand sides of the strategy     */
  const double *F;           /* the system's right-hand side r             */
} ctx;

/* y = (**) z, gap rows times omega. */
static int
apply (void *vc, const double *z, double *y)
{
  ctx *c = vc;
  const lac_consistent *cs = c->cs;
  const lac_csc *C = cs->sys->C, *B = cs->T->B;
  const double *mu = z + c->n;
  int status = lac_csc_matvec_pair (cs->sys->K, z, y, c->w); /* K_T dU */
  memset (c->h, 0, c->n * sizeof *c->h);
  lac_contact_tangent_apply (cs->T, z, c->h);
  for (size_t r = 0; r < c->n; r++)
    if (!cs->fixed[r])
      y[r] -= c->h[r];                                  /* - H dU */
  for (size_t i = 0; i < c->k; i++)
    {
      double b = 0;
      if (!cs->active[i])
        {
          y[c->n + i] = mu[i];
          continue;
        }
      for (int q = C->p[i]; q < C->p[i + 1]; q++)
        y[C->i[q]] -= C->x[q] * mu[i];                  /* - C_A lambda */
      for (int q = B->p[i]; q < B->p[i + 1]; q++)
        b += B->x[q] * z[B->i[q]];
      y[c->n + i] = c->omega * b;                       /* B_A^T dU */
    }
  return status;
}

/* z = the frozen system's solution for the right-hand side v. */
static int
precondition (void *vc, const double *v, double *z)
{
  ctx *c = vc;
  const lac_consistent *cs = c->cs;
  memcpy (c->f, v, c->n * sizeof *c->f);
  for (size_t i = 0; i < c->k; i++)
    c->g[i] = cs->active[i] ? v[c->n + i] / c->omega : 0.0;
  memset (z, 0, (c->n + c->k) * sizeof *z);
  int status = lac_strategy_solve_rhs (cs->strategy, cs->active, c->f, c->g,
                                       z, z + c->n);
  for (size_t i = 0; i < c->k; i++)
    if (!cs->active[i])
      z[c->n + i] = v[c->n + i];
  return status;
}

/* b = the residual of (**) at (dU, lambda), and *nrhs = the norm of the
 * right-hand side of (**) (both with the gap rows scaled). */
static int
start_residual (ctx *c, const double *dU, const double *lambda, double *b,
                double *nrhs)
{
  const lac_consistent *cs = c->cs;
  size_t n = c->n;
  double *z = lac_malloc ((n + c->k) * sizeof *z);
  if (!z)
    LAC_ERROR (LAC_ENOMEM, "Newton step of %zu unknowns", n + c->k);
  double nr = 0;
  for (size_t r = 0; r < n; r++)
    z[r] = cs->fixed[r] ? 0.0 : dU[r];            /* the free part */
  memcpy (z + n, lambda, c->k * sizeof *z);
  int status = apply (c, z, b);
  memset (c->h, 0, n * sizeof *c->h);             /* H on the fixed part */
  for (size_t r = 0; r < n; r++)
    z[r] = cs->fixed[r] ? dU[r] : 0.0;
  lac_contact_tangent_apply (cs->T, z, c->h);
  for (size_t r = 0; r < n; r++)
    {
      b[r] = cs->fixed[r] ? 0.0 : c->F[r] - b[r] + c->h[r];
      nr += cs->fixed[r] ? 0.0 : c->F[r] * c->F[r];
    }
  for (size_t i = 0; i < c->k; i++)
    {
      const lac_csc *B = cs->T->B;
      double bu = 0;
      for (int q = B->p[i]; q < B->p[i + 1]; q++)
        if (cs->fixed[B->i[q]])
          bu += B->x[q] * dU[B->i[q]];
      b[n + i] = cs->active[i] ? c->omega * (cs->d[i] - bu) - b[n + i] : 0.0;
      nr += cs->active[i] ? c->omega * c->omega * cs->d[i] * cs->d[i] : 0.0;
    }
  *nrhs = sqrt (nr);
  lac_free (z);
  return status;
}

int
lac_consistent_solve (const lac_consistent *cs, double *dU, double *lambda,
                      lac_consistent_info *info)
{
  size_t n = cs->sys->K->ncol, k = cs->sys->C->ncol;
  double normK, normC, nrhs = 0, nb = 0;
  ctx c = { cs, n, k, 1.0, NULL, NULL, NULL, NULL, cs->sys->F };
  int status = lac_system_norm_k (cs->sys, &normK);
  if (!status)
    status = lac_system_norm_c (cs->sys, &normC);
  c.omega = normC > 0 ? normK / normC : 1.0;
  c.h = lac_malloc (n * sizeof *c.h);
  c.w = lac_malloc (n * sizeof *c.w);
  c.f = lac_malloc (n * sizeof *c.f);
  c.g = lac_malloc ((k + 1) * sizeof *c.g);
  double *b = lac_malloc ((n + k) * sizeof *b);
  double *z = lac_calloc (n + k, sizeof *z);
  if (!status && !(c.h && c.w && c.f && c.g && b && z))
    status = LAC_ERRMSG (LAC_ENOMEM, "Newton step of %zu unknowns", n + k);
  lac_gmres_info gi = { 0, 0 };
  if (!status)
    status = start_residual (&c, dU, lambda, b, &nrhs);
  for (size_t q = 0; !status && q < n + k; q++)
    nb += b[q] * b[q];
  nb = sqrt (nb);
  double rtol = nb > 0 ? cs->eta * nrhs / nb : 1.0;
  if (!status && rtol < 1)
    {
      int maxit = cs->maxit > 0 ? cs->maxit : MAXIT;
      status = lac_gmres (n + k, apply, precondition, &c, b, z, rtol,
                          LAC_CONSISTENT_RESTART, maxit, &gi);
      if (status == LAC_EMAXITER)
        {
          lac_error_clear ();              /* the best step found */
          status = LAC_SUCCESS;
        }
      for (size_t r = 0; !status && r < n; r++)
        dU[r] += z[r];
      for (size_t i = 0; !status && i < k; i++)
        lambda[i] = cs->active[i] ? lambda[i] + z[n + i] : 0.0;
    }
  if (info)
    {
      info->iterations = gi.iterations;
      info->start = nrhs > 0 ? nb / nrhs : nb;
      info->residual = rtol < 1 ? gi.residual * info->start : info->start;
    }
  lac_free (c.h);
  lac_free (c.w);
  lac_free (c.f);
  lac_free (c.g);
  lac_free (b);
  lac_free (z);
  return status;
}
