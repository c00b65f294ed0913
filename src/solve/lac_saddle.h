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
 * Ownership: the system is borrowed from lac_saddle_set until the next
 * set or lac_saddle_free.
 */
#ifndef LAC_SADDLE_H
#define LAC_SADDLE_H

#include "linalg/lac_linalg.h"
#include "solve/lac_system.h"

typedef struct lac_saddle lac_saddle;     /* opaque */

/* kind: LAC_SOLVER_DENSE or LAC_SOLVER_UMFPACK. */
lac_saddle *lac_saddle_alloc (lac_solver_kind kind);
void lac_saddle_free (lac_saddle *s);      /* NULL allowed */
int lac_saddle_set (lac_saddle *s, const lac_contact_system *sys);
/* U, lambda of (*) for the statuses `active` (lambda_i = 0 when
 * inactive), with F and G replaced by f and g (the right-hand sides of a
 * refinement step; NULL: those of the system).  Factorizes when the
 * statuses changed since the last factorization. */
int lac_saddle_solve (lac_saddle *s, const char *active, const double *f,
                      const double *g, double *U, double *lambda);
/* Numeric factorizations, symbolic analyses, their time and flops made so
 * far, and the condition estimate of the last factorization (the solves
 * and iterations are not counted: 0). */
void lac_saddle_get_counts (const lac_saddle *s, lac_solve_counts *c);

#endif /* LAC_SADDLE_H */
