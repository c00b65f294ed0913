/* lac_schur.c -- multipliers through the Schur complement of K
 *                (see lac_schur.h)                [LAC (17), Alg. 1 l. 21]
 */
#include "solve/lac_schur.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* The nonzeros of a vector of n: y[i[p]] = x[p], p < nz.  A forward
 * half y = L^{-1} P c is zero but on the rows of the elimination tree
 * above those of c (on the fine ring of chapter 10, 5 % of them). */
typedef struct lac_sparse_column
{
  int *i;
  double *x;
  size_t nz;
} lac_sparse_column;

typedef struct lac_schur
{
  const lac_contact_system *sys;   /* borrowed                            */
  lac_csc *C;                      /* owned: a copy of the C of the last
                                      set or reset                         */
  int kept;                        /* 1 after keep: S and the solves are
                                      C's, not sys->C's                    */
  size_t n, k;
  lac_solver *chol;                /* owned: K = L L^T                    */
  double *S;                       /* owned, k x k: S(j, i) at S[i k + j] */
  char *have;                      /* owned, k: column i of S computed    */
  double *x;                       /* owned, n: scratch                   */
  double *X;                       /* owned, n x k, or NULL: column i is
                                      K^{-1} c_i where have[i] (made with
                                      S without the halves, kept when it
                                      takes no more room than the factor) */
  int no_X;                        /* X would take more than the factor   */
  lac_sparse_column *Y;            /* owned, k, or NULL: y_i = L^{-1} P c_i
                                      where have[i] (the halves)          */
  int routed;                      /* halves chosen since the last borrow */
  int halves;                      /* S = Y^T Y from the forward halves   */
  int factor_failed;               /* the last set's K = L L^T failed     */
  lac_solve_counts counts;
} lac_schur;

static void *
schur_alloc (void)
{
  lac_schur *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "Schur-complement solver");
  if (!(s->chol = lac_solver_alloc (LAC_SOLVER_CHOLMOD)))
    {
      lac_free (s);
      return NULL;
    }
  return s;
}

static void
free_arrays (lac_schur *s)
{
  lac_free (s->S);
  lac_free (s->have);
  lac_free (s->x);
  lac_free (s->X);
  for (size_t i = 0; s->Y && i < s->k; i++)
    {
      lac_free (s->Y[i].i);
      lac_free (s->Y[i].x);
    }
  lac_free (s->Y);
  s->S = s->x = s->X = NULL;
  s->Y = NULL;
  s->have = NULL;
  s->no_X = 0;
}

static void
schur_free (void *w)
{
  lac_schur *s = w;
  if (!s)
    return;
  free_arrays (s);
  lac_csc_free (s->C);
  lac_solver_free (s->chol);
  lac_free (s);
}

static void
schur_get_counts (const void *w, lac_solve_counts *c)
{
  *c = ((const lac_schur *) w)->counts;
}

static int
schur_factor_failed (const void *w)
{
  return ((const lac_schur *) w)->factor_failed;
}

/* Borrow the system: arrays for its sizes, no column of S yet. */
static int
borrow (lac_schur *s, const lac_contact_system *sys)
{
  size_t n = sys->K->ncol, k = sys->C->ncol;
  if (!s->x || s->n != n || s->k != k)
    {
      free_arrays (s);
      s->S = lac_malloc ((k ? k * k : 1) * sizeof *s->S);
      s->have = lac_malloc (k ? k : 1);
      s->x = lac_malloc (n * sizeof *s->x);
      if (!s->S || !s->have || !s->x)
        LAC_ERROR (LAC_ENOMEM, "Schur complement of %zu multipliers", k);
      s->n = n;
      s->k = k;
    }
  s->sys = sys;
  s->kept = 0;
  s->routed = s->halves = 0;
  memset (s->have, 0, k);
  lac_csc_free (s->C);
  if (!(s->C = lac_csc_copy (sys->C)))
    LAC_ERROR (LAC_ENOMEM, "a copy of C (%zu columns)", k);
  return LAC_SUCCESS;
}

static int
schur_set (void *w, const lac_contact_system *sys)
{
  lac_schur *s = w;
  int status = borrow (s, sys);
  if (!status)
    status = lac_solve_counts_factor (&s->counts, s->chol, sys->K);
  s->factor_failed = status == LAC_ESING;                   /* K = L L^T */
  return status;
}

/* The factorization of the last set's K kept (the strategy checked that
 * K has the same order). */
static int
schur_reset (void *w, const lac_contact_system *sys)
{
  return borrow (w, sys);
}

/* The factorization, the C of the last set or reset and the columns of S
 * made of them kept: only the right-hand sides F, G are sys's (the
 * strategy checked that sys has as many dofs and columns). */
static int
schur_keep (void *w, const lac_contact_system *sys)
{
  lac_schur *s = w;
  s->sys = sys;
  s->kept = 1;
  return LAC_SUCCESS;
}

/* The C that S is made of. */
static const lac_csc *
c_of (const lac_schur *s)
{
  return s->kept ? s->C : s->sys->C;
}

/* Columns idx[0..nb) of X = K^{-1} C, kept in s->X if it takes no more
 * room than the factor (n k <= nnz(L)): with them a solve of a kept
 * system (schur_keep) needs one solve with the factor, not two. */
static void
keep_X (lac_schur *s, const size_t *idx, size_t nb, const double *X)
{
  lac_solver_info info;
  if (!s->X && !s->no_X)
    {
      s->no_X = lac_solver_get_info (s->chol, &info) != LAC_SUCCESS
                || (double) s->n * (double) s->k > info.nnz_factor
                || !(s->X = lac_malloc (s->n * s->k * sizeof *s->X));
      lac_error_clear ();                 /* no room: two solves, as before */
    }
  for (size_t b = 0; s->X && b < nb; b++)
    memcpy (s->X + idx[b] * s->n, X + b * s->n, s->n * sizeof *X);
}

/* Without the halves: S(j, i) = c_j^T X(:, i) for every j, X = K^{-1}
 * C(:, idx). */
static void
product (lac_schur *s, const size_t *idx, size_t nb, const double *X)
{
  const lac_csc *C = c_of (s);
  size_t n = s->n;
  for (size_t b = 0; b < nb; b++)
    for (size_t j = 0; j < s->k; j++)                    /* S(:,i) = C^T X */
      {
        double sum = 0;
        for (int p = C->p[j]; p < C->p[j + 1]; p++)
          sum += C->x[p] * X[b * n + (size_t) C->i[p]];
        s->S[idx[b] * s->k + j] = sum;
      }
  keep_X (s, idx, nb, X);
}

/* y_i: the nonzeros of w (n), into Y[i]. */
static int
keep_y (lac_schur *s, size_t i, const double *w)
{
  lac_sparse_column *y = &s->Y[i];
  size_t nz = 0;
  for (size_t r = 0; r < s->n; r++)
    nz += w[r] != 0;
  lac_free (y->i);
  lac_free (y->x);
  y->i = lac_malloc ((nz ? nz : 1) * sizeof *y->i);
  y->x = lac_malloc ((nz ? nz : 1) * sizeof *y->x);
  y->nz = 0;
  if (!y->i || !y->x)
    LAC_ERROR (LAC_ENOMEM, "a column of %zu nonzeros", nz);
  for (size_t r = 0; r < s->n; r++)
    if (w[r] != 0)
      {
        y->i[y->nz] = (int) r;
        y->x[y->nz++] = w[r];
      }
  return LAC_SUCCESS;
}

/* With the halves: W = L^{-1} P C(:, idx), kept as the sparse y_i, and
 * S(j, i) = y_j^T w_i = c_j^T K^{-1} c_i for every column j made, mirrored
 * into row i. */
static int
gram (lac_schur *s, const size_t *idx, size_t nb, const double *W)
{
  size_t n = s->n, k = s->k;
  int status = LAC_SUCCESS;
  if (!s->Y && !(s->Y = lac_calloc (k ? k : 1, sizeof *s->Y)))
    LAC_ERROR (LAC_ENOMEM, "forward halves of %zu columns", k);
  for (size_t b = 0; !status && b < nb; b++)
    {
      status = keep_y (s, idx[b], W + b * n);
      s->have[idx[b]] = !status;
    }
  for (size_t b = 0; !status && b < nb; b++)
    for (size_t j = 0; j < k; j++)
      {
        const lac_sparse_column *y = &s->Y[j];
        double sum = 0;
        for (size_t p = 0; s->have[j] && p < y->nz; p++)
          sum += y->x[p] * W[b * n + (size_t) y->i[p]];
        if (s->have[j])                   /* S symmetric */
          s->S[idx[b] * k + j] = s->S[j * k + idx[b]] = sum;
      }
  return status;
}

/* Columns idx[0..nb) of S, from one block solve of C(:, idx): its
 * forward halves where the factor has them (the first block after a
 * factorization asks), else whole solves. */
static int
schur_block (lac_schur *s, const size_t *idx, size_t nb)
{
  const lac_csc *C = c_of (s);
  size_t n = s->n;
  double *B = lac_calloc (n * nb, sizeof *B), *W = lac_malloc (n * nb
                                                               * sizeof *W);
  int status = B && W ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "Schur block of %zu columns", nb);
  for (size_t b = 0; !status && b < nb; b++)            /* B = C(:, idx) */
    for (int p = C->p[idx[b]]; p < C->p[idx[b] + 1]; p++)
      B[b * n + (size_t) C->i[p]] = C->x[p];
  if (!status && !s->routed)
    {
      s->halves = lac_solver_halves (s->chol);
      s->routed = 1;
    }
  if (!status)
    status = s->halves ? lac_solver_forward_many (s->chol, nb, B, W)
                       : lac_solver_solve_many (s->chol, nb, B, W);
  if (!status && s->halves)
    status = gram (s, idx, nb, W);                       /* W = L^-1 P B */
  else if (!status)
    product (s, idx, nb, W);                             /* W = K^-1 B */
  for (size_t b = 0; !status && b < nb; b++)
    s->have[idx[b]] = 1;
  if (!status)
    s->counts.solves += (int) nb;
  lac_free (B);
  lac_free (W);
  return status;
}

/* The columns of S that the active multipliers need and do not have. */
static int
schur_columns (lac_schur *s, const char *active)
{
  size_t idx[LAC_SCHUR_BLOCK], nb = 0;
  int status = LAC_SUCCESS;
  for (size_t i = 0; !status && i < s->k; i++)
    {
      if (active[i] && !s->have[i])
        idx[nb++] = i;
      if (nb == LAC_SCHUR_BLOCK || (nb > 0 && i + 1 == s->k))
        {
          status = schur_block (s, idx, nb);
          nb = 0;
        }
    }
  return status;
}

/* lambda_A = S_AA^{-1} b_A (dense Cholesky), A = the active ones. */
static int
schur_multipliers (lac_schur *s, const char *active, const double *b,
                   double *lambda)
{
  size_t m = 0, *A = lac_malloc ((s->k ? s->k : 1) * sizeof *A);
  int status = A ? LAC_SUCCESS : LAC_ENOMEM;
  for (size_t i = 0; A && i < s->k; i++)
    if (active[i])
      A[m++] = i;
  gsl_matrix *SAA = m ? gsl_matrix_alloc (m, m) : NULL;
  gsl_vector *x = m ? gsl_vector_alloc (m) : NULL;
  if (m && (!SAA || !x))
    status = LAC_ERRMSG (LAC_ENOMEM, "Schur matrix %zu x %zu", m, m);
  for (size_t a = 0; !status && a < m; a++)
    {
      gsl_vector_set (x, a, b[A[a]]);
      for (size_t c = 0; c < m; c++)
        gsl_matrix_set (SAA, a, c, s->S[A[c] * s->k + A[a]]);
    }
  if (!status && m && gsl_linalg_cholesky_decomp1 (SAA))
    status = LAC_ERRMSG (LAC_ESING, "the Schur complement C_A^T K^-1 C_A "
                         "of the %zu active multipliers is not positive "
                         "definite: the contact constraints are linearly "
                         "dependent (inf-sup condition [LAC (10)])", m);
  if (!status && m)
    gsl_linalg_cholesky_svx (SAA, x);
  for (size_t i = 0; !status && i < s->k; i++)
    lambda[i] = 0;
  for (size_t a = 0; !status && a < m; a++)
    lambda[A[a]] = gsl_vector_get (x, a);
  gsl_matrix_free (SAA);
  gsl_vector_free (x);
  lac_free (A);
  return status;
}

/* With the halves, one solve with the factor: w = L^{-1} P f, then
 * g - C^T K^{-1} f = g - Y^T w, and U = P^T L^{-T} (w + Y_A lambda_A). */
static int
solve_halves (lac_schur *s, const char *active, const double *f,
              const double *g, double *U, double *lambda)
{
  int status = lac_solver_forward_many (s->chol, 1, f, s->x);
  for (size_t i = 0; !status && i < s->k; i++)
    {
      const lac_sparse_column *y = &s->Y[i];
      double yw = 0;
      for (size_t p = 0; active[i] && p < y->nz; p++)
        yw += y->x[p] * s->x[y->i[p]];
      lambda[i] = g[i] - yw;
    }
  if (!status)
    status = schur_multipliers (s, active, lambda, lambda);
  for (size_t i = 0; !status && i < s->k; i++)
    {
      const lac_sparse_column *y = &s->Y[i];
      for (size_t p = 0; active[i] && p < y->nz; p++)
        s->x[y->i[p]] += y->x[p] * lambda[i];
    }
  if (!status)
    status = lac_solver_backward (s->chol, s->x, U);
  if (!status)
    s->counts.solves++;
  return status;
}

static int
schur_solve (void *w, const char *active, const double *f, const double *g,
             double rtol, double *U, double *lambda)
{
  lac_schur *s = w;
  const lac_csc *C = c_of (s);
  int status;
  (void) rtol;
  s->factor_failed = 0;
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  if ((status = schur_columns (s, active)))
    return status;
  if (s->halves)
    return solve_halves (s, active, f, g, U, lambda);
  if ((status = lac_solver_solve (s->chol, f, U)))     /* U_0 = K^-1 f */
    return status;
  s->counts.solves++;
  for (size_t i = 0; i < s->k; i++)                    /* g - C^T U_0 */
    {
      double cu = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        cu += C->x[p] * U[C->i[p]];
      lambda[i] = g[i] - cu;
    }
  if ((status = schur_multipliers (s, active, lambda, lambda)))
    return status;
  if (s->kept && s->X)                     /* U = U_0 + K^-1 C_A lambda_A */
    {
      for (size_t i = 0; i < s->k; i++)
        for (size_t r = 0; active[i] && r < s->n; r++)
          U[r] += s->X[i * s->n + r] * lambda[i];
      return LAC_SUCCESS;
    }
  memcpy (s->x, f, s->n * sizeof *s->x);               /* f + C_A lambda_A */
  for (size_t i = 0; i < s->k; i++)
    for (int p = C->p[i]; active[i] && p < C->p[i + 1]; p++)
      s->x[C->i[p]] += C->x[p] * lambda[i];
  s->counts.solves++;
  return lac_solver_solve (s->chol, s->x, U);          /* U = K^-1 (.) */
}

/* ---- the equations of a contact law (friction) ---------------------------- */

/* min |U_ii| / max |U_ii| of an LU factorization (0: singular). */
static double
pivot_ratio (const gsl_matrix *LU)
{
  double lo = HUGE_VAL, hi = 0;
  for (size_t i = 0; i < LU->size1; i++)
    {
      double u = fabs (gsl_matrix_get (LU, i, i));
      lo = fmin (lo, u);
      hi = fmax (hi, u);
    }
  return hi > 0 ? lo / hi : 0.0;
}

/* The free multipliers of R by a dense LU of
 *   M(j, i) = Q(j, i) - sum_b P(j, b) S(g q + b, i)    (j, i free, j in group g)
 * with b(j) = r_j + sum_b P(j, b) c_{g q + b}^T K^-1 f in lambda on entry
 * (every j) and lambda on return (0 where not free). */
static int
rows_multipliers (lac_schur *s, const lac_contact_rows *R, double *lambda)
{
  size_t q = (size_t) R->q, m = 0, *F = lac_malloc ((s->k ? s->k : 1)
                                                    * sizeof *F);
  int status = F ? LAC_SUCCESS : LAC_ENOMEM, sign;
  for (size_t i = 0; F && i < s->k; i++)
    if (R->free[i])
      F[m++] = i;
  gsl_matrix *M = m ? gsl_matrix_alloc (m, m) : NULL;
  gsl_vector *x = m ? gsl_vector_alloc (m) : NULL;
  gsl_permutation *perm = m ? gsl_permutation_alloc (m) : NULL;
  if (m && (!M || !x || !perm))
    status = LAC_ERRMSG (LAC_ENOMEM, "Schur matrix %zu x %zu", m, m);
  for (size_t a = 0; !status && a < m; a++)
    {
      size_t j = F[a], g = j / q;
      gsl_vector_set (x, a, lambda[j]);
      for (size_t c = 0; c < m; c++)
        {
          size_t i = F[c];
          double v = i / q == g ? R->Q[j * q + i % q] : 0.0;
          for (size_t b = 0; b < q; b++)
            v -= R->P[j * q + b] * s->S[i * s->k + g * q + b];
          gsl_matrix_set (M, a, c, v);
        }
    }
  if (!status && m && (gsl_linalg_LU_decomp (M, perm, &sign)
                       || pivot_ratio (M) < 1e-14))
    status = LAC_ERRMSG (LAC_ESING, "the Schur complement of the %zu "
                         "multipliers of the contact law is singular", m);
  if (!status && m)
    gsl_linalg_LU_svx (M, perm, x);
  for (size_t i = 0; !status && i < s->k; i++)
    lambda[i] = 0;
  for (size_t a = 0; !status && a < m; a++)
    lambda[F[a]] = gsl_vector_get (x, a);
  gsl_permutation_free (perm);
  gsl_matrix_free (M);
  gsl_vector_free (x);
  lac_free (F);
  return status;
}

/* The columns of S that rows_multipliers reads: those of the free
 * multipliers and, with the halves (S(j, i) only where both columns are
 * made), those of every group with a free one. */
static int
rows_columns (lac_schur *s, const lac_contact_rows *R)
{
  size_t q = (size_t) R->q;
  if (!lac_solver_halves (s->chol))
    return schur_columns (s, R->free);
  char *need = lac_calloc (s->k ? s->k : 1, 1);
  if (!need)
    LAC_ERROR (LAC_ENOMEM, "flags of %zu multipliers", s->k);
  for (size_t i = 0; i < s->k; i++)
    if (R->free[i])
      memset (need + i / q * q, 1, q);
  int status = schur_columns (s, need);
  lac_free (need);
  return status;
}

static int
schur_solve_rows (void *w, const lac_contact_rows *R, const double *f,
                  const double *r, double *U, double *lambda)
{
  lac_schur *s = w;
  const lac_csc *C = c_of (s);
  size_t q = (size_t) R->q;
  int status;
  s->factor_failed = 0;
  f = f ? f : s->sys->F;
  r = r ? r : R->r;
  if ((status = rows_columns (s, R))
      || (status = lac_solver_solve (s->chol, f, U)))   /* U_0 = K^-1 f */
    return status;
  s->counts.solves++;
  for (size_t i = 0; i < s->k; i++)                    /* c_i^T U_0 */
    {
      double cu = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        cu += C->x[p] * U[C->i[p]];
      lambda[i] = cu;
    }
  for (size_t g = 0; g < s->k / q; g++)               /* r + P C^T U_0 */
    {
      double b[3];
      for (size_t a = 0; a < q; a++)
        {
          size_t j = g * q + a;
          b[a] = r[j];
          for (size_t c = 0; c < q; c++)
            b[a] += R->P[j * q + c] * lambda[g * q + c];
        }
      for (size_t a = 0; a < q; a++)
        lambda[g * q + a] = b[a];
    }
  if ((status = rows_multipliers (s, R, lambda)))
    return status;
  memcpy (s->x, f, s->n * sizeof *s->x);               /* f + C_F lambda_F */
  for (size_t i = 0; i < s->k; i++)
    for (int p = C->p[i]; R->free[i] && p < C->p[i + 1]; p++)
      s->x[C->i[p]] += C->x[p] * lambda[i];
  s->counts.solves++;
  return lac_solver_solve (s->chol, s->x, U);          /* U = K^-1 (.) */
}

const lac_strategy_ops lac_schur_ops = {
  .alloc = schur_alloc, .free = schur_free, .set = schur_set,
  .reset = schur_reset, .keep = schur_keep, .solve = schur_solve,
  .get_counts = schur_get_counts, .factor_failed = schur_factor_failed,
  .solve_rows = schur_solve_rows
};
