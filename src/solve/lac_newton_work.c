/* lac_newton_work.c -- the workspace of Algorithm 1: options, allocation,
 *                      the iteration records (see lac_newton.h)
 *
 * What the loop (lac_newton.c) runs on, and the ways to drive it that
 * are not the loop itself: go back to the start of a loop (a load step
 * cut), solve a linear system given directly.
 */
#include "solve/lac_newton.h"

#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "solve/lac_linear_model.h"
#include "solve/lac_newton_internal.h"

void
lac_newton_opts_init (lac_newton_opts *o)
{
  memset (o, 0, sizeof *o);
  o->kind = LAC_STRATEGY_AUTO;
  o->maxit = LAC_NEWTON_MAXIT;
  o->tol = LAC_NEWTON_TOL;
  o->pen_tol = LAC_NEWTON_PEN_TOL;
}

static void
work_free (lac_newton_work *w)
{
  if (!w)
    return;
  lac_free (w->klam);
  lac_free (w->kact);
  lac_free (w->klin);
  lac_free (w->x);
  lac_free (w->dU);
  lac_free (w->active0);
  lac_free (w->lam_step);
  lac_free (w->lam_lin);
  lac_free (w->want);
  lac_free (w->col);
  lac_free (w->set_slot);
  lac_free (w->pair);
  lac_free (w->target);
  lac_free (w->fl);
  lac_free (w->ffree);
  lac_free (w->fP);
  lac_free (w->fQ);
  lac_free (w->fr);
  lac_free (w->dir_new);
  lac_cycle_guard_free (&w->guard);
  if (w->lin)
    lac_linear_model_clear (w->lin);
  lac_free (w->lin);
  lac_free (w);
}

void
lac_newton_free (lac_newton *s)
{
  if (!s)
    return;
  lac_free (s->U);
  lac_free (s->U0);
  lac_free (s->lambda);
  lac_free (s->lambda0);
  lac_free (s->d);
  lac_free (s->active);
  lac_free (s->lambda_t);
  lac_free (s->lambda0_t);
  lac_free (s->slip_conv);
  lac_free (s->dir);
  lac_free (s->hist);
  lac_strategy_free (s->strategy);
  work_free (s->w);
  lac_free (s);
}

/* The options with their defaults where they are 0. */
static void
opts_defaults (lac_newton_opts *o)
{
  if (o->maxit <= 0)
    o->maxit = LAC_NEWTON_MAXIT;
  if (!(o->tol > 0))
    o->tol = LAC_NEWTON_TOL;
  if (o->pen_tol == 0)
    o->pen_tol = LAC_NEWTON_PEN_TOL;
}

/* The arrays of friction (lac_friction.h) for ns slots; 0 without memory. */
static int
friction_alloc (lac_newton *s, size_t ns)
{
  lac_newton_work *w = s->w;
  size_t nt = (size_t) s->model.ntan, q = 1 + nt;
  s->ntan = (int) nt;
  double **arr[] = { &s->lambda_t, &s->lambda0_t, &s->slip_conv, &s->dir,
                     &w->dir_new };
  for (size_t j = 0; j < sizeof arr / sizeof *arr; j++)
    if (!(*arr[j] = lac_calloc (ns * nt, sizeof (double))))
      return 0;
  return (w->fl = lac_calloc (ns * q, sizeof *w->fl))
         && (w->ffree = lac_calloc (ns * q, 1))
         && (w->fP = lac_calloc (ns * q * q, sizeof *w->fP))
         && (w->fQ = lac_calloc (ns * q * q, sizeof *w->fQ))
         && (w->fr = lac_calloc (ns * q, sizeof *w->fr));
}

lac_newton *
lac_newton_alloc (const lac_contact_model *m, const lac_newton_opts *opts)
{
  lac_newton *s = lac_calloc (1, sizeof *s);
  if (!s || !(s->w = lac_calloc (1, sizeof *s->w)))
    {
      lac_free (s);
      LAC_ERROR_NULL (LAC_ENOMEM, "workspace of Algorithm 1");
    }
  s->model = *m;
  if (opts)
    s->opts = *opts;
  else
    lac_newton_opts_init (&s->opts);
  opts_defaults (&s->opts);
  s->n = m->n;
  s->nslot = m->nslot;
  s->first = 1;
  size_t n = s->n ? s->n : 1, ns = s->nslot ? s->nslot : 1;
  lac_newton_work *w = s->w;
  double **per_dof[] = { &s->U, &s->U0, &w->x, &w->dU };
  double **per_slot[] = { &s->lambda, &s->lambda0, &s->d, &w->lam_step,
                          &w->lam_lin, &w->klam, &w->klin };
  int ok = (s->active = lac_calloc (ns, 1)) && (w->want = lac_calloc (ns, 1))
           && (w->active0 = lac_calloc (ns, 1))
           && (w->kact = lac_calloc (ns, 1))
           && (w->col = lac_calloc (ns, sizeof *w->col))
           && (w->set_slot = lac_calloc (ns, sizeof *w->set_slot))
           && (w->pair = lac_calloc (2 * ns, sizeof *w->pair));
  for (size_t j = 0; j < sizeof per_dof / sizeof *per_dof; j++)
    ok = ok && (*per_dof[j] = lac_calloc (n, sizeof (double)));
  for (size_t j = 0; j < sizeof per_slot / sizeof *per_slot; j++)
    ok = ok && (*per_slot[j] = lac_calloc (ns, sizeof (double)));
  ok = ok && (w->target = lac_calloc (ns, 1));
  if (ok && m->ntan > 0)
    ok = friction_alloc (s, ns);
  if (!ok)
    {
      lac_newton_free (s);
      LAC_ERROR_NULL (LAC_ENOMEM, "workspace of Algorithm 1 for %zu dofs "
                      "and %zu macro-elements", m->n, m->nslot);
    }
  return s;
}

size_t
lac_newton_iterations (const lac_newton *s)
{
  return s->nhist - s->nhist0;
}

void
lac_newton_restart (lac_newton *s)
{
  memcpy (s->U, s->U0, s->n * sizeof *s->U);
  memcpy (s->lambda, s->lambda0, s->nslot * sizeof *s->lambda);
  if (s->ntan)
    memcpy (s->lambda_t, s->lambda0_t, s->nslot * (size_t) s->ntan
            * sizeof *s->lambda_t);
  memcpy (s->active, s->w->active0, s->nslot);
  s->first = s->w->first0;
}

int
lac_newton_solve_system (lac_strategy_kind kind,
                         const lac_contact_system *sys, int maxit, double tol,
                         lac_newton **out)
{
  lac_linear_model *lin = lac_calloc (1, sizeof *lin);
  lac_contact_model m;
  lac_newton_opts o;
  *out = NULL;
  if (!lin)
    LAC_ERROR (LAC_ENOMEM, "linear model");
  int status = lac_linear_model_init (lin, sys, 1.0, &m);
  if (status)
    {
      lac_free (lin);
      return status;
    }
  lac_newton_opts_init (&o);
  o.kind = kind;
  o.maxit = maxit;
  o.tol = tol;
  if (!(*out = lac_newton_alloc (&m, &o)))
    {
      lac_linear_model_clear (lin);
      lac_free (lin);
      return LAC_ENOMEM;
    }
  (*out)->w->lin = lin;
  return lac_newton_solve (*out);
}
