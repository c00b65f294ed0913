/* lac_run_nonlinear.h -- stage 5 of a large-deformation run: the load
 *                        steps                [LAC §4.5, Alg. 1; §5.4]
 *
 * In:  the scene ([steps], loads, Dirichlet values and their ramp flags,
 *      [contact]), the mesh, the material, the contact set-up (the
 *      macro-mesh, built once on the reference mesh [LAC Remark 3]; the
 *      pairing is recomputed on the current coordinates at every Newton
 *      iteration), the system of stage 4 (F; the bodies held by contact
 *      alone, N).
 * Out: the displacement at every load step, the records of the steps and
 *      of every multiplier at every step, the displacements of the steps
 *      that get a step_NNN.vtu (run/lac_run_steplog.h).
 * The load factors: [steps] n equal steps to 1, after a first step to
 * `start` if given; one call per step (LAC_CONTINUE until the last), each
 * the generalized Newton loop of [LAC Alg. 1] (solve/lac_nonlinear.h,
 * solve/lac_loadstep.h).
 * Loads of [load] sections are dead loads (given on the reference
 * configuration), times t.
 */
#ifndef LAC_RUN_NONLINEAR_H
#define LAC_RUN_NONLINEAR_H

#include <stddef.h>
#include "io/lac_scene.h"
#include "run/lac_run_material.h"
#include "run/lac_run_setup.h"
#include "run/lac_run_steplog.h"
#include "run/lac_run_system.h"
#include "solve/lac_loadstep.h"
#include "solve/lac_nonlinear.h"

typedef struct lac_run_nl
{
  lac_dirichlet *dir;         /* owned: Dirichlet data at t = 1           */
  char *ramp;                 /* owned, dir->n flags                      */
  lac_obstacle ob;
  lac_nl_problem prob;
  lac_nl *model;              /* owned: the large-deformation model       */
  lac_loadstep *ls;           /* owned: the load steps and the loop of
                                 Algorithm 1 (U, lambda, records)         */
  lac_run_steplog log;        /* the load factors and the records of the
                                 steps (imposed_ref: the first non-zero
                                 ramped value)                            */
  int in_step;                /* a load step is under way                 */
  int cuts_seen;              /* its cuts already reported                */
} lac_run_nl;

/* strategy: asked for on the command line (0: the scene's [contact]
 * strategy, else the type that factorizes as [scene] solver says).
 * One Newton iteration per call (solve/lac_loadstep.h), with its line in
 * progress (iteration, residual, statuses changed, active count, GMRES
 * iterations, time; a cut sub-step said once), and at the end of a load
 * step the step's line (load factor, iterations, cuts, residual, active
 * count, the monitor, and the times of assembly, pairing, factorization,
 * solves and the whole step): LAC_CONTINUE until the last step, then
 * LAC_SUCCESS with u (ndof, the caller's) the final displacement. */
int lac_run_nl_solve (const lac_scene *sc, int strategy, const lac_mesh *m,
                      const lac_run_material *mat, const lac_run_setup *setup,
                      const lac_run_system *sys, lac_run_nl *nl, double *u,
                      char *progress, size_t size);
void lac_run_nl_clear (lac_run_nl *nl);

#endif /* LAC_RUN_NONLINEAR_H */
