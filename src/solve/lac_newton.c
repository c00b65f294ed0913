/* lac_newton.c -- Algorithm 1, one loop for every contact model
 *                 (see lac_newton.h)             [LAC §4.5, Alg. 1, (18)]
 *
 * The file follows one iteration: evaluate (with the line search), the
 * statuses (with the first-contact rule and the cycle guard), the test
 * (with the check of the macro-elements without a multiplier), the solve
 * (with the held start and the consistent step).
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
#include "base/lac_vec.h"
#include "solve/lac_complementarity.h"
#include "solve/lac_linear_model.h"

#define ETA_FIRST 1e-5    /* accuracy of the first consistent step of a loop */
#define ETA_FACTOR 1e-2   /* then this times the residual of step 3, ...    */
#define ETA_MAX 1e-3      /*   at most this,                                */
#define ETA_MIN 1e-12     /*   at least this                                */
#define LAZY_K 1e-5       /* the tangent left out of an evaluation after a
                             step on settled statuses from this residual:
                             quadratic convergence makes it the last     */

struct lac_newton_work  /* (a model has at most one column per slot) */
{
  double *klam;          /* nslot: lambda per column, the unknown of (*)   */
  char *kact;            /* nslot: statuses per column                     */
  double *klin;          /* nslot: lambda of the linearization point       */
  double *x;             /* n: the solution of (*) (U or dU)               */
  double *dU;            /* n: the last step                               */
  char *active0;         /* nslot: the statuses the loop began with        */
  int first0;            /* and s->first then                             */
  double *lam_step;      /* nslot: lambda before the last solve           */
  double *lam_lin;       /* nslot: lambda before the statuses of step 2   */
  char *want;            /* nslot: statuses asked for by the rule         */
  long *col;             /* nslot: the column of the slot (-1: none)      */
  double *pair;          /* 2 nslot: (value, index) to sort                */
  unsigned long long *seen;  /* checksums of the statuses of the loop     */
  size_t nseen, capseen;
  int it;                /* solves in the loop                            */
  int converged;
  size_t nactive1;       /* active multipliers of the loop's first solve  */
  int settled;           /* the last solve changed no status              */
  double res_solved;     /* the residual it started from                  */
  double merit, merit_best, alpha;
  int backtracks;
  int strategy_set;      /* the strategy holds a factorization            */
  int gmres_last;        /* GMRES iterations since the last one           */
  lac_linear_model *lin; /* owned by lac_newton_solve_system               */
};

void
lac_newton_opts_init (lac_newton_opts *o)
{
  memset (o, 0, sizeof *o);
  o->kind = LAC_STRATEGY_AUTO;
  o->maxit = 50;
  o->tol = 1e-10;
  o->pen_tol = 1e-2;
}

/* ---- workspace ---------------------------------------------------------- */

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
  lac_free (w->pair);
  lac_free (w->seen);
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
  lac_free (s->hist);
  lac_strategy_free (s->strategy);
  work_free (s->w);
  lac_free (s);
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
  if (s->opts.maxit <= 0)
    s->opts.maxit = 50;
  if (!(s->opts.tol > 0))
    s->opts.tol = 1e-10;
  if (s->opts.pen_tol == 0)
    s->opts.pen_tol = 1e-2;
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
           && (w->pair = lac_calloc (2 * ns, sizeof *w->pair));
  for (size_t j = 0; j < sizeof per_dof / sizeof *per_dof; j++)
    ok = ok && (*per_dof[j] = lac_calloc (n, sizeof (double)));
  for (size_t j = 0; j < sizeof per_slot / sizeof *per_slot; j++)
    ok = ok && (*per_slot[j] = lac_calloc (ns, sizeof (double)));
  if (!ok)
    {
      lac_newton_free (s);
      LAC_ERROR_NULL (LAC_ENOMEM, "workspace of Algorithm 1 for %zu dofs "
                      "and %zu macro-elements", m->n, m->nslot);
    }
  return s;
}

size_t
lac_newton_nactive (const lac_newton *s)
{
  size_t m = 0;
  for (size_t i = 0; i < s->nslot; i++)
    m += s->active[i] != 0;
  return m;
}

size_t
lac_newton_iterations (const lac_newton *s)
{
  return s->nhist - s->nhist0;
}

static int
push_record (lac_newton *s, const lac_newton_record *r)
{
  if (lac_grow (&s->hist, s->nhist + 1, &s->caphist, sizeof *s->hist, 16))
    LAC_ERROR (LAC_ENOMEM, "iteration records");
  s->hist[s->nhist++] = *r;
  return LAC_SUCCESS;
}

/* ---- the model's columns: slots, units ---------------------------------- */

static size_t
slot_of (const lac_model_point *p, size_t i)
{
  return p->slot ? p->slot[i] : i;
}

/* h_i, the size of T^m cap Gamma_C of column i as a length. */
static double
h_of (const lac_newton *s, size_t i)
{
  const lac_model_point *p = &s->pt;
  if (!p->size)
    return 1.0;
  return s->model.dim == 3 ? sqrt (p->size[i]) : p->size[i];
}

static double
area_of (const lac_newton *s, size_t i)
{
  return s->pt.area ? s->pt.area[i] : 1.0;
}

/* rho_i = E / (h_i |T^m cap Gamma_C|) (lac_contact_model.h), unless the
 * options or the model give it. */
static double
rho_of (const lac_newton *s, size_t i)
{
  double a = area_of (s, i) * h_of (s, i);
  if (s->opts.rho > 0)
    return s->opts.rho;
  if (s->pt.rho)
    return s->pt.rho[i];
  return a > 0 ? s->model.E / a : 1.0;
}

/* The scale of what d_i was computed from, |d_i| + sum |C_ri U_r|: d_i
 * is zero when it is below 1e-12 of it (lac_snap, base/lac_vec.h; the
 * mean gaps of the model were snapped at their assembly already, with
 * the scale of the coordinates). */
static double
gap_scale (const lac_newton *s, size_t i)
{
  const lac_csc *C = s->pt.C;
  double sc = fabs (s->pt.d[i]);
  for (int q = C->p[i]; q < C->p[i + 1]; q++)
    sc += fabs (C->x[q] * s->U[C->i[q]]);
  return sc;
}

/* Penetration of column i as a length: -d_i / |C(:,i)|_1 (the mean gap
 * per unit weight of the column; 0 for an empty column). */
static double
penetration (const lac_newton *s, size_t i)
{
  const lac_csc *C = s->pt.C;
  double csum = 0;
  for (int q = C->p[i]; q < C->p[i + 1]; q++)
    csum += fabs (C->x[q]);
  return csum > 0 ? -s->pt.d[i] / csum : 0.0;
}

/* ---- step 1: evaluate, residuals, line search --------------------------- */

/* Step 3's two residuals at the last evaluation, with lambda of the slots:
 * |r + C lambda| on the free dofs over max(force scale, |C lambda|), and
 * max |d_i| / (h_i |T^m cap Gamma_C|) over the active columns. */
static void
residuals (lac_newton *s, double *res, double *gres)
{
  const lac_model_point *p = &s->pt;
  double *w = s->w->x, nr = 0, ncl = 0, g = 0;
  memcpy (w, p->r, s->n * sizeof *w);
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = slot_of (p, i);
      double lam = s->lambda[m], a = area_of (s, i) * h_of (s, i);
      for (int q = p->C->p[i]; q < p->C->p[i + 1]; q++)
        {
          double v = p->C->x[q] * lam;
          w[p->C->i[q]] += v;                          /* + C lambda */
          ncl += v * v;
        }
      if (s->active[m] && a > 0)
        g = fmax (g, fabs (p->d[i]) / a);
    }
  for (size_t j = 0; j < s->n; j++)
    if (!p->fixed || !p->fixed[j])
      nr += w[j] * w[j];
  double scale = fmax (p->fscale, sqrt (ncl));
  *res = scale > 0 ? sqrt (nr) / scale : sqrt (nr);
  *gres = g;
}

/* Back to U_old + alpha dU and halfway back for lambda, alpha halved (the
 * last solve gave U_old + 2 alpha dU). */
static void
backtrack (lac_newton *s)
{
  lac_newton_work *w = s->w;
  w->alpha *= 0.5;
  for (size_t j = 0; j < s->n; j++)
    s->U[j] -= w->alpha * w->dU[j];
  for (size_t m = 0; m < s->nslot; m++)
    s->lambda[m] = w->lam_step[m] + 0.5 * (s->lambda[m] - w->lam_step[m]);
  lac_error_clear ();
  w->backtracks++;
}

/* Step 1 at U with the line search of a nonlinear model: a step that
 * turns a cell inside out (LAC_ESING), or, after a solve on settled
 * statuses, does not lower max(residual, gap residual), is halved up to
 * LAC_NEWTON_HALVINGS times, then taken as it is (or its error returned).
 * The tangent is left to the solve when the last step was made on
 * settled statuses from a residual below LAZY_K. */
static int
evaluate (lac_newton *s, lac_newton_record *rec)
{
  lac_newton_work *w = s->w;
  const lac_contact_model_type *t = s->model.type;
  int tangent = !(w->it > 0 && w->settled && w->res_solved <= LAZY_K);
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
      int worse = t->nonlinear
                  && ((status == LAC_ESING && w->it >= 1)
                      || (!status && w->it >= 2 && w->settled
                          && !(merit < w->merit)));
      if (!worse || w->alpha <= 1.0 / (1 << LAC_NEWTON_HALVINGS))
        {
          if (!status)
            w->merit = merit;
          return status;
        }
      backtrack (s);
    }
}

/* ---- step 2: the statuses ----------------------------------------------- */

static unsigned long long
status_hash (const char *active, size_t k)
{
  unsigned long long h = 1469598103934665603ull;       /* FNV-1a */
  for (size_t i = 0; i < k; i++)
    h = (h ^ (unsigned long long) (active[i] != 0)) * 1099511628211ull;
  return h;
}

static int
seen_before (const lac_newton_work *w, unsigned long long h)
{
  for (size_t j = 0; j < w->nseen; j++)
    if (w->seen[j] == h)
      return 1;
  return 0;
}

static int
remember (lac_newton *s)
{
  lac_newton_work *w = s->w;
  if (lac_grow (&w->seen, w->nseen + 1, &w->capseen, sizeof *w->seen, 16))
    LAC_ERROR (LAC_ENOMEM, "status checksums");
  w->seen[w->nseen++] = status_hash (s->active, s->nslot);
  return LAC_SUCCESS;
}

static int
cmp_down (const void *a, const void *b)
{
  const double *x = a, *y = b;                 /* pairs (value, index) */
  return x[0] < y[0] ? 1 : x[0] > y[0] ? -1 : 0;
}

/* The first contact (lac_newton.h): of the elements switched on, only
 * those that penetrate by at least frac times the deepest stay on. */
static void
first_contact (const lac_newton *s, char *want)
{
  const lac_model_point *p = &s->pt;
  double frac = s->held_start ? LAC_NEWTON_HELD_CONTACT
                              : LAC_NEWTON_FIRST_CONTACT, pmax = 0;
  for (size_t i = 0; i < p->k; i++)
    if (want[slot_of (p, i)] && !s->active[slot_of (p, i)])
      pmax = fmax (pmax, penetration (s, i));
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = slot_of (p, i);
      if (want[m] && !s->active[m] && penetration (s, i) < frac * pmax)
        want[m] = 0;
    }
}

/* The cycle guard: the changes of want (ranked by |A_i| in pair[], nch of
 * them) that lead to statuses not tried yet: the most violated half, a
 * quarter, ..., one.  Returns the number kept. */
static size_t
damp (const lac_newton *s, char *want, double *pair, size_t nch)
{
  qsort (pair, nch, 2 * sizeof *pair, cmp_down);
  for (size_t keep = nch / 2 > 0 ? nch / 2 : 1;; keep = keep / 2 > 0
       ? keep / 2 : 1)
    {
      memcpy (want, s->active, s->nslot);
      for (size_t c = 0; c < keep; c++)
        want[(size_t) pair[2 * c + 1]] ^= 1;
      if (keep == 1 || !seen_before (s->w, status_hash (want, s->nslot)))
        return keep;
    }
}

/* Step 2 [Alg. 1, lines 26-33; 2-8 in the first iteration of a run]:
 * the statuses of the slots from lambda and the mean gaps of the
 * evaluation; a slot without a column is inactive (lambda = 0).  The
 * changes are ranked by |A_i| for the cycle guard (a slot that lost its
 * column first).  Returns the number of changes. */
static size_t
update_status (lac_newton *s, lac_newton_record *rec)
{
  const lac_model_point *p = &s->pt;
  lac_newton_work *w = s->w;
  double lmax = lac_complementarity_lmax (s->nslot, s->lambda);
  char *want = w->want;
  size_t nch = 0;
  memset (want, 0, s->nslot);
  memset (s->d, 0, s->nslot * sizeof *s->d);
  for (size_t m = 0; m < s->nslot; m++)
    w->col[m] = -1;
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = slot_of (p, i);
      double sc = gap_scale (s, i);
      w->col[m] = (long) i;
      s->d[m] = p->d[i];
      want[m] = s->first ? lac_snap (p->d[i], sc) <= 0
                : (char) lac_complementarity_active (s->lambda[m], p->d[i],
                                                     rho_of (s, i), lmax,
                                                     sc);
      rec->max_penetration = fmax (rec->max_penetration, penetration (s, i));
    }
  if (w->it == 1 && (w->nactive1 == 0 || s->held_start > 0))
    first_contact (s, want);
  for (size_t m = 0; m < s->nslot; m++)        /* the changes, ranked */
    if (want[m] != s->active[m])
      {
        long i = w->col[m];                    /* a column lost: first */
        w->pair[2 * nch] = i < 0 ? HUGE_VAL : lac_complementarity_residual
          (s->lambda[m], p->d[i], rho_of (s, (size_t) i), lmax,
           gap_scale (s, (size_t) i));
        w->pair[2 * nch++ + 1] = (double) m;
      }
  if (nch > 0 && seen_before (w, status_hash (want, s->nslot)))
    {
      nch = damp (s, want, w->pair, nch);
      rec->damped = 1;
    }
  memcpy (s->active, want, s->nslot);
  for (size_t m = 0; m < s->nslot; m++)
    if (!s->active[m])
      s->lambda[m] = 0;
  return nch;
}

/* ---- step 3: no silent penetration --------------------------------------- */

/* An active column that lost part of its surface to failed projections:
 * its C and G miss that part, the pressure is wrong. */
static int
check_lost (const lac_newton *s)
{
  const lac_model_point *p = &s->pt;
  for (size_t i = 0; p->lost && i < p->k; i++)
    {
      size_t m = slot_of (p, i);
      if (s->active[m] && p->lost[i] > 0)
        LAC_ERROR (LAC_EADMISS, "macro-element %zu is in contact, but the "
                   "pairing lost %.3g of its surface (%.3g paired): the "
                   "projections of its points onto the master failed "
                   "there (a master facet folded or far from flat?)", m,
                   p->lost[i], p->size ? p->size[i] : 0.0);
    }
  return LAC_SUCCESS;
}

/* The test passed: are macro-elements without a multiplier inside the
 * master?  Then pair again with a longer reach (*more = 1: the loop goes
 * on with the new columns), or stop with an error. */
static int
check_covered (lac_newton *s, int *more)
{
  const lac_contact_model_type *t = s->model.type;
  lac_contact_uncovered u;
  size_t gained = 0;
  double umax = 0;
  int status;
  *more = 0;
  if ((status = check_lost (s)))
    return status;
  if (s->opts.pen_tol < 0 || !t->uncovered)
    return LAC_SUCCESS;
  if ((status = t->uncovered (s->model.self, s->U, s->opts.pen_tol, &u))
      || u.count == 0)
    return status;
  for (size_t j = 0; j < s->n; j++)
    umax = fmax (umax, fabs (s->U[j]));
  if (t->widen && (status = t->widen (s->model.self, s->U,
                                      2 * umax + u.depth, &gained)))
    return status;
  if (gained > 0)
    {
      s->widened++;
      s->w->merit = HUGE_VAL;          /* a new problem: no line search */
      s->w->settled = 0;
      *more = 1;
      return LAC_SUCCESS;
    }
  LAC_ERROR (LAC_EADMISS, "macro-element %zu at (%.6g, %.6g, %.6g) has no "
             "contact multiplier (%s) and passes %.3g into the master (%.3g "
             "of its size; %zu macro-element%s beyond %g of their size): "
             "refine the master side, or lower [contact] epsilon",
             u.macro, u.x[0], u.x[1], u.x[2], u.paired ? "not admissible"
             : "not paired", u.depth, u.depth / u.h, u.count,
             u.count == 1 ? "" : "s", s->opts.pen_tol);
}

/* ---- step 4: the solve ---------------------------------------------------- */

static int
cmp_up (const void *a, const void *b)
{
  return -cmp_down (a, b);
}

/* The held start (lac_newton.h): the columns of the m smallest gaps, m =
 * 1, 2, 4, ... until the active ones hold every body held by contact
 * alone (all of them if fewer do not). */
static void
hold_start (lac_newton *s, const lac_contact_system *sys)
{
  lac_newton_work *w = s->w;
  size_t k = s->pt.k, m = k < 1 ? k : 1;
  for (size_t i = 0; i < k; i++)
    {
      w->pair[2 * i] = s->pt.d[i];
      w->pair[2 * i + 1] = (double) i;
    }
  qsort (w->pair, k, 2 * sizeof *w->pair, cmp_up);
  for (;; m = 2 * m < k ? 2 * m : k)
    {
      memset (w->kact, 0, k);
      for (size_t j = 0; j < m; j++)
        w->kact[(size_t) w->pair[2 * j + 1]] = 1;
      int held = !lac_system_check_held (sys, w->kact);
      lac_error_clear ();
      if (held || m == k)
        break;
    }
  s->held_start = m;
  s->restarted = 1;
}

/* The frozen system (*) by the strategy, from x, klam; a body held by
 * contact alone that the system did not declare (no N) makes the first
 * solve of a run singular: every multiplier active then, the rule
 * releases those in tension. */
static int
solve_frozen (lac_newton *s, lac_newton_record *rec)
{
  lac_newton_work *w = s->w;
  size_t k = s->pt.k;
  int status = lac_strategy_solve (s->strategy, w->kact, w->x, w->klam);
  if (status == LAC_ESING && s->first && rec->nactive < k)
    {
      lac_error_clear ();
      memset (w->kact, 1, k);
      s->restarted = 1;
      rec->nactive = k;
      status = lac_strategy_solve (s->strategy, w->kact, w->x, w->klam);
    }
  return status;
}

/* Set the strategy on sys (a new tangent), or reset it (only C is new),
 * or leave it.  *lagged: the tangent is new but the factorization of an
 * older one was kept (schur, lac_strategy_reset) as the preconditioner of
 * the consistent step, which then makes the whole step.  A loop starts
 * with a factorization of its own tangent: the one of the step before
 * preconditions the first step of a new load badly (the CI ring: 56
 * Newton iterations and 4 cut steps with it, 39 and none without). */
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
  if (!w->strategy_set || (news == LAC_MODEL_NEW_K
                           && (w->it == 0 || !consistent
                               || w->gmres_last > LAC_NEWTON_LAG)))
    {
      status = lac_strategy_set (s->strategy, sys);
      w->strategy_set = !status;
      w->gmres_last = 0;
      return status;
    }
  if (news == LAC_MODEL_SAME)
    return LAC_SUCCESS;
  status = lac_strategy_reset (s->strategy, sys, &kept);
  *lagged = kept && news == LAC_MODEL_NEW_K;
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
      s->lambda[slot_of (p, i)] = w->kact[i] ? w->klam[i] : 0.0;
      s->active[slot_of (p, i)] = w->kact[i];
    }
  for (size_t j = 0; j < s->n; j++)
    {
      w->dU[j] = s->model.type->nonlinear ? w->x[j] : w->x[j] - s->U[j];
      s->U[j] += w->dU[j];
      nu += s->U[j] * s->U[j];
      ndu += w->dU[j] * w->dU[j];
    }
  rec->du = nu > 0 ? sqrt (ndu / nu) : sqrt (ndu);
  w->alpha = 1;
}

/* Step 4 [Alg. 1, lines 11-23]. */
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
  for (size_t i = 0; i < p->k; i++)
    {
      size_t m = slot_of (p, i);
      w->kact[i] = s->active[m];
      w->klam[i] = s->active[m] ? s->lambda[m] : 0.0;
      w->klin[i] = w->lam_lin[m];
    }
  if (w->it == 0 && p->k > 0 && sys->nfree > 0
      && lac_system_check_held (sys, w->kact))
    {
      lac_error_clear ();
      hold_start (s, sys);
    }
  rec->nactive = 0;
  for (size_t i = 0; i < p->k; i++)
    rec->nactive += w->kact[i] != 0;
  if ((status = prepare (s, sys, news, consistent, &lagged)))
    return status;
  lac_strategy_get_counts (s->strategy, &c0);
  if (t->nonlinear)
    memset (w->x, 0, s->n * sizeof *w->x);
  else
    memcpy (w->x, s->U, s->n * sizeof *w->x);     /* the warm start */
  for (size_t j = 0; lagged && j < s->n; j++)     /* the factor of an older */
    w->x[j] = p->fixed && p->fixed[j] ? sys->F[j] : 0.0; /* tangent: GMRES */
  if (!lagged)                                    /* from the increments */
    status = solve_frozen (s, rec);
  rec->factored = !lagged;
  double tf = count (s, &c0, rec), t1 = lac_seconds ();
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
  scatter (s, rec);
  s->time_solve += lac_seconds () - t0;
  return remember (s);
}

/* ---- the loop ------------------------------------------------------------- */

int
lac_newton_begin (lac_newton *s)
{
  lac_newton_work *w = s->w;
  w->it = 0;
  w->converged = 0;
  w->nactive1 = 0;
  w->settled = 0;
  w->res_solved = 0;
  w->merit = w->merit_best = HUGE_VAL;
  w->alpha = 1;
  w->backtracks = 0;
  w->nseen = 0;
  s->predicted = 0;
  s->restarted = 0;
  s->held_start = 0;
  s->nhist0 = s->nhist;
  memcpy (s->U0, s->U, s->n * sizeof *s->U);
  memcpy (s->lambda0, s->lambda, s->nslot * sizeof *s->lambda);
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

void
lac_newton_restart (lac_newton *s)
{
  memcpy (s->U, s->U0, s->n * sizeof *s->U);
  memcpy (s->lambda, s->lambda0, s->nslot * sizeof *s->lambda);
  memcpy (s->active, s->w->active0, s->nslot);
  s->first = s->w->first0;
}

static int
maxit_error (const lac_newton *s, const lac_newton_record *r, int diverged)
{
  LAC_ERROR (LAC_EMAXITER, "no convergence in %d iteration%s of Algorithm "
             "1%s: the last changed %zu status%s (%zu of %zu multipliers "
             "active), residual %.3e; raise the iteration limit or load in "
             "more steps", s->w->it, s->w->it == 1 ? "" : "s", diverged
             ? " (the residual grew 1000 times above its best)" : "",
             r->nchanged, r->nchanged == 1 ? "" : "es",
             lac_newton_nactive (s), r->k, r->residual);
}

/* Steps 1-3 at U: LAC_SUCCESS and *done = 1 when converged. */
static int
evaluate_and_test (lac_newton *s, lac_newton_record *rec, int *done)
{
  lac_newton_work *w = s->w;
  int status, more = 0;
  do
    {
      double start = rec->start;
      int bt = rec->backtracks;
      memset (rec, 0, sizeof *rec);
      rec->start = start;
      rec->backtracks = bt;
      if ((status = evaluate (s, rec)))
        return status;
      memcpy (w->lam_lin, s->lambda, s->nslot * sizeof *s->lambda);
      rec->nchanged = update_status (s, rec);               /* step 2 */
      rec->k = s->pt.k;
      s->residual = rec->residual;
      *done = w->it > 0 && rec->nchanged == 0                /* step 3 */
              && rec->residual <= s->opts.tol
              && rec->gap_residual <= s->opts.tol;
      if (*done && (status = check_covered (s, &more)))
        return status;
    }
  while (*done && more);
  return LAC_SUCCESS;
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
  rec.backtracks = w->backtracks;
  w->backtracks = 0;
  if ((status = evaluate_and_test (s, &rec, &done)))
    return status;
  rec.backtracks += w->backtracks;
  if (done)
    {
      w->converged = 1;
      return LAC_SUCCESS;
    }
  if (w->it >= 2)
    w->merit_best = fmin (w->merit_best, w->merit);
  int diverged = s->model.type->nonlinear && w->it >= 4
                 && w->merit > LAC_NEWTON_DIVERGED * w->merit_best;
  if (w->it >= s->opts.maxit || diverged)
    return maxit_error (s, &rec, diverged);
  double eta = w->it == 0 ? ETA_FIRST
               : fmax (ETA_MIN, fmin (ETA_MAX, ETA_FACTOR * rec.residual));
  memcpy (w->lam_step, s->lambda, s->nslot * sizeof *s->lambda);
  w->settled = rec.nchanged == 0;
  w->res_solved = rec.residual;
  if ((status = step (s, eta, &rec)))                      /* step 4 */
    return status;
  s->first = 0;
  w->it++;
  rec.iter = w->it;
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
