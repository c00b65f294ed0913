/* lac_newton.c -- primal-dual active set for the LAC saddle system
 *                                                    [LAC §4.5, (18), Alg. 1]
 *
 * See lac_newton.h.  One iteration: (*) for the statuses by the strategy
 * (solve/lac_strategy.c), d = G - C^T U, the statuses by the rule of
 * solve/lac_complementarity.c, the cycle safeguard, a history record.
 *
 * References: M. Hintermüller, K. Ito, K. Kunisch, The primal-dual active
 * set strategy as a semismooth Newton method, SIAM J. Optim. 13 (2002);
 * S. Hüeber, B. Wohlmuth [LAC ref. 45].
 */
#include "solve/lac_newton.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "solve/lac_complementarity.h"

lac_newton *
lac_newton_alloc (lac_strategy_kind kind, size_t n, size_t k)
{
  lac_newton *s = lac_calloc (1, sizeof *s);
  size_t k1 = k ? k : 1;
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "newton workspace");
  s->kind = kind;
  s->n = n;
  s->k = k;
  s->U = lac_calloc (n ? n : 1, sizeof *s->U);
  s->lambda = lac_calloc (k1, sizeof *s->lambda);
  s->d = lac_calloc (k1, sizeof *s->d);
  s->active = lac_calloc (k1, 1);
  s->work = lac_calloc (3 * k1, sizeof *s->work);
  s->strategy = lac_strategy_alloc (kind);
  if (!s->U || !s->lambda || !s->d || !s->active || !s->work || !s->strategy)
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
  lac_free (s->seen);
  lac_strategy_free (s->strategy);
  lac_free (s);
}

size_t
lac_newton_nactive (const lac_newton *s)
{
  size_t m = 0;
  for (size_t i = 0; i < s->k; i++)
    m += s->active[i] != 0;
  return m;
}

/* Scale of the mean gap i (what d_i was computed from), for deciding that
 * it is zero up to roundoff. */
static double
gap_scale (const lac_newton *s, size_t i)
{
  const lac_csc *C = s->sys->C;
  double sc = fabs (s->sys->G[i]);
  for (int p = C->p[i]; p < C->p[i + 1]; p++)
    sc += fabs (C->x[p] * s->U[C->i[p]]);
  return sc;
}

/* Penetration of macro-element i as a length: -d_i / |C(:,i)|_1 (the mean
 * gap per unit weight; 0 for an empty column). */
static double
penetration (const lac_newton *s, size_t i)
{
  const lac_csc *C = s->sys->C;
  double csum = 0;
  for (int p = C->p[i]; p < C->p[i + 1]; p++)
    csum += fabs (C->x[p]);
  return csum > 0 ? -s->d[i] / csum : 0.0;
}

/* The first contact.  When the first solve had no active multiplier, the
 * gaps d are those of the bodies passing through each other, and every
 * penetrating element would be switched on: for a curved body that is the
 * whole overlap, wider than the contact zone, and the rule then releases
 * about half of the excess per iteration.  For a paraboloid pressed by a
 * depth delta (gap -delta + r^2 / 2R) the overlap radius is sqrt(2 R delta)
 * and Hertz's contact radius sqrt(R delta), where the overlap is delta / 2:
 * so only the elements that penetrate by at least half the deepest
 * penetration are switched on now; the others, if they belong to the
 * contact, are switched on by the rule at the next iteration.  A flat
 * contact (all penetrations equal) is switched on whole.  Returns the
 * number of changes left in want[]. */
static size_t
first_contact (const lac_newton *s, char *want)
{
  double frac = s->held_start ? LAC_NEWTON_HELD_CONTACT
                              : LAC_NEWTON_FIRST_CONTACT, pmax = 0;
  size_t nch = 0;
  for (size_t i = 0; i < s->k; i++)
    if (want[i] && !s->active[i])
      pmax = fmax (pmax, penetration (s, i));
  for (size_t i = 0; i < s->k; i++)
    {
      if (want[i] && !s->active[i]
          && penetration (s, i) < frac * pmax)
        want[i] = 0;
      nch += want[i] != s->active[i];
    }
  return nch;
}

static double
rho_of (const lac_newton *s, size_t i)
{
  return s->sys->rho ? s->sys->rho[i] : 1.0;
}

/* FNV-1a checksum of the statuses. */
static unsigned long long
status_hash (const char *active, size_t k)
{
  unsigned long long h = 1469598103934665603ull;
  for (size_t i = 0; i < k; i++)
    h = (h ^ (unsigned long long) (active[i] != 0)) * 1099511628211ull;
  return h;
}

static int
push_record (lac_newton *s, const lac_newton_record *r)
{
  if (s->nhist == s->caphist)
    {
      size_t cap = s->caphist ? 2 * s->caphist : 16;
      lac_newton_record *h = lac_realloc (s->hist, cap * sizeof *h);
      unsigned long long *q = h ? lac_realloc (s->seen, (cap + 1)
                                               * sizeof *q) : NULL;
      if (h)
        s->hist = h;
      if (!q)
        LAC_ERROR (LAC_ENOMEM, "newton history");
      s->seen = q;
      s->caphist = cap;
    }
  s->hist[s->nhist++] = *r;
  return LAC_SUCCESS;
}

static int
cmp_gap (const void *a, const void *b)
{
  const double *x = a, *y = b;                 /* pairs (G_i, i) */
  return x[0] < y[0] ? -1 : x[0] > y[0] ? 1 : 0;
}

/* Statuses that hold the bodies held by contact alone: the multipliers of
 * the m smallest initial gaps, m = 1, 2, 4, ... until the active ones
 * hold every body (lac_system_check_held); every multiplier if fewer do
 * not.  held_start = m. */
static void
hold_start (lac_newton *s)
{
  double *pair = s->work;                      /* (G_i, i), 2 k doubles */
  size_t m = s->k < 1 ? s->k : 1;
  for (size_t i = 0; i < s->k; i++)
    {
      pair[2 * i] = s->sys->G[i];
      pair[2 * i + 1] = (double) i;
    }
  qsort (pair, s->k, 2 * sizeof *pair, cmp_gap);
  for (;; m = 2 * m < s->k ? 2 * m : s->k)
    {
      int held;
      memset (s->active, 0, s->k);
      for (size_t j = 0; j < m; j++)
        s->active[(size_t) pair[2 * j + 1]] = 1;
      held = !lac_system_check_held (s->sys, s->active);
      lac_error_clear ();
      if (held || m == s->k)
        break;
    }
  s->held_start = m;
}

int
lac_newton_set (lac_newton *s, const lac_contact_system *sys,
                const char *active0)
{
  double normK;
  int status;
  if (!sys || !sys->K || !sys->F || !sys->C || !sys->G)
    LAC_ERROR (LAC_EINVAL, "incomplete contact system");
  if (sys->K->nrow != s->n || sys->K->ncol != s->n || sys->C->nrow != s->n
      || sys->C->ncol != s->k)
    LAC_ERROR (LAC_EBADLEN, "K is %zux%zu and C %zux%zu, workspace n = %zu, k = %zu",
               sys->K->nrow, sys->K->ncol, sys->C->nrow, sys->C->ncol, s->n, s->k);
  s->sys = sys;
  s->nhist = 0;
  s->restarted = 0;
  s->held_start = 0;
  memset (s->U, 0, s->n * sizeof *s->U);
  memset (s->lambda, 0, s->k * sizeof *s->lambda);
  lac_system_norms (sys, &normK, &s->normC);
  /* Initial statuses [LAC Alg. 1, lines 2-8]: closed or penetrating */
  for (size_t i = 0; i < s->k; i++)
    {
      s->active[i] = active0 ? active0[i] != 0 : sys->G[i] <= 0;
      s->d[i] = sys->G[i];
    }
  if (sys->nfree > 0 && lac_system_check_held (sys, s->active))
    {
      lac_error_clear ();       /* a body held by contact alone */
      hold_start (s);
      s->restarted = 1;
    }
  if (!s->seen && !(s->seen = lac_malloc (sizeof *s->seen)))
    LAC_ERROR (LAC_ENOMEM, "newton history");
  s->seen[0] = status_hash (s->active, s->k);
  status = lac_strategy_set (s->strategy, sys);
  return status;
}

/* Was this set of statuses used by an earlier iteration? */
static int
seen_before (const lac_newton *s, unsigned long long h)
{
  for (size_t j = 0; j <= s->nhist; j++)
    if (s->seen[j] == h)
      return 1;
  return 0;
}

static int
cmp_violation (const void *a, const void *b)
{
  const double *x = a, *y = b;                 /* pairs (|A_i|, i) */
  return x[0] < y[0] ? 1 : x[0] > y[0] ? -1 : 0;
}

/* Steps 26-33: the statuses by the rule; the changes in want[].  If the
 * new statuses were tried before (a cycle), keep only the most violated
 * half of the changes, again while the result was tried before. */
static size_t
update_status (lac_newton *s, int *damped)
{
  double lmax = lac_complementarity_lmax (s->k, s->lambda);
  double *pair = s->work;                      /* (|A_i|, i) of changes */
  size_t nch = 0;
  char *want = (char *) (s->work + 2 * s->k);  /* k flags in k doubles */
  *damped = 0;
  for (size_t i = 0; i < s->k; i++)
    {
      double sc = gap_scale (s, i), rho = rho_of (s, i);
      want[i] = (char) lac_complementarity_active (s->lambda[i], s->d[i],
                                                   rho, lmax, sc);
      if (want[i] != s->active[i])
        {
          pair[2 * nch] = lac_complementarity_residual (s->lambda[i],
                                                        s->d[i], rho, lmax,
                                                        sc);
          pair[2 * nch++ + 1] = (double) i;
        }
    }
  if (s->nhist == 0 && nch > 0
      && (lac_newton_nactive (s) == 0 || s->held_start > 0))
    nch = first_contact (s, want);
  if (nch == 0 || !seen_before (s, status_hash (want, s->k)))
    {
      memcpy (s->active, want, s->k);
      return nch;
    }
  qsort (pair, nch, 2 * sizeof *pair, cmp_violation);
  *damped = 1;
  for (size_t keep = nch / 2 > 0 ? nch / 2 : 1;; keep = keep / 2 > 0
       ? keep / 2 : 1)
    {
      memcpy (want, s->active, s->k);
      for (size_t c = 0; c < keep; c++)
        {
          size_t i = (size_t) pair[2 * c + 1];
          want[i] = !s->active[i];
        }
      if (keep == 1 || !seen_before (s, status_hash (want, s->k)))
        {
          memcpy (s->active, want, s->k);
          return keep;
        }
    }
}

/* Residuals of the current iterate for the history record. */
static void
record (lac_newton *s, lac_newton_record *r)
{
  double lmax = lac_complementarity_lmax (s->k, s->lambda), ncp = 0, pen = 0;
  lac_strategy_counts c;
  lac_strategy_get_counts (s->strategy, &c);
  r->residual = c.backward_error;
  for (size_t i = 0; i < s->k; i++)
    {
      ncp = fmax (ncp, lac_complementarity_residual (s->lambda[i], s->d[i],
                                                     rho_of (s, i), lmax,
                                                     gap_scale (s, i)));
      pen = fmax (pen, penetration (s, i));
    }
  r->ncp = ncp / (lmax > 0 ? lmax : 1.0);
  r->max_penetration = pen;
}

int
lac_newton_iterate (lac_newton *s)
{
  lac_newton_record r;
  lac_strategy_counts c0, c1;
  double t0 = lac_seconds ();
  int status, damped;
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_newton_set was not called");
  memset (&r, 0, sizeof r);
  r.iter = (int) s->nhist + 1;
  r.nactive = lac_newton_nactive (s);
  lac_strategy_get_counts (s->strategy, &c0);
  /* Step 21: solve (*) for the current statuses, from the last iterate */
  status = lac_strategy_solve (s->strategy, s->active, s->U, s->lambda);
  if (status == LAC_ESING && s->nhist == 0 && r.nactive < s->k)
    {
      /* A body held by contact alone that the system did not declare
       * (no N): its stiffness alone is singular; start again from every
       * multiplier active, the rule releases those in tension. */
      lac_error_clear ();
      memset (s->active, 1, s->k);
      s->restarted = 1;
      r.nactive = s->k;
      status = lac_strategy_solve (s->strategy, s->active, s->U, s->lambda);
    }
  if (status)
    return status;
  lac_strategy_get_counts (s->strategy, &c1);
  r.cg_iterations = c1.iterations - c0.iterations;
  r.factorizations = c1.factorizations - c0.factorizations;
  r.krylov_iterations = c1.last_iterations;
  r.krylov_residual = c1.last_residual;
  lac_system_gaps (s->sys, s->U, s->d);                    /* d = G - C^T U */
  record (s, &r);
  s->changed = update_status (s, &damped);                 /* steps 26-33 */
  r.nchanged = s->changed;
  r.damped = damped;
  r.seconds = lac_seconds () - t0;
  if ((status = push_record (s, &r)))
    return status;
  s->seen[s->nhist] = status_hash (s->active, s->k);
  return LAC_SUCCESS;
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
lac_newton_maxiter_error (const lac_newton *s, int maxit)
{
  LAC_ERROR (LAC_EMAXITER, "the active set did not settle in %d iterations:"
             " the last one changed %zu status%s (%zu of %zu multipliers "
             "active); raise [contact] max_iterations or load in steps",
             maxit, s->changed, s->changed == 1 ? "" : "es",
             lac_newton_nactive (s), s->k);
}

int
lac_newton_solve (lac_newton *s, const lac_contact_system *sys, int maxit,
                  double tol)
{
  int status = lac_newton_set (s, sys, NULL);
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
  return lac_newton_maxiter_error (s, maxit);
}
