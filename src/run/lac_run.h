/* lac_run.h -- one run of a scene, stage by stage             [LAC §2-§5]
 *
 * The pipeline of one scene.  Each stage is a function of its own module
 * whose signature shows what it reads and what it makes; the run hands
 * the products on, in the order data flows:
 *
 *   1 mesh      scene                          -> mesh     (lac_run_mesh.h)
 *   2 contact   scene, mesh                    -> setup    (lac_run_setup.h)
 *                                  (the mesh is replaced by its refinement)
 *   3 material  scene, mesh                    -> material (lac_run_material.h)
 *   4 assemble  scene, mesh, material, setup   -> system   (lac_run_system.h)
 *   5 solve     scene, system                  -> solution (lac_run_solve.h)
 *               large deformation: + mesh, material, setup -> load steps
 *                                                    (lac_run_nonlinear.h)
 *               small strain with [steps]: + mesh   -> load steps
 *                                                    (lac_run_steps.h)
 *   6 post      all of the above               -> results  (lac_run_post.h)
 *   7 output    all of the above, directory    -> files    (lac_run_output.h)
 *
 * in the GSL style alloc / iterate / free, so that the caller (main) can
 * report each stage without the library printing anything:
 *
 *   lac_run *r = lac_run_alloc (scene, &opts);
 *   while ((status = lac_run_iterate (r)) == LAC_CONTINUE)
 *     fprintf (stderr, "%s\n", r->progress);
 *
 * The solve stage returns LAC_CONTINUE after each active-set iteration
 * (linear scenes with contact, with [steps] of every load step) or each
 * Newton iteration (large deformation),
 * with r->progress about it.  A scene without [contact] runs no search
 * and no active set; a scene without large_deformation no Newton loop: a
 * run simulates the effects the scene asks for and lists them
 * (r->effects).
 *
 * The summary (run/lac_summary.h) is a list of "name = value" lines made
 * to be compared (fixed formats, no timings unless opts.timings, no paths,
 * no solver name): the same scene gives the same summary with every
 * solver up to rounding.
 *
 * Ownership: the scene is borrowed and must outlive the run; everything in
 * lac_run is owned by it and freed by lac_run_free.
 */
#ifndef LAC_RUN_H
#define LAC_RUN_H

#include <signal.h>
#include <stddef.h>
#include "io/lac_output_batch.h"
#include "io/lac_scene.h"
#include "run/lac_run_material.h"
#include "run/lac_run_nonlinear.h"
#include "run/lac_run_post.h"
#include "run/lac_run_setup.h"
#include "run/lac_run_solve.h"
#include "run/lac_run_steps.h"
#include "run/lac_run_system.h"
#include "run/lac_summary.h"

typedef enum
{
  LAC_STAGE_MESH, LAC_STAGE_CONTACT, LAC_STAGE_MATERIAL, LAC_STAGE_ASSEMBLE,
  LAC_STAGE_SOLVE, LAC_STAGE_POST, LAC_STAGE_OUTPUT, LAC_NSTAGES
} lac_stage;

typedef struct lac_run_opts
{
  const char *out_dir;   /* borrowed; NULL: [scene] out, else
                            out/<scene basename>                        */
  int timings;           /* add time_<stage> lines to the summary       */
  int no_output;         /* skip the output stage (no files at all)     */
  int strategy;          /* lac_strategy_kind; LAC_STRATEGY_AUTO: the
                            scene's [contact] strategy                   */
  double max_memory;     /* bytes a mesh may need (gmsh's limit and the
                            size estimate of a .geo, io/lac_mesh_opts.h);
                            0: 80 % of the machine's memory              */
  const volatile sig_atomic_t *stop;  /* a flag a signal handler sets: the
                            output stage then stops between two files and
                            publishes nothing (io/lac_output_batch.h);
                            NULL: never                                  */
  int keep_k;            /* 1: K stays whole after stage 4 for a caller
                            that reads r->sys.K (lac infsup); else it is
                            not kept when the solver assembles K from the
                            cells itself (lac_run_system_stiffness)      */
  int infsup_solve;      /* 0: the mesh guard (max_memory) estimates the
                            solve of the strategy; lac infsup, which runs
                            the stages up to assemble and then solves an
                            eigenvalue problem instead: the
                            LAC_MESH_SOLVE_INFSUP... of that problem
                            (io/lac_mesh_opts.h)                          */
} lac_run_opts;

#define LAC_RUN_MAX_EFFECTS 8

typedef struct lac_run
{
  const lac_scene *scene;   /* borrowed                                  */
  lac_run_opts opts;        /* out_dir replaced by an owned copy         */
  char *out_dir;            /* owned: resolved output directory          */
  int stage;                /* next stage to run (LAC_NSTAGES: done)     */
  lac_model model;

  /* the products of the stages, in the order they are made (all owned) */
  lac_mesh *mesh;           /* 1 (replaced by its refinement in 2)       */
  lac_run_setup setup;      /* 2                                         */
  lac_run_material mat;     /* 3                                         */
  lac_run_system sys;       /* 4                                         */
  lac_run_solution sol;     /* 5: U (both kinds), the active set         */
  lac_run_nl nl;            /* 5, large deformation: the load steps      */
  lac_run_steps steps;      /* 5, small strain with [steps]: the steps   */
  lac_run_results res;      /* 6: stresses, errors, the summary          */
  int hold;                 /* lac_run_hold_files was called           */
  lac_output_batch *batch;  /* 7, held: the files, written, not yet
                               published                                 */

  /* reports */
  double time[LAC_NSTAGES]; /* seconds per stage                         */
  char progress[256];       /* one line about the last stage or iteration */
  size_t neffects;
  const char *effects[LAC_RUN_MAX_EFFECTS];  /* static strings, or:      */
  char friction_text[96];   /* "Coulomb friction (mu = 0.3)"              */
  char effects_text[256];   /* the same, joined by ", "                  */
} lac_run;

/* construct / destroy */
lac_run *lac_run_alloc (const lac_scene *sc, const lac_run_opts *opts);
void lac_run_free (lac_run *r);     /* NULL allowed */

/* compute */
/* Run the next stage (or the next iteration or load step of the solve
 * stage): LAC_CONTINUE if more remains, LAC_SUCCESS after the last one,
 * an error status (message set) otherwise. */
int lac_run_iterate (lac_run *r);
/* Run every remaining stage. */
int lac_run_all (lac_run *r);
/* The output stage will write the files but not publish them: the caller
 * does what else could fail first (main: the summary on stdout), then
 * calls lac_run_publish.  Unpublished files are removed by lac_run_free. */
void lac_run_hold_files (lac_run *r);
/* After the last stage of a run that holds its files: put them in place
 * (lac_output_commit), or, on failure, leave the earlier ones with a
 * message.  LAC_SUCCESS when there is nothing to publish. */
int lac_run_publish (lac_run *r);

/* query */
const char *lac_run_stage_name (int stage);     /* "mesh", ... */
/* The summary value of `key`, NULL if absent. */
const char *lac_run_summary_get (const lac_run *r, const char *key);

#endif /* LAC_RUN_H */
