/* lac_augmented.c -- multipliers by conjugate gradients on the Schur
 *                   complement of the augmented system (see
 *                   lac_augmented.h)              [LAC (17), Alg. 1 l. 21]
 *
 * One solve of (*) for the statuses A:
 *   1. K_W = K + C_A W_A C_A^T, factorized when the statuses or the
 *      numbers changed (analysis kept; omega = 0: K, once in set);
 *   2. U_0 = K_W^{-1} (f + C_A W_A g_A);
 *   3. S_W lambda_A = g_A - C_A^T U_0 by conjugate gradients from the
 *      given lambda_A, product v -> C_A^T K_W^{-1} C_A v;
 *   4. U = K_W^{-1} (f + C_A W_A g_A + C_A lambda_A).
 */
#include "solve/lac_augmented.h"

#include <math.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_pcg.h"

/* Conjugate-gradient iterations at most: about ten are needed with
 * omega = 10 (lac_augmented.h); many more mean a singular S_W. */
#define PCG_MAXIT 300

struct lac_augmented
{
  double omega;                    /* W = omega / s_i; 0: K alone         */
  const lac_contact_system *sys;   /* borrowed                            */
  size_t n, k;
  lac_solver *chol;                /* owned: the factor of K or K_W       */
  lac_csc *A;                      /* owned, (b): K + C W C^T's pattern   */
  unsigned long long hK, hC;       /* patterns A was made for             */
  double *s;                       /* owned, k: c_i^T diag(K)^-1 c_i      */
  double *w;                       /* owned, k: W of the factor (0: off)  */
  char *factored_for;              /* owned, k: statuses of the factor    */
  int have_factor, factor_failed;
  size_t na, *idx;                 /* owned, k: the active columns        */
  double *x, *y;                   /* owned, n: scratch of the products   */
  double *b, *lamA;                /* owned, k: PCG right side, unknown   */
  lac_solve_counts counts;
};

lac_augmented *
lac_augmented_alloc (double omega)
{
  lac_augmented *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "augmented solver");
  s->omega = omega;
  if (!(s->chol = lac_solver_alloc (LAC_SOLVER_CHOLMOD)))
    {
      lac_free (s);
      return NULL;
    }
  return s;
}

static void
free_arrays (lac_augmented *s)
{
  lac_free (s->s);
  lac_free (s->w);
  lac_free (s->factored_for);
  lac_free (s->idx);
  lac_free (s->x);
  lac_free (s->y);
  lac_free (s->b);
  lac_free (s->lamA);
  s->s = s->w = s->x = s->y = s->b = s->lamA = NULL;
  s->factored_for = NULL;
  s->idx = NULL;
}

void
lac_augmented_free (lac_augmented *s)
{
  if (!s)
    return;
  free_arrays (s);
  lac_csc_free (s->A);
  lac_solver_free (s->chol);
  lac_free (s);
}

void
lac_augmented_get_counts (const lac_augmented *s, lac_solve_counts *c)
{
  *c = s->counts;
}

static int
alloc_arrays (lac_augmented *s, size_t n, size_t k)
{
  size_t k1 = k ? k : 1;
  if (s->x && s->n == n && s->k == k)
    return LAC_SUCCESS;
  free_arrays (s);
  s->s = lac_malloc (k1 * sizeof *s->s);
  s->w = lac_calloc (k1, sizeof *s->w);
  s->factored_for = lac_calloc (k1, 1);
  s->idx = lac_malloc (k1 * sizeof *s->idx);
  s->b = lac_malloc (k1 * sizeof *s->b);
  s->lamA = lac_malloc (k1 * sizeof *s->lamA);
  s->x = lac_malloc (n * sizeof *s->x);
  s->y = lac_malloc (n * sizeof *s->y);
  if (!s->s || !s->w || !s->factored_for || !s->idx || !s->b || !s->lamA
      || !s->x || !s->y)
    LAC_ERROR (LAC_ENOMEM, "augmented solver, n = %zu, k = %zu", n,
               k);
  s->n = n;
  s->k = k;
  return LAC_SUCCESS;
}

static int
factor (lac_augmented *s, const lac_csc *A)
{
  return lac_solve_counts_factor (&s->counts, s->chol, A);
}

int
lac_augmented_set (lac_augmented *s, const lac_contact_system *sys)
{
  int status = alloc_arrays (s, sys->K->ncol, sys->C->ncol);
  if (status)
    return status;
  s->sys = sys;
  s->have_factor = 0;
  lac_system_column_scales (sys, s->x, s->s);
  if (s->omega == 0)                          /* K = L L^T, once */
    {
      if ((status = factor (s, sys->K)))
        return status;
      s->have_factor = 1;
      return LAC_SUCCESS;
    }
  unsigned long long hK = lac_csc_pattern_hash (sys->K);
  unsigned long long hC = lac_csc_pattern_hash (sys->C);
  if (!s->A || hK != s->hK || hC != s->hC)    /* (b): K + C C^T pattern */
    {
      lac_csc_free (s->A);
      if (!(s->A = lac_csc_augment_pattern (sys->K, sys->C)))
        return LAC_ENOMEM;
      s->hK = hK;
      s->hC = hC;
    }
  return LAC_SUCCESS;
}

/* (b): K_W for the statuses, factorized if they or the numbers changed. */
static int
factor_augmented (lac_augmented *s, const char *active)
{
  int status;
  if (s->have_factor && memcmp (active, s->factored_for, s->k) == 0)
    return LAC_SUCCESS;
  for (size_t i = 0; i < s->k; i++)
    s->w[i] = active[i] && s->s[i] > 0 ? s->omega / s->s[i] : 0.0;
  if ((status = lac_csc_augment (s->A, s->sys->K, s->sys->C, s->w)))
    return status;
  if ((status = factor (s, s->A)))
    {
      s->factor_failed = 1;
      return status;
    }
  memcpy (s->factored_for, active, s->k);
  s->have_factor = 1;
  return LAC_SUCCESS;
}

/* y = K_W^{-1} x */
static int
solve_kw (lac_augmented *s, const double *x, double *y)
{
  s->counts.solves++;
  return lac_solver_solve (s->chol, x, y);
}

/* q = S_W v = C_A^T K_W^{-1} C_A v (the operator of the conjugate
 * gradients, on the active multipliers). */
static int
schur_product (void *ctx, const double *v, double *q)
{
  lac_augmented *s = ctx;
  const lac_csc *C = s->sys->C;
  int status;
  memset (s->x, 0, s->n * sizeof *s->x);
  for (size_t a = 0; a < s->na; a++)                   /* x = C_A v */
    for (int p = C->p[s->idx[a]]; p < C->p[s->idx[a] + 1]; p++)
      s->x[C->i[p]] += C->x[p] * v[a];
  if ((status = solve_kw (s, s->x, s->y)))              /* y = K_W^-1 x */
    return status;
  for (size_t a = 0; a < s->na; a++)                   /* q = C_A^T y */
    {
      double sum = 0;
      for (int p = C->p[s->idx[a]]; p < C->p[s->idx[a] + 1]; p++)
        sum += C->x[p] * s->y[C->i[p]];
      q[a] = sum;
    }
  return LAC_SUCCESS;
}

/* z = P r: W_A, or diag(s_A)^{-1} when omega = 0. */
static int
schur_precondition (void *ctx, const double *r, double *z)
{
  const lac_augmented *s = ctx;
  for (size_t a = 0; a < s->na; a++)
    {
      size_t i = s->idx[a];
      z[a] = s->omega > 0 ? s->w[i] * r[a]
             : s->s[i] > 0 ? r[a] / s->s[i] : r[a];
    }
  return LAC_SUCCESS;
}

/* x = f + C_A (W_A g_A + lambda_A): the right-hand side of K_W U = x. */
static void
load_vector (lac_augmented *s, const double *f, const double *g,
             const double *lamA, double *x)
{
  const lac_csc *C = s->sys->C;
  memcpy (x, f, s->n * sizeof *x);
  for (size_t a = 0; a < s->na; a++)
    {
      size_t i = s->idx[a];
      double v = s->w[i] * g[i] + (lamA ? lamA[a] : 0.0);
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        x[C->i[p]] += C->x[p] * v;
    }
}

int
lac_augmented_factor_failed (const lac_augmented *s)
{
  return s->factor_failed;
}

int
lac_augmented_solve (lac_augmented *s, const char *active, const double *f,
                 const double *g, double rtol, double *U, double *lambda)
{
  const lac_csc *C;
  lac_pcg_info info;
  int status;
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_augmented_set was not called");
  s->factor_failed = 0;
  C = s->sys->C;
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  if (s->omega > 0 && (status = factor_augmented (s, active)))  /* 1. */
    return status;
  s->na = 0;
  for (size_t i = 0; i < s->k; i++)
    if (active[i])
      s->lamA[s->na] = lambda[i], s->idx[s->na++] = i;
  load_vector (s, f, g, NULL, s->x);                     /* 2. U_0 */
  if ((status = solve_kw (s, s->x, U)))
    return status;
  for (size_t a = 0; a < s->na; a++)                     /* 3. */
    {
      double cu = 0;
      for (int p = C->p[s->idx[a]]; p < C->p[s->idx[a] + 1]; p++)
        cu += C->x[p] * U[C->i[p]];
      s->b[a] = g[s->idx[a]] - cu;                       /* g_A - C_A^T U_0 */
    }
  status = lac_pcg (s->na, schur_product, schur_precondition, s, s->b,
                    s->lamA, rtol, PCG_MAXIT, &info);
  s->counts.iterations += info.iterations;
  s->counts.last_iterations = info.iterations;
  s->counts.last_residual = info.residual;
  if (status == LAC_EMAXITER || status == LAC_ESING)
    return LAC_ERRMSG (LAC_ESING, "the multipliers of the %zu active "
                       "macro-elements are not determined (%s): their "
                       "system is singular, the contact constraints are "
                       "linearly dependent (inf-sup condition [LAC (10)])", s->na, lac_error_message ());
  if (status)
    return status;
  for (size_t i = 0; i < s->k; i++)
    lambda[i] = 0;
  for (size_t a = 0; a < s->na; a++)
    lambda[s->idx[a]] = s->lamA[a];
  load_vector (s, f, g, s->lamA, s->x);                  /* 4. U */
  return solve_kw (s, s->x, U);
}
