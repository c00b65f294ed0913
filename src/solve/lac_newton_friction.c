/* lac_newton_friction.c -- the friction law's part of the loop of
 *                          Algorithm 1 (see lac_newton_friction.h)
 *                                 [LAC Alg. 1 with friction; chapter 15]
 *
 * Steps 2 and 4 of the loop (solve/lac_newton.c) for a model with
 * tangential columns: the status of each macro-element (open, stick,
 * slip) from lac_friction_status, the equations of its slot from
 * lac_friction_rows, the check that friction holds the bodies held by
 * contact alone, the slip measured from the last converged loop, and the
 * held start with sticking columns.
 */
#include "solve/lac_newton_friction.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_status.h"
#include "solve/lac_complementarity.h"
#include "solve/lac_friction.h"
#include "solve/lac_newton_internal.h"
#include "solve/lac_rows.h"

/* The slip of column i since the last converged loop (ds, ntan), and the
 * scale of the terms it was computed from. */
static double
friction_slip (const lac_newton *s, size_t i, double *ds)
{
  const lac_model_point *p = &s->pt;
  size_t nt = (size_t) s->ntan, m = lac_model_slot (p, i);
  double sc = 0;
  for (size_t b = 0; b < nt; b++)
    {
      size_t c = i * nt + b;
      ds[b] = p->slip[c] - s->slip_conv[m * nt + b];
      sc += fabs (p->slip[c]) + fabs (s->slip_conv[m * nt + b]);
      for (int q = p->Ct->p[c]; q < p->Ct->p[c + 1]; q++)
        sc += fabs (p->Ct->x[q] * s->U[p->Ct->i[q]]);
    }
  return sc;
}

/* Column i's slot at the iterate, for lac_friction.h (ds: ntan). */
static lac_friction_slot
friction_slot (const lac_newton *s, size_t i, double lmax, double *ds)
{
  const lac_model_point *p = &s->pt;
  size_t m = lac_model_slot (p, i), nt = (size_t) s->ntan;
  double sc = friction_slip (s, i, ds);
  return (lac_friction_slot) { s->ntan, p->mu[i], lac_newton_rho (s, i),
                               s->lambda[m], s->lambda_t + m * nt, p->d[i],
                               ds, lmax, lac_newton_gap_scale (s, i), sc };
}

/* max |lambda| over the normal and tangential multipliers. */
double
lac_newton_friction_lmax (const lac_newton *s)
{
  return fmax (lac_complementarity_lmax (s->nslot, s->lambda),
               lac_complementarity_lmax (s->nslot * (size_t) s->ntan,
                                         s->lambda_t));
}

/* Step 2 with friction: the status of column i's slot (its slip
 * direction into w->dir_new; the direction it had where the status is not
 * slip, so that a slot the cycle guard keeps slipping keeps its e).  At
 * the start of a load step (iteration 0) ds = 0 and a slot that slipped
 * is at the limit, |xi| = b: it starts from stick, the step's elastic
 * predictor (kept slipping, a step that unloads would first reverse its
 * whole slip, and stick and slip alternate for ever). */
char
lac_newton_friction_want (lac_newton *s, size_t i, double lmax)
{
  size_t m = lac_model_slot (&s->pt, i), nt = (size_t) s->ntan;
  double ds[2];
  lac_friction_slot x = friction_slot (s, i, lmax, ds);
  int current = s->active[m];
  if (s->w->it == 0 && current == LAC_FRICTION_SLIP)
    current = LAC_FRICTION_STICK;     /* a load step starts from stick */
  memcpy (s->w->dir_new + m * nt, s->dir + m * nt, nt * sizeof *s->dir);
  return (char) lac_friction_status (&x, s->first, current,
                                     s->w->dir_new + m * nt);
}

/* The slots that slip on in a direction turned by more than
 * LAC_FRICTION_TURN (a change of status); the directions taken; lambda_t
 * of the inactive slots 0. */
size_t
lac_newton_friction_turns (lac_newton *s)
{
  size_t nt = (size_t) s->ntan, turns = 0;
  for (size_t m = 0; m < s->nslot; m++)
    {
      double *e = s->dir + m * nt, *e1 = s->w->dir_new + m * nt, t = 0;
      int slip = s->w->want[m] == LAC_FRICTION_SLIP;
      for (size_t b = 0; slip && b < nt; b++)
        t += (e1[b] - e[b]) * (e1[b] - e[b]);
      turns += slip && s->active[m] == LAC_FRICTION_SLIP
               && sqrt (t) > LAC_FRICTION_TURN;
      for (size_t b = 0; slip && b < nt; b++)
        e[b] = e1[b];
      for (size_t b = 0; !s->w->want[m] && b < nt; b++)
        s->lambda_t[m * nt + b] = 0;
    }
  return turns;
}

/* The bodies held by contact alone must be held by the normal
 * multipliers in contact and the tangential ones that stick: where every
 * macro-element that touches a body slips, friction cannot stop it, and
 * there is no static solution. */
static int
friction_held (const lac_newton *s, const lac_contact_system *sys)
{
  const lac_model_point *p = &s->pt;
  size_t q = 1 + (size_t) s->ntan, nslip = 0;
  char *held = s->w->ffree;              /* reused: set again by the caller */
  for (size_t i = 0; i < p->k; i++)
    {
      int st = s->active[lac_model_slot (p, i)];
      nslip += st == LAC_FRICTION_SLIP;
      for (size_t b = 0; b < q; b++)
        held[i * q + b] = b == 0 ? st != LAC_FRICTION_INACTIVE
                                 : st == LAC_FRICTION_STICK;
    }
  if (sys->nfree == 0 || nslip == 0 || !lac_system_check_held (sys, held))
    return LAC_SUCCESS;
  char msg[400];
  snprintf (msg, sizeof msg, "%s", lac_error_message ());
  LAC_ERROR (LAC_ESING, "no static solution with friction: %s; friction "
             "holds it only where the contact sticks, and every "
             "macro-element in contact with it slips (%zu): the tangential "
             "load exceeds mu times the normal force", msg, nslip);
}

/* Step 4 with friction: the equations of every column's slot from its
 * status (lac_friction_rows), solved by the strategy (solve_rows), or by
 * GMRES preconditioned by its symmetric solve (solve/lac_rows.h); lambda
 * into w->klam (normal) and s->lambda_t. */
int
lac_newton_friction_solve (lac_newton *s, const lac_contact_system *sys)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  size_t nt = (size_t) s->ntan, q = 1 + nt;
  double lmax = lac_newton_friction_lmax (s);
  int status = friction_held (s, sys);
  if (status)
    return status;
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      double an = 0, gt[2], at[2], ds[2];
      lac_friction_slot x = friction_slot (s, i, lmax, ds);
      for (int c = p->C->p[i]; c < p->C->p[i + 1]; c++)
        an += p->C->x[c] * s->U[p->C->i[c]];           /* c_n^T U */
      for (size_t b = 0; b < nt; b++)
        {
          gt[b] = s->slip_conv[m * nt + b] - p->sfix[i * nt + b];
          at[b] = p->slip[i * nt + b] - p->sfix[i * nt + b];  /* c_t^T U */
        }
      lac_friction_rows (s->active[m], &x, s->dir + m * nt, p->d[i] + an, gt,
                         an, at, w->fP + i * q * q, w->fQ + i * q * q,
                         w->fr + i * q);
      w->fl[i * q] = s->lambda[m];
      for (size_t b = 0; b < q; b++)
        {
          w->ffree[i * q + b] = s->active[m] != LAC_FRICTION_INACTIVE;
          if (b > 0)
            w->fl[i * q + b] = s->lambda_t[m * nt + b - 1];
        }
    }
  lac_contact_rows R = { (int) q, w->fP, w->fQ, w->fr, w->ffree };
  if (lac_strategy_solves_rows (lac_strategy_kind_of (s->strategy)))
    status = lac_strategy_solve_rows (s->strategy, &R, w->x, w->fl);
  else                  /* GMRES, preconditioned by the symmetric solve */
    status = lac_rows_gmres (s->strategy, sys, &R, w->x, w->fl,
                             &w->rows_its, &w->rows_berr);
  for (size_t i = 0; !status && i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      w->klam[i] = w->fl[i * q];
      for (size_t b = 0; b < nt; b++)
        s->lambda_t[m * nt + b] = w->fl[i * q + 1 + b];
    }
  return status;
}

/* A loop converged: its tangential jumps are where the next one's slip is
 * measured from. */
void
lac_newton_friction_converged (lac_newton *s)
{
  const lac_model_point *p = &s->pt;
  size_t nt = (size_t) s->ntan;
  for (size_t i = 0; i < p->k; i++)
    for (size_t b = 0; b < nt; b++)
      s->slip_conv[lac_model_slot (p, i) * nt + b] = p->slip[i * nt + b];
}

static int
cmp_gap (const void *a, const void *b)
{
  const double *x = a, *y = b;                 /* pairs (gap, column) */
  return x[0] < y[0] ? -1 : x[0] > y[0] ? 1 : 0;
}

/* The held start with friction (lac_newton_rules.h): when the first
 * statuses do not hold the bodies held by contact alone, the columns of
 * the m smallest gaps stick, m = 1, 2, 4, ... until the normal and
 * tangential multipliers of the sticking ones hold them. */
void
lac_newton_friction_held_start (lac_newton *s, const lac_contact_system *sys)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  size_t k = p->k, q = 1 + (size_t) s->ntan, m = 1;
  char *held = w->ffree;                 /* reused: set again by the solve */
  for (size_t i = 0; i < k * q; i++)
    held[i] = w->kact[i / q] != LAC_FRICTION_INACTIVE
              && (i % q == 0 || w->kact[i / q] == LAC_FRICTION_STICK);
  if (!lac_system_check_held (sys, held))
    return;
  lac_error_clear ();
  for (size_t i = 0; i < k; i++)
    {
      w->pair[2 * i] = p->d[i];
      w->pair[2 * i + 1] = (double) i;
    }
  qsort (w->pair, k, 2 * sizeof *w->pair, cmp_gap);
  for (;; m = 2 * m < k ? 2 * m : k)
    {
      for (size_t j = 0; j < m; j++)
        {
          size_t i = (size_t) w->pair[2 * j + 1];
          w->kact[i] = LAC_FRICTION_STICK;
          s->active[lac_model_slot (p, i)] = LAC_FRICTION_STICK;
          memset (held + i * q, 1, q);
        }
      int ok = !lac_system_check_held (sys, held);
      lac_error_clear ();
      if (ok || m == k)
        break;
    }
  s->held_start = m;
  s->restarted = 1;
}
