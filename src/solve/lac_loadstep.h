/* lac_loadstep.h -- load steps of a large-deformation scene: sub-steps,
 *                   cuts and growth back           [LAC §4.5, Alg. 1; §5.4]
 *
 * The load is applied in steps.  A load step takes the load factor from
 * the last converged value t_0 to t.  It is made of sub-steps, each a loop
 * of Algorithm 1 (solve/lac_newton.h) on the large-deformation model
 * (solve/lac_nonlinear.h) at the load factor t_0 + dt:
 *
 *   - the first sub-step is the whole step (dt = t - t_0), or, after a
 *     step that had to be cut, the last sub-step that worked (doubled if
 *     it converged fast);
 *   - a sub-step that fails (no convergence in opts.maxit iterations, a
 *     residual that grows 1000 times above its best, a cell turned
 *     inside out that the line search could not avoid, a singular
 *     tangent) is CUT: the state of its beginning is restored and dt is
 *     halved, down to (t - t_0) / 2^opts.max_cuts; the failure is kept in
 *     cut_msg;
 *   - a sub-step that converges in at most LAC_FAST_ITERS iterations GROWS
 *     dt back: the next one is twice as long (never past t).
 *
 * A sub-step starts from a prediction (opts.predict): U and the active
 * multipliers extrapolated linearly from the last two converged states
 * (the Dirichlet values, linear in t, land exactly on theirs), which
 * saves about one Newton iteration per step; if the prediction turns a
 * cell inside out, the loop starts from the last converged state.
 *
 * The step record (steps) counts the Newton iterations of all sub-steps
 * (the failed ones too), the cuts and the sub-steps.
 *
 * Usage, one Newton iteration per call (the caller reports each one):
 *   lac_loadstep *ls = lac_loadstep_alloc (model, &opts);
 *   lac_loadstep_begin (ls, t);
 *   while ((st = lac_loadstep_iterate (ls)) == LAC_CONTINUE)
 *     { report ls->loop->hist[ls->loop->nhist - 1] }
 *   (st: LAC_SUCCESS, the record ls->steps[ls->nsteps - 1]; or the error
 *   of the last sub-step when no cut is left)
 * or the whole step at once: lac_loadstep_to (ls, t).
 *
 * Ownership: the model is borrowed; the driver owns the loop (U, lambda,
 * statuses, the iteration records) and the step records.
 */
#ifndef LAC_LOADSTEP_H
#define LAC_LOADSTEP_H

#include "solve/lac_newton.h"
#include "solve/lac_nonlinear.h"

#define LAC_FAST_ITERS 4     /* a sub-step this quick doubles the next one */

/* One load step (converged or not). */
typedef struct lac_nl_step
{
  double t;              /* load factor reached                             */
  int iters;             /* Newton iterations (solves), all sub-steps        */
  int cuts;              /* sub-steps cut (failed and halved)               */
  int substeps;          /* sub-steps that converged                        */
  double dt_min;         /* the shortest of them (load factor)              */
  int grown;             /* sub-steps longer than the one before them       */
  double seconds;        /* wall time of the step, and in it:               */
  double time_assemble, time_pairing, time_solve;
  double time_factor;    /*   the factorizations (part of time_solve)       */
  double residual;       /* final relative residual (the test that ended
                            the step)                                      */
  size_t k, nactive;     /* multipliers and active ones at the end          */
  int status;            /* LAC_SUCCESS or the error                        */
} lac_nl_step;

typedef struct lac_loadstep
{
  lac_nl *model;         /* borrowed                                        */
  lac_newton *loop;      /* owned: U, lambda, statuses, iteration records   */
  int max_cuts, predict; /* the options                                     */
  double t_prev;         /* the last converged load factor                  */
  double dt_next;        /* > 0: the sub-step length to start the next load
                            step with (the last one was cut)               */
  char cut_msg[256];     /* why the last sub-step was cut ("" if none)      */
  size_t nsteps, capsteps;
  lac_nl_step *steps;    /* owned, nsteps records                           */
  /* the load step under way */
  int in_step, in_sub;   /* a step, a sub-step under way                    */
  double t0, t;          /* the step: from t0 to t                          */
  double dt;             /* the sub-step length in use                      */
  int iters, cuts, substeps, grown;
  double dt_min, dt_last;  /* sub-steps converged: shortest, last         */
  double start;          /* lac_seconds () at the step's beginning          */
  double time0[4];       /* time_assemble, _pairing, _solve, _factor then   */
  /* the converged state before the last one, for the predictor */
  double *U_old, *lambda_old;   /* owned                                  */
  double dt_old;         /* the load factor between the two converged states
                            the predictor extrapolates (0: none yet)       */
} lac_loadstep;

lac_loadstep *lac_loadstep_alloc (lac_nl *model, const lac_nl_opts *opts);
void lac_loadstep_free (lac_loadstep *ls);        /* NULL allowed */
/* Begin the load step to factor t (> the last converged one). */
int lac_loadstep_begin (lac_loadstep *ls, double t);
/* One Newton iteration of the step (sub-steps and cuts inside):
 * LAC_CONTINUE after an iteration (its record the loop's last, with the
 * step, the load factor and the cuts so far), LAC_SUCCESS once the step
 * has converged at t (its record appended), an error status once it
 * failed (its record appended, with the status). */
int lac_loadstep_iterate (lac_loadstep *ls);
/* The whole step to t. */
int lac_loadstep_to (lac_loadstep *ls, double t);

#endif /* LAC_LOADSTEP_H */
