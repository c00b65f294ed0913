/* lac_run_output.c -- stage 7 of a run: the files (see lac_run_output.h)
 */
#include "run/lac_run_output.h"

#include <stdio.h>
#include "base/lac_file.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_post.h"
#include "io/lac_output.h"
#include "io/lac_output_batch.h"
#include "io/lac_vtu.h"
#include "run/lac_run_contact_files.h"
#include "run/lac_run_scene.h"

/* ---- linear runs ------------------------------------------------------ */

/* contact.csv ([output] csv) and contact.vtu ([output] vtu). */
static int
contact_files (const lac_run_output_in *in, lac_output_batch *b)
{
  const lac_scene_output *o = &in->post.sc->output;
  lac_run_contact_data d = { in->post.model, in->post.mesh, in->post.setup,
                             in->post.setup->data.all, in->post.sol->newton,
                             &in->res->mult, &in->res->contact,
                             in->post.sc->exact.sec.line != 0, in->post.sc,
                             in->post.u };
  const char *path;
  int status = LAC_SUCCESS;
  if (o->csv)
    status = (path = lac_output_batch_add (b, "contact.csv"))
             ? lac_run_contact_csv (&d, path) : LAC_ENOMEM;
  if (o->vtu && !status)
    status = (path = lac_output_batch_add (b, "contact.vtu"))
             ? lac_run_contact_vtu (&d, o->vtu_format, path) : LAC_ENOMEM;
  return status;
}

/* solution.vtu and nodes.csv, as [output] asks, into the batch b: the
 * displacement, the exact one (linear runs with [exact]), the stresses. */
static int
write_fields (const lac_run_output_in *in, lac_output_batch *b)
{
  const lac_scene_output *o = &in->post.sc->output;
  const lac_run_results *res = in->res;
  lac_output_fields f = { in->post.mesh, in->post.model, in->post.u,
                          res->u_exact, res->sigma, res->vm, o->vtu_format };
  const char *path;
  int status = LAC_SUCCESS;
  if (o->vtu && !status)
    status = (path = lac_output_batch_add (b, "solution.vtu"))
             ? lac_output_vtu (path, &f) : LAC_ENOMEM;
  if (o->csv && !status)
    status = (path = lac_output_batch_add (b, "nodes.csv"))
             ? lac_output_csv (path, &f) : LAC_ENOMEM;
  return status;
}

/* summary.txt, written last. */
static int
write_summary (const lac_run_output_in *in, lac_output_batch *b)
{
  const lac_summary *s = &in->res->summary;
  const char *path = lac_output_batch_add (b, "summary.txt");
  return path ? lac_output_summary (path, s->n, (const char *const *) s->key,
                                    (const char *const *) s->val)
              : LAC_ENOMEM;
}

/* The records of the load steps: large deformation, or small strain
 * with [steps]. */
static const lac_run_steplog *
steplog (const lac_run_output_in *in)
{
  return in->post.nl ? &in->post.nl->log : &in->post.steps->log;
}

static int
write_curve (const lac_run_output_in *in, const char *path)
{
  const lac_run_steplog *nl = steplog (in);
  int dim = in->post.mesh->dim;
  FILE *f;
  int status = lac_file_create (path, "w", &f);
  if (status)
    return status;
  fprintf (f, "step,load_factor,imposed,monitor_ux,monitor_uy%s,iterations,"
           "cuts,residual,multipliers,active,contact_force,lambda_min\n",
           dim == 3 ? ",monitor_uz" : "");
  fprintf (f, "0,0,0,0,0%s,0,0,0,0,0,0,0\n", dim == 3 ? ",0" : "");
  for (size_t j = 0; j < nl->nfactor; j++)
    {
      const lac_run_step_record *q = &nl->step[j];
      const lac_nl_step *h = &q->solver;
      fprintf (f, "%zu,%.10e,%.10e", j + 1, h->t, q->imposed);
      for (int k = 0; k < dim; k++)
        fprintf (f, ",%.10e", q->um[k]);
      fprintf (f, ",%d,%d,%.3e,%zu,%zu,%.10e,%.10e\n", h->iters, h->cuts,
               h->residual, h->k, h->nactive, q->force, q->lambda_min);
    }
  return lac_file_close (f, path);
}

/* contact_steps.csv (every step) or contact.csv (last step only). */
static int
write_mults (const lac_run_output_in *in, const char *path, int last_only)
{
  const lac_run_steplog *nl = steplog (in);
  FILE *f;
  int status = lac_file_create (path, "w", &f);
  if (status)
    return status;
  fprintf (f, "%smacro,x,y,z,lambda,mean_gap,active,covered,pair\n",
           last_only ? "" : "step,");
  for (size_t q = 0; q < nl->nmult; q++)
    {
      const lac_run_mult_record *u = &nl->mult[q];
      if (last_only && u->step != (int) nl->nfactor)
        continue;
      if (!last_only)
        fprintf (f, "%d,", u->step);
      size_t p = lac_contact_set_pair_of (&in->post.setup->set, u->macro);
      fprintf (f, "%zu,%.10e,%.10e,%.10e,%.10e,%.10e,%d,%.10e,%s\n",
               u->macro, u->x[0], u->x[1], u->x[2], u->lambda, u->gap,
               u->active, u->covered, in->post.sc->contact[p].sec.name);
    }
  return lac_file_close (f, path);
}

/* step_NNN.vtu of step j (0-based): the displacement u, its Cauchy
 * stresses in sigma, vm (the last step: those of solution.vtu). */
static int
write_step_vtu (const lac_run_output_in *in, lac_output_batch *b, size_t j,
                const double *u, const double *sigma, const double *vm)
{
  lac_output_fields f = { in->post.mesh, in->post.model, u, NULL, sigma, vm,
                          in->post.sc->output.vtu_format };
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
write_pvd (const lac_run_output_in *in, const char *path)
{
  const lac_run_steplog *nl = steplog (in);
  FILE *f;
  int status = lac_file_create (path, "w", &f);
  if (status)
    return status;
  lac_vtu_xml_head (f, "Collection", "0.1", "");
  fprintf (f, "  <Collection>\n");
  for (size_t j = 0; j < nl->nfactor; j++)
    if (lac_run_steplog_file (j, nl->nfactor, in->post.sc->steps.vtu_every))
      fprintf (f, "    <DataSet timestep=\"%.10g\" group=\"\" part=\"0\" "
               "file=\"step_%03zu.vtu\"/>\n", nl->step[j].solver.t,
               j + 1);
  fprintf (f, "  </Collection>\n</VTKFile>\n");
  return lac_file_close (f, path);
}

/* The stresses of the displacement u of a kept step, as in stage post:
 * Cauchy's (large deformation) or the linear ones. */
static int
step_stresses (const lac_run_output_in *in, const double *u, double *sigma,
               double *vm)
{
  const lac_run_post_in *p = &in->post;
  return p->nl ? lac_hyper_cauchy_nodal (p->mesh, &p->mat->hyper, u, NULL,
                                         sigma, vm)
         : lac_post_stress_nodal (p->mesh, &p->mat->elastic, u, NULL, sigma,
                                  vm);
}

/* The step files ([steps] vtu_every) and steps.pvd; stresses of the kept
 * steps as in stage post. */
static int
write_steps (const lac_run_output_in *in, lac_output_batch *b)
{
  const lac_run_steplog *nl = steplog (in);
  const lac_mesh *m = in->post.mesh;
  size_t nn = m->nnodes, ndof = (size_t) m->dim * nn;
  int ns = lac_model_nstress (in->post.model);
  double *sigma = lac_malloc (nn * (size_t) ns * sizeof *sigma),
    *vm = lac_malloc (nn * sizeof *vm);
  const char *path;
  int status = sigma && vm ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "stresses of the step files");
  for (size_t q = 0; q < nl->nkept && !status; q++)
    {
      const double *u = nl->ukept + q * ndof;
      if (!(status = step_stresses (in, u, sigma, vm)))
        status = write_step_vtu (in, b, nl->kept[q], u, sigma, vm);
    }
  if (!status)
    status = write_step_vtu (in, b, nl->nfactor - 1, in->post.u,
                             in->res->sigma, in->res->vm);
  if (!status)
    status = (path = lac_output_batch_add (b, "steps.pvd"))
             ? write_pvd (in, path) : LAC_ENOMEM;
  lac_free (sigma);
  lac_free (vm);
  return status;
}

/* ---- the stage -------------------------------------------------------- */

/* A small-strain run with [steps]: the curve, contact_steps.csv, the step
 * files; their names in list. */
static int
linear_steps (const lac_run_output_in *in, lac_output_batch *b, char *list,
              size_t size)
{
  const lac_scene *sc = in->post.sc;
  const char *curve = sc->steps.curve ? sc->steps.curve : "curve.csv";
  const char *path;
  char nsteps[64] = "";
  int status = LAC_SUCCESS;
  if (!(path = lac_output_batch_add (b, curve))
      || (status = write_curve (in, path))
      || !(path = lac_output_batch_add (b, "contact_steps.csv"))
      || (status = write_mults (in, path, 0)))
    return status ? status : LAC_ENOMEM;
  if (sc->steps.vtu_every > 0 && (status = write_steps (in, b)))
    return status;
  if (sc->steps.vtu_every > 0)
    snprintf (nsteps, sizeof nsteps, "%zu step_NNN.vtu, steps.pvd, ",
              steplog (in)->nkept + 1);
  snprintf (list, size, "%s, contact_steps.csv, %s", curve, nsteps);
  return LAC_SUCCESS;
}

static int
output_linear (const lac_run_output_in *in, lac_output_batch *b,
               char *progress, size_t size)
{
  const lac_scene_output *o = &in->post.sc->output;
  const char *path = "";
  char steps[128] = "";
  int contact = in->post.setup->data.all != NULL;
  int status = write_fields (in, b);
  if (!status && contact)
    status = contact_files (in, b);
  if (!status && o->matrix
      && (!(path = lac_output_batch_add (b, "K.mtx"))
          || (status = lac_csc_write_mm (in->post.sys->K0, path))))
    return status ? status : LAC_ENOMEM;
  if (!status && in->post.steps)
    status = linear_steps (in, b, steps, sizeof steps);
  if (!status && !(status = write_summary (in, b)))
    snprintf (progress, size, "%s/: %s%s%s%s%s%ssummary.txt", in->dir,
              o->vtu ? "solution.vtu, " : "", o->csv ? "nodes.csv, " : "",
              o->csv && contact ? "contact.csv, " : "",
              o->vtu && contact ? "contact.vtu, " : "",
              o->matrix ? "K.mtx, " : "", steps);
  return status;
}

static int
output_nonlinear (const lac_run_output_in *in, lac_output_batch *b,
                  char *progress, size_t size)
{
  const lac_scene *sc = in->post.sc;
  const lac_scene_output *o = &sc->output;
  const char *curve = sc->steps.curve ? sc->steps.curve : "curve.csv";
  const char *path = "";
  int macro = in->post.setup->npairs > 0;
  char nsteps[64];
  int status = write_fields (in, b);
  if (!status && (!(path = lac_output_batch_add (b, curve))
                  || (status = write_curve (in, path))))
    return status ? status : LAC_ENOMEM;
  if (!status && macro && (!(path = lac_output_batch_add (b, "contact.csv"))
                           || (status = write_mults (in, path, 1))))
    return status ? status : LAC_ENOMEM;
  if (!status && macro
      && (!(path = lac_output_batch_add (b, "contact_steps.csv"))
          || (status = write_mults (in, path, 0))))
    return status ? status : LAC_ENOMEM;
  if (!status && sc->steps.vtu_every > 0)
    status = write_steps (in, b);
  if (status || (status = write_summary (in, b)))
    return status;
  snprintf (nsteps, sizeof nsteps, "%zu step_NNN.vtu, steps.pvd, ",
            steplog (in)->nkept + 1);
  snprintf (progress, size, "%s/: %s%s%s%s%ssummary.txt", in->dir,
            o->vtu ? "solution.vtu, " : "", o->csv ? "nodes.csv, " : "",
            curve, macro ? ", contact.csv, contact_steps.csv, " : ", ",
            sc->steps.vtu_every > 0 ? nsteps : "");
  return LAC_SUCCESS;
}

int
lac_run_output_failed (const char *scene, const char *dir, int status,
                       const volatile sig_atomic_t *stop)
{
  char msg[700];
  lac_run_inner_message (msg, sizeof msg);
  if (stop && *stop)                  /* the batch's own words suffice */
    return lac_error_set (LAC_EIO, scene, "%s", msg);
  return lac_error_set (status, scene, "%s; nothing was published: the "
                        "files in '%s' are those of the earlier run", msg,
                        dir);
}

int
lac_run_output (const lac_run_output_in *in, lac_output_batch **keep,
                char *progress, size_t size)
{
  lac_output_batch *b = lac_output_batch_alloc (in->dir, in->stop);
  int status = b ? LAC_SUCCESS : LAC_EIO;
  if (!status)
    status = in->post.nl ? output_nonlinear (in, b, progress, size)
                         : output_linear (in, b, progress, size);
  if (!status && !keep)
    status = lac_output_commit (b);
  if (!status && keep)
    *keep = b;
  else
    lac_output_batch_free (b);
  return status ? lac_run_output_failed (in->post.sc->path, in->dir, status,
                                         in->stop) : LAC_SUCCESS;
}
