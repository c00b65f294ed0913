/* lac_run.h -- one run of a scene: mesh, assembly, solve, post, output
 *
 * The pipeline of design.md for a scene without contact: the stages run one
 * after the other, each a plain function of the results of the previous
 * ones, in the GSL style alloc / iterate / free, so that the caller (main)
 * can report each stage without the library printing anything:
 *
 *   lac_run *r = lac_run_alloc (scene, &opts);
 *   while ((status = lac_run_iterate (r)) == LAC_CONTINUE)
 *     fprintf (stderr, "%s\n", r->progress);
 *
 * A scene with [scene] large_deformation = yes runs the same stages with
 * the large-deformation versions of contact (macro-mesh only: the pairing
 * moves with the bodies), solve (load steps, [LAC Alg. 1]; the solve stage
 * then returns LAC_CONTINUE after each load step, with r->progress about
 * that step), post (Cauchy stresses) and output (lac_run_nonlinear.c).
 *
 * Stages: mesh (read/mesh through gmsh, check groups against the scene),
 * contact (macro-mesh and pairing, lac_run_contact.c; skipped without a
 * [contact] section), material (E, nu per cell), assemble (K, F, Dirichlet, rigid-motion
 * check), solve (dense | umfpack | cholmod), post (nodal stresses, von
 * Mises, errors against the exact solution, the summary), output (VTU, CSV,
 * Matrix Market, summary.txt, all renamed into place at the end).
 *
 * The summary is a list of "name = value" lines made to be compared (fixed
 * formats, no timings unless opts.timings, no paths, no solver name): the
 * same scene gives the same summary with every solver up to rounding.
 *
 * Ownership: the scene is borrowed and must outlive the run; everything in
 * lac_run is owned by it and freed by lac_run_free.
 */
#ifndef LAC_RUN_H
#define LAC_RUN_H

#include <stddef.h>
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_newton.h"
#include "io/lac_scene.h"

typedef enum
{
  LAC_STAGE_MESH, LAC_STAGE_CONTACT, LAC_STAGE_MATERIAL, LAC_STAGE_ASSEMBLE, LAC_STAGE_SOLVE,
  LAC_STAGE_POST, LAC_STAGE_OUTPUT, LAC_NSTAGES
} lac_stage;

typedef struct lac_run_opts
{
  const char *out_dir;   /* borrowed; NULL: [scene] out, else
                            out/<scene basename>                        */
  int timings;           /* add time_<stage> lines to the summary       */
  int no_output;         /* skip the output stage (no files at all)     */
  int strategy;          /* lac_strategy_kind; LAC_STRATEGY_AUTO: the
                            scene's [contact] strategy                   */
} lac_run_opts;

#define LAC_RUN_MAX_EFFECTS 8

typedef struct lac_run
{
  const lac_scene *scene;   /* borrowed                                  */
  lac_run_opts opts;        /* out_dir replaced by an owned copy         */
  char *out_dir;            /* owned: resolved output directory          */
  int stage;                /* next stage to run (LAC_NSTAGES: done)     */
  lac_model model;
  int dim, ns;              /* space dimension, stress components        */
  const char *solver_name;  /* static                                    */

  /* mesh and material */
  lac_mesh *mesh;           /* owned                                     */
  double *E, *nu;           /* owned, ncells                             */
  lac_elastic mat;          /* points into E, nu                         */

  /* linear system K u = F (K, b: after the Dirichlet elimination)      */
  size_t ndof, nfixed, nnz;
  lac_csc *K;               /* owned until solved                        */
  lac_csc *K0;              /* owned: K before Dirichlet ([output] matrix) */
  double *F;                /* owned, ndof: the load vector              */
  double *b;                /* owned, ndof: right-hand side after Dirichlet */
  double *u;                /* owned, ndof: the displacement, dim*node+i  */
  double rcond;             /* solver's condition estimate (0 if none)   */

  /* contact (all NULL without a [contact] section) */
  lac_macro *macro;         /* owned: the macro-mesh of the slave group  */
  lac_pairing *pairing;     /* owned: its sub-facets against the master */
  lac_pairing_facets master; /* points into the mesh's master group      */
  lac_contact *contact;     /* owned: admissibility, C, G                */
  lac_newton *newton;       /* owned: U, lambda, statuses, history       */
  char *on_contact;         /* owned, nnodes: node on a contact surface  */
  const char *fallback;     /* static: why the solver was changed, or NULL */
  double *lam_x;            /* owned, 3k: centroid of T^m cap Gamma_C    */
  double *lam_exact;        /* owned, k: mean exact n.sigma.n there      */
  double time_refine, time_pairing;  /* seconds, parts of stage contact  */

  /* large deformation ([scene] large_deformation = yes; NULL otherwise):
   * lac_run_nonlinear.c, one load step per call of the solve stage */
  char *law;                /* owned, ncells: lac_law of each cell       */
  struct lac_run_nl *nl;    /* owned: the Newton workspace and records   */

  /* post-processing */
  double *sigma;            /* owned, nnodes*ns: nodal stresses          */
  double *vm;               /* owned, nnodes: von Mises                  */
  double *u_exact;          /* owned, ndof, or NULL without [exact]      */
  double err_l2, err_h1, norm_l2, norm_h1;

  /* reports */
  double time[LAC_NSTAGES]; /* seconds per stage                         */
  char progress[256];       /* one line about the last stage             */
  size_t neffects;
  const char *effects[LAC_RUN_MAX_EFFECTS];  /* static strings           */
  size_t nsummary, capsummary;
  char **key, **val;        /* owned, nsummary: the summary lines        */
} lac_run;

/* construct / destroy */
lac_run *lac_run_alloc (const lac_scene *sc, const lac_run_opts *opts);
void lac_run_free (lac_run *r);     /* NULL allowed */

/* compute */
/* Run the next stage: LAC_CONTINUE if stages remain, LAC_SUCCESS after the
 * last one, an error status (message set) otherwise. */
int lac_run_iterate (lac_run *r);
/* Run every remaining stage. */
int lac_run_all (lac_run *r);

/* query */
const char *lac_run_stage_name (int stage);     /* "mesh", ... */
/* The summary value of `key`, NULL if absent. */
const char *lac_run_summary_get (const lac_run *r, const char *key);

#endif /* LAC_RUN_H */
