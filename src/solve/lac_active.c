/* lac_active.c -- the active multipliers of an augmented solve
 *                 (see lac_active.h)              [LAC (17), Alg. 1 l. 21]
 */
#include "solve/lac_active.h"

#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

int
lac_active_init (lac_active *act, size_t k)
{
  size_t k1 = k ? k : 1;
  lac_active_clear (act);
  act->s = lac_malloc (k1 * sizeof *act->s);
  act->w = lac_calloc (k1, sizeof *act->w);
  act->factored_for = lac_calloc (k1, 1);
  act->idx = lac_malloc (k1 * sizeof *act->idx);
  act->b = lac_malloc (k1 * sizeof *act->b);
  act->lamA = lac_malloc (k1 * sizeof *act->lamA);
  if (!act->s || !act->w || !act->factored_for || !act->idx || !act->b || !act->lamA)
    LAC_ERROR (LAC_ENOMEM, "active multipliers, k = %zu", k);
  act->k = k;
  return LAC_SUCCESS;
}

void
lac_active_clear (lac_active *act)
{
  double omega = act->omega;
  lac_free (act->s);
  lac_free (act->w);
  lac_free (act->factored_for);
  lac_free (act->idx);
  lac_free (act->b);
  lac_free (act->lamA);
  memset (act, 0, sizeof *act);
  act->omega = omega;
}

int
lac_active_weights (lac_active *act, const char *active)
{
  if (act->have_factor && memcmp (active, act->factored_for, act->k) == 0)
    return 0;
  for (size_t i = 0; i < act->k; i++)
    act->w[i] = active[i] && act->s[i] > 0 ? act->omega / act->s[i] : 0.0;
  return 1;
}

void
lac_active_factored (lac_active *act, const char *active)
{
  memcpy (act->factored_for, active, act->k);
  act->have_factor = 1;
}

void
lac_active_gather (lac_active *act, const char *active, const double *lambda)
{
  act->na = 0;
  for (size_t i = 0; i < act->k; i++)
    if (active[i])
      act->lamA[act->na] = lambda[i], act->idx[act->na++] = i;
}

void
lac_active_add_C (const lac_active *act, const lac_csc *C, const double *v,
                  double *x)
{
  for (size_t a = 0; a < act->na; a++)
    for (int p = C->p[act->idx[a]]; p < C->p[act->idx[a] + 1]; p++)
      x[C->i[p]] += C->x[p] * v[a];
}

void
lac_active_Ct (const lac_active *act, const lac_csc *C, const double *U,
               double *q)
{
  for (size_t a = 0; a < act->na; a++)
    {
      double sum = 0;
      for (int p = C->p[act->idx[a]]; p < C->p[act->idx[a] + 1]; p++)
        sum += C->x[p] * U[C->i[p]];
      q[a] = sum;
    }
}

void
lac_active_rhs (lac_active *act, const lac_csc *C, const double *g,
                const double *U)
{
  lac_active_Ct (act, C, U, act->b);
  for (size_t a = 0; a < act->na; a++)
    act->b[a] = g[act->idx[a]] - act->b[a];          /* g_A - C_A^T U */
}

void
lac_active_scatter (const lac_active *act, double *lambda)
{
  for (size_t i = 0; i < act->k; i++)
    lambda[i] = 0;
  for (size_t a = 0; a < act->na; a++)
    lambda[act->idx[a]] = act->lamA[a];
}
