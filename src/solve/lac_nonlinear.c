/* lac_nonlinear.c -- the contact model of large deformations
 *                    (see lac_nonlinear.h)       [LAC §4.5, Alg. 1; §5.4]
 *
 * The file follows the operations of the model: set-up (fixed dofs, the
 * pattern of K_T), evaluate (F_int, K_T, the contact data on the current
 * coordinates), linearize (the Dirichlet increments moved in), the
 * consistent step, and the pair's uncovered / widen.
 */
#include "solve/lac_nonlinear.h"

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_tasks.h"
#include "solve/lac_consistent.h"

void
lac_nl_opts_init (lac_nl_opts *o)
{
  memset (o, 0, sizeof *o);
  o->kind = lac_strategy_choose_factor (LAC_FACTOR_LU, 0);    /* saddle */
  o->maxit = LAC_NL_MAXIT;
  o->tol = LAC_NL_TOL;
  o->rho = 0;
  o->max_cuts = 6;
  o->predict = 1;
  lac_pairing_opts_init (&o->popts);
  o->popts.degree_nonaffine = 8;   /* see lac_nonlinear.h */
}

void
lac_nl_free (lac_nl *s)
{
  if (!s)
    return;
  lac_contact_set_data_clear (&s->data);
  lac_contact_set_clear (&s->set);
  lac_free (s->pair);
  lac_free (s->delta);
  lac_contact_tangent_free (s->tangent);
  lac_pattern_free (s->pat);
  lac_csc_free (s->C0);
  lac_free (s->x);
  lac_free (s->fixed);
  lac_free (s->g1);
  lac_free (s->g0);
  lac_free (s->r);
  lac_free (s->Fint);
  lac_free (s->inc.dof);
  lac_free (s->inc.val);
  lac_free (s->kgap);
  lac_free (s->ug);
  lac_free (s->Floc);
  lac_free (s);
}

/* The slabs of the kept pattern (lac_pattern.h): enough that the core
 * which joins the assembly after the pairing still finds runs to take
 * (evaluate, below), few enough that they stay thicker than a cell (16
 * on the ring's coarse and fine meshes set no cell apart, 32 half the
 * coarse one).  Halved while the cells set apart, which one thread adds alone,
 * outnumber a slab's. */
#define SLABS 16

/* The kept pattern of K_T: the cells with E > 0, in slabs for the two
 * threads of the assembly. */
static lac_pattern *
pattern (const lac_mesh *m, const lac_hyper *h)
{
  char *cells = lac_malloc (m->ncells + 1);
  if (!cells)
    LAC_ERROR_NULL (LAC_ENOMEM, "cell flags");
  for (size_t c = 0; c < m->ncells; c++)
    cells[c] = h->E[c] > 0;
  lac_pattern *p = lac_pattern_build (m, cells);
  lac_free (cells);
  for (size_t nslab = SLABS; p; nslab /= 2)
    {
      if (lac_pattern_slabs (p, m, nslab))
        {
          lac_pattern_free (p);
          return NULL;
        }
      size_t apart = p->run[p->nrun] - p->run[p->nrun - 1];
      if (nslab <= 2 || apart * nslab <= p->run[p->nrun])
        break;
    }
  return p;
}

/* Fixed dofs: fixed[dof], g1 (ramped value at t = 1), g0 (constant). */
static int
set_fixed (lac_nl *s)
{
  const lac_dirichlet *d = s->prob.dir;
  for (size_t j = 0; d && j < d->n; j++)
    {
      size_t k = d->dof[j];
      if (k >= s->ndof)
        LAC_ERROR (LAC_EBADLEN, "fixed dof %zu out of range (%zu dofs)", k,
                   s->ndof);
      int ramp = !s->prob.ramp || s->prob.ramp[j];
      s->fixed[k] = 1;                                /* later entries win */
      s->g1[k] = ramp ? d->val[j] : 0.0;
      s->g0[k] = ramp ? 0.0 : d->val[j];
    }
  return LAC_SUCCESS;
}

/* With the nodal frames of rollers (fem/lac_frames.h, the Dirichlet
 * data's): the room for U in the axes, and the load in the frames. */
static int
set_frames (lac_nl *s)
{
  const lac_frames *f = s->prob.dir->frames;
  s->F = s->prob.F;
  if (!f)
    return LAC_SUCCESS;
  size_t n = s->ndof ? s->ndof : 1;
  if (!(s->ug = lac_calloc (n, sizeof *s->ug))
      || !(s->Floc = lac_calloc (n, sizeof *s->Floc)))
    LAC_ERROR (LAC_ENOMEM, "nodal frames of %zu dofs", s->ndof);
  if (s->prob.F)
    memcpy (s->Floc, s->prob.F, s->ndof * sizeof *s->Floc);
  lac_frames_to_local (f, s->Floc);                        /* T^T F */
  s->F = s->prob.F ? s->Floc : NULL;
  return LAC_SUCCESS;
}

/* U in the axes: U itself, or T U with frames (in s->ug). */
static const double *
in_axes (lac_nl *s, const double *U)
{
  if (!s->ug)
    return U;
  memcpy (s->ug, U, s->ndof * sizeof *s->ug);
  lac_frames_to_global (s->prob.dir->frames, s->ug);
  return s->ug;
}

/* The pairs of the problem (contact/lac_contact_pair.h): copies of the
 * set's, or the one pair of M, master, obstacle, epsilon; the pairing
 * options are the model's (allow_empty forced: nothing in reach is no
 * constraint) with a set's pair's own reach added (its dist_abs: the
 * scene's gap_bound), and nothing widened yet; the offset of a set's
 * pair is its interference at t = 1, ramped by lac_nl_set_load. */
static int
set_pairs (lac_nl *s, const lac_nl_opts *o)
{
  const lac_nl_problem *p = &s->prob;
  s->npair = p->set ? p->set->n : p->M ? 1 : 0;
  if (s->npair == 0)
    return LAC_SUCCESS;
  if (!(s->pair = lac_calloc (s->npair, sizeof *s->pair))
      || !(s->delta = lac_calloc (s->npair, sizeof *s->delta)))
    LAC_ERROR (LAC_ENOMEM, "%zu contact pairs", s->npair);
  for (size_t q = 0; q < s->npair; q++)
    {
      if (p->set)
        s->pair[q] = p->set->pair[q];
      else
        s->pair[q] = (lac_contact_pair) { p->mesh, p->mat->model, p->M,
                                          p->master, p->obstacle,
                                          p->epsilon, 0, { 0 }, 0, 0, 0, 0 };
      s->pair[q].model = p->mat->model;
      if (!(s->pair[q].epsilon > 0))
        s->pair[q].epsilon = LAC_EPSILON_DEFAULT;
      s->pair[q].popts = o->popts;
      s->pair[q].popts.dist_abs += p->set ? p->set->pair[q].popts.dist_abs
                                          : 0.0;
      s->pair[q].popts.allow_empty = 1;
      s->pair[q].widened = 0;
      s->delta[q] = s->pair[q].offset;          /* at t = 1; 0 at t = 0 */
      s->pair[q].offset = 0;
    }
  return lac_contact_set_init (&s->set, s->pair, s->npair);
}

lac_nl *
lac_nl_alloc (const lac_nl_problem *p, const lac_nl_opts *opts)
{
  lac_nl_opts o;
  if (!p || !p->mesh || !p->mat || !p->dir)
    LAC_ERROR_NULL (LAC_EINVAL, "incomplete nonlinear problem (mesh, "
                    "material and Dirichlet data are needed)");
  if (!p->set && p->M && !p->master && !p->obstacle)
    LAC_ERROR_NULL (LAC_EINVAL, "contact without a master surface or an "
                    "obstacle");
  lac_nl *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "nonlinear model");
  if (opts)
    o = *opts;
  else
    lac_nl_opts_init (&o);
  s->prob = *p;
  s->frozen = o.frozen;
  if (set_pairs (s, &o))
    {
      lac_nl_free (s);
      return NULL;
    }
  const lac_mesh *m = p->mesh;
  s->ndof = (size_t) m->dim * m->nnodes;
  s->nmacro = lac_contact_set_nslot (&s->set);
  size_t n = s->ndof ? s->ndof : 1;
  double **dof[] = { &s->x, &s->g1, &s->g0, &s->r, &s->Fint, &s->inc.val };
  int ok = (s->fixed = lac_calloc (n, 1)) != NULL
           && (s->inc.dof = lac_calloc (n, sizeof *s->inc.dof)) != NULL
           && (s->kgap = lac_calloc (s->nmacro + 1, sizeof *s->kgap));
  for (size_t k = 0; k < sizeof dof / sizeof *dof; k++)
    ok = ok && (*dof[k] = lac_calloc (n, sizeof **dof[k])) != NULL;
  if (!ok || !(s->C0 = lac_csc_alloc (s->ndof, 0, 0)))
    {
      lac_nl_free (s);
      LAC_ERROR_NULL (LAC_ENOMEM, "nonlinear model for %zu dofs",
                      (size_t) m->dim * m->nnodes);
    }
  s->cur = *m;                       /* shallow: only x differs */
  s->cur.x = s->x;
  memcpy (s->x, m->x, s->ndof * sizeof *s->x);
  if (set_fixed (s) || set_frames (s) || !(s->pat = pattern (m, p->mat)))
    {
      lac_nl_free (s);
      return NULL;
    }
  return s;
}

void
lac_nl_set_load (lac_nl *s, double t)
{
  s->t = t;
  s->fref = 0;
  for (size_t q = 0; q < s->npair; q++)
    s->pair[q].offset = t * s->delta[q];       /* ramped, as the loads */
}

double
lac_nl_contact_force (const lac_nl *s, const double *lambda)
{
  double f = 0;
  const lac_contact *c = s->contact;
  for (size_t i = 0; c && i < c->k; i++)
    f += lambda[c->macro[i]] * c->area[i];
  return f;
}

/* ---- evaluate: F_int, K_T, contact data on the current coordinates ----- */

/* [LAC Alg. 1, line 25]: the pairs on x = X + U.  No pair or no
 * admissible macro-element is not an error: no constraint (contact =
 * NULL). */
static int
contact_update_axes (lac_nl *s, const double *U)
{
  lac_contact_set_data_clear (&s->data);
  s->contact = NULL;
  for (size_t j = 0; j < s->ndof; j++)
    s->x[j] = s->prob.mesh->x[j] + U[j];             /* x = X + U */
  double t0 = lac_seconds ();
  int status = lac_contact_set_build (&s->set, s->x, &s->data);
  s->contact = s->data.all;
  if (!status && s->data.all)                     /* T^T C, every pair */
    status = lac_frames_rotate_rows (s->prob.dir->frames, &s->data.all->C);
  s->npairings++;
  s->time_pairing += lac_seconds () - t0;
  return status;
}

static int
contact_update (lac_nl *s, const double *U)
{
  return contact_update_axes (s, in_axes (s, U));
}

/* After an assembly that started at t0: F_int and K_T in the frames of
 * the rollers, the time counted (s->have_K says whether K_T is the
 * tangent at U). */
static int
assembled (lac_nl *s, int status, double *Fint, int want_K, double t0)
{
  const lac_frames *f = s->prob.dir->frames;
  if (!status && Fint)                       /* in the frames: T^T F_int, */
    lac_frames_to_local (f, Fint);
  if (!status && want_K)                                   /* T^T K_T T */
    status = lac_frames_rotate_matrix (f, s->pat->K);
  s->have_K = want_K && !status;
  s->time_assemble += lac_seconds () - t0;
  return status;
}

/* K_T at U alone (linearize, after an evaluation that left it out). */
static int
assemble (lac_nl *s, const double *U)
{
  double t0 = lac_seconds ();
  int status = lac_hyper_assemble_pattern (s->prob.mesh, s->prob.mat,
                                           in_axes (s, U), NULL, s->pat);
  return assembled (s, status, NULL, 1, t0);
}

/* An evaluation, on both cores (linalg/lac_tasks.h): the assembly of
 * F_int and K_T in the runs of the pattern's slabs (fem/lac_hyper.h,
 * lac_hyper_job), started at once in the calling thread; in the other,
 * the pairing with C and the mean gaps, and then the runs of the
 * assembly still left.  They share only the mesh and U (read) and the
 * job, which hands out the runs: F_int and K_T have the same bits
 * whoever adds which run.  Without contact both threads assemble from
 * the start. */
typedef struct eval_job
{
  lac_nl *s;
  const double *U;     /* in the axes */
  int tangent;
  double t0;           /* the assembly's start */
  lac_hyper_job asm_job;
} eval_job;

static int
assemble_task (void *ctx)
{
  eval_job *j = ctx;
  int status = lac_hyper_job_work (&j->asm_job, SIZE_MAX);
  return assembled (j->s, status, j->s->Fint, j->tangent, j->t0);
}

/* The pairing, then the assembly's runs left (their failure is reported
 * by assemble_task, which waits for them). */
static int
contact_task (void *ctx)
{
  eval_job *j = ctx;
  int status = contact_update_axes (j->s, j->U);
  if (!status)
    lac_hyper_job_work (&j->asm_job, SIZE_MAX);
  return status;
}

static int
join_task (void *ctx)
{
  eval_job *j = ctx;
  lac_hyper_job_work (&j->asm_job, SIZE_MAX);
  return LAC_SUCCESS;
}

/* r = t F - F_int and the force scale max(|F_int|, |t F|, r_0). */
static double
out_of_balance (lac_nl *s)
{
  double nfi = 0, nf = 0;
  for (size_t j = 0; j < s->ndof; j++)
    {
      double f = s->F ? s->t * s->F[j] : 0.0;
      s->r[j] = f - s->Fint[j];
      nfi += s->Fint[j] * s->Fint[j];
      nf += f * f;
    }
  return fmax (fmax (sqrt (nfi), sqrt (nf)), s->fref);
}

static int
evaluate (void *self, const double *U, int tangent, lac_model_point *p)
{
  lac_nl *s = self;
  eval_job j = { s, in_axes (s, U), tangent, lac_seconds (), { 0 } };
  memset (s->Fint, 0, s->ndof * sizeof *s->Fint);
  int status = lac_hyper_job_init (&j.asm_job, s->prob.mesh, s->prob.mat,
                                   j.U, s->Fint, s->pat, tangent);
  if (status)
    return status;
  status = lac_tasks_pair (assemble_task, &j, s->npair ? contact_task
                                                       : join_task, &j);
  lac_hyper_job_clear (&j.asm_job);
  if (status)
    return status;
  const lac_contact *c = s->contact;
  *p = (lac_model_point) { .k = c ? c->k : 0, .C = c ? c->C : s->C0,
                           .d = c ? c->G : NULL, .area = c ? c->area : NULL,
                           .size = c ? c->size : NULL,
                           .slot = c ? c->macro : NULL,
                           .lost = c ? c->lost : NULL, .r = s->r,
                           .fixed = s->fixed, .fscale = out_of_balance (s) };
  return LAC_SUCCESS;
}

/* ---- linearize: the Newton step's system -------------------------------- */

/* The Dirichlet increments of the step from U: dof, value. */
static void
increments (lac_nl *s, const double *U)
{
  lac_dirichlet *inc = &s->inc;
  inc->n = 0;
  for (size_t j = 0; j < s->ndof; j++)
    if (s->fixed[j])
      {
        inc->dof[inc->n] = j;
        inc->val[inc->n++] = s->t * s->g1[j] + s->g0[j] - U[j];
      }
}

static int
linearize (void *self, const double *U, const lac_contact_system **sys,
           int *news)
{
  lac_nl *s = self;
  int status;
  if (!s->have_K && (status = assemble (s, U)))          /* left out by */
    return status;                                       /* evaluate    */
  increments (s, U);
  if (s->contact)                 /* d(U) before the increments, for the */
    memcpy (s->kgap, s->contact->G,       /* consistent step (** of */
            s->contact->k * sizeof *s->kgap);      /* lac_consistent.h) */
  if ((status = lac_dirichlet_apply (&s->inc, s->pat->K, s->r)))
    return status;
  if (s->fref == 0)
    {
      /* the force the increments put on the free dofs: the scale of the
       * residual when every force vanishes (a rigid motion) */
      double nr = 0;
      for (size_t j = 0; j < s->ndof; j++)
        if (!s->fixed[j])
          nr += s->r[j] * s->r[j];
      s->fref = sqrt (nr);
    }
  const lac_contact *c = s->contact;
  if (c && (status = lac_contact_apply_dirichlet (s->data.all, s->inc.n,
                                                  s->inc.dof, s->inc.val)))
    return status;
  s->sys = (lac_contact_system) { s->pat->K, s->r, c ? c->C : s->C0,
                                  c ? c->G : NULL, NULL, s->prob.nfree,
                                  s->prob.N, s->prob.N_what, NULL };
  *sys = &s->sys;
  *news = LAC_MODEL_NEW_K;
  s->have_K = 0;                      /* the increments are in K now */
  return LAC_SUCCESS;
}

/* ---- the consistent step ------------------------------------------------ */

/* H and B of pair q at the current coordinates, for its columns
 * i0 <= i < i1 (lam_lin, active from its first column on). */
static int
pair_tangent (lac_nl *s, size_t q, size_t i0, size_t i1, const char *active,
              const double *lam_lin, lac_contact_tangent **t)
{
  const lac_contact_pair *p = &s->pair[q];
  const lac_contact *c = s->data.c[q];
  size_t c0 = s->data.col[q];
  lac_pairing_facets Mf;
  static const lac_contact none = { 0 };
  if (p->master)
    {
      Mf = *p->master;
      Mf.mesh = &s->cur;
    }
  return lac_contact_tangent_build_cols (&s->cur, p->model, p->M,
                                         s->data.P[q], p->master ? &Mf : NULL,
                                         p->obstacle, c ? c : &none,
                                         lam_lin + c0, active + c0, i0, i1,
                                         t);
}

/* Where to cut pair q's columns into two pieces of equal work. */
static size_t
half_work (const lac_nl *s, size_t q, const char *active,
           const double *lam_lin)
{
  const lac_contact *c = s->data.c[q];
  size_t c0 = s->data.col[q], total = 0, sum = 0, i = 0;
  if (!c)
    return 0;
  for (size_t j = 0; j < c->k; j++)
    total += lac_contact_tangent_work (s->pair[q].M, s->data.P[q], c,
                                       lam_lin + c0, active + c0, j);
  while (i < c->k && 2 * sum < total)
    sum += lac_contact_tangent_work (s->pair[q].M, s->data.P[q], c,
                                     lam_lin + c0, active + c0, i++);
  return i;
}

/* A piece of pair q's tangent: its columns i0 <= i < i1, into t. */
typedef struct tangent_job
{
  lac_nl *s;
  size_t q, i0, i1;
  const char *active;
  const double *lam_lin;
  lac_contact_tangent *t;          /* out: the caller frees it */
} tangent_job;

static int
tangent_task (void *ctx)
{
  tangent_job *j = ctx;
  return pair_tangent (j->s, j->q, j->i0, j->i1, j->active, j->lam_lin,
                       &j->t);
}

/* s->tangent: H and B of every pair, each pair's columns cut in two
 * pieces of equal work built at the same time (linalg/lac_tasks.h; the
 * columns are independent, so the pieces side by side are the tangent of
 * one build, bit for bit). */
static int
tangent (lac_nl *s, const char *active, const double *lam_lin)
{
  size_t n = 2 * s->npair;
  lac_contact_tangent **t = lac_calloc (n, sizeof *t);
  int status = t ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "%zu tangents",
                                             s->npair);
  lac_contact_tangent_free (s->tangent);
  s->tangent = NULL;
  for (size_t q = 0; q < s->npair && !status; q++)
    {
      size_t k = s->data.c[q] ? s->data.c[q]->k : 0;
      size_t mid = half_work (s, q, active, lam_lin);
      tangent_job a = { s, q, 0, mid, active, lam_lin, NULL };
      tangent_job b = { s, q, mid, k, active, lam_lin, NULL };
      status = lac_tasks_pair (tangent_task, &a, tangent_task, &b);
      t[2 * q] = a.t;
      t[2 * q + 1] = b.t;
    }
  if (!status)
    status = lac_contact_tangent_cat (t, n, &s->tangent);
  for (size_t q = 0; t && q < n; q++)
    lac_contact_tangent_free (t[q]);
  lac_free (t);
  return status;
}

static int
consistent (void *self, lac_strategy *st, const char *active,
            const double *lam_lin, double eta, double *dU, double *lambda,
            int *its, double *res)
{
  lac_nl *s = self;
  const lac_contact *c = s->contact;
  lac_consistent_info info = { 0 };
  *its = 0;
  *res = 0;
  if (!c || s->frozen)
    return LAC_SUCCESS;
  double t0 = lac_seconds ();
  int status = tangent (s, active, lam_lin);
  if (!status)                              /* T^T B, T^T H T, every pair */
    status = lac_contact_tangent_rotate (s->tangent, s->prob.dir->frames);
  s->time_tangent += lac_seconds () - t0;
  if (status)
    return status;
  lac_consistent cs = { &s->sys, st, s->tangent, s->fixed, s->kgap, active,
                        eta, 0 };
  status = lac_consistent_solve (&cs, dU, lambda, &info);
  *its = info.iterations;
  *res = info.residual;
  return status;
}

/* ---- no silent penetration ---------------------------------------------- */

/* The pairing at x = X + U reaches about one facet from each slave
 * facet: a macro-element that went deeper into the master within one
 * Newton step stays out of reach at every pairing after it.  Nothing
 * penetrates in the reference shape (but for the interference, which the
 * depth counts), and each side has moved by max |U| at most since: look
 * that deep. */
static int
uncovered (void *self, const double *U, double tol, lac_contact_uncovered *u)
{
  lac_nl *s = self;
  double umax = 0;
  memset (u, 0, sizeof *u);
  if (!s->npair)
    return LAC_SUCCESS;
  (void) U;                           /* s->x = X + U: the evaluation's */
  for (size_t j = 0; j < s->ndof; j++)
    umax = fmax (umax, fabs (s->x[j] - s->prob.mesh->x[j]));
  return lac_contact_set_uncovered (&s->set, s->x, &s->data, 2 * umax, tol,
                                    u);
}

/* Pair again with `reach` more than the pairs' own reach: the largest
 * reach asked so far, not their sum (each is measured from the pairs'
 * own), kept for the rest of the solve: the later load steps bring the
 * parts it found closer still (two-columns.scene in large deformation at
 * level 4: 19 Newton iterations and one cut step with it kept, 36 and 4
 * cuts with it dropped at each load factor). */
static int
widen (void *self, const double *U, double reach, size_t *more)
{
  lac_nl *s = self;
  size_t k0 = s->contact ? s->contact->k : 0;
  *more = 0;
  if (!s->npair)
    return LAC_SUCCESS;
  for (size_t q = 0; q < s->npair; q++)
    s->pair[q].widened = fmax (s->pair[q].widened, reach);
  int status = contact_update (s, U);
  size_t k1 = s->contact ? s->contact->k : 0;
  *more = k1 > k0 ? k1 - k0 : 0;
  return status;
}

static const lac_contact_model_type nl_type =
  { "large deformation", 1, evaluate, linearize, consistent, uncovered,
    widen };

void
lac_nl_model (lac_nl *s, lac_contact_model *m)
{
  double E = HUGE_VAL;
  for (size_t c = 0; c < s->prob.mesh->ncells; c++)
    if (s->prob.mat->E[c] > 0)
      E = fmin (E, s->prob.mat->E[c]);
  *m = (lac_contact_model) { &nl_type, s, s->ndof, s->nmacro,
                             E < HUGE_VAL ? E : 1.0, s->prob.mesh->dim, 0 };
}
