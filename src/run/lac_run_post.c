/* lac_run_post.c -- stage 6 of a run: the results (see lac_run_post.h)
 *                                                                  [LAC §5]
 */
#include "run/lac_run_post.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_post.h"
#include "fem/lac_post_dist.h"
#include "run/lac_run_reaction.h"
#include "run/lac_run_scene.h"
#include "run/lac_run_sliding.h"

void
lac_run_results_clear (lac_run_results *res)
{
  lac_free (res->sigma);
  lac_free (res->vm);
  lac_free (res->u_exact);
  lac_run_multipliers_clear (&res->mult);
  lac_run_contact_clear (&res->contact);
  lac_summary_clear (&res->summary);
  memset (res, 0, sizeof *res);
}

/* ---- what every summary has ------------------------------------------- */

/* The first lines: the scene, the model, the mesh and its unknowns. */
static int
summary_head (const lac_run_post_in *in, lac_summary *sum)
{
  const lac_mesh *m = in->mesh;
  char types[128];
  int status;
  lac_run_cell_types (m, types, sizeof types);
  if ((status = lac_summary_add (sum, "title", "%s", in->sc->scene.title))
      || (status = lac_summary_add (sum, "model", "%s",
                                    lac_model_name (in->model)))
      || (status = lac_summary_add (sum, "element", "%s", types))
      || (status = lac_summary_add (sum, "effects", "%s", in->effects))
      || (status = lac_summary_add (sum, "nodes", "%zu", m->nnodes))
      || (status = lac_summary_add (sum, "cells", "%zu", m->ncells)))
    return status;
  return lac_summary_add (sum, "dofs", "%zu", in->sys->ndof);
}

/* max_u = max over the nodes of |u|, and max_von_mises. */
static int
summary_maxima (const lac_run_post_in *in, lac_run_results *r)
{
  const lac_mesh *m = in->mesh;
  int dim = m->dim, status;
  double umax = 0, vmax = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double s = 0;
      for (int i = 0; i < dim; i++)
        s += in->u[a * (size_t) dim + (size_t) i]
             * in->u[a * (size_t) dim + (size_t) i];
      umax = fmax (umax, sqrt (s));
      vmax = fmax (vmax, r->vm[a]);
    }
  if ((status = lac_summary_add (&r->summary, "max_u", LAC_SUMMARY_REAL,
                                 umax)))
    return status;
  return lac_summary_add (&r->summary, "max_von_mises", LAC_SUMMARY_REAL,
                          vmax);
}

/* ---- the summary of a linear run -------------------------------------- */

/* h = the largest cell diameter (largest distance between two vertices
 * of a cell), the mesh size of the convergence tables. */
static double
mesh_size (const lac_mesh *m)
{
  double h = 0;
  int d = m->dim;
  for (size_t c = 0; c < m->ncells; c++)
    {
      int nv = lac_refelem_get (m->type[c])->nvertices;
      const int *v = m->conn + m->ptr[c];
      for (int a = 0; a < nv; a++)
        for (int b = a + 1; b < nv; b++)
          {
            double s = 0;
            for (int k = 0; k < d; k++)
              {
                double t = m->x[(size_t) v[a] * d + k] - m->x[(size_t) v[b] * d + k];
                s += t * t;
              }
            h = fmax (h, sqrt (s));
          }
    }
  return h;
}

/* Mean radial displacement u.x/R (and its exact value) over the nodes at
 * radius R0; returns the number of such nodes. */
static size_t
radial_mean (const lac_run_post_in *in, const lac_run_results *res,
             const lac_exact *e, double R0, double *uh, double *ue)
{
  const lac_mesh *m = in->mesh;
  int dim = m->dim;
  size_t n = 0;
  *uh = *ue = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *x = m->x + a * (size_t) dim;
      double R = lac_exact_radius (e, x);
      if (fabs (R - R0) > 1e-8 * R0)
        continue;
      for (int i = 0; i < e->nr; i++)
        {
          *uh += in->u[a * (size_t) dim + (size_t) i] * x[i] / R;
          *ue += res->u_exact[a * (size_t) dim + (size_t) i] * x[i] / R;
        }
      n++;
    }
  if (n)
    *uh /= (double) n, *ue /= (double) n;
  return n;
}

static int
summary_exact (const lac_run_post_in *in, lac_run_results *r,
               const lac_exact *e)
{
  lac_summary *sum = &r->summary;
  const lac_scene_exact *x = &in->sc->exact;
  const char *side[2] = { "inner", "outer" };
  const double R0[2] = { x->a, x->b };
  int status = lac_summary_add (sum, "exact", "%s",
                                    lac_scene_exact_name (x->solution));
  if (!status)
    status = lac_summary_add (sum, "l2_err_u", LAC_SUMMARY_REAL, r->err_l2);
  if (!status)
    status = lac_summary_add (sum, "h1_err_u", LAC_SUMMARY_REAL, r->err_h1);
  if (!status)
    status = lac_summary_add (sum, "rel_l2_err_u", LAC_SUMMARY_REAL,
                              r->norm_l2 > 0 ? r->err_l2 / r->norm_l2 : 0.0);
  if (!status)
    status = lac_summary_add (sum, "rel_h1_err_u", LAC_SUMMARY_REAL,
                              r->norm_h1 > 0 ? r->err_h1 / r->norm_h1 : 0.0);
  for (int k = 0; k < 2 && !status && e->nr > 0; k++)   /* radial only */
    {
      double uh, ue;
      char key[64];
      if (!radial_mean (in, r, e, R0[k], &uh, &ue))
        continue;
      snprintf (key, sizeof key, "u_r_%s", side[k]);
      status = lac_summary_add (sum, key, LAC_SUMMARY_REAL, uh);
      snprintf (key, sizeof key, "u_r_%s_exact", side[k]);
      if (!status)
        status = lac_summary_add (sum, key, LAC_SUMMARY_REAL, ue);
      snprintf (key, sizeof key, "rel_err_u_r_%s", side[k]);
      if (!status)
        status = lac_summary_add (sum, key, LAC_SUMMARY_REAL, ue != 0
                                      ? fabs (uh - ue) / fabs (ue)
                                      : fabs (uh));
    }
  return status;
}

static int
make_summary (const lac_run_post_in *in, lac_run_results *r,
              const lac_exact *e)
{
  const lac_mesh *m = in->mesh;
  const lac_run_system *sys = in->sys;
  lac_summary *sum = &r->summary;
  double work = 0;
  int status;
  for (size_t k = 0; k < sys->ndof; k++)
    work += sys->F[k] * in->u[k];                /* l(u_h) = F . u */
  if ((status = summary_head (in, sum))
      || (status = lac_summary_add (sum, "h", LAC_SUMMARY_REAL, mesh_size (m)))
      || (status = lac_summary_add (sum, "fixed_dofs", "%zu", sys->nfixed))
      || (status = lac_summary_add (sum, "nnz_K", "%zu", sys->nnz))
      || (status = lac_summary_add (sum, "load_work", LAC_SUMMARY_REAL, work))
      || (status = summary_maxima (in, r)))
    return status;
  return r->u_exact ? summary_exact (in, r, e) : LAC_SUCCESS;
}

/* ---- the summary of a large-deformation run -------------------------- */

/* "what.name = value" into the summary. */
static int
pair_key (lac_summary *sum, const char *what, const char *name,
          const char *value)
{
  char key[300];
  snprintf (key, sizeof key, "%s.%s", what, name);
  return lac_summary_add (sum, key, "%s", value);
}

/* Pair p at the end of the last step, on the deformed surface: its force
 * as a vector, its normal force sum lambda_i |T^m_i cap Gamma_C| and its
 * active macro-elements. */
static int
nl_pair (const lac_run_post_in *in, const lac_newton *s, size_t p,
         lac_summary *sum)
{
  const lac_nl *model = in->nl->model;
  const lac_contact_set_data *d = &model->data;
  const lac_contact *c = d->all;
  const char *name = in->sc->contact[p].sec.name;
  double fn = 0, f[3] = { 0, 0, 0 };
  size_t nact = 0;
  char v[300];
  int dim = in->mesh->dim, status = LAC_SUCCESS;
  for (size_t i = d->col[p]; c && i < d->col[p + 1]; i++)
    {
      fn += s->lambda[c->macro[i]] * c->area[i];
      nact += s->active[c->macro[i]] != 0;
    }
  if (c && (status = lac_run_pair_force (in->model, &model->cur,
                                         in->setup->macro[p], d->P[p], c,
                                         d->col[p], d->col[p + 1],
                                         in->setup->set.offset[p],
                                         s->lambda, f)))
    return status;
  snprintf (v, sizeof v, "contact_force.%s", name);
  if ((status = lac_summary_add_vector (sum, v, f, dim)))
    return status;
  snprintf (v, sizeof v, LAC_SUMMARY_REAL, fn);
  if ((status = pair_key (sum, "contact_normal_force", name, v)))
    return status;
  snprintf (v, sizeof v, "%zu", nact);
  return pair_key (sum, "active_macro_elements", name, v);
}

/* Several pairs: the lines of each. */
static int
nl_pairs (const lac_run_post_in *in, const lac_newton *s, lac_summary *sum)
{
  int status = LAC_SUCCESS;
  for (size_t p = 0; p < in->setup->npairs && !status; p++)
    status = nl_pair (in, s, p, sum);
  return status;
}

static int
nl_summary (const lac_run_post_in *in, lac_run_results *r)
{
  const lac_run_steplog *nl = &in->nl->log;
  const lac_newton *s = in->nl->ls->loop;
  const lac_mesh *m = in->mesh;
  lac_summary *sum = &r->summary;
  int dim = m->dim, itmax = 0, ncut = 0, status;
  for (size_t j = 0; j < nl->nfactor; j++)
    {
      const lac_nl_step *h = &nl->step[j].solver;
      itmax = h->iters > itmax ? h->iters : itmax;
      ncut += h->cuts > 0;
    }
  if ((status = summary_head (in, sum))
      || (status = lac_summary_add (sum, "fixed_dofs", "%zu", in->sys->nfixed))
      || (status = lac_summary_add (sum, "load_steps", "%zu", nl->nfactor))
      || (status = lac_summary_add (sum, "newton_iterations", "%zu",
                                        s->nhist))
      || (status = lac_summary_add (sum, "max_iterations_per_step", "%d",
                                        itmax))
      || (status = lac_summary_add (sum, "cut_steps", "%d", ncut))
      || (status = summary_maxima (in, r)))
    return status;
  if ((status = lac_run_steplog_summary (nl, dim, sum)))
    return status;
  if (!in->setup->npairs)
    return LAC_SUCCESS;
  const lac_run_step_record *q = &nl->step[nl->nfactor - 1];
  if ((status = lac_run_pairs_dropped (&in->nl->model->data, s, sum)))
    return status;
  if ((status = lac_summary_add (sum, "macro_elements", "%zu",
                                 lac_contact_set_nslot (&in->setup->set)))
      || (status = lac_summary_add (sum, "multipliers", "%zu", q->solver.k))
      || (status = lac_summary_add (sum, "active", "%zu",
                                    q->solver.nactive))
      || (status = lac_summary_add (sum, "lambda_min", LAC_SUMMARY_REAL,
                                        q->lambda_min)))
    return status;
  if ((status = lac_summary_add (sum, "contact_force", LAC_SUMMARY_REAL,
                                 q->force)))
    return status;
  return in->setup->npairs > 1 ? nl_pairs (in, s, sum) : LAC_SUCCESS;
}

/* interference_gap: the largest mean gap of a macro-element without the
 * interference, over the interference (run/lac_run_interference.h). */
static int
fit_summary (const lac_run_post_in *in, lac_summary *sum)
{
  const lac_run_fit *f = &in->sys->fit;
  return f->measured ? lac_summary_add (sum, "interference_gap",
                                        LAC_SUMMARY_REAL, f->ratio)
                      : LAC_SUCCESS;
}

/* ---- the reactions of the Dirichlet sections ------------------------- */

/* With [output] reactions = yes, "reaction.NAME" lines
 * (run/lac_run_reaction.h): the pairs and the
 * multipliers of the last solve (large deformation: the model's pairs, on
 * the final coordinates). */
static int
reactions (const lac_run_post_in *in, lac_summary *sum)
{
  const lac_newton *nw = in->nl ? in->nl->ls->loop
                         : in->sol ? in->sol->newton : NULL;
  lac_run_reaction_in r = { in->sc, in->model, in->mesh, in->mat,
                            in->nl != NULL, in->sys->F, in->u, NULL, NULL,
                            in->setup->on_contact, &in->sys->ties };
  if (!in->sc->output.reactions)
    return LAC_SUCCESS;
  if (in->setup->npairs && nw)
    {
      r.set = in->nl ? &in->nl->model->set : &in->setup->set;
      r.lambda = nw->lambda;
    }
  return lac_run_reactions (&r, sum);
}

/* ---- the stage -------------------------------------------------------- */

/* The exact displacement at the nodes. */
static int
exact_nodes (const lac_run_post_in *in, const lac_exact *e,
             lac_run_results *res)
{
  const lac_mesh *m = in->mesh;
  size_t ndof = (size_t) m->dim * m->nnodes;
  if (!(res->u_exact = lac_malloc (ndof * sizeof *res->u_exact)))
    LAC_ERROR (LAC_ENOMEM, "exact displacement");
  for (size_t a = 0; a < m->nnodes; a++)
    lac_exact_u (m->x + a * (size_t) m->dim, (void *) e,
                 res->u_exact + a * (size_t) m->dim);
  return LAC_SUCCESS;
}

/* The nodal stresses and, with an exact solution (exact = 1), the errors
 * in L2 and H1: on the processes that hold the cells when the solver
 * assembled K there (st: its strategy; fem/lac_post_dist.h), else here
 * (st NULL). */
static int
stresses_errors (const lac_run_post_in *in, lac_strategy *st,
                 const lac_exact *e, int exact, lac_run_results *res)
{
  const lac_mesh *m = in->mesh;
  int status;
  if (exact && (status = exact_nodes (in, e, res)))
    return status;
  if (st)
    {
      lac_post_request p = { in->u, exact ? e : NULL, res->sigma, res->vm,
                             { 0, 0, 0, 0 } };
      if ((status = lac_strategy_post (st, &p)))
        return status;
      res->err_l2 = p.err[0], res->err_h1 = p.err[1];
      res->norm_l2 = p.err[2], res->norm_h1 = p.err[3];
      return LAC_SUCCESS;
    }
  if ((status = lac_post_stress_nodal (m, &in->mat->elastic, in->u, NULL,
                                       res->sigma, res->vm)))
    return status;
  return !exact ? LAC_SUCCESS
         : lac_post_errors (m, in->model, in->u, lac_exact_u, lac_exact_grad,
                            (void *) e, &res->err_l2, &res->err_h1,
                            &res->norm_l2, &res->norm_h1);
}

static int
post_linear (const lac_run_post_in *in, lac_run_results *res,
             char *progress, size_t size)
{
  const lac_scene *sc = in->sc;
  lac_strategy *st = in->sol->kst && lac_strategy_posts (in->sol->kst)
                     ? in->sol->kst : NULL;     /* stage 6 on the processes */
  lac_exact e;
  int status;
  lac_run_exact (sc, in->model, &e);
  if ((status = stresses_errors (in, st, &e, sc->exact.sec.line != 0, res))
      || (status = make_summary (in, res, &e)))
    return status;
  const lac_contact *c = in->setup->data.all;
  if (c && (status = lac_run_pairs_dropped (&in->setup->data,
                                            in->sol->newton, &res->summary)))
    return status;
  if (c && (status = lac_run_multipliers_post (in->model, in->mesh,
                                               in->setup, c, in->sol->newton,
                                               &e, res->sigma, &res->mult,
                                               &res->summary)))
    return status;
  if (c && (status = lac_run_contact_post (sc, in->model, in->mesh,
                                           in->setup, c, in->sol->newton,
                                           &res->contact, &res->summary)))
    return status;
  double sliding;                   /* the small sliding of the pairing */
  if (c && (status = lac_run_sliding_check (sc, in->mesh, in->sys->bodies,
                                            in->setup, in->sol->newton,
                                            in->u, &sliding)))
    return status;
  if ((status = fit_summary (in, &res->summary))
      || (status = lac_run_solve_summary (in->sol, &res->summary))
      || (in->steps && (status = lac_run_steps_summary (in->steps,
                                                        in->sol->newton,
                                                        in->mesh->dim,
                                                        &res->summary)))
      || (status = reactions (in, &res->summary)))
    return status;
  char where[64] = "";
  if (st)
    snprintf (where, sizeof where, " (on the %d processes' cells)",
              in->sol->processes);
  if (res->u_exact)
    snprintf (progress, size, "stresses, errors vs %s: L2 %.3e, H1 %.3e%s",
              lac_scene_exact_name (sc->exact.solution), res->err_l2,
              res->err_h1, where);
  else
    snprintf (progress, size, "stresses, von Mises%s", where);
  return LAC_SUCCESS;
}

static int
post_nonlinear (const lac_run_post_in *in, lac_run_results *res,
                char *progress, size_t size)
{
  int status;
  if ((status = lac_hyper_cauchy_nodal (in->mesh, &in->mat->hyper, in->u,
                                        NULL, res->sigma, res->vm))
      || (status = nl_summary (in, res))
      || (status = fit_summary (in, &res->summary))
      || (status = lac_run_strategy_summary (in->nl->ls->loop->strategy,
                                             &res->summary))
      || (status = reactions (in, &res->summary)))
    return status;
  snprintf (progress, size, "Cauchy stresses, von Mises; %zu Newton "
            "iterations in %zu load steps", in->nl->ls->loop->nhist,
            in->nl->log.nfactor);
  return LAC_SUCCESS;
}

/* The first entry of v[n] that is not finite, or n. */
static size_t
first_bad (const double *v, size_t n)
{
  size_t i = 0;
  while (i < n && isfinite (v[i]))
    i++;
  return i;
}

/* Everything the output stage would write is finite: the displacement,
 * the multipliers, the nodal stresses.  With the scene's values bounded
 * (io/lac_scene_types.h) an overflow is not expected; this is the net
 * under it and under a solver that failed without saying so. */
static int
check_finite (const lac_run_post_in *in, const lac_run_results *res)
{
  const lac_mesh *m = in->mesh;
  const char *comp = in->model == LAC_AXISYMMETRIC ? "rz" : "xyz";
  size_t d = (size_t) m->dim, ns = (size_t) lac_model_nstress (in->model);
  size_t n = m->nnodes * d, i = first_bad (in->u, n);
  const char *what = "the displacement is", *after = "";
  char where[96];
  const lac_newton *nt = in->sol ? in->sol->newton : NULL;
  if (i < n)
    snprintf (where, sizeof where, "u_%c = %g at node %zu", comp[i % d],
              in->u[i], m->node_tag[i / d]);
  else if (nt && (i = first_bad (nt->lambda, nt->nslot)) < nt->nslot)
    snprintf (where, sizeof where, "lambda = %g for macro-element %zu of %zu",
              nt->lambda[i], i + 1, nt->nslot),
      what = "the contact multipliers are";
  else if ((i = first_bad (res->sigma, m->nnodes * ns)) < m->nnodes * ns)
    snprintf (where, sizeof where, "stress component %zu = %g at node %zu",
              i % ns + 1, res->sigma[i], m->node_tag[i / ns]),
      what = "the stresses are", after = " (the displacement is finite)";
  else if ((i = first_bad (res->vm, m->nnodes)) < m->nnodes)
    snprintf (where, sizeof where, "von Mises = %g at node %zu",
              res->vm[i], m->node_tag[i]), what = "the stresses are";
  else
    return LAC_SUCCESS;
  return lac_error_set (LAC_ESING, in->sc->path, "%s not finite: %s%s; "
                        "nothing is written (the loads or prescribed "
                        "displacements are too large for the stiffness, or "
                        "the solver failed without saying so)", what, where,
                        after);
}

int
lac_run_post (const lac_run_post_in *in, lac_run_results *res,
              char *progress, size_t size)
{
  const lac_mesh *m = in->mesh;
  int ns = lac_model_nstress (in->model);
  res->sigma = lac_malloc (m->nnodes * (size_t) ns * sizeof *res->sigma);
  res->vm = lac_malloc (m->nnodes * sizeof *res->vm);
  if (!res->sigma || !res->vm)
    LAC_ERROR (LAC_ENOMEM, "nodal stresses of %zu nodes", m->nnodes);
  int status = in->nl ? post_nonlinear (in, res, progress, size)
                      : post_linear (in, res, progress, size);
  return status ? status : check_finite (in, res);
}
