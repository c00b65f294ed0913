/* lac_run_solve.c -- stage 5 of a linear run: the solution
 *                    (see lac_run_solve.h)        [LAC (8), §4.5, Alg. 1]
 */
#include "run/lac_run_solve.h"
#include <math.h>

#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "io/lac_scene_query.h"
#include "run/lac_run_mesh.h"
#include "run/lac_run_scene.h"

void
lac_run_solution_clear (lac_run_solution *sol)
{
  lac_free (sol->u);
  lac_newton_free (sol->newton);
  lac_linear_model_clear (&sol->lin);
  lac_strategy_free (sol->plain);
  memset (sol, 0, sizeof *sol);
}

/* A type that factorizes nothing: its Krylov iterations (all solves),
 * the true residual of its last solve and its processes, for the
 * summary. */
static void
krylov_counts (const lac_strategy *s, lac_run_solution *sol)
{
  lac_strategy_counts c;
  if (lac_strategy_get_type (s)->factor != LAC_FACTOR_NONE)
    return;
  lac_strategy_get_counts (s, &c);
  sol->krylov = 1;
  sol->krylov_iterations = c.iterations;
  sol->krylov_residual = c.last_residual;
  sol->processes = c.processes;
}

/* kop's product: the strategy's K x (sol->kst). */
static int
kmul_root (void *solution, const double *x, double *y)
{
  lac_run_solution *sol = solution;
  return lac_strategy_kmul (sol->kst, sol->kop.n, x, y);
}

/* kop's norm: the strategy's ||K||_inf. */
static int
knorm_root (void *solution, double *norm)
{
  const lac_run_solution *sol = solution;
  return lac_strategy_knorm (sol->kst, norm);
}

/* When the strategy assembles its own K from the cells (petsc,
 * lac_strategy_own_k): the root keeps nothing of K (the residuals take
 * K x and ||K||_inf from the strategy: cs's Kop; diag(K) stays on the
 * processes, which weigh the contact columns with it).  Stage 4 made no
 * K (lac_run_system_stiffness), or, when it kept one, K is freed before
 * the solve (a million hex8 dofs: 1 GB less on the root; chapter 13,
 * section 6).  Else nothing changes. */
static int
drop_root_k (lac_run_system *sys, lac_strategy *st, lac_run_solution *sol,
             lac_contact_system *cs)
{
  if (!lac_strategy_own_k (st, sys->ndof))
    {
      if (!sys->K)
        LAC_ERROR (LAC_ESANITY, "stage 4 kept no K, but the strategy "
                   "needs one");
      return LAC_SUCCESS;
    }
  lac_csc_free (sys->K);
  sys->K = NULL;
  sol->kst = st;
  sol->kop = (lac_stiffness_op) { sys->ndof, sol, kmul_root, knorm_root };
  cs->K = NULL;
  cs->Kop = &sol->kop;
  return LAC_SUCCESS;
}

/* K u = b, no contact (k = 0), by the strategy asked for (petsc from
 * the cells: the root's K freed first, as with contact). */
static int
solve_plain_strategy (int strategy, lac_run_system *sys,
                      lac_run_solution *sol, char *progress, size_t size)
{
  static const double G[1] = { 0 };
  double lambda[1] = { 0 };
  lac_csc *C = lac_csc_alloc (sys->ndof, 0, 0);
  lac_contact_system cs = { sys->K, sys->b, C, G, NULL, 0, NULL, NULL, NULL };
  lac_strategy_kind kind = (lac_strategy_kind) strategy;   /* any, k = 0 */
  lac_strategy *s = NULL;
  lac_strategy_counts c;
  int status = !C || !(s = lac_strategy_alloc (kind)) ? LAC_ENOMEM
               : LAC_SUCCESS;
  if (!status)
    {
      lac_strategy_set_coordinates (s, sys->coord_dim, sys->x);
      lac_strategy_set_mesh (s, sys->cells.mesh ? &sys->cells : NULL);
      memset (sol->u, 0, sys->ndof * sizeof *sol->u);
      if (!(status = drop_root_k (sys, s, sol, &cs))
          && !(status = lac_strategy_set (s, &cs)))
        status = lac_strategy_solve (s, "", sol->u, lambda);
      krylov_counts (s, sol);
      lac_strategy_get_counts (s, &c);
    }
  if (!status && sol->krylov)
    snprintf (progress, size, "%s: %s%s%s%s, %d iterations, true "
              "residual %.1e", lac_strategy_name (kind),
              lac_strategy_method (s), sol->why ? " (" : "",
              sol->why ? sol->why : "", sol->why ? ")" : "",
              c.last_iterations, c.last_residual);
  else if (!status)
    snprintf (progress, size, "%s, rcond %.1e", lac_strategy_method (s),
              sol->rcond = c.rcond);
  if (!status && lac_strategy_posts (s))
    sol->plain = s;             /* kept: stage 6 on the processes */
  else
    {
      lac_strategy_free (s);
      sol->kst = NULL;
    }
  lac_csc_free (C);
  return status;
}

/* K is singular although stage 4 found every body held against rigid
 * motion (lac_run_system.c): the solver's hint about rigid motions is
 * replaced by what remains, rounding, and the numbers that cause it. */
static int
singular_by_rounding (const lac_scene *sc, lac_solver_kind kind)
{
  static const char hint[] = "; is the body fixed against rigid motion?";
  char msg[600];
  double emin = HUGE_VAL, emax = 0, numax = -1;
  size_t n;
  lac_run_inner_message (msg, sizeof msg);
  n = strlen (msg);
  if (n >= sizeof hint - 1 && !strcmp (msg + n - (sizeof hint - 1), hint))
    msg[n - (sizeof hint - 1)] = '\0';
  for (size_t k = 0; k < sc->nmaterial; k++)
    {
      emin = fmin (emin, sc->material[k].E);
      emax = fmax (emax, sc->material[k].E);
      numax = fmax (numax, sc->material[k].nu);
    }
  return lac_error_set (LAC_ESING, sc->path, "stiffness is singular (%s "
                        "solver): %s; every body is held against rigid "
                        "motion, so K is singular to rounding: E from %g to "
                        "%g, nu up to %g (a contrast of E above about 1e12, "
                        "or cells of very different sizes, does this)",
                        lac_solver_kind_name (kind), msg, emin, emax, numax);
}

/* K u = b, no contact. */
static int
solve_plain (const lac_scene *sc, const lac_run_system *sys,
             lac_run_solution *sol, char *progress, size_t size)
{
  lac_solver_kind kind = (lac_solver_kind) sc->scene.solver;
  lac_solver *s = lac_solver_alloc (kind);
  lac_solver_info info;
  int status;
  if (!s)
    return LAC_ENOMEM;
  status = lac_solver_factor (s, sys->K);                /* K = L U, L L^T */
  if (status == LAC_ESING)
    status = singular_by_rounding (sc, kind);
  if (!status)
    status = lac_solver_solve (s, sys->b, sol->u);       /* u = K^-1 b */
  if (!status && lac_solver_get_info (s, &info) == LAC_SUCCESS)
    sol->rcond = info.rcond;
  lac_solver_free (s);
  if (!status)
    snprintf (progress, size, "%s, rcond %.1e", lac_solver_kind_name (kind),
              sol->rcond);
  return status;
}

/* The smallest Young modulus of the scene: E of rho (lac_newton.h). */
static double
young_min (const lac_scene *sc)
{
  double E = HUGE_VAL;
  for (size_t k = 0; k < sc->nmaterial; k++)
    E = fmin (E, sc->material[k].E);
  return E < HUGE_VAL ? E : 1.0;
}

/* Why auto took `kind` in the run ctx rather than by size (NULL: it
 * did not), for the progress line. */
static const char *
auto_why (lac_strategy_kind want, lac_strategy_kind kind, size_t n,
          size_t k, size_t nfree, const lac_strategy_context *ctx)
{
  lac_strategy_kind by_size = lac_strategy_choose (want, n, k, nfree);
  if (want != LAC_STRATEGY_AUTO || kind == by_size)
    return NULL;
  if (kind == LAC_STRATEGY_SADDLE && !lac_strategy_solves_rows (by_size))
    return "auto: friction on a body held by contact alone";
  return ctx->processes > 1 ? "auto: more than one MPI process"
         : !ctx->factor_fits
         ? "auto: a Cholesky factor would not fit in --max-memory"
         : "auto: in 3D a Cholesky factor this large costs far more memory "
           "than it saves time";
}

/* The strategy of a scene with contact: asked for (the command line,
 * else the scene's [contact]), or auto's choice in the run ctx;
 * LAC_NSTRATEGIES with a message if it does not apply. */
static lac_strategy_kind
contact_kind (const lac_scene *sc, int strategy,
              const lac_strategy_context *ctx, const lac_run_setup *setup,
              const lac_run_system *sys)
{
  const lac_scene_contact *c = &sc->contact[sc->contact_loop];
  lac_strategy_kind want = (lac_strategy_kind) (strategy ? strategy
                                                : c->strategy);
  lac_strategy_kind kind = lac_strategy_choose_in (want, sys->ndof,
                                                   setup->data.all->k,
                                                   sys->nfree, ctx);
  if (want == LAC_STRATEGY_AUTO && lac_scene_friction (sc)
      && kind != LAC_NSTRATEGIES && !lac_strategy_solves_rows (kind))
    kind = LAC_STRATEGY_SADDLE;    /* friction: a direct solve of its rows */
  return kind;
}

/* The loop of Algorithm 1 on the linear model of the pair: the strategy
 * chosen, the loop begun. */
static int
contact_start (const lac_scene *sc, int strategy,
               const lac_strategy_context *ctx, lac_run_setup *setup,
               lac_run_system *sys, lac_run_solution *sol)
{
  const lac_scene_contact *c = &sc->contact[sc->contact_loop];
  lac_strategy_kind want = (lac_strategy_kind) (strategy ? strategy
                                                : c->strategy);
  lac_contact_model model;
  lac_newton_opts o;
  lac_strategy *st;
  int status;
  sol->cs = (lac_contact_system) { sys->K, sys->b, NULL, NULL, NULL,
                                   sys->nfree, sys->N,
                                   (const char *const *) sys->N_what, NULL };
  sol->strategy = contact_kind (sc, strategy, ctx, setup, sys);
  if (sol->strategy == LAC_NSTRATEGIES)
    return lac_scene_error (sc, &c->sec, "strategy", LAC_EINVAL, "%s",
                            lac_error_message ());
  sol->why = auto_why (want, sol->strategy, sys->ndof, setup->data.all->k,
                       sys->nfree, ctx);
  if (!(st = lac_strategy_alloc (sol->strategy)))
    return LAC_EDEP;           /* the message says which and why */
  lac_strategy_set_coordinates (st, sys->coord_dim, sys->x);
  lac_strategy_set_mesh (st, sys->cells.mesh ? &sys->cells : NULL);
  if ((status = drop_root_k (sys, st, sol, &sol->cs))
      || (status = lac_linear_model_init_set (&sol->lin, &sol->cs,
                                              &setup->set, &setup->data,
                                              sys->dir, young_min (sc),
                                              &model)))
    {
      lac_strategy_free (st);
      return status;
    }
  if (sys->curves)             /* load steps: the Dirichlet part of G */
    lac_linear_model_keep_lift (&sol->lin, &sys->lift);
  lac_newton_opts_init (&o);
  o.kind = sol->strategy;
  o.maxit = c->max_iterations;
  o.off = c->rules_off;
  if (!(sol->newton = lac_newton_alloc (&model, &o)))
    {
      lac_strategy_free (st);
      return LAC_ENOMEM;
    }
  sol->newton->strategy = st;
  return lac_newton_begin (sol->newton);
}

/* "N Krylov iterations (true residual r), M with the refinement". */
static void
krylov_text (const lac_newton_record *h, char *buf, size_t size)
{
  snprintf (buf, size, "%d Krylov iteration%s (true residual %.1e), %d "
            "with the refinement", h->krylov_iterations,
            h->krylov_iterations == 1 ? "" : "s", h->krylov_residual,
            h->cg_iterations);
}

int
lac_run_solve_summary (const lac_run_solution *sol, lac_summary *sum)
{
  int status;
  if (!sol->krylov)
    return LAC_SUCCESS;
  if ((status = lac_summary_add (sum, "processes", "%d", sol->processes))
      || (status = lac_summary_add (sum, "solver_iterations", "%d",
                                    sol->krylov_iterations)))
    return status;
  return lac_summary_add (sum, "solver_residual", LAC_SUMMARY_REAL,
                          sol->krylov_residual);
}

int
lac_run_strategy_summary (const lac_strategy *s, lac_summary *sum)
{
  lac_run_solution sol;
  memset (&sol, 0, sizeof sol);
  if (s)
    krylov_counts (s, &sol);
  return lac_run_solve_summary (&sol, sum);
}

/* One iteration of [LAC Alg. 1]; LAC_CONTINUE until it settles. */
static int
contact_iterate (const lac_scene *sc, const lac_run_setup *setup,
                 const lac_run_system *sys, lac_run_solution *sol,
                 char *progress, size_t size)
{
  lac_newton *nw = sol->newton;
  const lac_newton_record *h;
  int status = lac_newton_iterate (nw);
  if (status != LAC_SUCCESS && status != LAC_CONTINUE)
    {
      char msg[600];
      lac_run_inner_message (msg, sizeof msg);
      return lac_error_set (status, sc->path, "%sactive-set iteration "
                            "%zu: %s", sol->step,
                            lac_newton_iterations (nw) + 1, msg);
    }
  krylov_counts (nw->strategy, sol);
  if (status == LAC_SUCCESS)
    {
      h = nw->nhist ? &nw->hist[nw->nhist - 1] : NULL;
      memcpy (sol->u, nw->U, sys->ndof * sizeof *sol->u);
      snprintf (progress, size, "%s%s%s%s, active set: %zu iteration%s, "
                "%zu of %zu multipliers active%s",
                lac_strategy_method (nw->strategy), sol->why ? " (" : "",
                sol->why ? sol->why : "", sol->why ? ")" : "",
                lac_newton_iterations (nw),
                lac_newton_iterations (nw) > 1 ? "s" : "",
                lac_newton_nactive (nw),
                setup->data.all->k, sol->krylov && h ? "; last solve: "
                : "");
      if (sol->krylov && h)
        krylov_text (h, progress + strlen (progress),
                     size - strlen (progress));
      return LAC_SUCCESS;
    }
  h = &nw->hist[nw->nhist - 1];
  snprintf (progress, size, "active set %d: %zu active, %zu changed%s, "
            "residual %.1e, ", h->iter, h->nactive, h->nchanged,
            h->damped ? " (cycle: damped)" : "", h->backward_error);
  if (sol->krylov)
    krylov_text (h, progress + strlen (progress), size - strlen (progress));
  else
    snprintf (progress + strlen (progress), size - strlen (progress),
              "%d CG iteration%s, %d factorization%s", h->cg_iterations,
              h->cg_iterations == 1 ? "" : "s", h->factorizations,
              h->factorizations == 1 ? "" : "s");
  return LAC_CONTINUE;
}

/* Without contact and nothing asked for ([scene] solver, a strategy):
 * the strategy auto takes in the run ctx if it factorizes nothing (N > 1
 * MPI processes, or a factor that does not fit), else 0: the scene's
 * solver. */
static int
plain_auto (const lac_scene *sc, const lac_strategy_context *ctx,
            const lac_run_system *sys)
{
  lac_strategy_kind kind = lac_strategy_choose_in (LAC_STRATEGY_AUTO,
                                                   sys->ndof, 0, 0, ctx);
  const lac_strategy_type *t = lac_strategy_type_of (kind);
  if (!lac_run_mesh_auto (sc, 0) || !t || t->factor != LAC_FACTOR_NONE)
    return LAC_STRATEGY_AUTO;
  return kind;
}

int
lac_run_solve_k_from_cells (const lac_scene *sc, int strategy,
                            const lac_strategy_context *ctx,
                            const lac_run_setup *setup,
                            const lac_run_system *sys)
{
  const lac_strategy_type *t;
  int kind = setup->data.all ? (int) contact_kind (sc, strategy, ctx, setup,
                                                   sys)
             : strategy ? strategy : plain_auto (sc, ctx, sys);
  if (kind == LAC_STRATEGY_AUTO || kind == LAC_NSTRATEGIES)
    {
      lac_error_clear ();        /* stage 5 says it, if it still holds */
      return 0;                  /* the scene's solver; or an error */
    }
  t = lac_strategy_type_of (kind);
  return t && t->ops && t->ops->own_k && sys->coord_dim >= 2;
}

int
lac_run_solve (const lac_scene *sc, int strategy,
               const lac_strategy_context *ctx, lac_run_setup *setup,
               lac_run_system *sys, lac_run_solution *sol, char *progress,
               size_t size)
{
  int status;
  if (!sol->u && !(sol->u = lac_malloc (sys->ndof * sizeof *sol->u)))
    LAC_ERROR (LAC_ENOMEM, "displacement of %zu dofs", sys->ndof);
  if (!setup->data.all && !strategy
      && (strategy = plain_auto (sc, ctx, sys)))
    sol->why = auto_why (LAC_STRATEGY_AUTO, strategy, sys->ndof, 0, 0, ctx);
  if (!setup->data.all)
    return strategy != LAC_STRATEGY_AUTO
           ? solve_plain_strategy (strategy, sys, sol, progress, size)
           : solve_plain (sc, sys, sol, progress, size);
  if (!sol->newton
      && (status = contact_start (sc, strategy, ctx, setup, sys, sol)))
    return status;
  status = contact_iterate (sc, setup, sys, sol, progress, size);
  sys->contact = setup->data.all;       /* the loop may have paired again */
  return status;
}
