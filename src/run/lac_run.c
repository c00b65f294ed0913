/* lac_run.c -- one run of a scene, stage by stage (see lac_run.h)
 *                                                             [LAC §2-§5]
 *
 * The run itself: alloc / iterate / free, the effects it simulates, and
 * one table of stages whose entries hand the products of the earlier
 * stages to the stage functions of run/lac_run_*.c.  Errors about the
 * scene point at the scene line (lac_scene_error); errors of the modules
 * keep their message.
 */
#include "run/lac_run.h"

#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_spaces.h"
#include "io/lac_mesh_opts.h"
#include "io/lac_scene_query.h"
#include "run/lac_run_cause.h"
#include "run/lac_run_mesh.h"
#include "run/lac_run_output.h"
#include "linalg/lac_petsc_env.h"
#include "solve/lac_strategy.h"

static const char *const stage_names[LAC_NSTAGES] =
  { "mesh", "contact", "material", "assemble", "solve", "post", "output" };

const char *
lac_run_stage_name (int stage)
{
  return stage >= 0 && stage < LAC_NSTAGES ? stage_names[stage] : "done";
}

const char *
lac_run_summary_get (const lac_run *r, const char *key)
{
  return lac_summary_get (&r->res.summary, key);
}

/* ---- the stages: the products handed on -------------------------------- */

static int
large (const lac_run *r)
{
  return r->scene->scene.large_deformation;
}

static int
stage_mesh (lac_run *r)
{
  return lac_run_mesh (r->scene, r->model, r->opts.strategy,
                       r->opts.infsup_solve, r->opts.max_memory, &r->mesh,
                       r->progress, sizeof r->progress);
}

static int
stage_contact (lac_run *r)
{
  return lac_run_setup_build (r->scene, large (r), &r->mesh, &r->setup,
                              r->progress, sizeof r->progress);
}

static int
stage_material (lac_run *r)
{
  return lac_run_material_build (r->scene, r->model, r->mesh, &r->mat,
                                 r->progress, sizeof r->progress);
}

/* What the strategy auto reads of the run: the MPI processes, whether
 * a Cholesky factor of K is estimated to fit in --max-memory (else
 * petsc, if lac has it), and in 3D the memory it is estimated at (petsc
 * from LAC_STRATEGY_ITERATIVE_BYTES on; chapter 13). */
static lac_strategy_context
auto_context (const lac_run *r)
{
  const lac_refelem *re = r->mesh->ncells
                         ? lac_refelem_get (r->mesh->type[0]) : NULL;
  lac_strategy_context ctx = { 1, 1, r->mesh->dim, re ? re->order : 0, 0 };
  int rank;
  lac_petsc_rank (&rank, &ctx.processes);
  if (lac_petsc_available ())
    {
      ctx.factor_fits = lac_run_mesh_factor_fits (r->scene, r->mesh,
                                                  r->opts.max_memory);
      if (!large (r))           /* large deformation: chapter 10 solves */
        ctx.cholesky_bytes = lac_run_mesh_bytes (r->scene, r->mesh,
                                                 LAC_MESH_SOLVE_CHOLESKY, 0);
    }
  return ctx;
}

/* The system, then K: not kept when the solve assembles it from the
 * cells (petsc) and the caller does not read it (opts.keep_k). */
static int
stage_assemble (lac_run *r)
{
  lac_strategy_context ctx = auto_context (r);
  int status = lac_run_system_build (r->scene, r->model, r->mesh, &r->mat,
                                     &r->setup, &r->sys, r->progress,
                                     sizeof r->progress);
  int from_cells = !status && !r->opts.keep_k
                   && lac_run_solve_k_from_cells (r->scene, r->opts.strategy,
                                                  &ctx, &r->setup, &r->sys);
  return status ? status
         : lac_run_system_stiffness (r->scene, r->mesh, &r->mat, from_cells,
                                     &r->sys, r->progress,
                                     sizeof r->progress);
}

/* A small-strain scene with [steps]: one loop of Algorithm 1 per load
 * step (run/lac_run_steps.h). */
static int
small_steps (const lac_run *r)
{
  return !large (r) && r->scene->steps.sec.line != 0;
}

/* The solve; a failure said with its cause where one is known
 * (lac_run_cause.h). */
static int
stage_solve (lac_run *r)
{
  int status;
  if (!large (r))
    {
      lac_strategy_context ctx = auto_context (r);
      status = small_steps (r)
        ? lac_run_steps_solve (r->scene, r->opts.strategy, &ctx, r->mesh,
                               &r->setup, &r->sys, &r->sol, &r->steps,
                               r->progress, sizeof r->progress)
        : lac_run_solve (r->scene, r->opts.strategy, &ctx, &r->setup,
                         &r->sys, &r->sol, r->progress, sizeof r->progress);
      if (!status)
        {
          lac_run_plate_untie (&r->sys.ties, r->sol.u);  /* rigid plates */
          lac_frames_to_global (r->sys.dir->frames, r->sol.u);  /* u = T u~ */
        }
    }
  else if (!r->sol.u
           && !(r->sol.u = lac_malloc (r->sys.ndof * sizeof *r->sol.u)))
    LAC_ERROR (LAC_ENOMEM, "displacement of %zu dofs", r->sys.ndof);
  else
    status = lac_run_nl_solve (r->scene, r->opts.strategy, r->mesh, &r->mat,
                               &r->setup, &r->sys, &r->nl, r->sol.u,
                               r->progress, sizeof r->progress);
  if (status == LAC_SUCCESS || status == LAC_CONTINUE)
    return status;
  return lac_run_cause (r->scene, r->mesh, &r->setup, r->sol.newton,
                        large (r) ? &r->nl : NULL, status);
}

/* What stages 6 and 7 read of the earlier ones. */
static lac_run_post_in
post_in (const lac_run *r)
{
  lac_run_post_in in = { r->scene, r->model, r->mesh, &r->mat, &r->setup,
                         &r->sys, r->sol.u, large (r) ? NULL : &r->sol,
                         large (r) ? &r->nl : NULL,
                         small_steps (r) ? &r->steps : NULL,
                         r->effects_text };
  return in;
}

static int
stage_post (lac_run *r)
{
  lac_run_post_in in = post_in (r);
  return lac_run_post (&in, &r->res, r->progress, sizeof r->progress);
}

/* time_<stage> lines for the stages before the output, and of their
 * parts, and the peak memory summed over the processes (--timings). */
static int
add_timings (lac_run *r)
{
  lac_summary *s = &r->res.summary;
  int nproc, status;
  double mb = lac_petsc_peak_rss_total_mb (&nproc);
  status = lac_summary_add (s, "peak_rss_total_mb", "%.0f", mb);
  for (int k = 0; k < LAC_STAGE_OUTPUT && !status; k++)
    {
      char key[32];
      snprintf (key, sizeof key, "time_%s", stage_names[k]);
      status = lac_summary_add (s, key, "%.3f", r->time[k]);
    }
  if (!status && large (r))
    {
      const lac_nl *n = r->nl.model;
      const lac_newton *w = r->nl.ls->loop;
      const char *key[] = { "time_assemble_KT", "time_pairing",
                            "time_saddle_solve", "time_factor_KT",
                            "time_frozen_solve", "time_consistent_step",
                            "time_contact_tangent" };
      double t[] = { n->time_assemble, n->time_pairing, w->time_solve,
                     w->time_factor, w->time_frozen, w->time_krylov,
                     n->time_tangent };
      for (size_t k = 0; k < sizeof t / sizeof *t && !status; k++)
        status = lac_summary_add (s, key[k], "%.3f", t[k]);
    }
  else if (!status && r->sol.newton)
    {
      lac_strategy_counts c;
      lac_strategy_get_counts (r->sol.newton->strategy, &c);
      if (!(status = lac_summary_add (s, "time_refine", "%.3f",
                                      r->setup.time_refine))
          && !(status = lac_summary_add (s, "time_pairing", "%.3f",
                                         r->setup.time_pairing))
          && !(status = lac_summary_add (s, "time_factor_K", "%.3f",
                                         c.time_factor)))
        status = lac_summary_add (s, "time_active_set", "%.3f",
                                  c.time_solve);
    }
  return status;
}

static int
stage_output (lac_run *r)
{
  lac_run_output_in in = { post_in (r), &r->res, r->out_dir, r->opts.stop };
  int status = r->opts.timings ? add_timings (r) : LAC_SUCCESS;
  if (status || r->opts.no_output)
    {
      snprintf (r->progress, sizeof r->progress, "no files written");
      return status;
    }
  return lac_run_output (&in, r->hold ? &r->batch : NULL,
                         r->progress, sizeof r->progress);
}

void
lac_run_hold_files (lac_run *r)
{
  r->hold = 1;
}

int
lac_run_publish (lac_run *r)
{
  int status = r->batch ? lac_output_commit (r->batch) : LAC_SUCCESS;
  lac_output_batch_free (r->batch);
  r->batch = NULL;
  return status ? lac_run_output_failed (r->scene->path, r->out_dir, status,
                                         r->opts.stop) : LAC_SUCCESS;
}

/* ---- the run ------------------------------------------------------------ */

/* "Coulomb friction (mu = 0.3)", one value for every pair, or each pair's
 * ("mu = 0.3 on a, 0 on b"). */
static const char *
friction_effect (lac_run *r)
{
  const lac_scene *sc = r->scene;
  char *t = r->friction_text;
  size_t size = sizeof r->friction_text, n;
  int same = 1;
  for (size_t k = 1; k < sc->ncontact; k++)
    same = same && sc->contact[k].friction == sc->contact[0].friction;
  n = (size_t) snprintf (t, size, "Coulomb friction (LAC; mu =");
  for (size_t k = 0; k < (same ? 1 : sc->ncontact) && n < size; k++)
    n += (size_t) snprintf (t + n, size - n, "%s %g%s%s", k ? "," : "",
                            sc->contact[k].friction, same ? "" : " on ",
                            same ? "" : sc->contact[k].sec.name);
  if (n < size)
    snprintf (t + n, size - n, ")");
  return t;
}

/* The effects the scene asks for, in words (printed by the caller, and a
 * summary line). */
static void
list_effects (lac_run *r)
{
  const lac_scene *sc = r->scene;
  r->effects[r->neffects++] = r->model == LAC_PLANE_STRAIN ? "plane strain"
    : r->model == LAC_AXISYMMETRIC ? "axisymmetric" : "3D solid";
  if (sc->ncontact && lac_scene_friction (sc))
    r->effects[r->neffects++] = friction_effect (r);
  else if (sc->ncontact)
    r->effects[r->neffects++] = "frictionless contact (LAC)";
  if (sc->scene.large_deformation)
    {
      int nh = 0;
      for (size_t k = 0; k < sc->nmaterial; k++)
        nh += sc->material[k].law != 0;
      r->effects[r->neffects++] = "large deformation";
      if (nh)
        r->effects[r->neffects++] = "neo-Hookean material";
      if (nh < (int) sc->nmaterial)
        r->effects[r->neffects++] = "Saint Venant-Kirchhoff material";
      if (sc->ncontact)
        r->effects[r->neffects++] = "re-pairing every iteration";
      if (sc->steps.n > 1 || sc->steps.start > 0)
        r->effects[r->neffects++] = "load steps";
    }
  else
    {
      r->effects[r->neffects++] = "small strain";
      r->effects[r->neffects++] = "linear elastic material";
      if (sc->steps.sec.line && (sc->steps.n > 1 || sc->steps.start > 0))
        r->effects[r->neffects++] = "load steps";
    }
  for (size_t k = 0; k < r->neffects; k++)
    snprintf (r->effects_text + strlen (r->effects_text),
              sizeof r->effects_text - strlen (r->effects_text), "%s%s",
              k ? ", " : "", r->effects[k]);
}

lac_run *
lac_run_alloc (const lac_scene *sc, const lac_run_opts *opts)
{
  lac_run *r;
  const char *out;
  size_t len;
  if (!sc)
    LAC_ERROR_NULL (LAC_EINVAL, "no scene");
  if (!(r = lac_calloc (1, sizeof *r)))
    LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
  if (opts)
    r->opts = *opts;
  r->scene = sc;
  r->model = (lac_model) sc->scene.model;
  out = r->opts.out_dir ? r->opts.out_dir : sc->scene.out;
  len = out ? strlen (out) + 1 : strlen (sc->basename) + 5;
  if (!(r->out_dir = lac_malloc (len)))
    {
      lac_free (r);
      LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
    }
  if (out)
    snprintf (r->out_dir, len, "%s", out);
  else
    snprintf (r->out_dir, len, "out/%s", sc->basename);
  r->opts.out_dir = r->out_dir;
  list_effects (r);
  return r;
}

void
lac_run_free (lac_run *r)
{
  if (!r)
    return;
  lac_output_batch_free (r->batch);      /* unpublished: removed */
  lac_run_results_clear (&r->res);
  lac_run_nl_clear (&r->nl);
  lac_run_steps_clear (&r->steps);
  lac_run_solution_clear (&r->sol);
  lac_run_system_clear (&r->sys);
  lac_run_material_clear (&r->mat);
  lac_run_setup_clear (&r->setup);
  lac_mesh_free (r->mesh);
  lac_free (r->out_dir);
  lac_free (r);
}

/* A failed stage whose message names no place (a module deep inside
 * knows a node or a vertex, not the run): the scene and the stage go in
 * front, so that the one line says which run and which step failed
 * (base/lac_status.h). */
static int
placed (const lac_run *r, int status)
{
  if (lac_error_placed ())
    return status;
  return lac_error_place (status, r->scene->path, "%s stage: %s",
                          stage_names[r->stage], *lac_error_message ()
                          ? lac_error_message () : lac_strerror (status));
}

int
lac_run_iterate (lac_run *r)
{
  static int (*const stage[LAC_NSTAGES]) (lac_run *) = {
    stage_mesh, stage_contact, stage_material, stage_assemble, stage_solve,
    stage_post, stage_output };
  double t0 = lac_seconds ();
  int status;
  if (r->stage >= LAC_NSTAGES)
    return LAC_SUCCESS;
  r->progress[0] = '\0';
  status = stage[r->stage] (r);
  r->time[r->stage] += lac_seconds () - t0;   /* solve: every iteration */
  if (status == LAC_CONTINUE)                 /* an iteration: same stage */
    return LAC_CONTINUE;
  if (status)
    return placed (r, status);
  r->stage++;
  return r->stage < LAC_NSTAGES ? LAC_CONTINUE : LAC_SUCCESS;
}

int
lac_run_all (lac_run *r)
{
  int status;
  while ((status = lac_run_iterate (r)) == LAC_CONTINUE)
    ;
  return status;
}
