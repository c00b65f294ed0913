/* lac_infsup.c -- beta_h as the smallest eigenvalue of (C^T A^-1 C, M)
 *                                                        [LAC (10)]
 *
 * The driver lac_infsup_estimate (argument checks, the CHOLMOD factor of
 * A, the choice of path, the normalization of the eigenvector) and the
 * dense path; the sparse path (shift-invert Lanczos) is in
 * lac_infsup_lanczos.c, the matrices A and M in lac_infsup_gram.c.  See
 * lac_infsup.h for the mathematics and the choice of norms.
 *
 * GSL gotchas (deps.md 3c): gsl_eigen_gensymmv overwrites both matrices,
 * so it gets copies; its eigenpairs come back unsorted
 * (gsl_eigen_gensymmv_sort); lac_init has switched GSL's aborting error
 * handler off, so its status is checked here.
 */
#include "contact/lac_infsup.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include "contact/lac_infsup_lanczos.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

void
lac_infsup_opts_init (lac_infsup_opts *o)
{
  o->path = LAC_INFSUP_AUTO;
  o->tol = 1e-10;
  o->maxit = 500;
}

void
lac_infsup_free (lac_infsup *r)
{
  if (!r)
    return;
  lac_free (r->mu);
  lac_free (r);
}

const char *
lac_infsup_path_name (lac_infsup_path p)
{
  return p == LAC_INFSUP_DENSE ? "dense" : p == LAC_INFSUP_SPARSE ? "sparse"
         : "auto";
}

/* ---- the eigenvector of both paths ----------------------------------- */

/* Scale mu to mu^T M mu = 1 with its largest entry positive; set imax,
 * the first index whose |mu_i| is within 1e-6 of the largest (symmetric
 * patterns have ties, which the two paths must break the same way).
 * work: k doubles. */
static void
normalize (const lac_csc *M, lac_infsup *r, double *work)
{
  double nrm = 0, big = 0;
  lac_csc_matvec (M, r->mu, work);                   /* work = M mu */
  for (size_t i = 0; i < r->k; i++)
    nrm += r->mu[i] * work[i];                       /* mu^T M mu */
  nrm = sqrt (fabs (nrm));
  for (size_t i = 0; i < r->k; i++)
    big = fmax (big, fabs (r->mu[i]));
  r->imax = 0;
  while (r->imax + 1 < r->k && fabs (r->mu[r->imax]) < (1 - 1e-6) * big)
    r->imax++;
  if (nrm > 0 && r->mu[r->imax] < 0)
    nrm = -nrm;
  for (size_t i = 0; i < r->k && nrm != 0; i++)
    r->mu[i] /= nrm;
}

/* ---- dense path ------------------------------------------------------- */

/* S = C^T A^{-1} C (k x k, row-major, symmetrized), by blocks of
 * LAC_INFSUP_BLOCK columns: X = A^{-1} C(:, block), S(:, block) = C^T X. */
static int
form_S (lac_solver *sA, const lac_csc *C, double *S)
{
  size_t n = C->nrow, k = C->ncol, nb = LAC_INFSUP_BLOCK;
  double *B = lac_malloc (n * nb * sizeof *B);
  double *X = lac_malloc (n * nb * sizeof *X);
  int status = LAC_SUCCESS;
  if (!B || !X)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "%zu x %zu blocks for A^-1 C", n, nb);
      goto done;
    }
  for (size_t j0 = 0; j0 < k && !status; j0 += nb)
    {
      size_t m = k - j0 < nb ? k - j0 : nb;
      memset (B, 0, n * m * sizeof *B);
      for (size_t jj = 0; jj < m; jj++)               /* B = C(:, j0..) */
        for (int p = C->p[j0 + jj]; p < C->p[j0 + jj + 1]; p++)
          B[jj * n + (size_t) C->i[p]] = C->x[p];
      if ((status = lac_solver_solve_many (sA, m, B, X)))  /* X = A^-1 B */
        break;
      for (size_t i = 0; i < k; i++)                  /* S(i, j) = c_i . x_j */
        for (size_t jj = 0; jj < m; jj++)
          {
            double s = 0;
            for (int p = C->p[i]; p < C->p[i + 1]; p++)
              s += C->x[p] * X[jj * n + (size_t) C->i[p]];
            S[i * k + j0 + jj] = s;
          }
    }
  for (size_t i = 0; i < k && !status; i++)           /* S = (S + S^T)/2 */
    for (size_t j = 0; j < i; j++)
      S[i * k + j] = S[j * k + i] = 0.5 * (S[i * k + j] + S[j * k + i]);
done:
  lac_free (X);
  lac_free (B);
  return status;
}

/* ||S mu - lambda M mu|| / (|lambda| ||M mu||) with the dense S. */
static double
dense_residual (const double *S, const lac_csc *M, const lac_infsup *r,
                double *Mmu)
{
  double num = 0, den = 0;
  lac_csc_matvec (M, r->mu, Mmu);
  for (size_t i = 0; i < r->k; i++)
    {
      double s = -r->lambda_min * Mmu[i];
      for (size_t j = 0; j < r->k; j++)
        s += S[i * r->k + j] * r->mu[j];              /* (S mu - lam M mu)_i */
      num += s * s;
      den += Mmu[i] * Mmu[i];
    }
  den = sqrt (den) * fabs (r->lambda_min);
  return den > 0 ? sqrt (num) / den : sqrt (num);
}

/* All eigenpairs of (S, M) with GSL, ascending; fills r. */
static int
dense_eigen (const double *S, const lac_csc *M, lac_infsup *r)
{
  size_t k = r->k;
  int gst = GSL_ENOMEM, status = LAC_SUCCESS;
  gsl_matrix *Sc = gsl_matrix_alloc (k, k), *Mc = gsl_matrix_calloc (k, k);
  gsl_matrix *V = gsl_matrix_alloc (k, k);
  gsl_vector *ev = gsl_vector_alloc (k);
  gsl_eigen_gensymmv_workspace *w = gsl_eigen_gensymmv_alloc (k);
  if (Sc && Mc && V && ev && w)
    {
      memcpy (Sc->data, S, k * k * sizeof *S);        /* copies: overwritten */
      for (size_t j = 0; j < k; j++)
        for (int p = M->p[j]; p < M->p[j + 1]; p++)
          gsl_matrix_set (Mc, (size_t) M->i[p], j, M->x[p]);
      gst = gsl_eigen_gensymmv (Sc, Mc, ev, V, w);   /* S V = M V diag(ev) */
      if (!gst)
        gst = gsl_eigen_gensymmv_sort (ev, V, GSL_EIGEN_SORT_VAL_ASC);
    }
  if (gst == GSL_ENOMEM)
    status = LAC_ERRMSG (LAC_ENOMEM, "GSL eigenproblem of order %zu", k);
  else if (gst)
    status = LAC_ERRMSG (LAC_EDEP, "gsl_eigen_gensymmv: %s (is M positive "
                         "definite?)", gsl_strerror (gst));
  else
    {
      r->lambda_min = gsl_vector_get (ev, 0);
      r->lambda_2 = k > 1 ? gsl_vector_get (ev, 1) : NAN;
      r->lambda_max = gsl_vector_get (ev, k - 1);
      for (size_t i = 0; i < k; i++)
        r->mu[i] = gsl_matrix_get (V, i, 0);          /* first eigenvector */
    }
  gsl_eigen_gensymmv_free (w);
  gsl_vector_free (ev);
  gsl_matrix_free (V);
  gsl_matrix_free (Mc);
  gsl_matrix_free (Sc);
  return status;
}

/* The dense path: sA holds the CHOLMOD factor of A. */
static int
dense_path (lac_solver *sA, const lac_csc *C, const lac_csc *M,
            lac_infsup *r)
{
  size_t k = C->ncol;
  double *S = lac_malloc (k * k * sizeof *S), *work = lac_malloc (k * sizeof
                                                                  *work);
  int status;
  if (!S || !work)
    {
      lac_free (S);
      lac_free (work);
      LAC_ERROR (LAC_ENOMEM, "dense S of order %zu (use the sparse path)", k);
    }
  if (!(status = form_S (sA, C, S))                   /* S = C^T A^-1 C */
      && !(status = dense_eigen (S, M, r)))           /* S mu = lam M mu */
    {
      normalize (M, r, work);
      r->residual = dense_residual (S, M, r, work);
      r->path = LAC_INFSUP_DENSE;
    }
  lac_free (work);
  lac_free (S);
  return status;
}

/* ---- sparse path ------------------------------------------------------ */

/* The sparse path (lac_infsup_lanczos.c), then the eigenvector's
 * normalization. */
static int
sparse_path (const lac_csc *A, const lac_csc *C, const lac_csc *M,
             const lac_infsup_opts *o, lac_infsup *r)
{
  double *work = lac_malloc (r->k * sizeof *work);
  int status;
  if (!work)
    LAC_ERROR (LAC_ENOMEM, "normalization of %zu multipliers", r->k);
  status = lac_infsup_sparse (A, C, M, o, r);
  if (!status)
    {
      normalize (M, r, work);
      r->path = LAC_INFSUP_SPARSE;
    }
  lac_free (work);
  return status;
}

/* ---- the driver ------------------------------------------------------- */

/* Sizes and indices of A, C, M (the messages name the estimate). */
static int
check_args (const lac_csc *A, const lac_csc *C, const lac_csc *M,
            lac_infsup **out)
{
  if (!A || !C || !M || !out)
    LAC_ERROR (LAC_EINVAL, "A, C, M or the output is NULL");
  *out = NULL;
  if (A->nrow != A->ncol || C->nrow != A->nrow)
    LAC_ERROR (LAC_EBADLEN, "A is %zu x %zu and C %zu x %zu: A must be "
               "square with as many rows as C", A->nrow, A->ncol, C->nrow,
               C->ncol);
  if (C->ncol == 0)
    LAC_ERROR (LAC_EINVAL, "C has no column: no multiplier, no inf-sup "
               "constant");
  if (M->nrow != C->ncol || M->ncol != C->ncol)
    LAC_ERROR (LAC_EBADLEN, "M is %zu x %zu, C has %zu columns", M->nrow,
               M->ncol, C->ncol);
  for (int p = 0; p < M->p[M->ncol]; p++)       /* GSL would ignore them */
    if (M->i[p] < 0 || (size_t) M->i[p] >= M->nrow)
      LAC_ERROR (LAC_EINVAL, "M has a row index %d out of 0..%zu", M->i[p],
                 M->nrow - 1);
  for (int p = 0; p < C->p[C->ncol]; p++)
    if (C->i[p] < 0 || (size_t) C->i[p] >= C->nrow)
      LAC_ERROR (LAC_EINVAL, "C has a row index %d out of 0..%zu", C->i[p],
                 C->nrow - 1);
  return LAC_SUCCESS;
}

int
lac_infsup_estimate (const lac_csc *A, const lac_csc *C, const lac_csc *M,
                     const lac_infsup_opts *opts, lac_infsup **out)
{
  lac_infsup_opts o;
  lac_infsup *r = NULL;
  lac_solver *sA = NULL;
  int status;
  if ((status = check_args (A, C, M, out)))
    return status;
  if (opts)
    o = *opts;
  else
    lac_infsup_opts_init (&o);
  if (!(r = lac_calloc (1, sizeof *r))
      || !(r->mu = lac_calloc (C->ncol, sizeof *r->mu))
      || !(sA = lac_solver_alloc (LAC_SOLVER_CHOLMOD)))
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "inf-sup result for %zu multipliers",
                           C->ncol);
      goto done;
    }
  r->n = C->nrow;
  r->k = C->ncol;
  r->lambda_2 = r->lambda_max = NAN;
  /* Step 1: A = L L^T; refused if A is not positive definite. */
  if ((status = lac_solver_factor (sA, A)))
    {
      if (status == LAC_ESING)
        status = LAC_ERRMSG (status, "the displacement norm matrix A is not "
                             "positive definite (%s): with the energy norm, "
                             "a body held by contact alone has a singular "
                             "stiffness; use the H1 norm",
                             lac_error_message ());
      goto done;
    }
  /* Step 2: the smallest eigenpair of S mu = lambda M mu. */
  if (o.path == LAC_INFSUP_DENSE
      || (o.path == LAC_INFSUP_AUTO && r->k <= LAC_INFSUP_DENSE_KMAX))
    status = dense_path (sA, C, M, r);
  else
    status = sparse_path (A, C, M, &o, r);
  if (!status)
    r->beta = sqrt (fmax (r->lambda_min, 0.0));       /* beta_h [LAC (10)] */
done:
  lac_solver_free (sA);
  if (status)
    lac_infsup_free (r);
  else
    *out = r;
  return status;
}
