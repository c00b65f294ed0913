/* lac_newton.c -- Algorithm 1, one loop for every contact model
 *                 (see lac_newton.h)             [LAC §4.5, Alg. 1, (18)]
 *
 * The loop comes first, as the paper writes it: an iteration evaluates the
 * model at U (step 1), sets the statuses (step 2), tests (step 3) and
 * solves (step 4).  Each step follows, in that order.  The rules that keep
 * the iterations few are calls into solve/lac_newton_rules.h, each behind
 * `rule (s, LAC_RULE_...)`; the checks after the test are
 * solve/lac_newton_check.h; the friction law's steps 2 and 4 are
 * solve/lac_newton_friction.h; the workspace is lac_newton_work.c.
 *
 * References: M. Hintermüller, K. Ito, K. Kunisch, The primal-dual active
 * set strategy as a semismooth Newton method, SIAM J. Optim. 13 (2002);
 * S. Hüeber, B. Wohlmuth [LAC ref. 45].
 */
#include "solve/lac_newton.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"
#include "solve/lac_complementarity.h"
#include "solve/lac_friction.h"
#include "solve/lac_newton_friction.h"
#include "solve/lac_newton_check.h"
#include "solve/lac_newton_internal.h"
#include "solve/lac_rows.h"

static int evaluate (lac_newton *s, lac_newton_record *rec);
static size_t update_status (lac_newton *s, lac_newton_record *rec);
static int covered (lac_newton *s, int *more);
static int stop_error (const lac_newton *s, const lac_newton_record *r,
                       int diverged);
static void gather (lac_newton *s, const lac_contact_system *sys,
                    lac_newton_record *rec);
static int prepare (lac_newton *s, const lac_contact_system *sys, int news,
                    int consistent, int *lagged);
static int solve_frozen (lac_newton *s, lac_newton_record *rec);
static double count (lac_newton *s, const lac_strategy_counts *c0,
                     lac_newton_record *rec);
static void scatter (lac_newton *s, lac_newton_record *rec);
static int push_record (lac_newton *s, const lac_newton_record *r);

/* 1 if rule r is on. */
static int
rule (const lac_newton *s, int r)
{
  return !(s->opts.off & r);
}

/* ---- the loop [Alg. 1] ---------------------------------------------------- */

int
lac_newton_begin (lac_newton *s)
{
  lac_newton_work *w = s->w;
  w->it = w->converged = w->settled = w->last_change = 0;
  w->nactive1 = 0;
  w->res_solved = 0;
  lac_line_search_clear (&w->ls);
  lac_cycle_guard_clear (&w->guard);
  s->predicted = s->restarted = 0;
  s->held_start = 0;
  s->nhist0 = s->nhist;
  memcpy (s->U0, s->U, s->n * sizeof *s->U);
  memcpy (s->lambda0, s->lambda, s->nslot * sizeof *s->lambda);
  if (s->ntan)
    memcpy (s->lambda0_t, s->lambda_t, s->nslot * (size_t) s->ntan
            * sizeof *s->lambda_t);
  memcpy (w->active0, s->active, s->nslot);
  w->first0 = s->first;
  if (s->strategy && lac_strategy_fallback (s->strategy))
    {
      lac_strategy_free (s->strategy);    /* try the Cholesky factor again */
      s->strategy = NULL;                 /* in every loop after a fallback */
      w->strategy_set = 0;
    }
  return LAC_SUCCESS;
}

/* Steps 1-3 at U: *done = 1 when the loop has converged [Alg. 1, l. 10]. */
static int
evaluate_and_test (lac_newton *s, lac_newton_record *rec, int *done)
{
  lac_newton_work *w = s->w;
  int status, more = 0;
  do
    {
      lac_newton_record keep = { .start = rec->start,
                                 .backtracks = rec->backtracks };
      *rec = keep;
      if ((status = evaluate (s, rec)))                      /* step 1 */
        return status;
      memcpy (w->lam_lin, s->lambda, s->nslot * sizeof *s->lambda);
      rec->nchanged = update_status (s, rec);                /* step 2 */
      rec->k = s->pt.k;
      s->residual = rec->residual;
      if (rec->nchanged > 0)
        w->last_change = w->it;
      *done = w->it > 0 && rec->nchanged == 0                /* step 3 */
              && rec->residual <= s->opts.tol
              && rec->gap_residual <= s->opts.tol;
      if (*done && (status = covered (s, &more)))
        return status;
    }
  while (*done && more);
  return LAC_SUCCESS;
}

/* The increment of fixed dof j: its row of the tangent reads d_j dU_j =
 * F_j (lac_dirichlet_apply keeps the diagonal d_j), the start of GMRES
 * with the factor of an older tangent. */
static double
fixed_increment (const lac_contact_system *sys, size_t j)
{
  const lac_csc *K = sys->K;
  for (int q = K->p[j]; q < K->p[j + 1]; q++)
    if ((size_t) K->i[q] == j && K->x[q] != 0)
      return sys->F[j] / K->x[q];
  return sys->F[j];
}

/* Step 4 [Alg. 1, lines 11-24]: linearize at U, solve (*) for the
 * statuses, U and lambda updated. */
static int
step (lac_newton *s, double eta, lac_newton_record *rec)
{
  const lac_contact_model_type *t = s->model.type;
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  const lac_contact_system *sys;
  lac_strategy_counts c0;
  int news, lagged, status;
  int consistent = t->nonlinear && t->consistent && !s->opts.frozen
                   && p->k > 0;
  double t0 = lac_seconds ();
  if ((status = t->linearize (s->model.self, s->U, &sys, &news)))
    return status;
  gather (s, sys, rec);                 /* the statuses of the columns */
  if (s->strategy)                      /* before prepare's factorization */
    lac_strategy_get_counts (s->strategy, &c0);
  else
    memset (&c0, 0, sizeof c0);
  if ((status = prepare (s, sys, news, consistent, &lagged)))
    return status;
  if (t->nonlinear)                               /* from the increments */
    memset (w->x, 0, s->n * sizeof *w->x);
  else
    memcpy (w->x, s->U, s->n * sizeof *w->x);     /* the warm start */
  for (size_t j = 0; lagged && j < s->n; j++)     /* the factor of an older */
    w->x[j] = p->fixed && p->fixed[j] ? fixed_increment (sys, j) : 0.0;
  if (!lagged && s->ntan)
    status = lac_newton_friction_solve (s, sys);             /* [Alg. 1, line 21] */
  else if (!lagged)
    status = solve_frozen (s, rec);               /* [Alg. 1, line 21] */
  rec->factored = !lagged;
  double tf = count (s, &c0, rec), t1 = lac_seconds ();
  if (s->ntan && w->rows_its > 0)       /* friction by GMRES (lac_rows.h) */
    {
      rec->krylov_iterations = w->rows_its;
      rec->backward_error = w->rows_berr;
      w->rows_its = 0;
    }
  s->time_frozen += t1 - t0 - tf;
  if (!status && consistent)
    {
      status = t->consistent (s->model.self, s->strategy, w->kact, w->klin,
                              eta, w->x, w->klam, &w->gmres_last,
                              &rec->krylov_residual);
      rec->krylov_iterations = w->gmres_last;
    }
  s->time_krylov += lac_seconds () - t1;
  if (status)
    return status;
  if (w->it == 0)
    w->nactive1 = rec->nactive;
  scatter (s, rec);                               /* [Alg. 1, lines 22-24] */
  s->time_solve += lac_seconds () - t0;
  return rule (s, LAC_RULE_CYCLE_GUARD)
         ? lac_cycle_guard_remember (&w->guard, s->active, s->nslot)
         : LAC_SUCCESS;
}

int
lac_newton_iterate (lac_newton *s)
{
  lac_newton_work *w = s->w;
  lac_newton_record rec = { 0 };
  int status, done;
  if (w->converged)
    return LAC_SUCCESS;
  rec.start = lac_seconds ();
  rec.backtracks = w->ls.backtracks;
  w->ls.backtracks = 0;
  if ((status = evaluate_and_test (s, &rec, &done)))      /* steps 1-3 */
    return status;
  rec.backtracks += w->ls.backtracks;
  if (done)
    {
      if (s->ntan)
        lac_newton_friction_converged (s);
      return w->converged = 1, LAC_SUCCESS;
    }
  int diverged = s->model.type->nonlinear && rule (s, LAC_RULE_LINE_SEARCH)
                 && lac_line_search_diverged (&w->ls, w->it);
  if (w->it >= s->opts.maxit || diverged)
    return stop_error (s, &rec, diverged);
  double eta = lac_rule_eta (rule (s, LAC_RULE_INEXACT), w->it, rec.residual);
  memcpy (w->lam_step, s->lambda, s->nslot * sizeof *s->lambda);
  w->settled = rec.nchanged == 0;
  w->res_solved = rec.residual;
  if ((status = step (s, eta, &rec)))                      /* step 4 */
    return status;
  s->first = 0;
  rec.iter = ++w->it;
  rec.seconds = lac_seconds () - rec.start;
  if ((status = push_record (s, &rec)))
    return status;
  return LAC_CONTINUE;
}

int
lac_newton_solve (lac_newton *s)
{
  int status = lac_newton_begin (s);
  if (!status)
    while ((status = lac_newton_iterate (s)) == LAC_CONTINUE)
      ;
  return status;
}

/* ---- step 1: evaluate --------------------------------------------------- */

/* Step 3's two residuals at the last evaluation, with lambda of the slots:
 * |r + C lambda| on the free dofs over max(force scale, |C lambda|), and
 * max |d_i| / (h_i |T^m cap Gamma_C|) over the active columns, a d_i at
 * the level of rounding of its terms counting as 0 (its slot in
 * w->worst_gap). */
static void
residuals (lac_newton *s, double *res, double *gres)
{
  const lac_model_point *p = &s->pt;
  double *w = s->w->x, nr = 0, ncl = 0, g = 0;
  s->w->worst_gap = -1;
  memcpy (w, p->r, s->n * sizeof *w);
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      double lam = s->lambda[m];
      double a = lac_newton_area (s, i) * lac_model_h (p, i, s->model.dim);
      for (int q = p->C->p[i]; q < p->C->p[i + 1]; q++)
        {
          double v = p->C->x[q] * lam;
          w[p->C->i[q]] += v;                          /* + C lambda */
          ncl += v * v;
        }
      double gi = a > 0 ? fabs (lac_snap (p->d[i], lac_newton_gap_scale (s, i))) / a
                  : 0.0;
      if (s->active[m] && gi > g)
        g = gi, s->w->worst_gap = (long) m;
    }
  for (size_t c = 0; s->ntan && c < p->Ct->ncol; c++)    /* + Ct lambda_t */
    for (int q = p->Ct->p[c]; q < p->Ct->p[c + 1]; q++)
      {
        size_t i = c / (size_t) s->ntan, b = c % (size_t) s->ntan;
        double v = p->Ct->x[q] * s->lambda_t[lac_model_slot (p, i)
                                             * (size_t) s->ntan + b];
        w[p->Ct->i[q]] += v;
        ncl += v * v;
      }
  for (size_t j = 0; j < s->n; j++)
    if (!p->fixed || !p->fixed[j])
      nr += w[j] * w[j];
  double scale = fmax (p->fscale, sqrt (ncl));
  *res = scale > 0 ? sqrt (nr) / scale : sqrt (nr);
  *gres = g;
}

/* Step 1 [Alg. 1, lines 11, 25]: the model at U, and step 3's residuals.
 * A predictor that turned a cell inside out is dropped; a nonlinear
 * model's step is halved by the line search (lac_newton_rules.h); the
 * tangent may be left to the solve (the inexact rule). */
static int
evaluate (lac_newton *s, lac_newton_record *rec)
{
  lac_newton_work *w = s->w;
  const lac_contact_model_type *t = s->model.type;
  int search = t->nonlinear && rule (s, LAC_RULE_LINE_SEARCH);
  int tangent = !lac_rule_lazy_tangent (rule (s, LAC_RULE_INEXACT), w->it,
                                        w->settled, w->res_solved);
  for (;;)
    {
      int status = t->evaluate (s->model.self, s->U, tangent, &s->pt);
      double merit = HUGE_VAL;
      if (!status && s->pt.k > s->nslot)
        status = LAC_ERRMSG (LAC_ESANITY, "the %s model gives %zu columns "
                             "for %zu macro-elements", t->name, s->pt.k,
                             s->nslot);
      if (!status)
        {
          residuals (s, &rec->residual, &rec->gap_residual);
          merit = fmax (rec->residual, rec->gap_residual);
        }
      if (status == LAC_ESING && w->it == 0 && s->predicted)
        {                             /* the predictor turned a cell inside */
          memcpy (s->U, s->U0, s->n * sizeof *s->U);   /* out: without it */
          memcpy (s->lambda, s->lambda0, s->nslot * sizeof *s->lambda);
          s->predicted = 0;
          lac_error_clear ();
          continue;
        }
      if (!search || !lac_line_search_reject (&w->ls, status, merit, w->it,
                                              w->settled))
        {
          if (!status)
            w->ls.merit = merit;
          return status;
        }
      lac_line_search_halve (&w->ls, s->n, s->U, w->dU, s->nslot, s->lambda,
                             w->lam_step);
    }
}

/* ---- step 2: the statuses ----------------------------------------------- */

/* The changes from s->active to want ranked for the cycle guard, in
 * w->pair: |A_i| of the complementarity function, a slot that lost its
 * column first.  Returns their number. */
static size_t
rank_changes (const lac_newton *s, double lmax)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  size_t nch = 0;
  for (size_t m = 0; m < s->nslot; m++)
    if (w->want[m] != s->active[m])
      {
        long i = w->col[m];
        w->pair[2 * nch] = i < 0 ? HUGE_VAL : lac_complementarity_residual
          (s->lambda[m], p->d[i], lac_newton_rho (s, (size_t) i), lmax,
           lac_newton_gap_scale (s, (size_t) i));
        w->pair[2 * nch++ + 1] = (double) m;
      }
  return nch;
}

/* Step 2 [Alg. 1, lines 26-33; 2-8 in the first iteration of a run]:
 * the statuses of the slots from lambda and the mean gaps of the
 * evaluation (lac_complementarity.h); a slot without a column is
 * inactive (lambda = 0).  The first-contact rule and the cycle guard may
 * hold some changes back.  Returns the number of changes. */
static size_t
update_status (lac_newton *s, lac_newton_record *rec)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  double lmax = s->ntan ? lac_newton_friction_lmax (s)   /* friction: lambda_t too */
                : lac_complementarity_lmax (s->nslot, s->lambda);
  char *want = w->want;
  memset (want, 0, s->nslot);
  memset (s->d, 0, s->nslot * sizeof *s->d);
  for (size_t m = 0; m < s->nslot; m++)
    w->col[m] = -1;
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      double sc = lac_newton_gap_scale (s, i);
      w->col[m] = (long) i;
      s->d[m] = p->d[i];
      if (s->ntan)                           /* solve/lac_friction.h */
        want[m] = lac_newton_friction_want (s, i, lmax);
      else
        want[m] = s->first ? lac_snap (p->d[i], sc) <= 0
                  : (char) lac_complementarity_active (s->lambda[m], p->d[i],
                                                       lac_newton_rho (s, i), lmax,
                                                       sc);
      rec->max_penetration = fmax (rec->max_penetration,
                                   lac_model_penetration (p, i));
    }
  if (w->it == 1 && (w->nactive1 == 0 || s->held_start > 0)
      && rule (s, LAC_RULE_FIRST_CONTACT))
    lac_rule_first_contact (p, s->active, s->held_start
                            ? LAC_NEWTON_HELD_CONTACT
                            : LAC_NEWTON_FIRST_CONTACT, want);
  size_t nch = rank_changes (s, lmax);
  if (nch > 0 && rule (s, LAC_RULE_CYCLE_GUARD)
      && lac_cycle_guard_seen (&w->guard, want, s->nslot))
    {
      memcpy (w->target, want, s->nslot);
      nch = lac_cycle_guard_damp (&w->guard, s->active, w->target, want,
                                  w->pair, nch, s->nslot);
      rec->damped = 1;
    }
  if (s->ntan)
    nch += lac_newton_friction_turns (s);
  memcpy (s->active, want, s->nslot);
  for (size_t m = 0; m < s->nslot; m++)
    if (!s->active[m])
      s->lambda[m] = 0;
  return nch;
}

/* ---- step 3: after the test, and when the loop stops --------------------- */

/* The test passed: the checks of solve/lac_newton_check.h.  *more = 1:
 * the model paired again and gained columns, the loop goes on. */
static int
covered (lac_newton *s, int *more)
{
  size_t gained = 0;
  int status;
  *more = 0;
  if ((status = lac_newton_check_lost (&s->pt, s->active, s->model.dim,
                                       s->opts.pen_tol))
      || (status = lac_newton_check_covered (&s->model, s->U,
                                             s->opts.pen_tol, &gained)))
    return status;
  if (gained > 0)
    {
      s->widened++;
      s->w->ls.merit = HUGE_VAL;          /* a new problem: no line search */
      s->w->settled = 0;
      *more = 1;
    }
  return LAC_SUCCESS;
}

size_t
lac_newton_nactive (const lac_newton *s)
{
  size_t m = 0;
  for (size_t i = 0; i < s->nslot; i++)
    m += s->active[i] != 0;
  return m;
}

/* The loop stops without converging (LAC_EMAXITER): say which part of
 * step 3's test failed. */
static int
stop_error (const lac_newton *s, const lac_newton_record *r, int diverged)
{
  const lac_newton_work *w = s->w;
  const char *its = w->it == 1 ? "" : "s";
  if (diverged)
    LAC_ERROR (LAC_EMAXITER, "no convergence of Algorithm 1: after %d "
               "iterations the residual is %.3e, %g times its best; the "
               "Newton steps diverge: load in more steps", w->it,
               w->ls.merit, LAC_NEWTON_DIVERGED);
  if (r->nchanged > 0)
    LAC_ERROR (LAC_EMAXITER, "no convergence in %d iteration%s of "
               "Algorithm 1: the statuses still change (%zu in the last, "
               "%zu of %zu multipliers active), residual %.3e; raise the "
               "iteration limit or load in more steps", w->it, its,
               r->nchanged, lac_newton_nactive (s), r->k, r->residual);
  if (r->residual > s->opts.tol)
    LAC_ERROR (LAC_EMAXITER, "no convergence in %d iteration%s of "
               "Algorithm 1: the statuses have not changed since iteration "
               "%d, but the residual of equilibrium stays at %.3e (tolerance "
               "%.1e; backward error of the last solve %.1e): the system is "
               "solved no better than that (stiffnesses or sizes far apart, "
               "a nearly singular tangent?)", w->it, its, w->last_change + 1,
               r->residual, s->opts.tol, r->backward_error);
  LAC_ERROR (LAC_EMAXITER, "no convergence in %d iteration%s of Algorithm 1: "
             "the statuses have not changed since iteration %d, but the "
             "mean gap of macro-element %ld stays at %.3e of its size "
             "(tolerance %.1e), above the rounding of its terms", w->it, its,
             w->last_change + 1, w->worst_gap, r->gap_residual, s->opts.tol);
}

/* ---- step 4: the solve's parts -------------------------------------------- */

/* The statuses and multipliers of the slots into the columns of the
 * evaluation (kact, klam; klin: lambda of the linearization point); the
 * held start where the first statuses do not hold the bodies. */
static void
gather (lac_newton *s, const lac_contact_system *sys, lac_newton_record *rec)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      w->kact[i] = s->active[m];
      w->klam[i] = s->active[m] ? s->lambda[m] : 0.0;
      w->klin[i] = w->lam_lin[m];
    }
  if (w->it == 0 && p->k > 0 && sys->nfree > 0 && !s->ntan
      && rule (s, LAC_RULE_HELD_START) && lac_system_check_held (sys, w->kact))
    {
      lac_error_clear ();
      s->held_start = lac_rule_held_start (sys, p->k, p->d, w->pair, w->kact);
      s->restarted = 1;
    }
  else if (w->it == 0 && p->k > 0 && sys->nfree > 0 && s->ntan
           && rule (s, LAC_RULE_HELD_START))
    lac_newton_friction_held_start (s, sys);
  rec->nactive = 0;
  for (size_t i = 0; i < p->k; i++)
    rec->nactive += w->kact[i] != 0;
}

/* Do the columns of the point have the slots the strategy's C had? */
static int
same_columns (const lac_newton *s)
{
  const lac_newton_work *w = s->w;
  int same = w->nset_slot == s->pt.k;
  for (size_t i = 0; same && i < s->pt.k; i++)
    same = w->set_slot[i] == lac_model_slot (&s->pt, i);
  return same;
}

/* The slots of the point's columns: those of the strategy's C from now
 * on (same_columns compares with them). */
static void
remember_columns (lac_newton *s)
{
  lac_newton_work *w = s->w;
  w->nset_slot = s->pt.k;
  for (size_t i = 0; i < s->pt.k; i++)
    w->set_slot[i] = lac_model_slot (&s->pt, i);
}

/* Set the strategy on sys (a new tangent), or reset it (only C is new),
 * or leave it.  *lagged: the tangent is new but the factorization of an
 * older one was kept (schur, lac_strategy_reset) as the preconditioner of
 * the consistent step, which then makes the whole step (the inexact
 * rule); if the columns are the same constraints as those of the C the
 * strategy holds, that C is kept too, and with it the columns of the
 * Schur complement made (on the coarse hex20 ring they cost as much as
 * the solves of GMRES).  A loop may start with the factor of the step
 * before (lac_rule_refactor); its first step then starts the fixed dofs
 * from their increments (fixed_increment): from F_j, GMRES began far
 * from the imposed displacement, and the CI ring turned a cell inside
 * out in its second step. */
static int
prepare (lac_newton *s, const lac_contact_system *sys, int news,
         int consistent, int *lagged)
{
  lac_newton_work *w = s->w;
  int kept = 0, status;
  *lagged = 0;
  if (s->opts.kind == LAC_STRATEGY_AUTO)    /* chosen from the problem */
    s->opts.kind = lac_strategy_choose (s->opts.kind, s->n, s->nslot,
                                        sys->nfree);
  if (s->opts.kind == LAC_NSTRATEGIES)
    return LAC_EINVAL;
  if (!s->strategy && !(s->strategy = lac_strategy_alloc (s->opts.kind)))
    return LAC_EDEP;                 /* the message says which and why */
  if (s->model.type->nonlinear)      /* a tangent may not be positive */
    lac_strategy_allow_fallback (s->strategy, 1);          /* definite */
  if (!w->strategy_set
      || (news == LAC_MODEL_NEW_K
          && lac_rule_refactor (rule (s, LAC_RULE_INEXACT), w->it,
                                consistent, w->gmres_last)))
    {
      status = lac_strategy_set (s->strategy, sys);
      w->strategy_set = !status;
      w->gmres_last = 0;
      remember_columns (s);
      return status;
    }
  if (news == LAC_MODEL_SAME)
    return LAC_SUCCESS;
  int same = same_columns (s);
  if (!same)                         /* the reset takes the point's C */
    remember_columns (s);
  int keep_c = same && news == LAC_MODEL_NEW_K && consistent;
  status = lac_strategy_reset (s->strategy, sys, keep_c, &kept);
  *lagged = kept && news == LAC_MODEL_NEW_K;
  return status;
}

/* The frozen system (*) by the strategy, from x, klam; a first solve of a
 * run that is singular may be made again with every multiplier active
 * (the all-active rule). */
static int
solve_frozen (lac_newton *s, lac_newton_record *rec)
{
  lac_newton_work *w = s->w;
  int status = lac_strategy_solve (s->strategy, w->kact, w->x, w->klam);
  if (status && s->first && rule (s, LAC_RULE_ALL_ACTIVE))
    {
      size_t na = rec->nactive;
      status = lac_rule_all_active (s->strategy, status, s->pt.k, w->kact,
                                    w->x, w->klam, &rec->nactive);
      if (rec->nactive != na)
        s->restarted = 1;
    }
  return status;
}

/* The counts of the strategy's solve into the record; returns the time of
 * its factorizations. */
static double
count (lac_newton *s, const lac_strategy_counts *c0, lac_newton_record *rec)
{
  lac_strategy_counts c1;
  lac_strategy_get_counts (s->strategy, &c1);
  rec->cg_iterations = c1.iterations - c0->iterations;
  rec->factorizations = c1.factorizations - c0->factorizations;
  rec->krylov_iterations = c1.last_iterations;
  rec->krylov_residual = c1.last_residual;
  rec->backward_error = c1.backward_error;
  s->time_factor += c1.time_factor - c0->time_factor;
  return c1.time_factor - c0->time_factor;
}

/* lambda and the statuses of the columns back into the slots; U moved by
 * the solution x (an increment, or U itself for a linear model). */
static void
scatter (lac_newton *s, lac_newton_record *rec)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  double nu = 0, ndu = 0;
  for (size_t i = 0; i < p->k; i++)
    {
      s->lambda[lac_model_slot (p, i)] = w->kact[i] ? w->klam[i] : 0.0;
      s->active[lac_model_slot (p, i)] = w->kact[i];
    }
  for (size_t j = 0; j < s->n; j++)
    {
      w->dU[j] = s->model.type->nonlinear ? w->x[j] : w->x[j] - s->U[j];
      s->U[j] += w->dU[j];
      nu += s->U[j] * s->U[j];
      ndu += w->dU[j] * w->dU[j];
    }
  rec->du = nu > 0 ? sqrt (ndu / nu) : sqrt (ndu);
  w->ls.alpha = 1;
}

static int
push_record (lac_newton *s, const lac_newton_record *r)
{
  if (lac_grow (&s->hist, s->nhist + 1, &s->caphist, sizeof *s->hist, 16))
    LAC_ERROR (LAC_ENOMEM, "iteration records");
  s->hist[s->nhist++] = *r;
  return LAC_SUCCESS;
}
