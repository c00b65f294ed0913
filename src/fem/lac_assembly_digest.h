/* lac_assembly_digest.h -- what the Dirichlet elimination leaves of K on
 *                          the program that reads the mesh, without K
 *                                                          [LAC §4.3]
 *
 * A solver that assembles K itself, cell by cell on every process (the
 * petsc strategy, chapter 13), takes diag(K) and ||K|| from its own rows.
 * The program that reads the mesh needs of K only the right-hand side b
 * of lac_dirichlet_apply, and the number of entries for the report.  b
 * differs from the loads F only by the lift, F -= K(:,j) g_j for the
 * fixed dofs j with g_j != 0, and b_j = d_j g_j: the columns of the nodes
 * with a nonzero Dirichlet value, from the cells around those nodes only
 * (a layer of cells on a loaded face; none when every value is zero).
 * Each column is summed over its cells in their order and the columns are
 * lifted in dof order, so that b is that of lac_assembly_stiffness_csc +
 * lac_dirichlet_apply, bit for bit (t409).  The entries are counted from
 * the nodes' neighbours (lac_pattern_count), without integrating.
 */
#ifndef LAC_ASSEMBLY_DIGEST_H
#define LAC_ASSEMBLY_DIGEST_H

#include <stddef.h>
#include "fem/lac_assembly.h"

/* F (loads, ndof) becomes lac_dirichlet_apply's b for K = sum of the
 * cells with E[c] > 0 (mat) and the Dirichlet pairs d; *nnz: K's entries.
 *   returns LAC_SUCCESS, LAC_EINVAL (also a fixed dof whose node is in no
 *   cell of a body, as lac_dirichlet_apply), LAC_EBADLEN, LAC_ESING (a
 *   cell integrated for the lift with det J <= 0), LAC_ENOMEM; on an
 *   error F is partly lifted (of no use) */
int lac_assembly_digest (const lac_mesh *m, const lac_elastic *mat,
                         const lac_dirichlet *d, double *F, size_t *nnz);

#endif /* LAC_ASSEMBLY_DIGEST_H */
