/* lac_augmented.c -- multipliers by conjugate gradients on the Schur
 *                   complement of the augmented system (see
 *                   lac_augmented.h)              [LAC (17), Alg. 1 l. 21]
 *
 * One solve of (*) for the statuses A:
 *   1. K_W = K + C_A W_A C_A^T, factorized when the statuses or the
 *      numbers changed (analysis kept);
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
#include "solve/lac_active.h"

/* Conjugate-gradient iterations at most: about ten are needed with
 * omega = 10 (lac_augmented.h); many more mean a singular S_W. */
#define PCG_MAXIT 300

typedef struct lac_augmented
{
  const lac_contact_system *sys;   /* borrowed                            */
  size_t n;
  lac_solver *chol;                /* owned: the factor of K_W            */
  lac_csc *A;                      /* owned: K + C W C^T's pattern        */
  unsigned long long hK, hC;       /* patterns A was made for             */
  lac_active act;                  /* owned                               */
  int factor_failed;
  double *x, *y;                   /* owned, n: scratch of the products   */
  lac_solve_counts counts;
} lac_augmented;

static void *
augmented_alloc (void)
{
  lac_augmented *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "augmented solver");
  s->act.omega = LAC_AUGMENT_OMEGA;
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
  lac_active_clear (&s->act);
  lac_free (s->x);
  lac_free (s->y);
  s->x = s->y = NULL;
}

static void
augmented_free (void *w)
{
  lac_augmented *s = w;
  if (!s)
    return;
  free_arrays (s);
  lac_csc_free (s->A);
  lac_solver_free (s->chol);
  lac_free (s);
}

static void
augmented_get_counts (const void *w, lac_solve_counts *c)
{
  *c = ((const lac_augmented *) w)->counts;
}

static int
alloc_arrays (lac_augmented *s, size_t n, size_t k)
{
  int status;
  if (s->x && s->n == n && s->act.k == k)
    return LAC_SUCCESS;
  free_arrays (s);
  if ((status = lac_active_init (&s->act, k)))
    return status;
  s->x = lac_malloc (n * sizeof *s->x);
  s->y = lac_malloc (n * sizeof *s->y);
  if (!s->x || !s->y)
    LAC_ERROR (LAC_ENOMEM, "augmented solver, n = %zu, k = %zu", n, k);
  s->n = n;
  return LAC_SUCCESS;
}

static int
augmented_set (void *w, const lac_contact_system *sys)
{
  lac_augmented *s = w;
  int status = alloc_arrays (s, sys->K->ncol, sys->C->ncol);
  if (status)
    return status;
  s->sys = sys;
  s->act.have_factor = 0;
  lac_system_column_scales (sys, s->x, s->act.s);
  unsigned long long hK = lac_csc_pattern_hash (sys->K);
  unsigned long long hC = lac_csc_pattern_hash (sys->C);
  if (!s->A || hK != s->hK || hC != s->hC)    /* K + C C^T's pattern */
    {
      lac_csc_free (s->A);
      if (!(s->A = lac_csc_augment_pattern (sys->K, sys->C)))
        return LAC_ENOMEM;
      s->hK = hK;
      s->hC = hC;
    }
  return LAC_SUCCESS;
}

/* K_W for the statuses, factorized if they or the numbers changed. */
static int
factor_augmented (lac_augmented *s, const char *active)
{
  int status;
  if (!lac_active_weights (&s->act, active))
    return LAC_SUCCESS;
  if ((status = lac_csc_augment (s->A, s->sys->K, s->sys->C, s->act.w)))
    return status;
  if ((status = lac_solve_counts_factor (&s->counts, s->chol, s->A)))
    {
      s->factor_failed = 1;
      return status;
    }
  lac_active_factored (&s->act, active);
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
  int status;
  memset (s->x, 0, s->n * sizeof *s->x);
  lac_active_add_C (&s->act, s->sys->C, v, s->x);       /* x = C_A v */
  if ((status = solve_kw (s, s->x, s->y)))              /* y = K_W^-1 x */
    return status;
  lac_active_Ct (&s->act, s->sys->C, s->y, q);          /* q = C_A^T y */
  return LAC_SUCCESS;
}

/* z = P r = W_A r. */
static int
schur_precondition (void *ctx, const double *r, double *z)
{
  const lac_active *act = &((const lac_augmented *) ctx)->act;
  for (size_t a = 0; a < act->na; a++)
    {
      size_t i = act->idx[a];
      z[a] = act->w[i] * r[a];
    }
  return LAC_SUCCESS;
}

/* x = f + C_A (W_A g_A + lambda_A): the right-hand side of K_W U = x. */
static void
load_vector (lac_augmented *s, const double *f, const double *g,
             const double *lamA, double *x)
{
  const lac_csc *C = s->sys->C;
  const lac_active *act = &s->act;
  memcpy (x, f, s->n * sizeof *x);
  for (size_t a = 0; a < act->na; a++)
    {
      size_t i = act->idx[a];
      double v = act->w[i] * g[i] + (lamA ? lamA[a] : 0.0);
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        x[C->i[p]] += C->x[p] * v;
    }
}

static int
augmented_factor_failed (const void *w)
{
  return ((const lac_augmented *) w)->factor_failed;
}

static int
augmented_solve (void *w, const char *active, const double *f,
                 const double *g, double rtol, double *U, double *lambda)
{
  lac_augmented *s = w;
  lac_active *act = &s->act;
  lac_pcg_info info;
  int status;
  s->factor_failed = 0;
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  if ((status = factor_augmented (s, active)))           /* 1. */
    return status;
  lac_active_gather (act, active, lambda);
  load_vector (s, f, g, NULL, s->x);                     /* 2. U_0 */
  if ((status = solve_kw (s, s->x, U)))
    return status;
  lac_active_rhs (act, s->sys->C, g, U);                 /* 3. */
  status = lac_pcg (act->na, schur_product, schur_precondition, s, act->b,
                    act->lamA, rtol, PCG_MAXIT, &info);
  if ((status = lac_solve_counts_krylov (&s->counts, status, info.iterations,
                                         info.residual, act->na)))
    return status;
  lac_active_scatter (act, lambda);
  load_vector (s, f, g, act->lamA, s->x);                /* 4. U */
  return solve_kw (s, s->x, U);
}

const lac_strategy_ops lac_augmented_ops = {
  .alloc = augmented_alloc, .free = augmented_free, .set = augmented_set,
  .solve = augmented_solve, .get_counts = augmented_get_counts,
  .factor_failed = augmented_factor_failed
};
