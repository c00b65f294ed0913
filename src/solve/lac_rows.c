/* lac_rows.c -- a contact law's equations by GMRES preconditioned by a
 *               strategy's symmetric solve (see lac_rows.h)
 *                                        [LAC (17), Alg. 1 l. 21; friction]
 */
#include "solve/lac_rows.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_gmres.h"

#define ROWS_RTOL 1e-11    /* of GMRES: the rest is rounding            */
#define ROWS_RESTART 60
#define ROWS_MAXIT 600

typedef struct rows_ctx
{
  lac_strategy *st;
  const lac_contact_system *sys;
  const lac_contact_rows *R;
  size_t n, k, q;
  char *cons;              /* k: row j is the constraint -c_j^T U = r_j  */
  double *cu;              /* k: c_j^T U                                  */
  double *g;               /* k: the constraints' G for the strategy      */
} rows_ctx;

/* Row j is a constraint: Q's row zero, P's row nonzero on j alone. */
static int
is_constraint (const lac_contact_rows *R, size_t j)
{
  size_t q = (size_t) R->q, a = j % q;
  for (size_t b = 0; b < q; b++)
    if (R->Q[j * q + b] != 0 || (b != a && R->P[j * q + b] != 0))
      return 0;
  return R->P[j * q + a] != 0;
}

/* y = A x, x = [U; lambda]. */
static int
apply_a (void *ctx, const double *x, double *y)
{
  rows_ctx *c = ctx;
  const lac_csc *C = c->sys->C;
  const lac_contact_rows *R = c->R;
  const double *U = x, *lam = x + c->n;
  int status = lac_system_k_mult (c->sys, U, y);             /* K U */
  for (size_t i = 0; !status && i < c->k; i++)
    {
      c->cu[i] = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        {
          c->cu[i] += C->x[p] * U[C->i[p]];
          if (R->free[i])
            y[C->i[p]] -= C->x[p] * lam[i];                  /* - C lambda */
        }
    }
  for (size_t j = 0; !status && j < c->k; j++)
    {
      size_t g = j / c->q;
      double v = R->free[j] ? 0.0 : lam[j];                  /* lambda_j */
      for (size_t b = 0; R->free[j] && b < c->q; b++)
        v += -R->P[j * c->q + b] * c->cu[g * c->q + b]
             + R->Q[j * c->q + b] * lam[g * c->q + b];
      y[c->n + j] = v;
    }
  return status;
}

/* z = M^{-1} v (lac_rows.h): the constraints by the strategy's solve of
 * (*), the other free multipliers by Q's diagonal. */
static int
apply_m (void *ctx, const double *v, double *z)
{
  rows_ctx *c = ctx;
  const lac_contact_rows *R = c->R;
  size_t q = c->q;
  for (size_t j = 0; j < c->k; j++)        /* -c_j^T U = v_j: G_j = -v_j */
    c->g[j] = c->cons[j] ? -v[c->n + j] / R->P[j * q + j % q] : 0.0;
  memset (z, 0, (c->n + c->k) * sizeof *z);
  int status = lac_strategy_solve_rhs (c->st, c->cons, v, c->g, z,
                                       z + c->n);
  for (size_t j = 0; !status && j < c->k; j++)
    if (!c->cons[j])
      z[c->n + j] = R->free[j] && R->Q[j * q + j % q] != 0
                    ? v[c->n + j] / R->Q[j * q + j % q] : v[c->n + j];
  return status;
}

int
lac_rows_gmres (lac_strategy *st, const lac_contact_system *sys,
                const lac_contact_rows *R, double *U, double *lambda,
                int *its, double *berr)
{
  size_t n = lac_system_n (sys), k = sys->C->ncol, N = n + k;
  rows_ctx c = { st, sys, R, n, k, (size_t) R->q, NULL, NULL, NULL };
  double *x = lac_malloc ((N + 1) * sizeof *x);
  double *b = lac_malloc ((N + 1) * sizeof *b);
  lac_gmres_info info = { 0, 0 };
  int status = LAC_SUCCESS;
  c.cons = lac_malloc (k + 1);
  c.cu = lac_malloc ((k + 1) * sizeof *c.cu);
  c.g = lac_malloc ((k + 1) * sizeof *c.g);
  if (!x || !b || !c.cons || !c.cu || !c.g)
    status = LAC_ERRMSG (LAC_ENOMEM, "GMRES on %zu unknowns", N);
  for (size_t j = 0; !status && j < k; j++)
    {
      c.cons[j] = R->free[j] && is_constraint (R, j);
      b[n + j] = R->free[j] ? R->r[j] : 0.0;
      x[n + j] = R->free[j] ? lambda[j] : 0.0;
    }
  if (!status)
    {
      memcpy (b, sys->F, n * sizeof *b);
      memcpy (x, U, n * sizeof *x);
      status = lac_gmres (N, apply_a, apply_m, &c, b, x, ROWS_RTOL,
                          ROWS_RESTART, ROWS_MAXIT, &info);
    }
  if (!status)
    {
      memcpy (U, x, n * sizeof *U);
      memcpy (lambda, x + n, k * sizeof *lambda);
      status = lac_system_rows_residual (sys, R, U, lambda, b, b + n, berr);
    }
  *its = info.iterations;
  lac_free (x), lac_free (b);
  lac_free (c.cons), lac_free (c.cu), lac_free (c.g);
  return status;
}
