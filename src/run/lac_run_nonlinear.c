/* lac_run_nonlinear.c -- the stages of a large-deformation scene
 *                                             [LAC §4.5, Alg. 1; §5.4]
 *
 * A scene with [scene] large_deformation = yes runs the stages mesh,
 * material and assemble of lac_run.c (the linear K and the rigid-motion
 * check are kept: the checks are the same), and these instead of the
 * linear ones:
 *   contact   the macro-mesh of the slave group, built once on the
 *             reference mesh [LAC Remark 3]; no pairing here: the bodies
 *             may start apart (the ring is 20 mm above the block), and
 *             the pairing is recomputed on the current coordinates at
 *             every Newton iteration (lac_nonlinear.h);
 *   solve     the load steps: [steps] n equal steps of the load factor t
 *             to 1, after a first step to `start` if given; one call per
 *             step (LAC_CONTINUE until the last), each the generalized
 *             Newton loop of [LAC Alg. 1] (lac_nl_step_to);
 *   post      Cauchy stresses at the nodes (lac_hyper_cauchy_nodal), the
 *             summary;
 *   output    solution.vtu and nodes.csv (reference mesh, displacement,
 *             Cauchy stress), contact.csv (the last step), the per-step
 *             curve ([steps] curve, default curve.csv: load factor,
 *             imposed displacement, the [steps] monitor node's
 *             displacement, iterations, residual, active multipliers,
 *             contact force, lambda_min), contact_steps.csv (every
 *             multiplier at every step) and summary.txt; with [steps]
 *             vtu_every = K > 0 also step_NNN.vtu after every K-th step
 *             and the last (NNN the 1-based step number, the fields of
 *             solution.vtu at that step) and steps.pvd, the ParaView
 *             collection of them with the load factor t as timestep.
 * The step files go through the same batch as the other files (written
 * under temporary names, renamed together at the end), so a run that
 * fails at step 40 leaves the files of an earlier run untouched: the
 * solve stage keeps a copy of the displacement of each step to be
 * written (only those, only when K > 0: (n / K) * dofs numbers), and the
 * output stage computes their Cauchy stresses (one nodal pass per file,
 * cheap next to a load step) and writes them.  The last step's file is
 * solution.vtu's fields, written again under its step name.  The step
 * files do not depend on [output] vtu (asking for them is enough);
 * --no-output writes none.
 * Loads of [load] sections are dead loads (given on the reference
 * configuration), times t.
 */
#include "run/lac_run_internal.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "fem/lac_hyper.h"
#include "base/lac_mem.h"
#include "solve/lac_nonlinear.h"
#include "io/lac_output.h"
#include "base/lac_status.h"

/* One converged load step, as written to the curve. */
typedef struct nl_step
{
  double t, imposed;    /* load factor, t * the reference imposed value   */
  double um[3];         /* displacement of the monitor node               */
  int iters, cuts;
  double residual;
  size_t k, nactive;
  double force;         /* sum of lambda |T^m cap Gamma_C| (<= 0)          */
  double lambda_min;    /* the largest pressure (most negative lambda)     */
  double seconds;
} nl_step;

/* Every multiplier at the end of a step (contact_steps.csv). */
typedef struct nl_mult
{
  int step;
  size_t macro;
  double x[3];          /* centroid of T^m cap Gamma_C, current coords    */
  double lambda, gap;   /* multiplier, mean gap d / |T^m cap Gamma_C|     */
  char active;
} nl_mult;

struct lac_run_nl
{
  lac_hyper mat;              /* points into r->E, r->nu, r->law          */
  lac_dirichlet *dir;         /* owned: Dirichlet data at t = 1           */
  char *ramp;                 /* owned, dir->n flags                      */
  lac_obstacle ob;
  lac_nl_problem prob;
  lac_nl *s;                  /* owned                                    */
  double *factor;             /* owned, nfactor load factors              */
  size_t nfactor, next;
  size_t monitor;             /* node, SIZE_MAX: none                     */
  double imposed_ref;         /* first non-zero ramped value (t = 1)      */
  nl_step *step;              /* owned, nfactor                           */
  size_t nmult, capmult;
  nl_mult *mult;              /* owned                                    */
  size_t nkept;               /* steps before the last with a step file   */
  size_t *kept;               /* owned, their indices j (0-based)         */
  double *ukept;              /* owned, nkept * ndof displacements        */
};

void
lac_run_nl_free (struct lac_run_nl *nl)
{
  if (!nl)
    return;
  lac_dirichlet_free (nl->dir);
  lac_free (nl->ramp);
  lac_nl_free (nl->s);
  lac_free (nl->factor);
  lac_free (nl->step);
  lac_free (nl->mult);
  lac_free (nl->kept);
  lac_free (nl->ukept);
  lac_free (nl);
}

/* ---- stage contact ------------------------------------------------------ */


/* The macro-mesh [LAC Hyp. 1, Remark 3], the master facets, the marks of
 * the contact nodes (for the rigid-motion check). */
int
lac_run_nl_contact (lac_run *r)
{
  const lac_scene *sc = r->scene;
  const lac_scene_contact *c;
  if (sc->ncontact == 0)
    {
      snprintf (r->progress, sizeof r->progress, "no [contact]: skipped");
      return LAC_SUCCESS;
    }
  c = &sc->contact[0];
  if (!lac_run_contact_group (r, "slave", c->slave)
      || (c->master && !lac_run_contact_group (r, "master", c->master)))
    return LAC_EINVAL;
  double t0 = lac_run_now ();
  int status = lac_macromesh_build (&r->mesh, c->slave, NULL, &r->macro);
  if (status)
    return lac_scene_error (sc, &c->sec, "slave", status, "%s",
                            lac_error_message ());
  r->time_refine = lac_run_now () - t0;
  r->ndof = (size_t) r->dim * r->mesh->nnodes;
  const lac_group *gs = lac_mesh_group (r->mesh, c->slave);
  const lac_group *gm = c->master ? lac_mesh_group (r->mesh, c->master) : NULL;
  memset (&r->master, 0, sizeof r->master);
  if (gm)
    r->master = lac_pairing_facets_of (r->mesh, gm);
  if (!(r->on_contact = lac_calloc (r->mesh->nnodes, 1)))
    LAC_ERROR (LAC_ENOMEM, "contact node marks");
  for (size_t k = 0; k < gs->nnodes; k++)
    r->on_contact[gs->node[k]] = 1;
  for (size_t k = 0; gm && k < gm->nnodes; k++)
    r->on_contact[gm->node[k]] = 1;
  snprintf (r->progress, sizeof r->progress, "%zu macro-elements on '%s' "
            "(%zu cells cut, %zu nodes added); pairing with %s%s%s at every"
            " Newton iteration", r->macro->n, c->slave, r->macro->ncut,
            r->macro->nnew, gm ? "'" : "the rigid obstacle",
            gm ? c->master : "", gm ? "'" : "");
  return LAC_SUCCESS;
}

/* ---- stage solve: set-up ------------------------------------------------ */

/* Dirichlet data at t = 1 with the ramp flag of each entry; the reference
 * imposed value (the first non-zero ramped one). */
static int
nl_dirichlet (lac_run *r, struct lac_run_nl *nl)
{
  const lac_scene *sc = r->scene;
  int status = LAC_SUCCESS;
  if (!(nl->dir = lac_dirichlet_alloc ()))
    return LAC_ENOMEM;
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      const lac_scene_dirichlet *bc = &sc->dirichlet[k];
      const lac_group *g = lac_mesh_group (r->mesh, bc->group);
      size_t n0 = nl->dir->n;
      for (int c = 0; c < r->dim && !status; c++)
        if (bc->fixed[c])
          {
            status = lac_dirichlet_add_group (nl->dir, r->mesh, g, c,
                                              bc->value[c]);
            if (bc->ramp && bc->value[c] != 0 && nl->imposed_ref == 0)
              nl->imposed_ref = bc->value[c];
          }
      char *p = lac_realloc (nl->ramp, nl->dir->n ? nl->dir->n : 1);
      if (!p)
        return LAC_ERRMSG (LAC_ENOMEM, "ramp flags");
      nl->ramp = p;
      memset (nl->ramp + n0, bc->ramp ? 1 : 0, nl->dir->n - n0);
    }
  return status;
}

/* The load factors: `start` (if > 0), then n equal steps to 1. */
static int
nl_factors (lac_run *r, struct lac_run_nl *nl)
{
  const lac_scene_steps *st = &r->scene->steps;
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

/* 1 if step j (0-based) of n gets a step_NNN.vtu: every K-th, the last. */
static int
step_file_wanted (size_t j, size_t n, int K)
{
  return K > 0 && ((j + 1) % (size_t) K == 0 || j + 1 == n);
}

/* Room for the displacements of the step files before the last one. */
static int
nl_kept_alloc (lac_run *r, struct lac_run_nl *nl)
{
  int K = r->scene->steps.vtu_every;
  size_t n = 0;
  for (size_t j = 0; j + 1 < nl->nfactor; j++)
    n += (size_t) step_file_wanted (j, nl->nfactor, K);
  if (n == 0)
    return LAC_SUCCESS;
  nl->kept = lac_malloc (n * sizeof *nl->kept);
  nl->ukept = lac_malloc (n * r->ndof * sizeof *nl->ukept);
  if (!nl->kept || !nl->ukept)
    LAC_ERROR (LAC_ENOMEM, "displacements of %zu step files", n);
  return LAC_SUCCESS;
}

/* The node of the [steps] monitor group. */
static int
nl_monitor (lac_run *r, struct lac_run_nl *nl)
{
  const lac_scene_steps *st = &r->scene->steps;
  nl->monitor = SIZE_MAX;
  if (!st->monitor)
    return LAC_SUCCESS;
  const lac_group *g = lac_mesh_group (r->mesh, st->monitor);
  if (!g || g->nnodes == 0)
    return lac_scene_error (r->scene, &st->sec, "monitor", LAC_EINVAL,
                            "%s in mesh '%s' (a physical point is best)",
                            g ? "the group has no node"
                              : "no physical group of that name",
                            r->scene->mesh.file);
  nl->monitor = g->node[0];
  return LAC_SUCCESS;
}

static int
nl_setup (lac_run *r)
{
  const lac_scene *sc = r->scene;
  struct lac_run_nl *nl = lac_calloc (1, sizeof *nl);
  int status;
  if (!(r->nl = nl))
    LAC_ERROR (LAC_ENOMEM, "large-deformation run");
  nl->mat.model = r->model;
  nl->mat.E = r->E;
  nl->mat.nu = r->nu;
  nl->mat.law = r->law;
  if ((status = nl_dirichlet (r, nl)) || (status = nl_factors (r, nl))
      || (status = nl_monitor (r, nl)) || (status = nl_kept_alloc (r, nl)))
    return status;
  lac_nl_problem *p = &nl->prob;
  p->mesh = r->mesh;
  p->mat = &nl->mat;
  p->F = r->F;
  p->dir = nl->dir;
  p->ramp = nl->ramp;
  if (sc->ncontact)
    {
      const lac_scene_contact *c = &sc->contact[0];
      p->M = r->macro;
      p->epsilon = c->epsilon;
      if (c->master)
        p->master = &r->master;
      else
        {
          lac_obstacle ob = { r->dim, c->height, { c->curvature[0],
                              c->curvature[1] }, { c->center[0],
                              c->center[1] } };
          nl->ob = ob;
          p->obstacle = &nl->ob;
        }
    }
  lac_nl_opts o;
  lac_nl_opts_init (&o);
  o.kind = sc->scene.solver == LAC_SOLVER_DENSE ? LAC_STRATEGY_DENSE
           : sc->scene.solver == LAC_SOLVER_CHOLMOD ? LAC_STRATEGY_SCHUR
           : LAC_STRATEGY_SADDLE;
  o.tol = sc->steps.tol;
  o.maxit = sc->steps.maxit;
  if (!(nl->s = lac_nl_alloc (p, &o)))
    return LAC_ENOMEM;
  lac_csc_free (r->K);               /* the linear K of stage assemble */
  r->K = NULL;
  return LAC_SUCCESS;
}

/* ---- stage solve: one load step per call -------------------------------- */

/* Append the multipliers of the converged step to the records. */
static int
record_mults (struct lac_run_nl *nl, const lac_run *r, int step)
{
  const lac_nl *s = nl->s;
  const lac_contact *c = s->contact;
  const lac_pairing *P = s->pairing;
  const lac_macro *M = r->macro;
  int dim = r->dim, nodes[LAC_MAX_FACE_NODES];
  lac_map mp;
  for (size_t i = 0; c && i < c->k; i++)
    {
      if (nl->nmult == nl->capmult)
        {
          size_t cap = nl->capmult ? 2 * nl->capmult : 256;
          nl_mult *q = lac_realloc (nl->mult, cap * sizeof *q);
          if (!q)
            LAC_ERROR (LAC_ENOMEM, "multiplier records");
          nl->mult = q;
          nl->capmult = cap;
        }
      nl_mult *q = &nl->mult[nl->nmult++];
      size_t m = c->macro[i];
      double wsum = 0;
      memset (q, 0, sizeof *q);
      q->step = step;
      q->macro = m;
      q->lambda = s->lambda[m];
      q->gap = c->area[i] > 0 ? c->G[i] / c->area[i] : 0.0;
      q->active = s->active[m];
      for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)   /* centroid */
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
record_step (struct lac_run_nl *nl, size_t j, const lac_run *r, double sec)
{
  const lac_nl *s = nl->s;
  const lac_nl_step *h = &s->steps[s->nsteps - 1];
  nl_step *q = &nl->step[j];
  q->t = h->t;
  q->imposed = h->t * nl->imposed_ref;
  for (int k = 0; k < r->dim && nl->monitor != SIZE_MAX; k++)
    q->um[k] = s->U[nl->monitor * (size_t) r->dim + (size_t) k];
  q->iters = h->iters;
  q->cuts = h->cuts;
  q->residual = h->residual;
  q->k = h->k;
  q->nactive = h->nactive;
  q->force = lac_nl_contact_force (s);
  q->lambda_min = 0;
  for (size_t m = 0; m < s->nmacro; m++)
    q->lambda_min = fmin (q->lambda_min, s->lambda[m]);
  q->seconds = sec;
}

int
lac_run_nl_solve (lac_run *r)
{
  int status;
  if (!r->nl && (status = nl_setup (r)))
    return status;
  struct lac_run_nl *nl = r->nl;
  size_t j = nl->next;
  double t0 = lac_run_now ();
  status = lac_nl_step_to (nl->s, nl->factor[j]);
  if (status)
    {
      char msg[600];
      snprintf (msg, sizeof msg, "%s", lac_error_message ());
      return lac_error_set (status, r->scene->path, "load step %zu of %zu "
                            "(load factor %g): %s", j + 1, nl->nfactor,
                            nl->factor[j], msg);
    }
  record_step (nl, j, r, lac_run_now () - t0);
  if ((status = record_mults (nl, r, (int) j + 1)))
    return status;
  if (j + 1 < nl->nfactor
      && step_file_wanted (j, nl->nfactor, r->scene->steps.vtu_every))
    {
      nl->kept[nl->nkept] = j;                  /* room: nl_kept_alloc */
      memcpy (nl->ukept + nl->nkept++ * r->ndof, nl->s->U,
              r->ndof * sizeof *nl->ukept);
    }
  const nl_step *q = &nl->step[j];
  char mon[80] = "";
  if (nl->monitor != SIZE_MAX)
    snprintf (mon, sizeof mon, ", %s %s = %.4f", r->scene->steps.monitor,
              r->dim == 2 ? "u_y" : "u_z", q->um[r->dim - 1]);
  snprintf (r->progress, sizeof r->progress, "step %zu/%zu: t = %.4f "
            "(imposed %.3f), %d Newton iteration%s%s, residual %.1e, "
            "%zu/%zu active%s (%.1f s)", j + 1, nl->nfactor, q->t,
            q->imposed, q->iters, q->iters == 1 ? "" : "s",
            q->cuts ? " (step cut)" : "", q->residual, q->nactive, q->k,
            mon, q->seconds);
  nl->next++;
  if (nl->next < nl->nfactor)
    return LAC_CONTINUE;
  if (!(r->u = lac_malloc (r->ndof * sizeof *r->u)))
    LAC_ERROR (LAC_ENOMEM, "displacement of %zu dofs", r->ndof);
  memcpy (r->u, nl->s->U, r->ndof * sizeof *r->u);
  return LAC_SUCCESS;
}

/* ---- stage post --------------------------------------------------------- */


static int
nl_summary (lac_run *r)
{
  const struct lac_run_nl *nl = r->nl;
  const lac_nl *s = nl->s;
  const lac_mesh *m = r->mesh;
  double umax = 0, vmax = 0;
  char effects[256] = "", types[128];
  int itmax = 0, status;
  lac_run_cell_types (m, types, sizeof types);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double q = 0;
      for (int i = 0; i < r->dim; i++)
        q += r->u[a * (size_t) r->dim + (size_t) i]
             * r->u[a * (size_t) r->dim + (size_t) i];
      umax = fmax (umax, sqrt (q));
      vmax = fmax (vmax, r->vm[a]);
    }
  for (size_t j = 0; j < nl->nfactor; j++)
    itmax = nl->step[j].iters > itmax ? nl->step[j].iters : itmax;
  for (size_t k = 0; k < r->neffects; k++)
    snprintf (effects + strlen (effects), sizeof effects - strlen (effects),
              "%s%s", k ? ", " : "", r->effects[k]);
  if ((status = lac_run_summary_add (r, "title", "%s", r->scene->scene.title))
      || (status = lac_run_summary_add (r, "model", "%s",
                                        lac_model_name (r->model)))
      || (status = lac_run_summary_add (r, "element", "%s", types))
      || (status = lac_run_summary_add (r, "effects", "%s", effects))
      || (status = lac_run_summary_add (r, "nodes", "%zu", m->nnodes))
      || (status = lac_run_summary_add (r, "cells", "%zu", m->ncells))
      || (status = lac_run_summary_add (r, "dofs", "%zu", r->ndof))
      || (status = lac_run_summary_add (r, "fixed_dofs", "%zu", r->nfixed))
      || (status = lac_run_summary_add (r, "load_steps", "%zu", nl->nfactor))
      || (status = lac_run_summary_add (r, "newton_iterations", "%zu",
                                        s->niters))
      || (status = lac_run_summary_add (r, "max_iterations_per_step", "%d",
                                        itmax))
      || (status = lac_run_summary_add (r, "max_u", "%.10e", umax))
      || (status = lac_run_summary_add (r, "max_von_mises", "%.10e", vmax)))
    return status;
  if (nl->monitor != SIZE_MAX)
    {
      const char *ax[3] = { "x", "y", "z" };
      double ext = 0;
      for (size_t j = 0; j < nl->nfactor; j++)
        if (fabs (nl->step[j].um[r->dim - 1]) > fabs (ext))
          ext = nl->step[j].um[r->dim - 1];
      for (int k = 0; k < r->dim && !status; k++)
        {
          char key[32];
          snprintf (key, sizeof key, "monitor_u%s", ax[k]);
          status = lac_run_summary_add (r, key, "%.10e",
                                        nl->step[nl->nfactor - 1].um[k]);
        }
      if (!status)
        status = lac_run_summary_add (r, "monitor_extreme", "%.10e", ext);
      if (status)
        return status;
    }
  if (!r->macro)
    return LAC_SUCCESS;
  const nl_step *q = &nl->step[nl->nfactor - 1];
  if ((status = lac_run_summary_add (r, "macro_elements", "%zu", r->macro->n))
      || (status = lac_run_summary_add (r, "multipliers", "%zu", q->k))
      || (status = lac_run_summary_add (r, "active", "%zu", q->nactive))
      || (status = lac_run_summary_add (r, "lambda_min", "%.10e",
                                        q->lambda_min)))
    return status;
  return lac_run_summary_add (r, "contact_force", "%.10e", q->force);
}

int
lac_run_nl_post (lac_run *r)
{
  const lac_mesh *m = r->mesh;
  int status;
  r->sigma = lac_malloc (m->nnodes * (size_t) r->ns * sizeof *r->sigma);
  r->vm = lac_malloc (m->nnodes * sizeof *r->vm);
  if (!r->sigma || !r->vm)
    LAC_ERROR (LAC_ENOMEM, "nodal stresses of %zu nodes", m->nnodes);
  if ((status = lac_hyper_cauchy_nodal (m, &r->nl->mat, r->u, NULL, r->sigma,
                                        r->vm))
      || (status = nl_summary (r)))
    return status;
  snprintf (r->progress, sizeof r->progress, "Cauchy stresses, von Mises; "
            "%zu Newton iterations in %zu load steps", r->nl->s->niters,
            r->nl->nfactor);
  return LAC_SUCCESS;
}

/* ---- stage output ------------------------------------------------------- */

static int
write_curve (const lac_run *r, const char *path)
{
  const struct lac_run_nl *nl = r->nl;
  FILE *f = fopen (path, "w");
  if (!f)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  fprintf (f, "step,load_factor,imposed,monitor_ux,monitor_uy%s,iterations,"
           "cuts,residual,multipliers,active,contact_force,lambda_min\n",
           r->dim == 3 ? ",monitor_uz" : "");
  fprintf (f, "0,0,0,0,0%s,0,0,0,0,0,0,0\n", r->dim == 3 ? ",0" : "");
  for (size_t j = 0; j < nl->nfactor; j++)
    {
      const nl_step *q = &nl->step[j];
      fprintf (f, "%zu,%.10e,%.10e", j + 1, q->t, q->imposed);
      for (int k = 0; k < r->dim; k++)
        fprintf (f, ",%.10e", q->um[k]);
      fprintf (f, ",%d,%d,%.3e,%zu,%zu,%.10e,%.10e\n", q->iters, q->cuts,
               q->residual, q->k, q->nactive, q->force, q->lambda_min);
    }
  if (fclose (f) != 0)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  return LAC_SUCCESS;
}

/* contact_steps.csv (every step) or contact.csv (last step only). */
static int
write_mults (const lac_run *r, const char *path, int last_only)
{
  const struct lac_run_nl *nl = r->nl;
  FILE *f = fopen (path, "w");
  if (!f)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  fprintf (f, "%smacro,x,y,z,lambda,mean_gap,active\n",
           last_only ? "" : "step,");
  for (size_t q = 0; q < nl->nmult; q++)
    {
      const nl_mult *u = &nl->mult[q];
      if (last_only && u->step != (int) nl->nfactor)
        continue;
      if (!last_only)
        fprintf (f, "%d,", u->step);
      fprintf (f, "%zu,%.10e,%.10e,%.10e,%.10e,%.10e,%d\n", u->macro, u->x[0],
               u->x[1], u->x[2], u->lambda, u->gap, u->active);
    }
  if (fclose (f) != 0)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  return LAC_SUCCESS;
}

/* step_NNN.vtu of step j (0-based): the displacement u, its Cauchy
 * stresses in sigma, vm (the last step: those of solution.vtu). */
static int
write_step_vtu (const lac_run *r, lac_output_batch *b, size_t j,
                const double *u, const double *sigma, const double *vm)
{
  lac_output_fields f = { r->mesh, r->model, u, NULL, sigma, vm };
  char name[64];
  const char *path;
  snprintf (name, sizeof name, "step_%03zu.vtu", j + 1);
  if (!(path = lac_output_batch_add (b, name)))
    return LAC_ENOMEM;
  return lac_output_vtu (path, &f);
}

/* steps.pvd: the ParaView collection of the step files, timestep = the
 * load factor t (VTK file formats, "ParaView data (PVD)"). */
static int
write_pvd (const lac_run *r, const char *path)
{
  const struct lac_run_nl *nl = r->nl;
  FILE *f = fopen (path, "w");
  if (!f)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  fprintf (f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n");
  for (size_t j = 0; j < nl->nfactor; j++)
    if (step_file_wanted (j, nl->nfactor, r->scene->steps.vtu_every))
      fprintf (f, "    <DataSet timestep=\"%.10g\" group=\"\" part=\"0\" "
               "file=\"step_%03zu.vtu\"/>\n", nl->step[j].t, j + 1);
  fprintf (f, "  </Collection>\n</VTKFile>\n");
  if (fclose (f) != 0)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  return LAC_SUCCESS;
}

/* The step files ([steps] vtu_every) and steps.pvd; stresses of the kept
 * steps as in stage post (lac_hyper_cauchy_nodal). */
static int
write_steps (const lac_run *r, lac_output_batch *b)
{
  const struct lac_run_nl *nl = r->nl;
  size_t nn = r->mesh->nnodes;
  double *sigma = lac_malloc (nn * (size_t) r->ns * sizeof *sigma),
    *vm = lac_malloc (nn * sizeof *vm);
  const char *path;
  int status = sigma && vm ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "stresses of the step files");
  for (size_t q = 0; q < nl->nkept && !status; q++)
    {
      const double *u = nl->ukept + q * r->ndof;
      if (!(status = lac_hyper_cauchy_nodal (r->mesh, &nl->mat, u, NULL,
                                             sigma, vm)))
        status = write_step_vtu (r, b, nl->kept[q], u, sigma, vm);
    }
  if (!status)
    status = write_step_vtu (r, b, nl->nfactor - 1, r->u, r->sigma, r->vm);
  if (!status)
    status = (path = lac_output_batch_add (b, "steps.pvd"))
             ? write_pvd (r, path) : LAC_ENOMEM;
  lac_free (sigma);
  lac_free (vm);
  return status;
}

static int
nl_timings (lac_run *r)
{
  const lac_nl *s = r->nl->s;
  int status = lac_run_stage_timings (r);
  if (!status)
    status = lac_run_summary_add (r, "time_assemble_KT", "%.3f",
                                  s->time_assemble);
  if (!status)
    status = lac_run_summary_add (r, "time_pairing", "%.3f", s->time_pairing);
  if (!status)
    status = lac_run_summary_add (r, "time_saddle_solve", "%.3f",
                                  s->time_solve);
  return status;
}

int
lac_run_nl_output (lac_run *r)
{
  const lac_scene *sc = r->scene;
  const lac_scene_output *o = &sc->output;
  lac_output_fields f = { r->mesh, r->model, r->u, NULL, r->sigma, r->vm };
  const char *curve = sc->steps.curve ? sc->steps.curve : "curve.csv";
  lac_output_batch *b;
  const char *path = "";
  char nsteps[64];
  int status = r->opts.timings ? nl_timings (r) : LAC_SUCCESS;
  if (status || r->opts.no_output)
    {
      snprintf (r->progress, sizeof r->progress, "no files written");
      return status;
    }
  if (!(b = lac_output_batch_alloc (r->out_dir)))
    return LAC_EIO;
  if ((status = lac_run_write_fields (r, b, &f)))
    goto done;
  if (!(path = lac_output_batch_add (b, curve))
      || (status = write_curve (r, path)))
    goto done;
  if (r->macro && (!(path = lac_output_batch_add (b, "contact.csv"))
                   || (status = write_mults (r, path, 1))))
    goto done;
  if (r->macro && (!(path = lac_output_batch_add (b, "contact_steps.csv"))
                   || (status = write_mults (r, path, 0))))
    goto done;
  if (sc->steps.vtu_every > 0 && (status = write_steps (r, b)))
    goto done;
  if ((status = lac_run_write_summary (r, b)))
    goto done;
  snprintf (nsteps, sizeof nsteps, "%zu step_NNN.vtu, steps.pvd, ",
            r->nl->nkept + 1);
  snprintf (r->progress, sizeof r->progress, "%s/: %s%s%s%s%ssummary.txt",
            r->out_dir, o->vtu ? "solution.vtu, " : "",
            o->csv ? "nodes.csv, " : "", curve,
            r->macro ? ", contact.csv, contact_steps.csv, " : ", ",
            sc->steps.vtu_every > 0 ? nsteps : "");
done:
  if (!status && !path)
    status = LAC_ENOMEM;
  lac_output_batch_free (b);
  return status;
}
