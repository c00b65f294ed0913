/* lac_newton_check.h -- no silent penetration: what the test of Algorithm 1
 *                       cannot see                  [LAC Alg. 1, line 10]
 *
 * The test of the loop (solve/lac_newton.h, step 3) looks at the
 * macro-elements that have a column, on the part of their surface that
 * was paired.  Two things escape it, and are checked when it passes:
 *
 *   - a macro-element WITHOUT a column (not paired: the master was out of
 *     reach of the pairing; or not admissible, Definition 1) that the
 *     solution pushed into the master: the model says how deep
 *     (lac_contact_model_type.uncovered); deeper than pen_tol of its size,
 *     the model pairs again with a longer reach (widen) and the loop goes
 *     on with the new columns, or, if that gains nothing, the run stops
 *     with an error naming the macro-element, where and how deep;
 *   - a macro-element that lost part of its surface to projections that
 *     failed (a folded or far master facet): its C and G miss that part.
 *     In contact, its pressure is wrong; out of contact but within pen_tol
 *     of its size of closing, the lost part may be inside the master.
 *     Both are errors naming the macro-element.
 *
 * Ownership: everything is borrowed.
 */
#ifndef LAC_NEWTON_CHECK_H
#define LAC_NEWTON_CHECK_H

#include <stddef.h>
#include "solve/lac_contact_model.h"

/* The columns of p (statuses per slot: active) that lost surface, as
 * above; dim: 2 or 3 (the sizes as lengths).  LAC_EADMISS with a
 * message, or LAC_SUCCESS. */
int lac_newton_check_lost (const lac_model_point *p, const char *active,
                           int dim, double pen_tol);
/* The macro-elements without a column at U (n dofs) deeper than pen_tol
 * of their size: *gained > 0 when m paired again and gave that many new
 * columns; LAC_EADMISS with a message when it could not.  A model
 * without `uncovered`, or pen_tol < 0: nothing is checked. */
int lac_newton_check_covered (const lac_contact_model *m, const double *U,
                              double pen_tol, size_t *gained);

#endif /* LAC_NEWTON_CHECK_H */
