/* lac_run_nonlinear.c -- stage 5 of a large-deformation run: the load
 *                        steps (see lac_run_nonlinear.h)
 *                                             [LAC §4.5, Alg. 1; §5.4]
 *
 * The solve stage keeps a copy of the displacement of each step that gets
 * a step_NNN.vtu (only those, only when [steps] vtu_every = K > 0: (n / K)
 * * dofs numbers), so that the output stage can write them through the
 * same batch as the other files: a run that fails at step 40 leaves the
 * files of an earlier run untouched.
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
  lac_free (nl->factor);
  lac_free (nl->step);
  lac_free (nl->mult);
  lac_free (nl->kept);
  lac_free (nl->ukept);
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
            if (bc->ramp && bc->value[c] != 0 && nl->imposed_ref == 0)
              nl->imposed_ref = bc->value[c];
          }
      char *p = lac_realloc (nl->ramp, nl->dir->n ? nl->dir->n : 1);
      if (!p)
        return LAC_ERRMSG (LAC_ENOMEM, "ramp flags");
      nl->ramp = p;
      memset (nl->ramp + n0, bc->ramp ? 1 : 0, nl->dir->n - n0);
      if (bc->kind == LAC_BC_NORMAL && bc->ramp && bc->normal != 0
          && nl->imposed_ref == 0)
        nl->imposed_ref = bc->normal;
    }
  return status ? status : nl_rollers (sc, model, m, nl);
}

/* The load factors: `start` (if > 0), then n equal steps to 1. */
static int
nl_factors (const lac_scene_steps *st, lac_run_nl *nl)
{
  int n = st->n > 0 ? st->n : 1;
  double t0 = st->start > 0 ? st->start : 0.0;
  nl->nfactor = (size_t) n + (t0 > 0);
  nl->factor = lac_malloc (nl->nfactor * sizeof *nl->factor);
  nl->step = lac_calloc (nl->nfactor, sizeof *nl->step);
  if (!nl->factor || !nl->step)
    LAC_ERROR (LAC_ENOMEM, "%zu load steps", nl->nfactor);
  size_t j = 0;
  if (t0 > 0)
    nl->factor[j++] = t0;
  for (int k = 1; k <= n; k++)
    nl->factor[j++] = k == n ? 1.0 : t0 + (1 - t0) * (double) k / n;
  return LAC_SUCCESS;
}

int
lac_run_nl_step_file (size_t j, size_t n, int K)
{
  return K > 0 && ((j + 1) % (size_t) K == 0 || j + 1 == n);
}

/* Room for the displacements of the step files before the last one. */
static int
nl_kept_alloc (int K, size_t ndof, lac_run_nl *nl)
{
  size_t n = 0;
  for (size_t j = 0; j + 1 < nl->nfactor; j++)
    n += (size_t) lac_run_nl_step_file (j, nl->nfactor, K);
  if (n == 0)
    return LAC_SUCCESS;
  nl->kept = lac_malloc (n * sizeof *nl->kept);
  nl->ukept = lac_malloc (n * ndof * sizeof *nl->ukept);
  if (!nl->kept || !nl->ukept)
    LAC_ERROR (LAC_ENOMEM, "displacements of %zu step files", n);
  return LAC_SUCCESS;
}

/* The node of the [steps] monitor group. */
static int
nl_monitor (const lac_scene *sc, const lac_mesh *m, lac_run_nl *nl)
{
  const lac_scene_steps *st = &sc->steps;
  nl->monitor = SIZE_MAX;
  if (!st->monitor)
    return LAC_SUCCESS;
  const lac_group *g = lac_mesh_group (m, st->monitor);
  if (!g || g->nnodes == 0)
    return lac_scene_error (sc, &st->sec, "monitor", LAC_EINVAL,
                            "%s in mesh '%s' (a physical point is best)",
                            g ? "the group has no node"
                              : "no physical group of that name",
                            sc->mesh.file);
  nl->monitor = g->node[0];
  return LAC_SUCCESS;
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
  size_t ndof = (size_t) m->dim * m->nnodes;
  if ((status = nl_dirichlet (sc, mat->hyper.model, m, nl)) || (status = nl_factors (&sc->steps,
                                                                   nl))
      || (status = nl_monitor (sc, m, nl))
      || (status = nl_kept_alloc (sc->steps.vtu_every, ndof, nl)))
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

static int
push_mult (lac_run_nl *nl, lac_run_nl_mult **q)
{
  if (lac_grow (&nl->mult, nl->nmult + 1, &nl->capmult, sizeof *nl->mult,
                256))
    LAC_ERROR (LAC_ENOMEM, "multiplier records");
  *q = &nl->mult[nl->nmult++];
  memset (*q, 0, sizeof **q);
  return LAC_SUCCESS;
}

/* Append the multipliers of the converged step to the records: value,
 * mean gap, status and the centroid of T^m cap Gamma_C (current
 * coordinates). */
static int
record_mults (lac_run_nl *nl, const lac_run_setup *st, int step)
{
  const lac_nl *s = nl->model;
  const lac_newton *loop = nl->ls->loop;
  const lac_contact *c = s->contact;
  int dim = s->cur.dim, nodes[LAC_MAX_FACE_NODES], status;
  lac_map mp;
  for (size_t i = 0; c && i < c->k; i++)
    {
      lac_run_nl_mult *q = NULL;
      size_t m = c->macro[i], pr = lac_contact_set_pair_of (&st->set, m);
      const lac_macro *M = st->macro[pr];
      const lac_pairing *P = s->data.P[pr];
      size_t ml = m - st->set.offset[pr];        /* in its pair */
      double wsum = 0;
      if ((status = push_mult (nl, &q)))
        return status;
      q->step = step;
      q->macro = m;
      q->lambda = loop->lambda[m];
      q->gap = c->area[i] > 0 ? loop->d[m] / c->area[i] : 0.0;
      q->covered = c->area[i];
      q->active = loop->active[m];
      for (size_t j = M->ptr[ml]; j < M->ptr[ml + 1]; j++)  /* centroid */
        for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
          {
            int nn = lac_contact_facet_eval (&s->cur, M->cell[j], M->face[j],
                                             P->xs + p * (size_t) (dim - 1),
                                             nodes, &mp);
            if (nn < 0)
              return -nn;
            wsum += P->w[p];
            for (int k = 0; k < dim; k++)
              q->x[k] += P->w[p] * mp.x[k];
          }
      for (int k = 0; k < dim && wsum > 0; k++)
        q->x[k] /= wsum;
    }
  return LAC_SUCCESS;
}

static void
record_step (lac_run_nl *nl, size_t j, int dim)
{
  const lac_newton *s = nl->ls->loop;
  lac_run_nl_step *q = &nl->step[j];
  q->solver = nl->ls->steps[nl->ls->nsteps - 1];
  q->imposed = q->solver.t * nl->imposed_ref;
  const double *R = nl->monitor != SIZE_MAX
                    ? lac_frames_of (nl->dir->frames, nl->monitor) : NULL;
  for (int k = 0; k < dim && nl->monitor != SIZE_MAX; k++)
    {
      const double *U = s->U + nl->monitor * (size_t) dim;
      q->um[k] = R ? 0 : U[k];
      for (int i = 0; R && i < dim; i++)       /* in the axes: R U~ */
        q->um[k] += R[3 * k + i] * U[i];
    }
  q->force = lac_nl_contact_force (nl->model, s->lambda);
  q->lambda_min = 0;
  for (size_t m = 0; m < s->nslot; m++)
    q->lambda_min = fmin (q->lambda_min, s->lambda[m]);
}

static void
report_step (const lac_scene *sc, const lac_run_nl *nl, size_t j, int dim,
             char *progress, size_t size)
{
  const lac_run_nl_step *q = &nl->step[j];
  const lac_nl_step *h = &q->solver;
  char mon[80] = "", cut[80] = "";
  if (nl->monitor != SIZE_MAX)
    snprintf (mon, sizeof mon, ", %s %s = %.4f", sc->steps.monitor,
              dim == 2 ? "u_y" : "u_z", q->um[dim - 1]);
  if (h->cuts)
    snprintf (cut, sizeof cut, " (step cut %d time%s: %d sub-steps)",
              h->cuts, h->cuts == 1 ? "" : "s", h->substeps);
  snprintf (progress, size, "step %zu/%zu: t = %.4f (imposed %.3f), %d "
            "Newton iteration%s%s, residual %.1e, %zu/%zu active%s; "
            "assembly %.1f s, pairing %.1f s, factorization %.1f s, solves "
            "%.1f s, step %.1f s", j + 1, nl->nfactor, h->t, q->imposed,
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
            nl->nfactor, nl->ls->iters, r->residual, r->nchanged,
            r->nchanged == 1 ? "" : "es", r->nactive, r->k, gm, r->seconds,
            cut);
}

/* The step converged: its records, its displacement if it gets a file. */
static int
step_done (const lac_scene *sc, const lac_mesh *m, const lac_run_setup *setup,
           lac_run_nl *nl, size_t j, char *progress, size_t size)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  int status;
  record_step (nl, j, m->dim);
  if ((status = record_mults (nl, setup, (int) j + 1)))
    return status;
  if (j + 1 < nl->nfactor
      && lac_run_nl_step_file (j, nl->nfactor, sc->steps.vtu_every))
    {
      nl->kept[nl->nkept] = j;                  /* room: nl_kept_alloc */
      memcpy (nl->ukept + nl->nkept * ndof, nl->ls->loop->U,
              ndof * sizeof *nl->ukept);
      lac_frames_to_global (nl->dir->frames, nl->ukept + nl->nkept++ * ndof);
    }
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
  j = nl->next;
  if (!nl->in_step)
    {
      if ((status = lac_loadstep_begin (nl->ls, nl->factor[j])))
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
                            "(load factor %g): %s", j + 1, nl->nfactor,
                            nl->factor[j], msg);
    }
  if ((status = step_done (sc, m, setup, nl, j, progress, size)))
    return status;
  if (++nl->next < nl->nfactor)
    return LAC_CONTINUE;
  memcpy (u, nl->ls->loop->U, ndof * sizeof *u);
  lac_frames_to_global (nl->dir->frames, u);    /* u = T u~ (rollers) */
  return LAC_SUCCESS;
}
