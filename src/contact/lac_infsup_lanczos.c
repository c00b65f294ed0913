/* lac_infsup_lanczos.c -- the sparse path of the inf-sup estimate
 *                                                        [LAC (10)]
 *
 * The smallest eigenvalue lambda_1 = beta_h^2 of S mu = lambda M mu,
 * S = C^T A^{-1} C, without forming S: Lanczos on T = S^{-1} M, whose
 * eigenvalues theta = 1/lambda have lambda_1 at the top, well separated
 * from the rest (shift-and-invert at sigma = 0; Saad, Numerical Methods
 * for Large Eigenvalue Problems, 2011, §6.3 and §8.1).  T is self-adjoint
 * in the M inner product <x, y>_M = x^T M y, so with M-orthonormal
 * Lanczos vectors q_1..q_j
 *
 *   T Q_j = Q_j T_j + b_j q_{j+1} e_j^T,   T_j tridiagonal (a_i, b_i),
 *
 * and a Ritz pair (theta, Q_j y) of T_j has the residual
 * ||T x - theta x||_M = b_j |y_j|, which bounds |theta - theta_true|
 * (T is M-self-adjoint).  Stop when b_j |y_j| <= tol theta: the relative
 * error of lambda_1 is then below tol, however clustered the spectrum.
 * Full reorthogonalization (classical Gram-Schmidt, twice) keeps the
 * vectors M-orthonormal: k x j numbers, small next to the factor.
 *
 * One step costs one solve with the saddle-point matrix
 *
 *   Z = [ A    s C ]      Z [w; y] = [0; -r]  =>  S^{-1} r = s^2 y,
 *       [ s C^T  0 ]
 *
 * factored once by UMFPACK; s = max|A| / max|C| balances the blocks.
 * The start vector is a fixed pseudo-random one (reproducible runs).
 */
#include "contact/lac_infsup_lanczos.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

#define CHECK_EVERY 5        /* Ritz values every this many steps, or every
                                j/10 steps beyond 50 (the O(j^3) eigensolve
                                of T_j stays a small part of the work)     */
#define BREAKDOWN 1e-12      /* b_j <= BREAKDOWN theta: invariant subspace  */

static double
amax (const lac_csc *A)
{
  double a = 0;
  for (int p = 0; p < A->p[A->ncol]; p++)
    a = fmax (a, fabs (A->x[p]));
  return a;
}

/* Z = [A sC; sC^T 0], rows sorted in each column. */
static lac_csc *
saddle (const lac_csc *A, const lac_csc *C, double s)
{
  size_t n = A->ncol, k = C->ncol, q = 0;
  size_t nnz = (size_t) A->p[n] + 2 * (size_t) C->p[k];
  lac_csc *Ct = lac_csc_transpose (C), *Z = NULL;
  if (Ct && (Z = lac_csc_alloc (n + k, n + k, nnz)))
    {
      for (size_t j = 0; j < n; j++)
        {
          Z->p[j] = (int) q;
          for (int p = A->p[j]; p < A->p[j + 1]; p++, q++)   /* A(:, j) */
            Z->i[q] = A->i[p], Z->x[q] = A->x[p];
          for (int p = Ct->p[j]; p < Ct->p[j + 1]; p++, q++) /* s C(j, :)^T */
            Z->i[q] = (int) n + Ct->i[p], Z->x[q] = s * Ct->x[p];
        }
      for (size_t i = 0; i < k; i++)
        {
          Z->p[n + i] = (int) q;
          for (int p = C->p[i]; p < C->p[i + 1]; p++, q++)   /* s C(:, i) */
            Z->i[q] = C->i[p], Z->x[q] = s * C->x[p];
        }
      Z->p[n + k] = (int) q;
    }
  lac_csc_free (Ct);
  return Z;
}

/* The largest two Ritz values of T_j (a, b; order j) and the last
 * component of the top Ritz vector's y, kept in y[0..j-1]. */
static int
ritz (size_t j, const double *a, const double *b, double *theta,
      double *theta2, double *y)
{
  gsl_matrix *T = gsl_matrix_calloc (j, j), *V = gsl_matrix_alloc (j, j);
  gsl_vector *ev = gsl_vector_alloc (j);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc (j);
  int gst = GSL_ENOMEM;
  if (T && V && ev && w)
    {
      for (size_t i = 0; i < j; i++)
        {
          gsl_matrix_set (T, i, i, a[i]);
          if (i + 1 < j)
            gsl_matrix_set (T, i, i + 1, b[i]), gsl_matrix_set (T, i + 1, i,
                                                                 b[i]);
        }
      if (!(gst = gsl_eigen_symmv (T, ev, V, w)))
        gst = gsl_eigen_symmv_sort (ev, V, GSL_EIGEN_SORT_VAL_DESC);
      if (!gst)
        {
          *theta = gsl_vector_get (ev, 0);
          *theta2 = j > 1 ? gsl_vector_get (ev, 1) : NAN;
          for (size_t i = 0; i < j; i++)
            y[i] = gsl_matrix_get (V, i, 0);
        }
    }
  gsl_eigen_symmv_free (w);
  gsl_vector_free (ev);
  gsl_matrix_free (V);
  gsl_matrix_free (T);
  if (gst)
    LAC_ERROR (gst == GSL_ENOMEM ? LAC_ENOMEM : LAC_EDEP, "gsl_eigen_symmv on"
               " the Lanczos matrix of order %zu: %s", j, gsl_strerror (gst));
  return LAC_SUCCESS;
}

/* w = S^{-1} r through the saddle-point factor (rhs, sol: n + k). */
static int
apply_Sinv (lac_solver *sZ, size_t n, size_t k, double s, const double *r,
            double *rhs, double *sol, double *w)
{
  int status;
  memset (rhs, 0, n * sizeof *rhs);
  for (size_t i = 0; i < k; i++)
    rhs[n + i] = -r[i];                               /* [0; -r] */
  if ((status = lac_solver_solve (sZ, rhs, sol)))
    return status;
  for (size_t i = 0; i < k; i++)
    w[i] = s * s * sol[n + i];                        /* S^-1 r = s^2 y */
  return LAC_SUCCESS;
}

/* w -= Q_j (MQ_j^T w), twice; h[i] += the coefficients. */
static void
reorthogonalize (size_t k, size_t j, const double *Q, const double *MQ,
                 double *w, double *h)
{
  for (int pass = 0; pass < 2; pass++)
    for (size_t i = 0; i <= j; i++)
      {
        double c = lac_vec_dot (k, MQ + i * k, w);    /* <q_i, w>_M */
        for (size_t l = 0; l < k; l++)
          w[l] -= c * Q[i * k + l];
        h[i] += c;
      }
}

/* Steps 1-3 of the Lanczos loop; the factor and the work arrays are
 * set up by lac_infsup_sparse. */
typedef struct lanczos
{
  size_t n, k, m;          /* dofs, multipliers, maximum steps           */
  double s;                /* scaling of C in Z                          */
  lac_solver *sZ;          /* borrowed: the factor of Z                  */
  double *Q, *MQ;          /* k x (m+1): q_i and M q_i                    */
  double *a, *b, *h, *y;   /* m each                                     */
  double *rhs, *sol;       /* n + k                                      */
} lanczos;

static int
lanczos_run (lanczos *L, const lac_csc *M, const lac_infsup_opts *o,
             lac_infsup *r)
{
  size_t k = L->k;
  double theta = 0, theta2 = NAN, res = HUGE_VAL;
  unsigned long seed = 12345;
  int status;
  /* Step 1: q_1 = a fixed pseudo-random vector, M-normalized. */
  for (size_t i = 0; i < k; i++)
    {
      seed = (seed * 1103515245UL + 12345UL) & 0x7fffffffUL;
      L->Q[i] = 2.0 * (double) seed / 2147483647.0 - 1.0;
    }
  lac_csc_matvec (M, L->Q, L->MQ);
  double nq = sqrt (lac_vec_dot (k, L->Q, L->MQ));
  for (size_t i = 0; i < k; i++)
    L->Q[i] /= nq, L->MQ[i] /= nq;
  for (size_t j = 0; j < L->m; j++)
    {
      double *w = L->Q + (j + 1) * k, *Mw = L->MQ + (j + 1) * k;
      /* Step 2: w = T q_j = S^-1 M q_j, M-orthogonalized against Q_j. */
      if ((status = apply_Sinv (L->sZ, L->n, k, L->s, L->MQ + j * k, L->rhs,
                                L->sol, w)))
        return status;
      memset (L->h, 0, (j + 1) * sizeof *L->h);
      reorthogonalize (k, j, L->Q, L->MQ, w, L->h);
      L->a[j] = L->h[j];                            /* a_j = <q_j, T q_j>_M */
      lac_csc_matvec (M, w, Mw);
      L->b[j] = sqrt (fmax (lac_vec_dot (k, w, Mw), 0.0)); /* b_j = ||w||_M */
      /* Step 3: the top Ritz pair of T_j and its residual b_j |y_j|. */
      int last = j + 1 == L->m;
      size_t every = j + 1 < 50 ? CHECK_EVERY : (j + 1) / 10;
      if ((j + 1) % every == 0 || last || L->b[j] <= BREAKDOWN * theta)
        {
          if ((status = ritz (j + 1, L->a, L->b, &theta, &theta2, L->y)))
            return status;
          res = L->b[j] * fabs (L->y[j]);
          if (res <= o->tol * theta || L->b[j] <= BREAKDOWN * theta)
            {
              r->iterations = j + 1;
              break;
            }
          if (last)
            LAC_ERROR (LAC_EMAXITER, "Lanczos: Ritz residual %.2e > tol %.1e"
                       " * theta after %zu steps (raise maxit or tol, or use"
                       " the dense path)", res / theta, o->tol, L->m);
        }
      for (size_t i = 0; i < k; i++)                  /* q_{j+1} = w / b_j */
        w[i] /= L->b[j], Mw[i] /= L->b[j];
    }
  if (!(theta > 0))
    LAC_ERROR (LAC_ESING, "S = C^T A^-1 C is not positive definite (top Ritz"
               " value %g of S^-1 M): beta_h = 0", theta);
  /* Step 4: mu = Q_j y, lambda = 1 / theta. */
  memset (r->mu, 0, k * sizeof *r->mu);
  for (size_t i = 0; i < r->iterations; i++)
    for (size_t l = 0; l < k; l++)
      r->mu[l] += L->y[i] * L->Q[i * k + l];
  r->lambda_min = 1.0 / theta;
  r->lambda_2 = theta2 > 0 ? 1.0 / theta2 : NAN;
  r->lambda_max = NAN;
  r->residual = res / theta;
  return LAC_SUCCESS;
}

int
lac_infsup_sparse (const lac_csc *A, const lac_csc *C, const lac_csc *M,
                   const lac_infsup_opts *o, lac_infsup *r)
{
  lanczos L;
  lac_csc *Z = NULL;
  int status = LAC_SUCCESS;
  memset (&L, 0, sizeof L);
  L.n = C->nrow;
  L.k = C->ncol;
  L.m = o->maxit < L.k ? o->maxit : L.k;
  if (L.m == 0)
    LAC_ERROR (LAC_EINVAL, "maxit = 0: no Lanczos step allowed");
  double ac = amax (C);
  if (!(ac > 0))
    LAC_ERROR (LAC_ESING, "C = 0: no displacement sees the multipliers, "
               "beta_h = 0");
  L.s = amax (A) / ac;
  Z = saddle (A, C, L.s);
  L.sZ = lac_solver_alloc (LAC_SOLVER_UMFPACK);
  L.Q = lac_malloc (L.k * (L.m + 1) * sizeof *L.Q);
  L.MQ = lac_malloc (L.k * (L.m + 1) * sizeof *L.MQ);
  L.a = lac_malloc (4 * L.m * sizeof *L.a);
  L.rhs = lac_malloc (2 * (L.n + L.k) * sizeof *L.rhs);
  if (!Z || !L.sZ || !L.Q || !L.MQ || !L.a || !L.rhs)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "Lanczos on %zu multipliers (%zu "
                           "steps)", L.k, L.m);
      goto done;
    }
  L.b = L.a + L.m;
  L.h = L.b + L.m;
  L.y = L.h + L.m;
  L.sol = L.rhs + L.n + L.k;
  if ((status = lac_solver_factor (L.sZ, Z)))          /* Z = L U */
    {
      if (status == LAC_ESING)
        status = LAC_ERRMSG (status, "the saddle-point matrix [A C; C^T 0] "
                             "is singular (%s): C has dependent columns, "
                             "beta_h = 0 (the dense path gives the "
                             "eigenvector)", lac_error_message ());
      goto done;
    }
  status = lanczos_run (&L, M, o, r);
done:
  lac_free (L.rhs);
  lac_free (L.a);
  lac_free (L.MQ);
  lac_free (L.Q);
  lac_solver_free (L.sZ);
  lac_csc_free (Z);
  return status;
}
