/* lac_saddle.h -- the saddle-point system of one active set, factorized
 *                 whole by an LU                   [LAC (17), Alg. 1 l. 21]
 *
 * Strategies (c) and (d) of solve/lac_strategy.h: the matrix of (*) in
 * solve/lac_system.h, with the identity row lambda_i = 0 for every
 * inactive multiplier [LAC Alg. 1, line 17], scaled symmetrically
 * (diag(K)^-1/2 on the displacements, the largest scaled entry of each
 * column of C on the multipliers) so that partly covered macro-elements
 * and contrasts of stiffness do not spoil its conditioning, and factorized
 * by GSL's dense LU (classroom sizes) or UMFPACK's sparse LU.  The pattern
 * holds every column of C whatever the statuses (inactive columns as
 * explicit zeros), so UMFPACK's ordering and symbolic analysis are made
 * once and kept across active sets (lac_solver_refactor).
 *
 * The operations of the types dense (GSL) and saddle (UMFPACK) of
 * solve/lac_strategy.h; their solve factorizes when the statuses changed
 * since the last factorization.
 */
#ifndef LAC_SADDLE_H
#define LAC_SADDLE_H

#include "solve/lac_system.h"

extern const lac_strategy_ops lac_saddle_dense_ops;   /* GSL's dense LU */
extern const lac_strategy_ops lac_saddle_lu_ops;      /* UMFPACK's LU   */

#endif /* LAC_SADDLE_H */
