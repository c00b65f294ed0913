/* lac_run_post.c -- stages 5 and 6 of a run (see lac_run.h)      [LAC §5]
 *
 * post: nodal stresses and von Mises (lac_post.c), errors in L2 and H1
 * against the [exact] solution (lac_exact.c), and the summary: "name =
 * value" lines in fixed formats, made to be compared (no paths, no solver
 * name, no timings unless asked).  For the radial solutions the summary
 * also has the mean radial displacement on the inner and outer surfaces.
 * output: solution.vtu, nodes.csv, K.mtx and summary.txt, written into a
 * batch and renamed into place at the end (lac_output.c).
 */
#include "run/lac_run_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "io/lac_output.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

/* ---- stage 5: post ---------------------------------------------------- */

/* Distinct cell types of the mesh, "tri6" or "tri6+quad8". */
void
lac_run_cell_types (const lac_mesh *m, char *buf, size_t size)
{
  int seen[LAC_NELEM_TYPES] = { 0 };
  size_t len = 0;
  buf[0] = '\0';
  for (size_t c = 0; c < m->ncells; c++)
    seen[m->type[c]] = 1;
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    if (seen[t] && len < size)
      len += (size_t) snprintf (buf + len, size - len, "%s%s", len ? "+" : "",
                                lac_refelem_get ((lac_elem_type) t)->name);
}

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
radial_mean (const lac_run *r, const lac_exact *e, double R0, double *uh,
             double *ue)
{
  const lac_mesh *m = r->mesh;
  size_t n = 0;
  *uh = *ue = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *x = m->x + a * (size_t) r->dim;
      double R = lac_exact_radius (e, x);
      if (fabs (R - R0) > 1e-8 * R0)
        continue;
      for (int i = 0; i < e->nr; i++)
        {
          *uh += r->u[a * (size_t) r->dim + (size_t) i] * x[i] / R;
          *ue += r->u_exact[a * (size_t) r->dim + (size_t) i] * x[i] / R;
        }
      n++;
    }
  if (n)
    *uh /= (double) n, *ue /= (double) n;
  return n;
}

static int
summary_exact (lac_run *r, const lac_exact *e)
{
  const lac_scene_exact *x = &r->scene->exact;
  const char *side[2] = { "inner", "outer" };
  const double R0[2] = { x->a, x->b };
  int status = lac_run_summary_add (r, "exact", "%s",
                                    lac_scene_exact_name (x->solution));
  if (!status)
    status = lac_run_summary_add (r, "l2_err_u", "%.10e", r->err_l2);
  if (!status)
    status = lac_run_summary_add (r, "h1_err_u", "%.10e", r->err_h1);
  if (!status)
    status = lac_run_summary_add (r, "rel_l2_err_u", "%.10e", r->norm_l2 > 0
                                  ? r->err_l2 / r->norm_l2 : 0.0);
  if (!status)
    status = lac_run_summary_add (r, "rel_h1_err_u", "%.10e", r->norm_h1 > 0
                                  ? r->err_h1 / r->norm_h1 : 0.0);
  for (int k = 0; k < 2 && !status && e->nr > 0; k++)   /* radial only */
    {
      double uh, ue;
      char key[64];
      if (!radial_mean (r, e, R0[k], &uh, &ue))
        continue;
      snprintf (key, sizeof key, "u_r_%s", side[k]);
      status = lac_run_summary_add (r, key, "%.10e", uh);
      snprintf (key, sizeof key, "u_r_%s_exact", side[k]);
      if (!status)
        status = lac_run_summary_add (r, key, "%.10e", ue);
      snprintf (key, sizeof key, "rel_err_u_r_%s", side[k]);
      if (!status)
        status = lac_run_summary_add (r, key, "%.10e", ue != 0
                                      ? fabs (uh - ue) / fabs (ue)
                                      : fabs (uh));
    }
  return status;
}

static int
make_summary (lac_run *r, const lac_exact *e)
{
  const lac_mesh *m = r->mesh;
  double work = 0, umax = 0, vmax = 0;
  char types[128], effects[256] = "";
  int status;
  for (size_t k = 0; k < r->ndof; k++)
    work += r->F[k] * r->u[k];                   /* l(u_h) = F . u */
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double s = 0;
      for (int i = 0; i < r->dim; i++)
        s += r->u[a * (size_t) r->dim + (size_t) i]
             * r->u[a * (size_t) r->dim + (size_t) i];
      umax = fmax (umax, sqrt (s));
      vmax = fmax (vmax, r->vm[a]);
    }
  lac_run_cell_types (m, types, sizeof types);
  for (size_t k = 0; k < r->neffects; k++)
    snprintf (effects + strlen (effects), sizeof effects - strlen (effects),
              "%s%s", k ? ", " : "", r->effects[k]);
  if ((status = lac_run_summary_add (r, "title", "%s",
                                     r->scene->scene.title))
      || (status = lac_run_summary_add (r, "model", "%s",
                                        lac_model_name (r->model)))
      || (status = lac_run_summary_add (r, "element", "%s", types))
      || (status = lac_run_summary_add (r, "effects", "%s", effects))
      || (status = lac_run_summary_add (r, "nodes", "%zu", m->nnodes))
      || (status = lac_run_summary_add (r, "cells", "%zu", m->ncells))
      || (status = lac_run_summary_add (r, "dofs", "%zu", r->ndof))
      || (status = lac_run_summary_add (r, "h", "%.10e", mesh_size (m)))
      || (status = lac_run_summary_add (r, "fixed_dofs", "%zu", r->nfixed))
      || (status = lac_run_summary_add (r, "nnz_K", "%zu", r->nnz))
      || (status = lac_run_summary_add (r, "load_work", "%.10e", work))
      || (status = lac_run_summary_add (r, "max_u", "%.10e", umax))
      || (status = lac_run_summary_add (r, "max_von_mises", "%.10e", vmax)))
    return status;
  return r->u_exact ? summary_exact (r, e) : LAC_SUCCESS;
}

int
lac_run_stage_post (lac_run *r)
{
  const lac_mesh *m = r->mesh;
  lac_exact e;
  int status;
  r->sigma = lac_malloc (m->nnodes * (size_t) r->ns * sizeof *r->sigma);
  r->vm = lac_malloc (m->nnodes * sizeof *r->vm);
  if (!r->sigma || !r->vm)
    LAC_ERROR (LAC_ENOMEM, "nodal stresses of %zu nodes", m->nnodes);
  status = lac_post_stress_nodal (m, &r->mat, r->u, NULL, r->sigma, r->vm);
  if (status)
    return status;
  lac_run_exact (r, &e);
  if (r->scene->exact.sec.line != 0)
    {
      if (!(r->u_exact = lac_malloc (r->ndof * sizeof *r->u_exact)))
        LAC_ERROR (LAC_ENOMEM, "exact displacement");
      for (size_t a = 0; a < m->nnodes; a++)
        lac_exact_u (m->x + a * (size_t) r->dim, &e,
                     r->u_exact + a * (size_t) r->dim);
      status = lac_post_errors (m, r->model, r->u, lac_exact_u,
                                lac_exact_grad, &e, &r->err_l2, &r->err_h1,
                                &r->norm_l2, &r->norm_h1);
      if (status)
        return status;
    }
  if ((status = make_summary (r, &e)))
    return status;
  if (r->contact && (status = lac_run_contact_post (r, &e)))
    return status;
  if (r->u_exact)
    snprintf (r->progress, sizeof r->progress, "stresses, errors vs %s: "
              "L2 %.3e, H1 %.3e", lac_scene_exact_name
              (r->scene->exact.solution), r->err_l2, r->err_h1);
  else
    snprintf (r->progress, sizeof r->progress, "stresses, von Mises");
  return LAC_SUCCESS;
}

/* ---- stage 6: output -------------------------------------------------- */

/* time_<stage> lines for the stages before the output (--timings). */
int
lac_run_stage_timings (lac_run *r)
{
  int status = LAC_SUCCESS;
  for (int s = 0; s < LAC_STAGE_OUTPUT && !status; s++)
    {
      char key[32];
      snprintf (key, sizeof key, "time_%s", lac_run_stage_name (s));
      status = lac_run_summary_add (r, key, "%.3f", r->time[s]);
    }
  return status;
}

/* solution.vtu and nodes.csv, as [output] asks, into the batch b. */
int
lac_run_write_fields (const lac_run *r, lac_output_batch *b,
                      const lac_output_fields *f)
{
  const lac_scene_output *o = &r->scene->output;
  const char *path;
  int status = LAC_SUCCESS;
  if (o->vtu && !status)
    status = (path = lac_output_batch_add (b, "solution.vtu"))
             ? lac_output_vtu (path, f) : LAC_ENOMEM;
  if (o->csv && !status)
    status = (path = lac_output_batch_add (b, "nodes.csv"))
             ? lac_output_csv (path, f) : LAC_ENOMEM;
  return status;
}

/* summary.txt, written last, then the batch renamed into place. */
int
lac_run_write_summary (lac_run *r, lac_output_batch *b)
{
  const char *path = lac_output_batch_add (b, "summary.txt");
  int status = path ? lac_output_summary (path, r->nsummary,
                                          (const char *const *) r->key,
                                          (const char *const *) r->val)
                    : LAC_ENOMEM;
  return status ? status : lac_output_commit (b);
}

int
lac_run_stage_output (lac_run *r)
{
  const lac_scene_output *o = &r->scene->output;
  lac_output_fields f = { r->mesh, r->model, r->u, r->u_exact, r->sigma,
                          r->vm };
  lac_output_batch *b;
  const char *path = "";
  int status = r->opts.timings ? lac_run_stage_timings (r) : LAC_SUCCESS;
  if (r->opts.timings && r->contact && !status)     /* parts of the stages */
    {
      lac_strategy_counts sc;
      lac_strategy_get_counts (r->newton->strategy, &sc);
      if ((status = lac_run_summary_add (r, "time_refine", "%.3f",
                                         r->time_refine))
          || (status = lac_run_summary_add (r, "time_pairing", "%.3f",
                                            r->time_pairing))
          || (status = lac_run_summary_add (r, "time_factor_K", "%.3f",
                                            sc.time_factor)))
        return status;
      status = lac_run_summary_add (r, "time_active_set", "%.3f",
                                    sc.time_solve);
    }
  if (status || r->opts.no_output)
    {
      snprintf (r->progress, sizeof r->progress, "no files written");
      return status;
    }
  if (!(b = lac_output_batch_alloc (r->out_dir)))
    return LAC_EIO;
  if ((status = lac_run_write_fields (r, b, &f)))
    goto done;
  if (o->csv && r->contact
      && (!(path = lac_output_batch_add (b, "contact.csv"))
          || (status = lac_run_contact_csv (r, path))))
    goto done;
  if (o->matrix && (!(path = lac_output_batch_add (b, "K.mtx"))
                    || (status = lac_csc_write_mm (r->K0, path))))
    goto done;
  if ((status = lac_run_write_summary (r, b)))
    goto done;
  snprintf (r->progress, sizeof r->progress, "%s/: %s%s%s%ssummary.txt",
            r->out_dir, o->vtu ? "solution.vtu, " : "",
            o->csv ? "nodes.csv, " : "",
            o->csv && r->contact ? "contact.csv, " : "",
            o->matrix ? "K.mtx, " : "");
done:
  if (!status && !path)
    status = LAC_ENOMEM;
  lac_output_batch_free (b);
  return status;
}
