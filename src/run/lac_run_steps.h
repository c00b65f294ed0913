/* lac_run_steps.h -- stage 5 of a small-strain run with [steps]: one loop
 *                    of Algorithm 1 per load step     [LAC §4.5, Alg. 1]
 *
 * In:  the scene ([steps]: n, start, end, monitor, vtu_every), the mesh,
 *      the contact set-up, the system of stage 4 with its loads by curve
 *      (run/lac_run_curves.h), a strategy asked for on the command line.
 * Out: the solution of the last step (run/lac_run_solve.h), the records
 *      of every step (run/lac_run_steplog.h).
 *
 * The load factor goes to `start` in one step (if start > 0), then to
 * `end` in n equal steps.  At each t_k the loads and the Dirichlet values
 * are those of the sections times their f(t_k) (F, b and the values of
 * the system replaced in place: lac_run_curves_set; the mean gaps G
 * follow the values, lac_linear_model_dirichlet), and one loop of
 * Algorithm 1 (solve/lac_newton.h) starts from the state of the last
 * converged step (lac_newton_begin keeps it in U0, lambda0).  K, C and
 * the pairing do not change, so that the strategy keeps its
 * factorization of K for the whole run: only the right-hand sides are
 * new.  A step that pairs again (no silent penetration) replaces C for
 * the steps after it.
 *
 * A frictionless small-strain solution does not depend on the path: the
 * last step's is that of one step to `end`.  What depends on the path is
 * what the loop keeps from one step to the next (a law with a history,
 * such as friction, reads U0 as the last converged step).
 *
 * One call per active-set iteration (LAC_CONTINUE, a progress line "step
 * k/n: ..."), the line of each converged step, LAC_SUCCESS after the
 * last.  An error names the step and its load factor.
 */
#ifndef LAC_RUN_STEPS_H
#define LAC_RUN_STEPS_H

#include <stddef.h>
#include "io/lac_scene.h"
#include "run/lac_run_setup.h"
#include "run/lac_run_solve.h"
#include "run/lac_run_steplog.h"
#include "run/lac_run_system.h"
#include "run/lac_summary.h"

typedef struct lac_run_steps
{
  lac_run_steplog log;        /* the load factors and the records        */
  size_t imposed_curve;       /* the curve of log.imposed_ref            */
  int in_step;                /* a load step is under way                */
  double start;               /* lac_seconds () at its start             */
} lac_run_steps;

/* strategy, ctx: as lac_run_solve.  u of sol: the displacement of the
 * last converged step (in the nodal frames, the rigid plates' tied dofs
 * following their plates). */
int lac_run_steps_solve (const lac_scene *sc, int strategy,
                         const lac_strategy_context *ctx, const lac_mesh *m,
                         lac_run_setup *setup, lac_run_system *sys,
                         lac_run_solution *sol, lac_run_steps *st,
                         char *progress, size_t size);
/* The summary lines of the steps: load_steps, max_iterations_per_step,
 * factorizations (the numeric factorizations of nw's strategy over all
 * the steps: for schur, that of K once), and the monitor's (monitor_ux
 * ..., monitor_extreme). */
int lac_run_steps_summary (const lac_run_steps *st, const lac_newton *nw,
                           int dim, lac_summary *sum);
void lac_run_steps_clear (lac_run_steps *st);

#endif /* LAC_RUN_STEPS_H */
