/* lac_loadstep.c -- one load step: sub-steps, cuts, growth back
 *                   (see lac_loadstep.h)           [LAC §4.5, Alg. 1; §5.4]
 */
#include "solve/lac_loadstep.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

static int
push_step (lac_nl *s, const lac_nl_step *r)
{
  if (lac_grow (&s->steps, s->nsteps + 1, &s->capsteps, sizeof *s->steps,
                32))
    LAC_ERROR (LAC_ENOMEM, "step records");
  s->steps[s->nsteps++] = *r;
  return LAC_SUCCESS;
}

static void
save_state (lac_nl *s)
{
  memcpy (s->U_save, s->U, s->ndof * sizeof *s->U);
  memcpy (s->lambda_save, s->lambda, s->nmacro * sizeof *s->lambda);
  memcpy (s->active_save, s->active, s->nmacro);
  s->ls.first_save = s->first;
}

static void
restore_state (lac_nl *s)
{
  memcpy (s->U, s->U_save, s->ndof * sizeof *s->U);
  memcpy (s->lambda, s->lambda_save, s->nmacro * sizeof *s->lambda);
  memcpy (s->active, s->active_save, s->nmacro);
  s->first = s->ls.first_save;
}

int
lac_nl_step_begin (lac_nl *s, double t)
{
  if (!s || !(t > s->t_prev))
    LAC_ERROR (LAC_EINVAL, "load factor %g: not beyond the last converged "
               "one (%g)", t, s ? s->t_prev : 0.0);
  lac_nl_loadstep *ls = &s->ls;
  memset (ls, 0, sizeof *ls);
  ls->in_step = 1;
  ls->t = t;
  ls->t0 = s->t_prev;
  ls->dt = t - s->t_prev;
  if (s->dt_next > 0 && s->dt_next < ls->dt)
    ls->dt = s->dt_next;                 /* after a cut step: its pace */
  ls->start = lac_seconds ();
  ls->time0[0] = s->time_assemble;
  ls->time0[1] = s->time_pairing;
  ls->time0[2] = s->time_solve;
  ls->time0[3] = s->time_factor;
  s->cut_msg[0] = '\0';
  return LAC_SUCCESS;
}

/* The predictor: U and lambda extrapolated linearly from the last two
 * converged states, (U - U_old) (tt - t_prev) / (t_prev - t_old) added. */
static void
predict (lac_nl *s, double tt)
{
  double r = (tt - s->t_prev) / s->dt_old;
  if (!s->opts.predict || !(s->dt_old > 0))
    return;
  for (size_t j = 0; j < s->ndof; j++)
    s->U[j] += r * (s->U[j] - s->U_old[j]);
  for (size_t m = 0; m < s->nmacro; m++)
    if (s->active[m])
      s->lambda[m] = fmin (0.0, s->lambda[m]
                                + r * (s->lambda[m] - s->lambda_old[m]));
  s->predicted = 1;
}

/* Begin the next sub-step: from t_prev by dt (the last one ends at t). */
static void
sub_begin (lac_nl *s)
{
  lac_nl_loadstep *ls = &s->ls;
  double tt = s->t_prev + ls->dt;
  if (tt >= ls->t - 1e-12 * (ls->t - ls->t0))
    tt = ls->t;
  save_state (s);
  lac_nl_begin (s, tt);
  predict (s, tt);
  ls->in_sub = 1;
}

/* A sub-step converged: 1 if it was the last. */
static int
sub_done (lac_nl *s)
{
  lac_nl_loadstep *ls = &s->ls;
  double len = s->t - s->t_prev;
  memcpy (s->U_old, s->U_save, s->ndof * sizeof *s->U_old);  /* at t_prev */
  memcpy (s->lambda_old, s->lambda_save, s->nmacro * sizeof *s->lambda_old);
  s->dt_old = len;
  if (ls->substeps && len > ls->dt_last * (1 + 1e-12))
    ls->grown++;                       /* longer than the one before */
  ls->dt_min = ls->substeps ? fmin (ls->dt_min, len) : len;
  ls->dt_last = len;
  s->t_prev = s->t;
  ls->substeps++;
  ls->in_sub = 0;
  if (s->it <= LAC_FAST_ITERS)
    ls->dt *= 2;                                      /* growth back */
  return s->t_prev >= ls->t;
}

/* A sub-step failed with `status`: 1 if it is cut (state restored, dt
 * halved), 0 if no cut is left or the failure is not one to cut. */
static int
cut (lac_nl *s, int status)
{
  lac_nl_loadstep *ls = &s->ls;
  double dtmin = (ls->t - ls->t0) / ldexp (1.0, s->opts.max_cuts);
  if ((status != LAC_EMAXITER && status != LAC_ESING)
      || s->opts.max_cuts < 0 || ls->dt <= dtmin * (1 + 1e-12)
      || ls->cuts >= 4 * s->opts.max_cuts)
    return 0;
  snprintf (s->cut_msg, sizeof s->cut_msg, "%s", lac_error_message ());
  lac_error_clear ();
  restore_state (s);
  ls->dt *= 0.5;
  ls->cuts++;
  ls->in_sub = 0;
  return 1;
}

/* The step's record, appended; returns status (or push_step's). */
static int
finish (lac_nl *s, int status)
{
  lac_nl_loadstep *ls = &s->ls;
  lac_nl_step rec = { 0 };
  rec.t = status == LAC_SUCCESS ? ls->t : s->t_prev;
  rec.iters = ls->iters;
  rec.cuts = ls->cuts;
  rec.substeps = ls->substeps;
  rec.dt_min = ls->dt_min;
  rec.grown = ls->grown;
  rec.residual = s->residual;
  rec.k = s->contact ? s->contact->k : 0;
  rec.nactive = lac_nl_nactive (s);
  rec.status = status;
  rec.seconds = lac_seconds () - ls->start;
  rec.time_assemble = s->time_assemble - ls->time0[0];
  rec.time_pairing = s->time_pairing - ls->time0[1];
  rec.time_solve = s->time_solve - ls->time0[2];
  rec.time_factor = s->time_factor - ls->time0[3];
  s->dt_next = ls->cuts ? ls->dt : 0;
  ls->in_step = 0;
  int st2 = push_step (s, &rec);
  return status ? status : st2;
}

int
lac_nl_step_iterate (lac_nl *s)
{
  lac_nl_loadstep *ls = &s->ls;
  if (!ls->in_step)
    LAC_ERROR (LAC_EINVAL, "no load step begun (lac_nl_step_begin)");
  for (;;)
    {
      if (!ls->in_sub)
        sub_begin (s);
      int status = lac_nl_iterate (s);
      if (status == LAC_CONTINUE)
        {
          ls->iters++;
          s->iters[s->niters - 1].cuts = ls->cuts;
          return LAC_CONTINUE;
        }
      if (status == LAC_SUCCESS)
        {
          if (sub_done (s))
            return finish (s, LAC_SUCCESS);
          continue;
        }
      if (!cut (s, status))
        return finish (s, status);
    }
}

int
lac_nl_step_to (lac_nl *s, double t)
{
  int status = lac_nl_step_begin (s, t);
  while (!status && (status = lac_nl_step_iterate (s)) == LAC_CONTINUE)
    status = LAC_SUCCESS;
  return status;
}
