/* lac_solver_internal.h -- shared by lac_solver.c and lac_solver_estimate.c
 * (not part of the library's interface). */
#ifndef LAC_SOLVER_INTERNAL_H
#define LAC_SOLVER_INTERNAL_H

#include <cholmod.h>
#include "linalg/lac_linalg.h"

typedef SuiteSparse_long ss_long;

/* Upper triangle of A as a CHOLMOD matrix with stype = 1 (xtype
 * CHOLMOD_PATTERN: no values); NULL (message set) if out of memory. */
cholmod_sparse *lac_solver_upper_copy (const lac_csc *A, int xtype,
                                       cholmod_common *cc);
/* The name of a CHOLMOD ordering (L->ordering): "AMD", "METIS", ... */
const char *lac_solver_chol_ordering (int ord);

#endif /* LAC_SOLVER_INTERNAL_H */
