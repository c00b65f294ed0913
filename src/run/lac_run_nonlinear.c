/* lac_run_nonlinear.c -- stage 5 of a large-deformation run: the load
 *                        steps (see lac_run_nonlinear.h)
 *                                             [LAC §4.5, Alg. 1; §5.4]
 *
 * The records of the steps, and the displacements of those that get a
 * step_NNN.vtu, in run/lac_run_steplog.h.
 */
#include "run/lac_run_nonlinear.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "contact/lac_contact.h"
#include "run/lac_run_roller.h"

void
lac_run_nl_clear (lac_run_nl *nl)
{
  lac_dirichlet_free (nl->dir);
  lac_free (nl->ramp);
  lac_loadstep_free (nl->ls);
  lac_nl_free (nl->model);
  lac_run_steplog_clear (&nl->log);
  memset (nl, 0, sizeof *nl);
}

/* ---- set-up ------------------------------------------------------------- */

/* The ramp flag of the entries of a node with a frame: that of its
 * conditions with a non-zero value (they must agree), else 1. */
static int
frame_ramp (const lac_scene *sc, const lac_run_conditions *cs, size_t a,
            char *flag)
{
  long first = -1;
  *flag = 1;
  for (size_t j = cs->ptr[a]; j < cs->ptr[a + 1]; j++)
    {
      const lac_scene_dirichlet *d = &sc->dirichlet[cs->c[j].sec];
      if (cs->c[j].v == 0)
        continue;
      if (first >= 0 && (*flag != 0) != (d->ramp != 0))
        return lac_scene_error (sc, &d->sec, "ramp", LAC_EINVAL, "node %zu "
                                "has non-zero values from [dirichlet %s] and "
                                "from this section, one ramped and one not: "
                                "a node with a frame (normal = ...) takes "
                                "one ramp", a + 1,
                                sc->dirichlet[first].sec.name);
      if (first < 0)
        first = (long) cs->c[j].sec, *flag = d->ramp != 0;
    }
  return LAC_SUCCESS;
}

/* With `normal` sections: the frames of their nodes (run/lac_run_roller.h)
 * rewrite the entries there, and the ramp flags follow: the last entry's
 * of a dof (later entries win), or frame_ramp at a node with a frame. */
static int
nl_rollers (const lac_scene *sc, lac_model model, const lac_mesh *m,
            lac_run_nl *nl)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  lac_run_conditions cs = { 0, NULL, NULL };
  char *of = lac_calloc (ndof + 1, 1), *p = NULL;
  int status = of ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "ramp flags");
  for (size_t i = 0; !status && i < nl->dir->n; i++)
    of[nl->dir->dof[i]] = nl->ramp[i];
  if (!status && !(status = lac_run_rollers (sc, model, m, nl->dir))
      && nl->dir->frames)
    {
      if (!(p = lac_realloc (nl->ramp, nl->dir->n ? nl->dir->n : 1)))
        status = LAC_ERRMSG (LAC_ENOMEM, "ramp flags");
      else
        nl->ramp = p;
      if (!status)
        status = lac_run_conditions_build (sc, model, m, NULL, &cs);
      for (size_t i = 0; !status && i < nl->dir->n; i++)
        {
          size_t q = nl->dir->dof[i], a = q / (size_t) m->dim;
          nl->ramp[i] = of[q];
          if (lac_frames_of (nl->dir->frames, a))
            status = frame_ramp (sc, &cs, a, nl->ramp + i);
        }
    }
  lac_run_conditions_clear (&cs);
  lac_free (of);
  return status;
}

/* Dirichlet data at t = 1 with the ramp flag of each entry; the reference
 * imposed value (the first non-zero ramped one). */
static int
nl_dirichlet (const lac_scene *sc, lac_model model, const lac_mesh *m,
              lac_run_nl *nl)
{
  int status = LAC_SUCCESS;
  if (!(nl->dir = lac_dirichlet_alloc ()))
    return LAC_ENOMEM;
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      const lac_scene_dirichlet *bc = &sc->dirichlet[k];
      const lac_group *g = lac_mesh_group (m, bc->group);
      size_t n0 = nl->dir->n;
      for (int c = 0; c < m->dim && !status; c++)
        if (bc->fixed[c])
          {
            status = lac_dirichlet_add_group (nl->dir, m, g, c, bc->value[c]);
            if (bc->ramp && bc->value[c] != 0 && nl->log.imposed_ref == 0)
              nl->log.imposed_ref = bc->value[c];
          }
      char *p = lac_realloc (nl->ramp, nl->dir->n ? nl->dir->n : 1);
      if (!p)
        return LAC_ERRMSG (LAC_ENOMEM, "ramp flags");
      nl->ramp = p;
      memset (nl->ramp + n0, bc->ramp ? 1 : 0, nl->dir->n - n0);
      if (bc->kind == LAC_BC_NORMAL && bc->ramp && bc->normal != 0
          && nl->log.imposed_ref == 0)
        nl->log.imposed_ref = bc->normal;
    }
  return status ? status : nl_rollers (sc, model, m, nl);
}

/* The problem of solve/lac_nonlinear.h and its workspace. */
/* The strategy: the one asked for (the command line, else [contact]),
 * else the first type that factorizes as [scene] solver says. */
static lac_strategy_kind
nl_strategy (const lac_scene *sc, int strategy, size_t nfree)
{
  static const lac_strategy_factor of_solver[] =      /* lac_solver_kind */
    { [LAC_SOLVER_DENSE] = LAC_FACTOR_DENSE,
      [LAC_SOLVER_UMFPACK] = LAC_FACTOR_LU,
      [LAC_SOLVER_CHOLMOD] = LAC_FACTOR_CHOLESKY };
  int want = strategy ? strategy
             : sc->ncontact ? sc->contact[sc->contact_loop].strategy
             : LAC_STRATEGY_AUTO;
  if (want != LAC_STRATEGY_AUTO)
    return (lac_strategy_kind) want;
  return lac_strategy_choose_factor (of_solver[sc->scene.solver], nfree);
}

/* The loop's strategy, made now to give it the coordinates: the rigid
 * motions of the current ones (lac_nl's x = X + U, read at each new
 * pattern of the system) are the near-null space of K_T for the
 * multigrid of petsc (chapter 13: on the CI ring 90 iterations per solve
 * with them, 106 with the reference coordinates, 260 without); the other
 * types ignore them.  Never given a mesh (lac_strategy_set_mesh): the
 * cells' assembly is linear elastic, K_T comes from lac_nl. */
static int
nl_strategy_alloc (lac_run_nl *nl, int dim, lac_strategy_kind kind)
{
  if (!(nl->ls->loop->strategy = lac_strategy_alloc (kind)))
    return LAC_EDEP;                   /* the message says which and why */
  lac_strategy_set_coordinates (nl->ls->loop->strategy, dim,
                                nl->model->cur.x);
  return LAC_SUCCESS;
}

static int
nl_setup (const lac_scene *sc, int strategy, const lac_mesh *m,
          const lac_run_material *mat, const lac_run_setup *setup,
          const lac_run_system *sys, lac_run_nl *nl)
{
  int status;
  if ((status = nl_dirichlet (sc, mat->hyper.model, m, nl))
      || (status = lac_run_steplog_init (&nl->log, sc, m, 1.0)))
    return status;
  lac_nl_problem *p = &nl->prob;
  *p = (lac_nl_problem) { .mesh = m, .mat = &mat->hyper, .F = sys->F,
                          .dir = nl->dir, .ramp = nl->ramp,
                          .nfree = sys->nfree, .N = sys->N,
                          .N_what = (const char *const *) sys->N_what };
  if (sc->ncontact)
    p->set = &setup->set;                      /* every pair */
  lac_nl_opts o;
  lac_nl_opts_init (&o);
  o.kind = lac_strategy_choose ((lac_strategy_kind) nl_strategy
                                 (sc, strategy, sys->nfree), sys->ndof,
                                 lac_contact_set_nslot (&setup->set),
                                 sys->nfree);
  if (o.kind == LAC_NSTRATEGIES)
    return lac_scene_error (sc, &sc->contact[sc->contact_loop].sec,
                            "strategy", LAC_EINVAL, "%s",
                            lac_error_message ());
  o.tol = sc->steps.tol;
  o.maxit = sc->steps.maxit;
  o.frozen = sc->steps.tangent == 1;
  o.off = sc->ncontact ? sc->contact[sc->contact_loop].rules_off : 0;
  if (!(nl->model = lac_nl_alloc (p, &o))
      || !(nl->ls = lac_loadstep_alloc (nl->model, &o)))
    return LAC_ENOMEM;       /* each pair's shrink fit: t delta, from its
                                offset (lac_run_setup.c, make_pair) */
  return nl_strategy_alloc (nl, m->dim, o.kind);
}

/* ---- one load step per call --------------------------------------------- */

static void
record_step (lac_run_nl *nl, size_t j, int dim)
{
  const lac_newton *s = nl->ls->loop;
  lac_run_step_record *q = &nl->log.step[j];
  q->solver = nl->ls->steps[nl->ls->nsteps - 1];
  q->imposed = q->solver.t * nl->log.imposed_ref;
  lac_run_steplog_monitor (&nl->log, nl->dir->frames, s->U, dim, q->um);
  q->force = lac_nl_contact_force (nl->model, s->lambda);
  q->lambda_min = 0;
  for (size_t m = 0; m < s->nslot; m++)
    q->lambda_min = fmin (q->lambda_min, s->lambda[m]);
}

static void
report_step (const lac_scene *sc, const lac_run_nl *nl, size_t j, int dim,
             char *progress, size_t size)
{
  const lac_run_step_record *q = &nl->log.step[j];
  const lac_nl_step *h = &q->solver;
  char mon[80] = "", cut[80] = "";
  if (nl->log.monitor != SIZE_MAX)
    snprintf (mon, sizeof mon, ", %s %s = %.4f", sc->steps.monitor,
              dim == 2 ? "u_y" : "u_z", q->um[dim - 1]);
  if (h->cuts)
    snprintf (cut, sizeof cut, " (step cut %d time%s: %d sub-steps)",
              h->cuts, h->cuts == 1 ? "" : "s", h->substeps);
  snprintf (progress, size, "step %zu/%zu: t = %.4f (imposed %.3f), %d "
            "Newton iteration%s%s, residual %.1e, %zu/%zu active%s; "
            "assembly %.1f s, pairing %.1f s, factorization %.1f s, solves "
            "%.1f s, step %.1f s", j + 1, nl->log.nfactor, h->t, q->imposed,
            h->iters, h->iters == 1 ? "" : "s", cut, h->residual, h->nactive,
            h->k, mon, h->time_assemble, h->time_pairing, h->time_factor,
            h->time_solve - h->time_factor, h->seconds);
}

/* The line of one Newton iteration. */
static void
report_iter (const lac_run_nl *nl, size_t j, char *progress, size_t size)
{
  const lac_newton *s = nl->ls->loop;
  const lac_newton_record *r = &s->hist[s->nhist - 1];
  char cut[160] = "", gm[48] = "";
  if (r->cuts > nl->cuts_seen)
    snprintf (cut, sizeof cut, "; sub-step cut (%.100s), now to t = %.4f",
              nl->ls->cut_msg, r->t);
  if (r->krylov_iterations > 0)
    snprintf (gm, sizeof gm, ", %d GMRES%s", r->krylov_iterations,
              r->factored ? " (K_T factored)" : "");
  snprintf (progress, size, "step %zu/%zu iteration %d: residual %.1e, %zu "
            "status%s changed, %zu/%zu active%s, %.2f s%s", j + 1,
            nl->log.nfactor, nl->ls->iters, r->residual, r->nchanged,
            r->nchanged == 1 ? "" : "es", r->nactive, r->k, gm, r->seconds,
            cut);
}

/* The step converged: its records, its displacement if it gets a file. */
static int
step_done (const lac_scene *sc, const lac_mesh *m, const lac_run_setup *setup,
           lac_run_nl *nl, size_t j, char *progress, size_t size)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  const lac_nl *s = nl->model;
  double *u;
  int status;
  record_step (nl, j, m->dim);
  if ((status = lac_run_steplog_mults (&nl->log, &s->cur, setup, s->data.P,
                                       s->contact, nl->ls->loop,
                                       (int) j + 1)))
    return status;
  if ((u = lac_run_steplog_keep (&nl->log, j, sc->steps.vtu_every,
                                 nl->ls->loop->U, ndof)))
    lac_frames_to_global (nl->dir->frames, u);
  report_step (sc, nl, j, m->dim, progress, size);
  return LAC_SUCCESS;
}

int
lac_run_nl_solve (const lac_scene *sc, int strategy, const lac_mesh *m,
                  const lac_run_material *mat, const lac_run_setup *setup,
                  const lac_run_system *sys, lac_run_nl *nl, double *u,
                  char *progress, size_t size)
{
  size_t ndof = (size_t) m->dim * m->nnodes, j;
  int status;
  if (!nl->ls && (status = nl_setup (sc, strategy, m, mat, setup, sys,
                                      nl)))
    return status;
  j = nl->log.next;
  if (!nl->in_step)
    {
      if ((status = lac_loadstep_begin (nl->ls, nl->log.factor[j])))
        return status;
      nl->in_step = 1;
      nl->cuts_seen = 0;
    }
  status = lac_loadstep_iterate (nl->ls);
  if (status == LAC_CONTINUE)
    {
      report_iter (nl, j, progress, size);
      nl->cuts_seen = nl->ls->loop->hist[nl->ls->loop->nhist - 1].cuts;
      return LAC_CONTINUE;
    }
  nl->in_step = 0;
  if (status)
    {
      char msg[600];
      snprintf (msg, sizeof msg, "%s", lac_error_message ());
      return lac_error_set (status, sc->path, "load step %zu of %zu "
                            "(load factor %g): %s", j + 1, nl->log.nfactor,
                            nl->log.factor[j], msg);
    }
  if ((status = step_done (sc, m, setup, nl, j, progress, size)))
    return status;
  if (++nl->log.next < nl->log.nfactor)
    return LAC_CONTINUE;
  memcpy (u, nl->ls->loop->U, ndof * sizeof *u);
  lac_frames_to_global (nl->dir->frames, u);    /* u = T u~ (rollers) */
  return LAC_SUCCESS;
}
