/* lac_newton_friction.h -- the friction law's part of the loop of
 *                          Algorithm 1; not part of the API
 *                                 [LAC Alg. 1 with friction; chapter 15]
 *
 * Called by the loop (solve/lac_newton.c) when the model has tangential
 * columns (s->ntan > 0); the law itself, statuses and equations of one
 * macro-element, is solve/lac_friction.h.
 *
 *   lac_newton_friction_lmax        max |lambda| over the normal and the
 *                                   tangential multipliers (step 2)
 *   lac_newton_friction_want        the status of column i's slot, its
 *                                   slip direction into w->dir_new; a load
 *                                   step starts from stick (step 2)
 *   lac_newton_friction_turns       the slots whose slip direction turned
 *                                   by more than LAC_FRICTION_TURN (counted
 *                                   as changes of status; step 2)
 *   lac_newton_friction_solve       the equations of every slot, solved
 *                                   (step 4); LAC_ESING when every
 *                                   macro-element under a body held by
 *                                   contact alone slips
 *   lac_newton_friction_converged   the tangential jumps the next loop's
 *                                   slip is measured from
 *   lac_newton_friction_held_start  the held start with sticking columns
 */
#ifndef LAC_NEWTON_FRICTION_H
#define LAC_NEWTON_FRICTION_H

#include <stddef.h>
#include "solve/lac_newton.h"
#include "solve/lac_system.h"

double lac_newton_friction_lmax (const lac_newton *s);
char lac_newton_friction_want (lac_newton *s, size_t i, double lmax);
size_t lac_newton_friction_turns (lac_newton *s);
int lac_newton_friction_solve (lac_newton *s, const lac_contact_system *sys);
void lac_newton_friction_converged (lac_newton *s);
void lac_newton_friction_held_start (lac_newton *s,
                                     const lac_contact_system *sys);

#endif /* LAC_NEWTON_FRICTION_H */
