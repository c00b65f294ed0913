/* lac_newton.c -- primal-dual active set for the LAC saddle system
 *                                                    [LAC §4.5, (18), Alg. 1]
 *
 * See lac_newton.h for the sign convention.  Two ways to solve one
 * iteration of [LAC Alg. 1, line 21] for a fixed active set A:
 *
 *   saddle (umfpack, dense)   assemble [K -C_A; -C_A^T 0] with identity rows
 *                             for the inactive multipliers and factorize it;
 *   schur  (cholmod)          with K = L L^T factorized once in set():
 *                               U0 = K^{-1} F,  S = C^T K^{-1} C  (k x k),
 *                               S_AA lambda_A = G_A - C_A^T U0,
 *                               U = K^{-1} (F + C_A lambda_A).
 *
 * References: M. Hintermüller, K. Ito, K. Kunisch, The primal-dual active
 * set strategy as a semismooth Newton method, SIAM J. Optim. 13 (2002);
 * S. Hüeber, B. Wohlmuth [LAC ref. 45].
 */
#include "solve/lac_newton.h"

#include <math.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_linalg.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

#define SCHUR_BLOCK 64   /* columns of K^{-1} C computed at a time */

static double
seconds (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

lac_newton *
lac_newton_alloc (lac_solver_kind kind, size_t n, size_t k)
{
  lac_newton *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "newton workspace");
  s->kind = kind;
  s->n = n;
  s->k = k;
  s->U = lac_calloc (n, sizeof *s->U);
  s->lambda = lac_calloc (k, sizeof *s->lambda);
  s->d = lac_calloc (k, sizeof *s->d);
  s->active = lac_calloc (k, 1);
  /* work: n+k (saddle rhs/solution) twice, or U0 (n) + k*k Schur + k*3 */
  size_t nw = kind == LAC_SOLVER_CHOLMOD ? 2 * n + k * k + 3 * k
                                         : 2 * (n + k);
  s->work = lac_calloc (nw, sizeof *s->work);
  if (!s->U || !s->lambda || !s->d || !s->active || !s->work)
    {
      lac_newton_free (s);
      LAC_ERROR_NULL (LAC_ENOMEM, "newton workspace for n = %zu, k = %zu", n, k);
    }
  return s;
}

void
lac_newton_free (lac_newton *s)
{
  if (!s)
    return;
  lac_free (s->U);
  lac_free (s->lambda);
  lac_free (s->d);
  lac_free (s->active);
  lac_free (s->work);
  lac_free (s->hist);
  lac_solver_free (s->solver);
  lac_csc_free (s->Ct);
  lac_free (s);
}

void
lac_newton_share_solver (lac_newton *s, lac_solver *so)
{
  s->shared = so;
}

size_t
lac_newton_nactive (const lac_newton *s)
{
  size_t m = 0;
  for (size_t i = 0; i < s->k; i++)
    m += s->active[i] != 0;
  return m;
}

/* d = G - C^T U, using the stored C^T (rows = multipliers). */
static void
mean_gaps (const lac_newton *s)
{
  const lac_csc *Ct = s->Ct;   /* C^T is k x n; its CSC columns are dofs */
  for (size_t i = 0; i < s->k; i++)
    s->d[i] = s->sys->G[i];
  for (size_t r = 0; r < s->n; r++)
    for (int p = Ct->p[r]; p < Ct->p[r + 1]; p++)
      s->d[Ct->i[p]] -= Ct->x[p] * s->U[r];                /* d -= C^T U */
}

/* Scale of the mean gap i, for deciding that it is zero up to roundoff. */
static double
gap_scale (const lac_newton *s, size_t i)
{
  const lac_csc *C = s->sys->C;
  double sc = fabs (s->sys->G[i]);
  for (int p = C->p[i]; p < C->p[i + 1]; p++)
    sc += fabs (C->x[p] * s->U[C->i[p]]);
  return sc;
}

static double
rho_of (const lac_newton *s, size_t i)
{
  return s->sys->rho ? s->sys->rho[i] : 1.0;
}

/* The factorization of K on the Schur path: the shared solver if one was
 * given (lac_newton_share_solver), the own one otherwise. */
static lac_solver *
k_solver (const lac_newton *s)
{
  return s->shared ? s->shared : s->solver;
}

/* Schur path, set-up: factorize K, U0 = K^{-1} F and the dense
 * S = C^T K^{-1} C (k x k, row-major), SCHUR_BLOCK columns at a time. */
static int
schur_setup (lac_newton *s)
{
  const lac_contact_system *sys = s->sys;
  size_t n = s->n, k = s->k;
  double *U0 = s->work, *S = s->work + 2 * n;
  double *B = NULL, *X = NULL;
  int status;

  if (s->shared)          /* K = L L^T, the analysis of the last K kept */
    status = lac_solver_refactor (s->shared, sys->K);
  else
    {
      lac_solver_free (s->solver);
      s->solver = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
      if (!s->solver)
        return LAC_ENOMEM;
      status = lac_solver_factor (s->solver, sys->K);      /* K = L L^T */
    }
  if (status)
    return status;
  status = lac_solver_solve (k_solver (s), sys->F, U0);    /* U0 = K^{-1} F */
  if (status)
    return status;
  B = lac_malloc (n * SCHUR_BLOCK * sizeof *B);
  X = lac_malloc (n * SCHUR_BLOCK * sizeof *X);
  if (!B || !X)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "Schur complement blocks (n = %zu)", n);
      goto done;
    }
  for (size_t j0 = 0; j0 < k; j0 += SCHUR_BLOCK)
    {
      size_t nb = k - j0 < SCHUR_BLOCK ? k - j0 : SCHUR_BLOCK;
      memset (B, 0, n * nb * sizeof *B);
      for (size_t j = 0; j < nb; j++)                      /* B = C(:, block) */
        for (int p = sys->C->p[j0 + j]; p < sys->C->p[j0 + j + 1]; p++)
          B[j * n + sys->C->i[p]] = sys->C->x[p];
      status = lac_solver_solve_many (k_solver (s), nb, B, X); /* X = K^-1 B */
      if (status)
        goto done;
      for (size_t i = 0; i < k; i++)                       /* S(i,block) = C_i^T X */
        for (size_t j = 0; j < nb; j++)
          {
            double sum = 0;
            for (int p = sys->C->p[i]; p < sys->C->p[i + 1]; p++)
              sum += sys->C->x[p] * X[j * n + sys->C->i[p]];
            S[i * k + j0 + j] = sum;
          }
    }
done:
  lac_free (B);
  lac_free (X);
  return status;
}

/* Schur path, one iteration: S_AA lambda_A = G_A - C_A^T U0, then
 * U = K^{-1} (F + C_A lambda_A). */
static int
schur_iterate (lac_newton *s)
{
  const lac_contact_system *sys = s->sys;
  size_t n = s->n, k = s->k, m = 0;
  double *U0 = s->work, *rhs = s->work + n, *S = s->work + 2 * n;
  int status = LAC_SUCCESS;

  size_t *A = lac_malloc ((k ? k : 1) * sizeof *A);
  if (!A)
    return LAC_ERRMSG (LAC_ENOMEM, "active set of %zu", k);
  for (size_t i = 0; i < k; i++)
    {
      s->lambda[i] = 0;
      if (s->active[i])
        A[m++] = i;
    }
  if (m > 0)
    {
      gsl_matrix *SAA = gsl_matrix_alloc (m, m);
      gsl_vector *b = gsl_vector_alloc (m), *x = gsl_vector_alloc (m);
      if (!SAA || !b || !x)
        status = LAC_ERRMSG (LAC_ENOMEM, "Schur matrix %zu x %zu", m, m);
      for (size_t a = 0; !status && a < m; a++)
        {
          double cu = 0;
          for (int p = sys->C->p[A[a]]; p < sys->C->p[A[a] + 1]; p++)
            cu += sys->C->x[p] * U0[sys->C->i[p]];
          gsl_vector_set (b, a, sys->G[A[a]] - cu);        /* G_A - C_A^T U0 */
          for (size_t c = 0; c < m; c++)
            gsl_matrix_set (SAA, a, c, S[A[a] * k + A[c]]);
        }
      if (!status && gsl_linalg_cholesky_decomp1 (SAA))
        status = LAC_ERRMSG (LAC_ESING, "the Schur complement C_A^T K^-1 C_A "
                             "of the %zu active multipliers is not positive "
                             "definite: the contact constraints are linearly "
                             "dependent (inf-sup condition [LAC (10)])", m);
      if (!status && gsl_linalg_cholesky_solve (SAA, b, x))
        status = LAC_ERRMSG (LAC_ESING, "Schur solve failed");
      for (size_t a = 0; !status && a < m; a++)
        s->lambda[A[a]] = gsl_vector_get (x, a);
      gsl_matrix_free (SAA);
      gsl_vector_free (b);
      gsl_vector_free (x);
    }
  if (!status)
    {
      memcpy (rhs, sys->F, n * sizeof *rhs);
      for (size_t a = 0; a < m; a++)                       /* F + C_A lambda_A */
        for (int p = sys->C->p[A[a]]; p < sys->C->p[A[a] + 1]; p++)
          rhs[sys->C->i[p]] += sys->C->x[p] * s->lambda[A[a]];
      status = lac_solver_solve (k_solver (s), rhs, s->U);
    }
  lac_free (A);
  return status;
}

/* Saddle path, scaling: a symmetric diagonal scaling D of the saddle
 * matrix, D = diag(K)^{-1/2} on the displacements and, on multiplier i,
 * 1 / max_r |D_r C_ri|.  Without it a partly covered macro-element (its
 * column of C scales with the covered fraction delta) or a contrast of
 * Young's moduli between the bodies would make the matrix look singular
 * to the solvers' condition test although the problem is well posed. */
static void
saddle_scaling (const lac_newton *s, double *D)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  for (size_t j = 0; j < s->n; j++)
    {
      double kjj = 0;
      for (int p = K->p[j]; p < K->p[j + 1]; p++)
        if ((size_t) K->i[p] == j)
          kjj = fabs (K->x[p]);
      D[j] = kjj > 0 ? 1 / sqrt (kjj) : 1.0;
    }
  for (size_t i = 0; i < s->k; i++)
    {
      double cmax = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        cmax = fmax (cmax, fabs (D[C->i[p]] * C->x[p]));
      D[s->n + i] = s->active[i] && cmax > 0 ? 1 / cmax : 1.0;
    }
}

/* Saddle path: the matrix D A D of [LAC Alg. 1, line 21] for the current
 * statuses, with identity rows for inactive multipliers (line 17). */
static lac_csc *
saddle_matrix (const lac_newton *s, const double *D)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  size_t n = s->n, k = s->k;
  size_t nnzC = (size_t) C->p[k];
  lac_triplet *T = lac_triplet_alloc (n + k, n + k,
                                      (size_t) K->p[n] + 2 * nnzC + k);
  lac_csc *A = NULL;
  int status = T ? LAC_SUCCESS : LAC_ENOMEM;

  for (size_t j = 0; !status && j < n; j++)                /* D K D */
    for (int p = K->p[j]; !status && p < K->p[j + 1]; p++)
      status = lac_triplet_add (T, (size_t) K->i[p], j,
                                D[K->i[p]] * K->x[p] * D[j]);
  for (size_t i = 0; !status && i < k; i++)
    {
      if (!s->active[i])
        {
          status = lac_triplet_add (T, n + i, n + i, 1.0); /* lambda_i = 0 */
          continue;
        }
      for (int p = C->p[i]; !status && p < C->p[i + 1]; p++)
        {
          double c = -D[C->i[p]] * C->x[p] * D[n + i];     /* -D C D */
          status = lac_triplet_add (T, (size_t) C->i[p], n + i, c);
          if (!status)
            status = lac_triplet_add (T, n + i, (size_t) C->i[p], c);
        }
    }
  if (!status)
    A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

static int
saddle_iterate (lac_newton *s)
{
  size_t n = s->n, k = s->k;
  double *rhs = s->work, *sol = s->work + n + k;
  double *D = lac_malloc ((n + k) * sizeof *D);
  int status;
  if (!D)
    return LAC_ERRMSG (LAC_ENOMEM, "saddle scaling of %zu unknowns", n + k);
  saddle_scaling (s, D);
  lac_csc *A = saddle_matrix (s, D);
  if (!A)
    {
      lac_free (D);
      return LAC_ENOMEM;
    }
  for (size_t j = 0; j < n; j++)                          /* D [F; -G_A; 0] */
    rhs[j] = D[j] * s->sys->F[j];
  for (size_t i = 0; i < k; i++)
    rhs[n + i] = s->active[i] ? -D[n + i] * s->sys->G[i] : 0.0;
  lac_solver_free (s->solver);
  s->solver = lac_solver_alloc (s->kind);
  status = s->solver ? lac_solver_factor (s->solver, A) : LAC_ENOMEM;
  if (status == LAC_ESING)
    status = LAC_ERRMSG (LAC_ESING, "the saddle-point system with %zu active "
                         "multipliers is singular: check the Dirichlet "
                         "conditions and the inf-sup condition [LAC (10)] (%s)",
                         lac_newton_nactive (s), lac_error_message ());
  if (!status)
    status = lac_solver_solve (s->solver, rhs, sol);
  if (!status)
    {
      for (size_t j = 0; j < n; j++)
        s->U[j] = D[j] * sol[j];                          /* x = D y */
      for (size_t i = 0; i < k; i++)
        s->lambda[i] = D[n + i] * sol[n + i];
    }
  lac_csc_free (A);
  lac_free (D);
  return status;
}

/* Residuals of the current iterate for the history record. */
static void
record (lac_newton *s, lac_newton_record *r)
{
  const lac_contact_system *sys = s->sys;
  size_t n = s->n;
  double *res = s->work + (s->kind == LAC_SOLVER_CHOLMOD ? n : 0);
  double nF = 0, nr = 0, nU = 0, lmax = 0, ncp = 0, pen = 0;

  lac_csc_matvec (sys->K, s->U, res);                      /* res = K U */
  for (size_t i = 0; i < s->k; i++)
    for (int p = sys->C->p[i]; p < sys->C->p[i + 1]; p++)
      res[sys->C->i[p]] -= sys->C->x[p] * s->lambda[i];  /* - C lambda */
  for (size_t j = 0; j < n; j++)
    {
      res[j] -= sys->F[j];                                /* - F */
      nr = fmax (nr, fabs (res[j]));
      nF = fmax (nF, fabs (sys->F[j]));
      nU = fmax (nU, fabs (s->U[j]));
    }
  for (size_t i = 0; i < s->k; i++)
    {
      double a = s->lambda[i] + rho_of (s, i) * s->d[i];
      double A = s->lambda[i] - (a < 0 ? a : 0);          /* A_i(U, lambda) */
      double csum = 0;
      for (int p = sys->C->p[i]; p < sys->C->p[i + 1]; p++)
        csum += fabs (sys->C->x[p]);
      lmax = fmax (lmax, fabs (s->lambda[i]));
      ncp = fmax (ncp, fabs (A));
      if (csum > 0)
        pen = fmax (pen, -s->d[i] / csum);
    }
  /* normwise backward error (infinity norms): independent of the units
   * and of the contrast of the stiffnesses */
  double scale = s->normK * nU + s->normC * lmax + nF;
  r->residual = nr / (scale > 0 ? scale : 1e-300);
  r->ncp = ncp / (lmax > 0 ? lmax : 1.0);
  r->max_penetration = pen;
}

/* Status update [LAC Alg. 1, lines 26-33]: active iff lambda + rho d < 0,
 * with values below roundoff treated as zero. */
static size_t
update_status (lac_newton *s)
{
  double lmax = 0;
  size_t changed = 0;
  for (size_t i = 0; i < s->k; i++)
    lmax = fmax (lmax, fabs (s->lambda[i]));
  for (size_t i = 0; i < s->k; i++)
    {
      double lam = fabs (s->lambda[i]) <= 1e-12 * lmax ? 0 : s->lambda[i];
      double d = fabs (s->d[i]) <= 1e-12 * gap_scale (s, i) ? 0 : s->d[i];
      char a = lam + rho_of (s, i) * d < 0;
      changed += a != s->active[i];
      s->active[i] = a;
    }
  return changed;
}

static int
push_record (lac_newton *s, const lac_newton_record *r)
{
  if (s->nhist == s->caphist)
    {
      size_t cap = s->caphist ? 2 * s->caphist : 16;
      lac_newton_record *h = lac_realloc (s->hist, cap * sizeof *h);
      if (!h)
        LAC_ERROR (LAC_ENOMEM, "newton history");
      s->hist = h;
      s->caphist = cap;
    }
  s->hist[s->nhist++] = *r;
  return LAC_SUCCESS;
}

int
lac_newton_set (lac_newton *s, const lac_contact_system *sys)
{
  if (!sys || !sys->K || !sys->F || !sys->C || !sys->G)
    LAC_ERROR (LAC_EINVAL, "incomplete contact system");
  if (sys->K->nrow != s->n || sys->K->ncol != s->n || sys->C->nrow != s->n
      || sys->C->ncol != s->k)
    LAC_ERROR (LAC_EBADLEN, "K is %zux%zu and C %zux%zu, workspace n = %zu, k = %zu",
               sys->K->nrow, sys->K->ncol, sys->C->nrow, sys->C->ncol, s->n, s->k);
  s->sys = sys;
  s->nhist = 0;
  s->normK = s->normC = 0;
  for (size_t j = 0; j < s->n; j++)       /* ||K||_inf = max column sum */
    {
      double sum = 0;
      for (int p = sys->K->p[j]; p < sys->K->p[j + 1]; p++)
        sum += fabs (sys->K->x[p]);
      s->normK = fmax (s->normK, sum);
    }
  s->restarted = 0;
  memset (s->U, 0, s->n * sizeof *s->U);
  memset (s->lambda, 0, s->k * sizeof *s->lambda);
  lac_csc_free (s->Ct);
  s->Ct = lac_csc_transpose (sys->C);
  if (!s->Ct)
    return LAC_ENOMEM;
  for (size_t r = 0; r < s->n; r++)       /* ||C||_inf = max row sum */
    {
      double sum = 0;
      for (int p = s->Ct->p[r]; p < s->Ct->p[r + 1]; p++)
        sum += fabs (s->Ct->x[p]);
      s->normC = fmax (s->normC, sum);
    }
  /* Initial status [LAC Alg. 1, lines 2-8]: closed or penetrating -> active */
  for (size_t i = 0; i < s->k; i++)
    {
      s->active[i] = sys->G[i] <= 0;     /* G is rounded by its producer */
      s->d[i] = sys->G[i];
    }
  s->time_setup = s->time_solve = 0;
  if (s->kind != LAC_SOLVER_CHOLMOD)
    return LAC_SUCCESS;
  double t0 = seconds ();
  int status = schur_setup (s);
  s->time_setup = seconds () - t0;
  return status;
}

int
lac_newton_iterate (lac_newton *s)
{
  lac_newton_record r = { 0 };
  int status;
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_newton_set was not called");
  r.iter = (int) s->nhist + 1;
  r.nactive = lac_newton_nactive (s);
  double t0 = seconds ();
  /* Step 21: solve the saddle system for the current active set */
  status = s->kind == LAC_SOLVER_CHOLMOD ? schur_iterate (s)
                                         : saddle_iterate (s);
  if (status == LAC_ESING && s->nhist == 0 && r.nactive < s->k)
    {
      /* A body held by contact alone cannot start with open gaps: its
       * stiffness alone is singular.  Start again from every multiplier
       * active; the status update releases those in tension. */
      memset (s->active, 1, s->k);
      s->restarted = 1;
      r.nactive = s->k;
      status = s->kind == LAC_SOLVER_CHOLMOD ? schur_iterate (s)
                                             : saddle_iterate (s);
    }
  s->time_solve += seconds () - t0;
  if (status)
    return status;
  mean_gaps (s);                                          /* d = G - C^T U */
  /* Steps 26-33: new statuses */
  s->changed = update_status (s);
  r.nchanged = s->changed;
  record (s, &r);
  return push_record (s, &r);
}

int
lac_newton_test (const lac_newton *s, double tol)
{
  if (s->nhist == 0)
    return LAC_CONTINUE;
  const lac_newton_record *r = &s->hist[s->nhist - 1];
  if (r->nchanged == 0 && r->residual <= tol && r->ncp <= tol)
    return LAC_SUCCESS;
  return LAC_CONTINUE;
}

int
lac_newton_solve (lac_newton *s, const lac_contact_system *sys, int maxit,
                  double tol)
{
  int status = lac_newton_set (s, sys);
  for (int it = 0; !status && it < maxit; it++)
    {
      status = lac_newton_iterate (s);
      if (status)
        return status;
      if (lac_newton_test (s, tol) == LAC_SUCCESS)
        return LAC_SUCCESS;
    }
  if (status)
    return status;
  LAC_ERROR (LAC_EMAXITER, "the active set did not settle in %d iterations "
             "(last: %zu active, %zu changed)", maxit, lac_newton_nactive (s),
             s->changed);
}
