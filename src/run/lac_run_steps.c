/* lac_run_steps.c -- stage 5 of a small-strain run with [steps]
 *                    (see lac_run_steps.h)            [LAC §4.5, Alg. 1]
 */
#include "run/lac_run_steps.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_status.h"

void
lac_run_steps_clear (lac_run_steps *st)
{
  lac_run_steplog_clear (&st->log);
  memset (st, 0, sizeof *st);
}

/* The reference imposed value of the curve: the first non-zero value of
 * a [dirichlet] section (a component, or u.n), and its curve. */
static void
imposed_ref (const lac_scene *sc, const lac_run_curves *cv,
             lac_run_steps *st)
{
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      const lac_scene_dirichlet *d = &sc->dirichlet[k];
      double v = d->kind == LAC_BC_NORMAL ? d->normal : 0.0;
      for (int c = 0; c < 3 && v == 0 && d->kind == LAC_BC_COMPONENTS; c++)
        v = d->fixed[c] ? d->value[c] : 0.0;
      if (v != 0)
        {
          st->log.imposed_ref = v;
          st->imposed_curve = cv->of_dirichlet[k];
          return;
        }
    }
}

/* The loads and Dirichlet values of step j, the loop begun from the last
 * converged step (the first step: lac_run_solve begins it). */
static void
step_begin (lac_run_system *sys, lac_run_solution *sol, lac_run_steps *st,
            size_t j)
{
  double t = st->log.factor[j];
  lac_run_curves_set (sys->curves, t, sys->F, sys->b, sys->dir);
  if (sol->newton)
    {
      lac_linear_model_dirichlet (&sol->lin);      /* G of the new values */
      lac_newton_begin (sol->newton);
    }
  snprintf (sol->step, sizeof sol->step, "load step %zu of %zu (load "
            "factor %g): ", j + 1, st->log.nfactor, t);
  st->in_step = 1;
  st->start = lac_seconds ();
}

/* The record of step j: its counts, the monitor, the normal contact
 * force sum lambda |T^m cap Gamma_C| and the largest pressure. */
static void
record_step (const lac_run_system *sys, const lac_contact *c,
             const lac_run_solution *sol, lac_run_steps *st, size_t j,
             int dim)
{
  const lac_newton *nw = sol->newton;
  lac_run_step_record *q = &st->log.step[j];
  double t = st->log.factor[j];
  q->solver = (lac_nl_step) { .t = t, .substeps = 1,
                              .iters = (int) lac_newton_iterations (nw),
                              .residual = nw->residual, .k = c ? c->k : 0,
                              .nactive = lac_newton_nactive (nw),
                              .seconds = lac_seconds () - st->start };
  q->imposed = lac_run_curves_factor (sys->curves, st->imposed_curve, t)
               * st->log.imposed_ref;
  lac_run_steplog_monitor (&st->log, sys->dir->frames, sol->u, dim, q->um);
  for (size_t i = 0; c && i < c->k; i++)
    q->force += nw->lambda[c->macro[i]] * c->area[i];
  for (size_t m = 0; m < nw->nslot; m++)
    q->lambda_min = fmin (q->lambda_min, nw->lambda[m]);
}

/* Step j converged: its records, its displacement if it gets a file, its
 * line. */
static int
step_done (const lac_scene *sc, const lac_mesh *m,
           const lac_run_setup *setup, const lac_run_system *sys,
           lac_run_solution *sol, lac_run_steps *st, size_t j,
           char *progress, size_t size)
{
  size_t ndof = sys->ndof;
  const lac_run_step_record *q = &st->log.step[j];
  char line[256], mon[80] = "";
  double *u;
  int status;
  lac_run_plate_untie (&sys->ties, sol->u);     /* (again at the end) */
  record_step (sys, setup->data.all, sol, st, j, m->dim);
  if ((status = lac_run_steplog_mults (&st->log, m, setup, setup->data.P,
                                       setup->data.all, sol->newton,
                                       (int) j + 1)))
    return status;
  if ((u = lac_run_steplog_keep (&st->log, j, sc->steps.vtu_every, sol->u,
                                 ndof)))
    lac_frames_to_global (sys->dir->frames, u);
  if (st->log.monitor != SIZE_MAX)
    snprintf (mon, sizeof mon, ", %s %s = %.4g", sc->steps.monitor,
              m->dim == 2 ? "u_y" : "u_z", q->um[m->dim - 1]);
  snprintf (line, sizeof line, "%s", progress);
  snprintf (progress, size, "step %zu/%zu: t = %.4f, %s%s, %.1f s", j + 1,
            st->log.nfactor, q->solver.t, line, mon, q->solver.seconds);
  return LAC_SUCCESS;
}

int
lac_run_steps_solve (const lac_scene *sc, int strategy,
                     const lac_strategy_context *ctx, const lac_mesh *m,
                     lac_run_setup *setup, lac_run_system *sys,
                     lac_run_solution *sol, lac_run_steps *st,
                     char *progress, size_t size)
{
  char line[200];
  size_t j;
  int status;
  if (!st->log.factor)
    {
      if ((status = lac_run_steplog_init (&st->log, sc, m, sc->steps.end)))
        return status;
      imposed_ref (sc, sys->curves, st);
    }
  j = st->log.next;
  if (!st->in_step)
    step_begin (sys, sol, st, j);
  status = lac_run_solve (sc, strategy, ctx, setup, sys, sol, line,
                          sizeof line);
  if (status == LAC_CONTINUE)
    {
      snprintf (progress, size, "step %zu/%zu: %s", j + 1, st->log.nfactor,
                line);
      return LAC_CONTINUE;
    }
  st->in_step = 0;
  if (status)
    return status;
  snprintf (progress, size, "%s", line);
  if ((status = step_done (sc, m, setup, sys, sol, st, j, progress, size)))
    return status;
  return ++st->log.next < st->log.nfactor ? LAC_CONTINUE : LAC_SUCCESS;
}

int
lac_run_steps_summary (const lac_run_steps *st, const lac_newton *nw,
                       int dim, lac_summary *sum)
{
  const lac_run_steplog *log = &st->log;
  lac_strategy_counts c;
  int itmax = 0, status;
  for (size_t j = 0; j < log->nfactor; j++)
    itmax = log->step[j].solver.iters > itmax ? log->step[j].solver.iters
            : itmax;
  lac_strategy_get_counts (nw->strategy, &c);
  if ((status = lac_summary_add (sum, "load_steps", "%zu", log->nfactor))
      || (status = lac_summary_add (sum, "max_iterations_per_step", "%d",
                                    itmax))
      || (status = lac_summary_add (sum, "factorizations", "%d",
                                    c.factorizations)))
    return status;
  return lac_run_steplog_summary (log, dim, sum);
}
