/* lac_friction.c -- Coulomb's law on the LAC averages
 *                   (see lac_friction.h)              [LAC (18), Alg. 1]
 */
#include "solve/lac_friction.h"

#include <math.h>
#include <string.h>
#include "base/lac_vec.h"

/* b = mu max(0, -(lambda_n + rho d)), the radius of the disc, and xi =
 * lambda_t - rho ds (ntan), each at the rounding rule of lac_snap. */
static double
bound_and_xi (const lac_friction_slot *x, double *xi)
{
  double a = lac_snap (x->lambda_n, x->lmax)
             + x->rho * lac_snap (x->d, x->dscale);
  for (int b = 0; b < x->ntan; b++)
    xi[b] = lac_snap (x->lambda_t[b], x->lmax)
            - x->rho * lac_snap (x->ds[b], x->sscale);
  return x->mu * fmax (0.0, -a);
}

static double
norm (int n, const double *v)
{
  double s = 0;
  for (int b = 0; b < n; b++)
    s += v[b] * v[b];
  return sqrt (s);
}

int
lac_friction_status (const lac_friction_slot *x, int first, int current,
                     double *dir)
{
  double xi[2], b;
  if (first)                               /* [Alg. 1, lines 2-8] */
    return lac_snap (x->d, x->dscale) <= 0 ? LAC_FRICTION_STICK
           : LAC_FRICTION_INACTIVE;
  double a = lac_snap (x->lambda_n, x->lmax)
             + x->rho * lac_snap (x->d, x->dscale);
  if (!(a < 0))
    return LAC_FRICTION_INACTIVE;          /* lambda_n + rho d >= 0 */
  b = bound_and_xi (x, xi);
  double nx = norm (x->ntan, xi);
  int tie = current != LAC_FRICTION_INACTIVE
            && fabs (nx - b) <= LAC_FRICTION_TIE * b;
  if (nx == 0 || (tie ? current == LAC_FRICTION_STICK
                      : nx <= b * (1 + LAC_ROUNDING)))
    return LAC_FRICTION_STICK;             /* |xi| <= b */
  for (int k = 0; k < x->ntan; k++)
    dir[k] = xi[k] / nx;                   /* e = xi / |xi| */
  return LAC_FRICTION_SLIP;
}

/* The slip equations of 3D at the iterate x (rows 1, 2 of the block):
 * Newton's linearization of lambda_t - b xi/|xi| = 0 (lac_friction.h). */
static void
slip_rows_3d (const lac_friction_slot *x, double an, const double *at,
              double *P, double *Q, double *r)
{
  double xi[2], b = bound_and_xi (x, xi), nx = norm (2, xi), e[2], M[4];
  double mu = x->mu, rho = x->rho;
  for (int a = 0; a < 2; a++)
    e[a] = xi[a] / nx;
  for (int a = 0; a < 2; a++)
    for (int c = 0; c < 2; c++)
      M[2 * a + c] = b / nx * ((a == c) - e[a] * e[c]);
  for (int a = 0; a < 2; a++)
    {
      int j = 1 + a;
      double *Pj = P + 3 * j, *Qj = Q + 3 * j;
      Pj[0] = mu * rho * e[a];                   /* -mu rho e c_n^T U */
      Qj[0] = mu * e[a];                         /* mu e lambda_n */
      r[j] = mu * e[a] * x->lambda_n - mu * rho * e[a] * an
             - (x->lambda_t[a] - b * e[a]);
      for (int c = 0; c < 2; c++)
        {
          Pj[1 + c] = -rho * M[2 * a + c];       /* rho M c_t^T U */
          Qj[1 + c] = (a == c) - M[2 * a + c];   /* (I - M) lambda_t */
          r[j] += ((a == c) - M[2 * a + c]) * x->lambda_t[c]
                  + rho * M[2 * a + c] * at[c];
        }
    }
}

void
lac_friction_rows (int st, const lac_friction_slot *x, const double *dir,
                   double G, const double *gt, double an, const double *at,
                   double *P, double *Q, double *r)
{
  int ntan = x->ntan, q = 1 + ntan;
  double mu = x->mu;
  memset (P, 0, (size_t) (q * q) * sizeof *P);
  memset (Q, 0, (size_t) (q * q) * sizeof *Q);
  memset (r, 0, (size_t) q * sizeof *r);
  if (st == LAC_FRICTION_INACTIVE)
    {
      for (int j = 0; j < q; j++)
        Q[j * q + j] = 1;                  /* lambda = 0 */
      return;
    }
  P[0] = 1;                                /* -c_n^T U = -G: d = 0 */
  r[0] = -G;
  if (st == LAC_FRICTION_SLIP && ntan == 2)
    {
      slip_rows_3d (x, an, at, P, Q, r);
      return;
    }
  for (int b = 0; b < ntan; b++)
    {
      int j = 1 + b;
      if (st == LAC_FRICTION_STICK)
        {
          P[j * q + j] = 1;                /* -c_t^T U = -gt: ds = 0 */
          r[j] = -gt[b];
        }
      else
        {
          Q[j * q + j] = 1;                /* lambda_t + mu e lambda_n = 0 */
          Q[j * q] = mu * dir[b];
        }
    }
}

double
lac_friction_residual (const lac_friction_slot *x)
{
  double xi[2], b = bound_and_xi (x, xi), nx = norm (x->ntan, xi), res = 0;
  double scale = nx > b ? b / nx : 1.0;    /* P_b(xi) = xi min(1, b/|xi|) */
  for (int k = 0; k < x->ntan; k++)
    {
      double e = lac_snap (x->lambda_t[k], x->lmax) - scale * xi[k];
      res += e * e;
    }
  return sqrt (res);
}
