/* lac_loadstep.c -- load steps: sub-steps, cuts, growth back
 *                   (see lac_loadstep.h)           [LAC §4.5, Alg. 1; §5.4]
 */
#include "solve/lac_loadstep.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

void
lac_loadstep_free (lac_loadstep *ls)
{
  if (!ls)
    return;
  lac_newton_free (ls->loop);
  lac_free (ls->steps);
  lac_free (ls->U_old);
  lac_free (ls->lambda_old);
  lac_free (ls);
}

lac_loadstep *
lac_loadstep_alloc (lac_nl *model, const lac_nl_opts *opts)
{
  lac_nl_opts o;
  lac_newton_opts lo;
  lac_contact_model m;
  if (opts)
    o = *opts;
  else
    lac_nl_opts_init (&o);
  lac_loadstep *ls = lac_calloc (1, sizeof *ls);
  if (!ls)
    LAC_ERROR_NULL (LAC_ENOMEM, "load steps");
  ls->model = model;
  ls->max_cuts = o.max_cuts == 0 ? 6 : o.max_cuts;
  ls->predict = o.predict;
  lac_newton_opts_init (&lo);
  lo.kind = o.kind;
  lo.maxit = o.maxit > 0 ? o.maxit : LAC_NL_MAXIT;
  lo.tol = o.tol > 0 ? o.tol : LAC_NL_TOL;
  lo.rho = o.rho;
  lo.frozen = o.frozen;
  lo.off = o.off;
  lac_nl_model (model, &m);
  size_t n = m.n ? m.n : 1, ns = m.nslot ? m.nslot : 1;
  if (!(ls->loop = lac_newton_alloc (&m, &lo))
      || !(ls->U_old = lac_calloc (n, sizeof (double)))
      || !(ls->lambda_old = lac_calloc (ns, sizeof (double))))
    {
      lac_loadstep_free (ls);
      LAC_ERROR_NULL (LAC_ENOMEM, "load steps of %zu dofs", m.n);
    }
  return ls;
}

static int
push_step (lac_loadstep *ls, const lac_nl_step *r)
{
  if (lac_grow (&ls->steps, ls->nsteps + 1, &ls->capsteps,
                sizeof *ls->steps, 32))
    LAC_ERROR (LAC_ENOMEM, "step records");
  ls->steps[ls->nsteps++] = *r;
  return LAC_SUCCESS;
}

int
lac_loadstep_begin (lac_loadstep *ls, double t)
{
  if (!(t > ls->t_prev))
    LAC_ERROR (LAC_EINVAL, "load factor %g: not beyond the last converged "
               "one (%g)", t, ls->t_prev);
  ls->in_step = 1;
  ls->in_sub = 0;
  ls->t = t;
  ls->t0 = ls->t_prev;
  ls->dt = t - ls->t_prev;
  if (ls->dt_next > 0 && ls->dt_next < ls->dt)
    ls->dt = ls->dt_next;                 /* after a cut step: its pace */
  ls->iters = ls->cuts = ls->substeps = ls->grown = 0;
  ls->dt_min = ls->dt_last = 0;
  ls->start = lac_seconds ();
  ls->time0[0] = ls->model->time_assemble;
  ls->time0[1] = ls->model->time_pairing;
  ls->time0[2] = ls->loop->time_solve;
  ls->time0[3] = ls->loop->time_factor;
  ls->cut_msg[0] = '\0';
  return LAC_SUCCESS;
}

/* The predictor: U and lambda extrapolated linearly from the last two
 * converged states, (U - U_old) (tt - t_prev) / (t_prev - t_old) added. */
static void
predict (lac_loadstep *ls, double tt)
{
  lac_newton *s = ls->loop;
  double r = (tt - ls->t_prev) / ls->dt_old;
  if (!ls->predict || !(ls->dt_old > 0))
    return;
  for (size_t j = 0; j < s->n; j++)
    s->U[j] += r * (s->U[j] - ls->U_old[j]);
  for (size_t m = 0; m < s->nslot; m++)
    if (s->active[m])
      s->lambda[m] = fmin (0.0, s->lambda[m]
                                + r * (s->lambda[m] - ls->lambda_old[m]));
  s->predicted = 1;
}

/* Begin the next sub-step: from t_prev by dt (the last one ends at t). */
static void
sub_begin (lac_loadstep *ls)
{
  double tt = ls->t_prev + ls->dt;
  if (tt >= ls->t - 1e-12 * (ls->t - ls->t0))
    tt = ls->t;
  lac_nl_set_load (ls->model, tt);
  lac_newton_begin (ls->loop);      /* the state to go back to on a cut */
  predict (ls, tt);
  ls->in_sub = 1;
}

/* A sub-step converged: 1 if it was the last. */
static int
sub_done (lac_loadstep *ls)
{
  const lac_newton *s = ls->loop;
  double len = ls->model->t - ls->t_prev;
  memcpy (ls->U_old, s->U0, s->n * sizeof *ls->U_old);       /* at t_prev */
  memcpy (ls->lambda_old, s->lambda0, s->nslot * sizeof *ls->lambda_old);
  ls->dt_old = len;
  if (ls->substeps && len > ls->dt_last * (1 + 1e-12))
    ls->grown++;                       /* longer than the one before */
  ls->dt_min = ls->substeps ? fmin (ls->dt_min, len) : len;
  ls->dt_last = len;
  ls->t_prev = ls->model->t;
  ls->substeps++;
  ls->in_sub = 0;
  if (lac_newton_iterations (s) <= LAC_FAST_ITERS)
    ls->dt *= 2;                                      /* growth back */
  return ls->t_prev >= ls->t;
}

/* A sub-step failed with `status`: 1 if it is cut (state restored, dt
 * halved), 0 if no cut is left or the failure is not one to cut. */
static int
cut (lac_loadstep *ls, int status)
{
  double dtmin = (ls->t - ls->t0) / ldexp (1.0, ls->max_cuts);
  if ((status != LAC_EMAXITER && status != LAC_ESING)
      || ls->max_cuts < 0 || ls->dt <= dtmin * (1 + 1e-12)
      || ls->cuts >= 4 * ls->max_cuts)
    return 0;
  snprintf (ls->cut_msg, sizeof ls->cut_msg, "%s", lac_error_message ());
  lac_error_clear ();
  lac_newton_restart (ls->loop);
  ls->dt *= 0.5;
  ls->cuts++;
  ls->in_sub = 0;
  return 1;
}

/* The step's record, appended; returns status (or push_step's). */
static int
finish (lac_loadstep *ls, int status)
{
  const lac_newton *s = ls->loop;
  const lac_nl *m = ls->model;
  lac_nl_step rec = { 0 };
  rec.t = status == LAC_SUCCESS ? ls->t : ls->t_prev;
  rec.iters = ls->iters;
  rec.cuts = ls->cuts;
  rec.substeps = ls->substeps;
  rec.dt_min = ls->dt_min;
  rec.grown = ls->grown;
  rec.residual = s->residual;
  rec.k = s->pt.k;
  rec.nactive = lac_newton_nactive (s);
  rec.status = status;
  rec.seconds = lac_seconds () - ls->start;
  rec.time_assemble = m->time_assemble - ls->time0[0];
  rec.time_pairing = m->time_pairing - ls->time0[1];
  rec.time_solve = s->time_solve - ls->time0[2];
  rec.time_factor = s->time_factor - ls->time0[3];
  ls->dt_next = ls->cuts ? ls->dt : 0;
  ls->in_step = 0;
  int st2 = push_step (ls, &rec);
  return status ? status : st2;
}

int
lac_loadstep_iterate (lac_loadstep *ls)
{
  if (!ls->in_step)
    LAC_ERROR (LAC_EINVAL, "no load step begun (lac_loadstep_begin)");
  for (;;)
    {
      if (!ls->in_sub)
        sub_begin (ls);
      int status = lac_newton_iterate (ls->loop);
      if (status == LAC_CONTINUE)
        {
          lac_newton_record *r = &ls->loop->hist[ls->loop->nhist - 1];
          ls->iters++;
          r->step = (int) ls->nsteps + 1;
          r->t = ls->model->t;
          r->cuts = ls->cuts;
          return LAC_CONTINUE;
        }
      if (status == LAC_SUCCESS)
        {
          if (sub_done (ls))
            return finish (ls, LAC_SUCCESS);
          continue;
        }
      if (!cut (ls, status))
        return finish (ls, status);
    }
}

int
lac_loadstep_to (lac_loadstep *ls, double t)
{
  int status = lac_loadstep_begin (ls, t);
  while (!status && (status = lac_loadstep_iterate (ls)) == LAC_CONTINUE)
    status = LAC_SUCCESS;
  return status;
}
