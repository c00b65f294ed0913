/* lac_loadstep.h -- one load step of the large-deformation loop: sub-steps,
 *                   cuts and growth back           [LAC §4.5, Alg. 1; §5.4]
 *
 * A load step takes the load factor from the last converged value t_0 to
 * t.  It is made of sub-steps, each a Newton loop of solve/lac_nonlinear.h
 * (lac_nl_begin, lac_nl_iterate) to t_0 + dt:
 *
 *   - the first sub-step is the whole step (dt = t - t_0), or, after a
 *     step that had to be cut, the last sub-step that worked (doubled if
 *     it converged fast);
 *   - a sub-step that fails (no convergence in opts.maxit iterations, a
 *     residual that grows DIVERGED times above its best, a cell turned
 *     inside out that the line search could not avoid) is CUT: the state
 *     of its beginning is restored and dt is halved, down to (t - t_0) /
 *     2^opts.max_cuts; the failure is kept in s->cut_msg;
 *   - a sub-step that converges in at most LAC_FAST_ITERS iterations GROWS
 *     dt back: the next one is twice as long (never past t).
 *
 * A sub-step starts from a prediction (opts.predict): U and the active
 * multipliers extrapolated linearly from the last two converged states
 * (the Dirichlet values, linear in t, land exactly on theirs), which
 * saves about one Newton iteration per step; if the prediction turns a
 * cell inside out, the sub-step starts from the last converged state.
 *
 * The step record (s->steps) counts the Newton iterations of all
 * sub-steps (the failed ones too), the cuts and the sub-steps.
 *
 * Usage, one Newton iteration per call (the caller reports each one):
 *   lac_nl_step_begin (s, t);
 *   while ((st = lac_nl_step_iterate (s)) == LAC_CONTINUE)
 *     { report s->iters[s->niters - 1] }
 *   (st: LAC_SUCCESS, the record s->steps[s->nsteps - 1]; or the error of
 *   the last sub-step when no cut is left)
 * or the whole step at once: lac_nl_step_to (s, t).
 */
#ifndef LAC_LOADSTEP_H
#define LAC_LOADSTEP_H

#include "solve/lac_nonlinear.h"

#define LAC_FAST_ITERS 4     /* a sub-step this quick doubles the next one */

/* Begin the load step to factor t (> the last converged one). */
int lac_nl_step_begin (lac_nl *s, double t);
/* One Newton iteration of the step (sub-steps and cuts inside):
 * LAC_CONTINUE after an iteration, LAC_SUCCESS once the step has
 * converged at t (its record appended), an error status once it failed
 * (its record appended, with the status). */
int lac_nl_step_iterate (lac_nl *s);
/* The whole step to t. */
int lac_nl_step_to (lac_nl *s, double t);

#endif /* LAC_LOADSTEP_H */
