/* lac_newton_rules.c -- the rules of the loop of Algorithm 1
 *                       (see lac_newton_rules.h)    [LAC Alg. 1; ch. 07 §5]
 */
#include "solve/lac_newton_rules.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

#define ETA_FIRST 1e-5    /* accuracy of the first consistent step of a loop */
#define ETA_FACTOR 1e-2   /* then this times the residual of step 3, ...    */
#define ETA_MAX 1e-3      /*   at most this,                                */
#define ETA_MIN 1e-12     /*   at least this (and always, the rule off)     */
#define LAZY_K 1e-5       /* the tangent left out of an evaluation after a
                             step on settled statuses from this residual:
                             quadratic convergence makes it the last     */

static const char *const rule_names[] = {
  "held_start", "all_active", "first_contact", "cycle_guard", "line_search",
  "inexact"
};

const char *
lac_rule_name (int r)
{
  for (size_t j = 0; j < sizeof rule_names / sizeof *rule_names; j++)
    if (r == 1 << j)
      return rule_names[j];
  return NULL;
}

/* The bit of the word w (n characters), or 0. */
static int
rule_bit (const char *w, size_t n)
{
  if (n == 3 && !strncmp (w, "all", 3))
    return LAC_RULES_ALL;
  for (size_t j = 0; j < sizeof rule_names / sizeof *rule_names; j++)
    if (strlen (rule_names[j]) == n && !strncmp (w, rule_names[j], n))
      return 1 << j;
  return 0;
}

int
lac_rule_parse (const char *list, int *bits)
{
  *bits = 0;
  if (!strcmp (list, "none"))
    return LAC_SUCCESS;
  for (const char *w = list; *w;)
    {
      w += strspn (w, ", ");
      size_t n = strcspn (w, ", ");
      int b = n ? rule_bit (w, n) : 0;
      if (n && !b)
        LAC_ERROR (LAC_EINVAL, "'%.*s' is not a rule of the loop (all, "
                   "none, or a list of held_start, all_active, "
                   "first_contact, cycle_guard, line_search, inexact)",
                   (int) n, w);
      *bits |= b;
      w += n;
    }
  return LAC_SUCCESS;
}

/* ---- held start, all active ---------------------------------------------- */

static int
cmp_down (const void *a, const void *b)
{
  const double *x = a, *y = b;                 /* pairs (value, index) */
  return x[0] < y[0] ? 1 : x[0] > y[0] ? -1 : 0;
}

static int
cmp_up (const void *a, const void *b)
{
  return -cmp_down (a, b);
}

size_t
lac_rule_held_start (const lac_contact_system *sys, size_t k,
                     const double *d, double *pair, char *kact)
{
  size_t m = k < 1 ? k : 1;
  for (size_t i = 0; i < k; i++)
    {
      pair[2 * i] = d[i];
      pair[2 * i + 1] = (double) i;
    }
  qsort (pair, k, 2 * sizeof *pair, cmp_up);
  for (;; m = 2 * m < k ? 2 * m : k)
    {
      memset (kact, 0, k);
      for (size_t j = 0; j < m; j++)
        kact[(size_t) pair[2 * j + 1]] = 1;
      int held = !lac_system_check_held (sys, kact);
      lac_error_clear ();
      if (held || m == k)
        return m;
    }
}

int
lac_rule_all_active (lac_strategy *st, int status, size_t k, char *kact,
                     double *x, double *klam, size_t *nactive)
{
  if (status != LAC_ESING || *nactive >= k)
    return status;
  lac_error_clear ();
  memset (kact, 1, k);
  *nactive = k;
  return lac_strategy_solve (st, kact, x, klam);
}

/* ---- first contact ------------------------------------------------------ */

void
lac_rule_first_contact (const lac_model_point *p, const char *active,
                        double frac, char *want)
{
  double pmax = 0;
  for (size_t i = 0; i < p->k; i++)
    if (want[lac_model_slot (p, i)] && !active[lac_model_slot (p, i)])
      pmax = fmax (pmax, lac_model_penetration (p, i));
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      if (want[m] && !active[m] && lac_model_penetration (p, i) < frac * pmax)
        want[m] = 0;
    }
}

/* ---- cycle guard ---------------------------------------------------------- */

static unsigned long long
status_hash (const char *active, size_t k)
{
  unsigned long long h = 1469598103934665603ull;       /* FNV-1a */
  for (size_t i = 0; i < k; i++)
    h = (h ^ (unsigned char) active[i]) * 1099511628211ull;  /* a status */
  return h;
}

void
lac_cycle_guard_free (lac_cycle_guard *g)
{
  lac_free (g->seen);
  memset (g, 0, sizeof *g);
}

void
lac_cycle_guard_clear (lac_cycle_guard *g)
{
  g->nseen = 0;
}

int
lac_cycle_guard_remember (lac_cycle_guard *g, const char *active,
                          size_t nslot)
{
  if (lac_grow (&g->seen, g->nseen + 1, &g->cap, sizeof *g->seen, 16))
    LAC_ERROR (LAC_ENOMEM, "status checksums");
  g->seen[g->nseen++] = status_hash (active, nslot);
  return LAC_SUCCESS;
}

int
lac_cycle_guard_seen (const lac_cycle_guard *g, const char *want,
                      size_t nslot)
{
  unsigned long long h = status_hash (want, nslot);
  for (size_t j = 0; j < g->nseen; j++)
    if (g->seen[j] == h)
      return 1;
  return 0;
}

size_t
lac_cycle_guard_damp (const lac_cycle_guard *g, const char *active,
                      const char *target, char *want, double *pair,
                      size_t nch, size_t nslot)
{
  qsort (pair, nch, 2 * sizeof *pair, cmp_down);
  for (size_t keep = nch / 2 > 0 ? nch / 2 : 1;; keep = keep / 2 > 0
       ? keep / 2 : 1)
    {
      memcpy (want, active, nslot);
      for (size_t c = 0; c < keep; c++)
        want[(size_t) pair[2 * c + 1]] = target[(size_t) pair[2 * c + 1]];
      if (keep == 1 || !lac_cycle_guard_seen (g, want, nslot))
        return keep;
    }
}

/* ---- line search ---------------------------------------------------------- */

void
lac_line_search_clear (lac_line_search *ls)
{
  ls->merit = ls->merit_best = HUGE_VAL;
  ls->alpha = 1;
  ls->backtracks = 0;
}

int
lac_line_search_reject (const lac_line_search *ls, int status, double merit,
                        int it, int settled)
{
  int worse = (status == LAC_ESING && it >= 1)
              || (!status && it >= 2 && settled && !(merit < ls->merit));
  return worse && ls->alpha > 1.0 / (1 << LAC_NEWTON_HALVINGS);
}

void
lac_line_search_halve (lac_line_search *ls, size_t n, double *U,
                       const double *dU, size_t nslot, double *lambda,
                       const double *lam_step)
{
  ls->alpha *= 0.5;
  for (size_t j = 0; j < n; j++)
    U[j] -= ls->alpha * dU[j];
  for (size_t m = 0; m < nslot; m++)
    lambda[m] = lam_step[m] + 0.5 * (lambda[m] - lam_step[m]);
  lac_error_clear ();
  ls->backtracks++;
}

int
lac_line_search_diverged (lac_line_search *ls, int it)
{
  if (it >= 2)
    ls->merit_best = fmin (ls->merit_best, ls->merit);
  return it >= 4 && ls->merit > LAC_NEWTON_DIVERGED * ls->merit_best;
}

/* ---- inexact consistent step ---------------------------------------------- */

double
lac_rule_eta (int on, int it, double residual)
{
  if (!on)
    return ETA_MIN;
  return it == 0 ? ETA_FIRST
         : fmax (ETA_MIN, fmin (ETA_MAX, ETA_FACTOR * residual));
}

int
lac_rule_refactor (int on, int it, int consistent, int gmres_last)
{
  if (!on || !consistent)
    return 1;
  return gmres_last > (it == 0 ? LAC_NEWTON_LAG : LAC_NEWTON_RENEW);
}

int
lac_rule_lazy_tangent (int on, int it, int settled, double res_solved)
{
  return on && it > 0 && settled && res_solved <= LAZY_K;
}
