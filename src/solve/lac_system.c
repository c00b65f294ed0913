/* lac_system.c -- the LAC system of one active set (see lac_system.h)
 *                                                 [LAC (17), (18), Alg. 1]
 */
#include "solve/lac_system.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

static int
is_active (const char *active, size_t i)
{
  return !active || active[i];
}

void
lac_system_gaps (const lac_contact_system *sys, const double *U, double *d)
{
  const lac_csc *C = sys->C;
  for (size_t i = 0; i < C->ncol; i++)
    {
      double cu = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        cu += C->x[p] * U[C->i[p]];
      d[i] = sys->G[i] - cu;                               /* d = G - C^T U */
    }
}

int
lac_system_norm_k (const lac_contact_system *sys, double *normK)
{
  *normK = 0;
  if (sys->K)
    {
      *normK = lac_csc_diag_norm1 (sys->K, NULL);
      return LAC_SUCCESS;
    }
  return sys->Kop->norm (sys->Kop->self, normK);
}

int
lac_system_norm_c (const lac_contact_system *sys, double *normC)
{
  const lac_csc *C = sys->C;
  size_t n = lac_system_n (sys);
  double *row = lac_calloc (n ? n : 1, sizeof *row);
  *normC = 0;
  if (!row)
    LAC_ERROR (LAC_ENOMEM, "the row sums of C (%zu rows)", n);
  for (size_t i = 0; i < C->ncol; i++)          /* row sums of C */
    for (int p = C->p[i]; p < C->p[i + 1]; p++)
      row[C->i[p]] += fabs (C->x[p]);
  for (size_t r = 0; r < C->nrow; r++)
    *normC = fmax (*normC, row[r]);
  lac_free (row);
  return LAC_SUCCESS;
}

static double
norm_inf (size_t n, const double *x)
{
  double m = 0;
  for (size_t i = 0; i < n; i++)
    m = fmax (m, fabs (x[i]));
  return m;
}

size_t
lac_system_n (const lac_contact_system *sys)
{
  return sys->K ? sys->K->ncol : sys->Kop->n;
}

int
lac_system_k_mult (const lac_contact_system *sys, const double *x, double *y)
{
  if (sys->K)
    return lac_csc_matvec (sys->K, x, y);
  return sys->Kop->mult (sys->Kop->self, x, y);
}

int
lac_system_residual (const lac_contact_system *sys, const char *active,
                     const double *U, const double *lambda, double *r,
                     double *g, double *berr)
{
  const lac_csc *C = sys->C;
  size_t n = lac_system_n (sys), k = C->ncol;
  double normK, normC, scale;
  int status = lac_system_k_mult (sys, U, r);
  if (status)
    return status;
  for (size_t j = 0; j < n; j++)
    r[j] = sys->F[j] - r[j];                               /* F - K U */
  for (size_t i = 0; i < k; i++)
    {
      double cu = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        {
          if (is_active (active, i))
            r[C->i[p]] += C->x[p] * lambda[i];             /* + C_A lambda_A */
          cu += C->x[p] * U[C->i[p]];
        }
      g[i] = is_active (active, i) ? sys->G[i] - cu : 0.0; /* G_A - C_A^T U */
    }
  double nu = norm_inf (n, U);          /* at U = 0 (before the first set:
                                           Kop knows no norm yet) no K */
  if ((nu > 0 && (status = lac_system_norm_k (sys, &normK)))
      || (status = lac_system_norm_c (sys, &normC)))
    return status;
  scale = (nu > 0 ? normK * nu : 0.0) + normC * norm_inf (k, lambda)
          + norm_inf (n, sys->F) + norm_inf (k, sys->G);
  *berr = fmax (norm_inf (n, r), norm_inf (k, g)) / (scale > 0 ? scale
                                                     : 1e-300);
  return LAC_SUCCESS;
}

int
lac_system_rows_residual (const lac_contact_system *sys,
                          const lac_contact_rows *R, const double *U,
                          const double *lambda, double *res_f, double *res_r,
                          double *berr)
{
  const lac_csc *C = sys->C;
  size_t n = lac_system_n (sys), k = C->ncol, q = (size_t) R->q;
  double normK, normC, scale;
  int status = lac_system_k_mult (sys, U, res_f);
  if (status)
    return status;
  for (size_t j = 0; j < n; j++)
    res_f[j] = sys->F[j] - res_f[j];                       /* F - K U */
  for (size_t i = 0; i < k; i++)
    {
      double cu = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        {
          if (R->free[i])
            res_f[C->i[p]] += C->x[p] * lambda[i];         /* + C lambda */
          cu += C->x[p] * U[C->i[p]];
        }
      res_r[i] = -cu;                                      /* -c_i^T U */
    }
  for (size_t g = 0; g < k / q; g++)                       /* r - P (.) - Q l */
    {
      double row[3];
      for (size_t a = 0; a < q; a++)
        {
          size_t j = g * q + a;
          row[a] = R->r[j];
          for (size_t b = 0; R->free[j] && b < q; b++)
            row[a] -= R->P[j * q + b] * res_r[g * q + b]
                      + R->Q[j * q + b] * lambda[g * q + b];
        }
      for (size_t a = 0; a < q; a++)
        res_r[g * q + a] = R->free[g * q + a] ? row[a] : 0.0;
    }
  double nu = norm_inf (n, U);
  if ((nu > 0 && (status = lac_system_norm_k (sys, &normK)))
      || (status = lac_system_norm_c (sys, &normC)))
    return status;
  scale = (nu > 0 ? normK * nu : 0.0) + normC * norm_inf (k, lambda)
          + norm_inf (n, sys->F) + norm_inf (k, R->r);
  *berr = fmax (norm_inf (n, res_f), norm_inf (k, res_r))
          / (scale > 0 ? scale : 1e-300);
  return LAC_SUCCESS;
}

/* H = M^T M, M = C_A^T N (k x nfree), and the scale of each motion over
 * all of C (Hall_jj = sum_i (c_i^T N_j)^2); v: nfree of work. */
static void
held_gram (const lac_contact_system *sys, const char *active, double *H,
           double *Hall, double *v)
{
  const lac_csc *C = sys->C;
  size_t n = C->nrow, m = sys->nfree;
  memset (H, 0, m * m * sizeof *H);
  memset (Hall, 0, m * sizeof *Hall);
  for (size_t i = 0; i < C->ncol; i++)
    {
      for (size_t a = 0; a < m; a++)                   /* v = N^T c_i */
        {
          v[a] = 0;
          for (int p = C->p[i]; p < C->p[i + 1]; p++)
            v[a] += sys->N[a * n + (size_t) C->i[p]] * C->x[p];
          Hall[a] += v[a] * v[a];
        }
      for (size_t a = 0; is_active (active, i) && a < m; a++)
        for (size_t b = 0; b < m; b++)
          H[a * m + b] += v[a] * v[b];
    }
}

/* The free motion of N that the eigenvector a of V (m x m) moves most. */
static size_t
worst_motion (const gsl_matrix *V, size_t m, size_t a)
{
  size_t worst = 0;
  for (size_t b = 1; b < m; b++)
    if (fabs (gsl_matrix_get (V, b, a)) > fabs (gsl_matrix_get (V, worst, a)))
      worst = b;
  return worst;
}

/* The smallest eigenvalue of H (m x m, overwritten) against hmax: the
 * error naming the motion it leaves free, or LAC_SUCCESS. */
static int
held_rank (const lac_contact_system *sys, double *H, size_t m, double hmax,
           size_t na)
{
  gsl_matrix_view A = gsl_matrix_view_array (H, m, m);
  gsl_vector *ev = gsl_vector_alloc (m);
  gsl_matrix *V = gsl_matrix_alloc (m, m);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc (m);
  int status = !ev || !V || !w || gsl_eigen_symmv (&A.matrix, ev, V, w)
               ? LAC_ERRMSG (LAC_ENOMEM, "rank test of C_A^T N") : 0;
  size_t kmin = 0;
  for (size_t a = 1; !status && a < m; a++)
    if (gsl_vector_get (ev, a) < gsl_vector_get (ev, kmin))
      kmin = a;
  if (!status && !(gsl_vector_get (ev, kmin) > 1e-12 * hmax))
    {
      size_t worst = worst_motion (V, m, kmin);
      status = LAC_ERRMSG (LAC_ESING, "%s is held by contact alone, and the "
                           "%zu active multiplier%s of %zu leave%s it free "
                           "(a load pulls it off the contact surface, or "
                           "the contact cannot hold it)",
                           sys->N_what && sys->N_what[worst]
                           ? sys->N_what[worst] : "a rigid motion", na,
                           na == 1 ? "" : "s", sys->C->ncol,
                           na == 1 ? "s" : "");
    }
  gsl_eigen_symmv_free (w);
  gsl_matrix_free (V);
  gsl_vector_free (ev);
  return status;
}

int
lac_system_check_held (const lac_contact_system *sys, const char *active)
{
  size_t m = sys->nfree, na = 0;
  double hmax = 0;
  if (m == 0)
    return LAC_SUCCESS;
  double *H = lac_malloc ((m * m + 2 * m) * sizeof *H);   /* H, Hall, v */
  if (!H)
    LAC_ERROR (LAC_ENOMEM, "rank test of %zu free rigid motions", m);
  for (size_t i = 0; i < sys->C->ncol; i++)
    na += is_active (active, i) != 0;
  held_gram (sys, active, H, H + m * m, H + m * m + m);
  for (size_t a = 0; a < m; a++)
    hmax = fmax (hmax, H[m * m + a]);
  int status = held_rank (sys, H, m, hmax, na);
  lac_free (H);
  return status;
}

void
lac_system_column_scales (const lac_contact_system *sys, double *work,
                          double *s)
{
  const lac_csc *C = sys->C;
  size_t n = lac_system_n (sys);
  lac_csc_diag_norm1 (sys->K, work);
  for (size_t j = 0; j < n; j++)
    work[j] = work[j] != 0 ? 1 / fabs (work[j]) : 0.0;   /* diag(K)^-1 */
  for (size_t i = 0; i < C->ncol; i++)
    {
      s[i] = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        s[i] += C->x[p] * C->x[p] * work[C->i[p]];
    }
}

void
lac_solve_counts_factored (lac_solve_counts *c, const lac_solver *chol)
{
  lac_solver_info info;
  c->factorizations++;
  c->solves += 2;                         /* the condition estimate's */
  if (lac_solver_get_info (chol, &info) == LAC_SUCCESS)
    {
      c->analyses += !info.analysis_reused;
      c->rcond = info.rcond;
      c->flops += info.flops;
    }
}

int
lac_solve_counts_factor (lac_solve_counts *c, lac_solver *chol,
                         const lac_csc *A)
{
  double t0 = lac_seconds ();
  int status = lac_solver_refactor (chol, A);
  c->time_factor += lac_seconds () - t0;
  if (!status)
    lac_solve_counts_factored (c, chol);
  return status;
}

int
lac_solve_counts_krylov (lac_solve_counts *c, int status, int iterations,
                         double residual, size_t na)
{
  c->iterations += iterations;
  c->last_iterations = iterations;
  c->last_residual = residual;
  if (status == LAC_EMAXITER || status == LAC_ESING)
    return LAC_ERRMSG (LAC_ESING, "the multipliers of the %zu active "
                       "macro-elements are not determined (%s): their "
                       "system is singular, the contact constraints are "
                       "linearly dependent (inf-sup condition [LAC (10)])",
                       na, lac_error_message ());
  return status;
}
