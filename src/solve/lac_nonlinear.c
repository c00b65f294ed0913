/* lac_nonlinear.c -- load steps and the generalized Newton loop
 *                                             [LAC §4.5, Alg. 1; §5.4]
 *
 * See lac_nonlinear.h for the algorithm.  The file follows it: set-up
 * (fixed dofs, the pattern of K_T), the contact data on the current
 * coordinates, the statuses, the residual with the line search, one
 * solve (the strategy's frozen one, then the consistent step).  The load
 * steps and their cuts: lac_loadstep.c.
 */
#include "solve/lac_nonlinear.h"

#include <math.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "contact/lac_contact_tangent.h"
#include "solve/lac_complementarity.h"
#include "solve/lac_consistent.h"
#include "solve/lac_strategy.h"
#include "base/lac_status.h"

#define LS_HALVINGS 4     /* line search: a step halved at most this often   */
#define DIVERGED 1e3      /* a residual this much above the best of the step:
                             no convergence                                 */
#define LAG_ITERATIONS 6  /* K_T's factorization is kept from iteration to
                             iteration while the consistent step's GMRES
                             takes at most this many iterations: about half
                             a factorization (one costs 12 GMRES iterations
                             on the coarse hex20 ring, 13 on the fine one) */
#define ETA_FIRST 1e-5    /* the accuracy of the first step of a sub-step  */
#define LAZY_K 1e-5       /* see evaluate ()                                 */
#define ETA_FACTOR 1e-2  /* accuracy of the consistent step: this times    */
#define ETA_MAX 1e-3      /*   the residual of step 4, within these bounds  */
#define ETA_MIN 1e-12
     /*   its right-hand side: the Newton residual,    */
                          /*   within these bounds                          */

void
lac_nl_opts_init (lac_nl_opts *o)
{
  memset (o, 0, sizeof *o);
  o->kind = LAC_STRATEGY_SADDLE;
  o->maxit = 25;
  o->tol = 1e-8;
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
  lac_free (s->U);
  lac_free (s->lambda);
  lac_free (s->active);
  lac_pairing_free (s->pairing);
  lac_contact_free (s->contact);
  lac_free (s->x);
  lac_free (s->steps);
  lac_free (s->iters);
  lac_free (s->fixed);
  lac_free (s->g1);
  lac_free (s->g0);
  lac_pattern_free (s->pat);
  lac_solver_free (s->solver);
  lac_strategy_free (s->strategy);
  lac_contact_tangent_free (s->tangent);
  lac_free (s->klam);
  lac_free (s->kact);
  lac_free (s->klin);
  lac_free (s->kgap);
  lac_free (s->lam_lin);
  lac_free (s->lam_step);
  lac_free (s->dU_last);
  lac_free (s->U_old);
  lac_free (s->lambda_old);
  lac_free (s->r);
  lac_free (s->Fint);
  lac_free (s->dU);
  lac_free (s->U_save);
  lac_free (s->lambda_save);
  lac_free (s->active_save);
  lac_free (s);
}

/* The kept pattern of K_T: the cells with E > 0 (lac_pattern.h). */
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

lac_nl *
lac_nl_alloc (const lac_nl_problem *p, const lac_nl_opts *opts)
{
  if (!p || !p->mesh || !p->mat || !p->dir)
    LAC_ERROR_NULL (LAC_EINVAL, "incomplete nonlinear problem (mesh, "
                    "material and Dirichlet data are needed)");
  if (p->M && !p->master && !p->obstacle)
    LAC_ERROR_NULL (LAC_EINVAL, "contact without a master surface or an "
                    "obstacle");
  lac_nl *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "nonlinear workspace");
  s->prob = *p;
  if (opts)
    s->opts = *opts;
  else
    lac_nl_opts_init (&s->opts);
  if (s->opts.maxit <= 0)
    s->opts.maxit = 25;
  if (!(s->opts.tol > 0))
    s->opts.tol = 1e-8;
  if (s->opts.max_cuts == 0)
    s->opts.max_cuts = 6;
  if (!(s->prob.epsilon > 0))
    s->prob.epsilon = LAC_EPSILON_DEFAULT;
  s->opts.popts.allow_empty = 1;
  const lac_mesh *m = p->mesh;
  s->ndof = (size_t) m->dim * m->nnodes;
  s->nmacro = p->M ? p->M->n : 0;
  size_t n = s->ndof, nm = s->nmacro ? s->nmacro : 1;
  /* the vectors, zeroed: per dof (n), per macro-element (nm), and the
   * flags: fixed per dof, the statuses per macro-element; one check */
  double **dof[] = { &s->U, &s->x, &s->g1, &s->g0, &s->r, &s->Fint, &s->dU,
                     &s->U_save, &s->dU_last, &s->U_old };
  double **macro[] = { &s->lambda, &s->lambda_save, &s->lam_lin,
                       &s->lam_step, &s->lambda_old };
  char **active[] = { &s->active, &s->active_save };
  int ok = (s->fixed = lac_calloc (n, 1)) != NULL;
  for (size_t k = 0; k < sizeof dof / sizeof *dof; k++)
    ok &= (*dof[k] = lac_calloc (n, sizeof **dof[k])) != NULL;
  for (size_t k = 0; k < sizeof macro / sizeof *macro; k++)
    ok &= (*macro[k] = lac_calloc (nm, sizeof **macro[k])) != NULL;
  for (size_t k = 0; k < sizeof active / sizeof *active; k++)
    ok &= (*active[k] = lac_calloc (nm, 1)) != NULL;
  if (!ok)
    {
      lac_nl_free (s);
      LAC_ERROR_NULL (LAC_ENOMEM, "nonlinear workspace for %zu dofs", n);
    }
  s->cur = *m;                       /* shallow: only x differs */
  s->cur.x = s->x;
  memcpy (s->x, m->x, n * sizeof *s->x);
  s->first = 1;
  if (set_fixed (s) || !(s->pat = pattern (m, p->mat)))
    {
      lac_nl_free (s);
      return NULL;
    }
  s->K = s->pat->K;
  return s;
}

/* ---- records ------------------------------------------------------------ */

static int
push_iter (lac_nl *s, const lac_nl_iter *r)
{
  if (lac_grow (&s->iters, s->niters + 1, &s->capiters, sizeof *s->iters,
                64))
    LAC_ERROR (LAC_ENOMEM, "iteration records");
  s->iters[s->niters++] = *r;
  return LAC_SUCCESS;
}

size_t
lac_nl_nactive (const lac_nl *s)
{
  size_t n = 0;
  for (size_t m = 0; m < s->nmacro; m++)
    n += s->active[m] != 0;
  return n;
}

double
lac_nl_contact_force (const lac_nl *s)
{
  double f = 0;
  const lac_contact *c = s->contact;
  for (size_t i = 0; c && i < c->k; i++)
    f += s->lambda[c->macro[i]] * c->area[i];
  return f;
}

/* ---- steps 1 and 2: F_int, K_T, contact data on the current coordinates - */

/* Step 2 [LAC Alg. 1, line 25]: pairing of the slave sub-facets with the
 * master on x = X + U, then admissibility, C and the mean gaps.  No pair or
 * no admissible macro-element is not an error: no constraint (k = 0). */
static int
contact_update (lac_nl *s)
{
  const lac_nl_problem *p = &s->prob;
  const lac_macro *M = p->M;
  int status;
  lac_pairing_free (s->pairing);
  lac_contact_free (s->contact);
  s->pairing = NULL;
  s->contact = NULL;
  for (size_t j = 0; j < s->ndof; j++)
    s->x[j] = p->mesh->x[j] + s->U[j];                /* x = X + U */
  lac_pairing_facets S = { &s->cur, M->ptr[M->n], M->cell, M->face };
  lac_pairing_facets Mf;
  double t0 = lac_seconds ();
  if (p->master)
    {
      Mf = *p->master;
      Mf.mesh = &s->cur;
      status = lac_pairing_build (&S, &Mf, &s->opts.popts, &s->pairing);
    }
  else
    status = lac_obstacle_pairing (&S, p->obstacle, s->opts.popts.degree,
                                   &s->pairing);
  s->npairings++;
  if (!status)
    status = lac_contact_build (&s->cur, p->mat->model, M, s->pairing,
                                p->master ? &Mf : NULL, p->epsilon,
                                &s->contact);
  s->time_pairing += lac_seconds () - t0;
  if (status == LAC_EADMISS)                          /* nothing in reach */
    {
      lac_error_clear ();
      s->contact = NULL;
      return LAC_SUCCESS;
    }
  return status;
}

/* Step 1: F_int and, if want_K, K_T at U (s->have_K says which). */
static int
assemble (lac_nl *s, int want_K)
{
  double t0 = lac_seconds ();
  int status;
  memset (s->Fint, 0, s->ndof * sizeof *s->Fint);
  if (want_K)
    status = lac_hyper_assemble_pattern (s->prob.mesh, s->prob.mat, s->U,
                                         s->Fint, s->pat);
  else
    status = lac_hyper_assemble (s->prob.mesh, s->prob.mat, s->U, s->Fint,
                                 NULL);
  s->have_K = want_K && !status;
  s->time_assemble += lac_seconds () - t0;
  return status;
}

/* K_T at U if step 1 left it out. */
static int
assemble_K (lac_nl *s)
{
  if (s->have_K)
    return LAC_SUCCESS;
  double t0 = lac_seconds ();
  int status = lac_hyper_assemble_pattern (s->prob.mesh, s->prob.mat, s->U,
                                           NULL, s->pat);
  s->have_K = !status;
  s->time_assemble += lac_seconds () - t0;
  return status;
}

/* ---- steps 3 and 4: statuses, residual ---------------------------------- */

/* rho of multiplier i (lac_nonlinear.h). */
static double
rho_of (const lac_nl *s, size_t i, double Eref)
{
  if (s->opts.rho > 0)
    return s->opts.rho;
  double a = s->contact->area[i];
  if (!(a > 0))
    return 1.0;
  int dim = s->prob.mesh->dim;
  double h = dim == 3 ? sqrt (a) : a;
  return Eref / (h * a);
}

static double
e_ref (const lac_nl *s)
{
  double E = HUGE_VAL;
  for (size_t c = 0; c < s->prob.mesh->ncells; c++)
    if (s->prob.mat->E[c] > 0)
      E = fmin (E, s->prob.mat->E[c]);
  return E < HUGE_VAL ? E : 1.0;
}

/* Step 3: the statuses of the macro-elements from lambda and the mean
 * gaps G at the current U (before this iteration's Dirichlet increments
 * are moved in); non-admissible ones are inactive with lambda = 0 (their
 * pressure is lost: the residual shows it).  Returns the number of
 * changes; *pen = the largest penetration of an active one (a mean gap,
 * a length). */
static size_t
update_status (lac_nl *s, double *pen)
{
  const lac_contact *c = s->contact;
  double Eref = e_ref (s);
  double lmax = lac_complementarity_lmax (s->nmacro, s->lambda);
  size_t changed = 0;
  *pen = 0;
  for (size_t m = 0; m < s->nmacro; m++)
    {
      long i = c ? c->mult[m] : -1;
      char a = 0;
      if (i >= 0)
        {
          double d = c->G[i];
          double scale = fabs (d);
          for (int q = c->C->p[i]; q < c->C->p[i + 1]; q++)
            scale += fabs (c->C->x[q] * s->U[c->C->i[q]]);
          if (fabs (d) <= 1e-12 * scale)
            d = 0;                                    /* roundoff: touching */
          double rho = rho_of (s, (size_t) i, Eref);
          a = s->first ? d <= 0                       /* [LAC Alg. 1, l. 2-8] */
                       : (char) lac_complementarity_active (s->lambda[m], d,
                                                            rho, lmax, scale);
          if (a && c->area[i] > 0)
            *pen = fmax (*pen, -d / c->area[i]);
        }
      changed += a != s->active[m];
      s->active[m] = a;
      if (!a)
        s->lambda[m] = 0;
    }
  return changed;
}

/* Step 4: |r + C lambda| / scale with r = t F - F_int (kept in s->r, the
 * right-hand side of the solve) on the free dofs (the reactions on the
 * fixed dofs are not residuals).  s->dU is the scratch (the last
 * correction is not needed any more). */
static double
residual (lac_nl *s)
{
  size_t n = s->ndof;
  double nr = 0, nfi = 0, nf = 0, ncl = 0, *w = s->dU;
  const lac_contact *c = s->contact;
  for (size_t j = 0; j < n; j++)
    {
      double f = s->prob.F ? s->t * s->prob.F[j] : 0.0;
      s->r[j] = f - s->Fint[j];                       /* r = t F - F_int */
      w[j] = s->r[j];
      nfi += s->Fint[j] * s->Fint[j];
      nf += f * f;
    }
  for (size_t i = 0; c && i < c->k; i++)
    {
      double lam = s->lambda[c->macro[i]];
      for (int q = c->C->p[i]; q < c->C->p[i + 1]; q++)
        {
          double v = c->C->x[q] * lam;
          w[c->C->i[q]] += v;                         /* + C lambda */
          ncl += v * v;
        }
    }
  for (size_t j = 0; j < n; j++)
    if (!s->fixed[j])
      nr += w[j] * w[j];
  double scale = fmax (fmax (sqrt (nfi), sqrt (nf)), fmax (sqrt (ncl),
                                                         s->fref));
  return scale > 0 ? sqrt (nr) / scale : sqrt (nr);
}

/* Gap residual of the active macro-elements: max |d_m| / (|T^m cap
 * Gamma_C| h_m), a mean gap in units of the macro-element size. */
static double
gap_residual (const lac_nl *s)
{
  const lac_contact *c = s->contact;
  double g = 0;
  int dim = s->prob.mesh->dim;
  for (size_t i = 0; c && i < c->k; i++)
    {
      double a = c->area[i];
      if (!s->active[c->macro[i]] || !(a > 0))
        continue;
      double h = dim == 3 ? sqrt (a) : a;
      g = fmax (g, fabs (c->G[i]) / (a * h));
    }
  return g;
}

/* ---- step 5: one solve -------------------------------------------------- */

/* The Dirichlet increments of the current iteration: dof, value. */
static int
increments (const lac_nl *s, lac_dirichlet *inc)
{
  for (size_t j = 0; j < s->ndof; j++)
    if (s->fixed[j])
      {
        size_t cap = inc->cap;           /* dof and val share it */
        if (lac_grow (&inc->dof, inc->n + 1, &cap, sizeof *inc->dof, 64)
            || lac_grow (&inc->val, inc->n + 1, &inc->cap, sizeof *inc->val,
                         64))
          LAC_ERROR (LAC_ENOMEM, "Dirichlet increments");
        inc->dof[inc->n] = j;
        inc->val[inc->n++] = s->t * s->g1[j] + s->g0[j] - s->U[j];
      }
  return LAC_SUCCESS;
}

/* K_T dU = r without contact (no admissible macro-element): CHOLMOD or
 * UMFPACK as the strategy, the analysis of K_T kept. */
static int
solve_plain (lac_nl *s)
{
  int status;
  lac_solver_kind kind = s->opts.kind == LAC_STRATEGY_DENSE
    ? LAC_SOLVER_DENSE : s->opts.kind == LAC_STRATEGY_SADDLE
    ? LAC_SOLVER_UMFPACK : LAC_SOLVER_CHOLMOD;
  if (!s->solver && !(s->solver = lac_solver_alloc (kind)))
    return LAC_ENOMEM;
  status = lac_solver_refactor (s->solver, s->K);      /* same pattern */
  if (status == LAC_ESING && kind == LAC_SOLVER_CHOLMOD)
    {
      lac_error_clear ();             /* K_T not positive definite: LU */
      lac_solver_free (s->solver);
      if (!(s->solver = lac_solver_alloc (LAC_SOLVER_UMFPACK)))
        return LAC_ENOMEM;
      status = lac_solver_refactor (s->solver, s->K);
    }
  return status ? status : lac_solver_solve (s->solver, s->r, s->dU);
}

/* Room for k multipliers: lambda, statuses, linearization point, gaps. */
static int
kroom (lac_nl *s, size_t k)
{
  if (k <= s->kcap)
    return LAC_SUCCESS;
  lac_free (s->klam);
  lac_free (s->kact);
  lac_free (s->klin);
  lac_free (s->kgap);
  s->klam = lac_malloc (k * sizeof *s->klam);
  s->kact = lac_malloc (k);
  s->klin = lac_malloc (k * sizeof *s->klin);
  s->kgap = lac_malloc (k * sizeof *s->kgap);
  if (!s->klam || !s->kact || !s->klin || !s->kgap)
    {
      s->kcap = 0;
      LAC_ERROR (LAC_ENOMEM, "%zu multipliers", k);
    }
  s->kcap = k;
  return LAC_SUCCESS;
}

/* The consistent step (solve/lac_consistent.h) from the frozen one in
 * s->dU, s->klam: the derivatives of the contact terms at the current
 * coordinates and the multipliers of the linearization point. */
static int
consistent (lac_nl *s, lac_nl_iter *rec)
{
  const lac_nl_problem *p = &s->prob;
  const lac_contact *c = s->contact;
  lac_pairing_facets Mf;
  lac_consistent_info info;
  double t0 = lac_seconds ();
  if (p->master)
    {
      Mf = *p->master;
      Mf.mesh = &s->cur;
    }
  for (size_t i = 0; i < c->k; i++)
    s->klin[i] = s->lam_lin[c->macro[i]];
  lac_contact_tangent_free (s->tangent);
  s->tangent = NULL;
  int status = lac_contact_tangent_build (&s->cur, p->mat->model, p->M,
                                          s->pairing, p->master ? &Mf : NULL,
                                          p->obstacle, c, s->klin, s->kact,
                                          &s->tangent);
  s->time_tangent += lac_seconds () - t0;
  if (status)
    return status;
  lac_consistent cs = { &s->sys, s->strategy, s->tangent, s->fixed, s->kgap,
                        s->kact, s->eta, 0 };
  status = lac_consistent_solve (&cs, s->dU, s->klam, &info);
  s->gmres_last = info.iterations;
  rec->krylov = info.iterations;
  rec->krylov_residual = info.residual;
  return status;
}

/* The saddle system of step 5 by the strategy (solve/lac_strategy.h),
 * kept between iterations (its analyses made once): the statuses and
 * the multipliers of the admissible macro-elements, the total lambda as
 * the unknown, the last one as the start; then, unless the geometry is
 * frozen, the consistent step from there.  If the statuses do not hold a
 * body held by contact alone, every admissible one is active in this
 * solve (step 3 releases those in tension at the next iteration). */
static int
solve_contact (lac_nl *s, const lac_dirichlet *inc, lac_nl_iter *rec)
{
  const lac_contact *c = s->contact;
  size_t k = c->k;
  int status, kept = 0;
  if (!s->strategy && !(s->strategy = lac_strategy_alloc (s->opts.kind)))
    return LAC_ENOMEM;
  if ((status = kroom (s, k)))
    return status;
  for (size_t i = 0; i < k; i++)
    {
      s->kact[i] = s->active[c->macro[i]];
      s->klam[i] = s->kact[i] ? s->lambda[c->macro[i]] : 0.0;
    }
  s->sys = (lac_contact_system) { s->K, s->r, c->C, c->G, NULL,
                                  s->prob.nfree, s->prob.N, s->prob.N_what };
  if (s->sys.nfree > 0 && lac_system_check_held (&s->sys, s->kact))
    {
      lac_error_clear ();
      memset (s->kact, 1, k);
    }
  memset (s->dU, 0, s->ndof * sizeof *s->dU);
  lac_strategy_counts c0, c1;       /* the factorizations' time, wherever */
  lac_strategy_get_counts (s->strategy, &c0);     /* the strategy makes them */
  double t0 = lac_seconds ();
  if (s->opts.frozen || !s->strategy_set || s->gmres_last > LAG_ITERATIONS)
    {
      status = lac_strategy_set (s->strategy, &s->sys);     /* new K_T */
      s->strategy_set = !status;
      s->gmres_last = 0;
    }
  else
    status = lac_strategy_reset (s->strategy, &s->sys, &kept);
  if (!status && kept)      /* the factor of an older K_T: GMRES from the */
    for (size_t q = 0; q < inc->n; q++)     /* Dirichlet increments alone */
      s->dU[inc->dof[q]] = inc->val[q];
  else if (!status)
    status = lac_strategy_solve (s->strategy, s->kact, s->dU, s->klam);
  rec->factored = !kept;
  double t2 = lac_seconds ();
  lac_strategy_get_counts (s->strategy, &c1);
  if (!status && !s->opts.frozen)
    status = consistent (s, rec);
  double tf = c1.time_factor - c0.time_factor;
  s->time_factor += tf;
  s->time_frozen += t2 - t0 - tf;
  s->time_krylov += lac_seconds () - t2;
  for (size_t i = 0; !status && i < k; i++)             /* total lambda */
    {
      s->lambda[c->macro[i]] = s->klam[i];
      s->active[c->macro[i]] = s->kact[i];
    }
  return status;
}

/* Step 5: Dirichlet increments into K_T, r and G, solve, U += dU. */
static int
solve (lac_nl *s, lac_nl_iter *rec)
{
  lac_dirichlet inc = { 0, 0, NULL, NULL };
  int status = assemble_K (s);
  if (!status)
    status = increments (s, &inc);
  if (!status && s->contact && (status = kroom (s, s->contact->k)) == 0)
    memcpy (s->kgap, s->contact->G, s->contact->k * sizeof *s->kgap);
  if (!status)
    status = lac_dirichlet_apply (&inc, s->K, s->r);
  if (!status && s->it == 0)
    {
      /* the force the step's increments put on the free dofs: the scale
       * of the residual when every force vanishes (a rigid motion) */
      double nr = 0;
      for (size_t j = 0; j < s->ndof; j++)
        if (!s->fixed[j])
          nr += s->r[j] * s->r[j];
      s->fref = sqrt (nr);
    }
  if (!status && s->contact)
    status = lac_contact_apply_dirichlet (s->contact, inc.n, inc.dof, inc.val);
  double t0 = lac_seconds ();
  if (!status)
    status = s->contact && s->contact->k > 0 ? solve_contact (s, &inc, rec)
                                             : solve_plain (s);
  s->time_solve += lac_seconds () - t0;
  lac_free (inc.dof);
  lac_free (inc.val);
  if (status)
    return status;
  if (s->contact)                 /* inactive after the solve: lambda = 0 */
    for (size_t m = 0; m < s->nmacro; m++)
      if (!s->active[m])
        s->lambda[m] = 0;
  double nu = 0, ndu = 0;
  for (size_t j = 0; j < s->ndof; j++)
    {
      s->U[j] += s->dU[j];                             /* U += dU */
      nu += s->U[j] * s->U[j];
      ndu += s->dU[j] * s->dU[j];
    }
  memcpy (s->dU_last, s->dU, s->ndof * sizeof *s->dU_last);
  s->last_du = nu > 0 ? sqrt (ndu / nu) : sqrt (ndu);
  s->alpha = 1;
  return LAC_SUCCESS;
}

/* ---- the loop ----------------------------------------------------------- */

int
lac_nl_begin (lac_nl *s, double t)
{
  if (!s)
    LAC_ERROR (LAC_EINVAL, "NULL workspace");
  s->t = t;
  s->it = 0;
  s->converged = 0;
  s->last_du = 0;
  s->fref = 0;
  s->alpha = 1;
  s->predicted = 0;
  s->merit = s->merit_best = HUGE_VAL;
  s->settled = 0;
  if (s->strategy && lac_strategy_fallback (s->strategy))
    {
      lac_strategy_free (s->strategy);   /* try Cholesky again in every */
      s->strategy = NULL;                /* step after a fallback       */
      s->strategy_set = 0;
    }
  return LAC_SUCCESS;
}

/* Back to U_old + alpha dU, lambda_old + alpha (lambda - lambda_old), with
 * alpha halved (the last solve gave U_old + 2 alpha dU). */
static void
backtrack (lac_nl *s)
{
  double a = s->alpha;
  s->alpha = 0.5 * a;
  for (size_t j = 0; j < s->ndof; j++)
    s->U[j] -= s->alpha * s->dU_last[j];
  for (size_t m = 0; m < s->nmacro; m++)
    s->lambda[m] = s->lam_step[m] + 0.5 * (s->lambda[m] - s->lam_step[m]);
  lac_error_clear ();
}

/* Steps 1, 2 and the residual of step 4 at the current U, with the line
 * search: a step that turns a cell inside out, or (from the second solve
 * of a step on, after a solve on settled statuses: none changed) does not
 * lower max(residual, gap residual), is halved, up to LS_HALVINGS times;
 * after that it is taken as it is (or its error returned). */
static int
evaluate (lac_nl *s, lac_nl_iter *rec)
{
  /* K_T is left to the solve when the last step was made on settled
   * statuses from a residual below LAZY_K: this evaluation is then most
   * likely the last of the sub-step (quadratic convergence) */
  int want_K = !(s->it > 0 && s->settled && s->res_solved <= LAZY_K);
  for (;;)
    {
      int status = assemble (s, want_K);
      if (!status && s->prob.M)
        status = contact_update (s);
      double merit = HUGE_VAL;
      if (!status)
        {
          rec->residual = residual (s);
          merit = fmax (rec->residual, gap_residual (s));
        }
      if (status == LAC_ESING && s->it == 0 && s->predicted)
        {                         /* the predictor turned a cell inside out: */
          memcpy (s->U, s->U_save, s->ndof * sizeof *s->U);   /* without it */
          memcpy (s->lambda, s->lambda_save, s->nmacro * sizeof *s->lambda);
          s->predicted = 0;
          lac_error_clear ();
          continue;
        }
      int worse = (status == LAC_ESING && s->it >= 1)      /* inside out */
                  || (!status && s->it >= 2 && s->settled /* no better */
                      && !(merit < s->merit));
      if (!worse || s->alpha <= 1.0 / (1 << LS_HALVINGS))
        {
          if (!status)
            s->merit = merit;
          return status;
        }
      backtrack (s);                    /* U_old + alpha dU, alpha /= 2 */
      rec->backtracks++;
    }
}

int
lac_nl_iterate (lac_nl *s)
{
  lac_nl_iter rec = { 0 };
  double pen = 0;
  int status;
  if (s->converged)
    return LAC_SUCCESS;
  rec.start = lac_seconds ();
  /* Steps 1-2 and step 4's residual (the lambda of the last solve, the
   * new C) */
  if ((status = evaluate (s, &rec)))
    return status;
  memcpy (s->lam_lin, s->lambda, s->nmacro * sizeof *s->lam_lin);
  /* Step 3 on the current mean gaps (the Dirichlet increments are moved
   * into G by solve() only) */
  rec.nchanged = update_status (s, &pen);
  rec.step = (int) s->nsteps + 1;
  rec.iter = s->it + 1;
  rec.t = s->t;
  rec.k = s->contact ? s->contact->k : 0;
  rec.nactive = lac_nl_nactive (s);
  rec.max_penetration = pen;
  s->residual = rec.residual;
  if (s->it > 0 && rec.nchanged == 0 && rec.residual <= s->opts.tol
      && gap_residual (s) <= s->opts.tol)
    {
      s->converged = 1;                 /* nothing solved, no record */
      return LAC_SUCCESS;
    }
  if (s->it >= 2)
    s->merit_best = fmin (s->merit_best, s->merit);
  if (s->it >= s->opts.maxit || (s->it >= 4 && s->merit > DIVERGED
                                                          * s->merit_best))
    LAC_ERROR (LAC_EMAXITER, "load factor %g: no convergence in %d Newton "
               "iterations (residual %.3e, %zu statuses changed)", s->t,
               s->it, rec.residual, rec.nchanged);
  /* Step 5: an inexact Newton step, to a fraction of the residual (the
   * first of a step carries the new Dirichlet increments: ETA_MAX) */
  s->eta = s->it == 0 ? ETA_FIRST
           : fmax (ETA_MIN, fmin (ETA_MAX, ETA_FACTOR * rec.residual));
  memcpy (s->lam_step, s->lambda, s->nmacro * sizeof *s->lam_step);
  s->settled = rec.nchanged == 0;
  s->res_solved = rec.residual;
  if ((status = solve (s, &rec)))
    return status;
  s->first = 0;
  s->it++;
  rec.du = s->last_du;
  rec.seconds = lac_seconds () - rec.start;
  status = push_iter (s, &rec);
  return status ? status : LAC_CONTINUE;
}
