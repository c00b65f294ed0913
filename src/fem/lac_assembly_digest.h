/* lac_assembly_digest.h -- what the Dirichlet elimination leaves of K,
 *                          without K whole                [LAC §4.3]
 *
 * A solver that assembles K itself, cell by cell on every process (the
 * petsc strategy, chapter 13), needs from the program that reads the mesh
 * only the right-hand side b with the Dirichlet lift, diag(K) and ||K||
 * (the scales of the contact terms and of the residuals), and the number
 * of entries for the report.  lac_dirichlet_apply gives all of them from
 * the assembled K; here K is assembled one block of node columns at a time
 * (lac_pattern_build_nodes), each block read and forgotten, so that the
 * memory is that of one block, not of K.  Every cell is added to a block
 * in the order of the whole assembly and the columns are read in their
 * order, so the numbers are those of lac_assembly_stiffness_csc +
 * lac_dirichlet_apply + lac_csc_diag_norm1, bit for bit (t409).  A cell
 * whose nodes fall in two blocks is integrated twice.
 */
#ifndef LAC_ASSEMBLY_DIGEST_H
#define LAC_ASSEMBLY_DIGEST_H

#include <stddef.h>
#include "fem/lac_assembly.h"

typedef struct lac_k_digest
{
  size_t nnz;        /* entries of K (of the cells' pattern)               */
  double norm1;      /* ||K||_1 = ||K||_inf after the elimination          */
  double *diag;      /* owned, ndof: diag(K) after the elimination (d_k on
                        a fixed dof k)                                     */
} lac_k_digest;

/* The digest of K = sum of the cells with E[c] > 0 (mat) and the
 * elimination of d: F (loads, ndof) becomes lac_dirichlet_apply's b.
 * block: entries of K at most in one block of columns (about; at least
 * one node's columns; 0: a default of 2^23, about 100 MB).
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_EBADLEN, LAC_ESING, LAC_ENOMEM
 *   (lac_assembly_stiffness_csc's and lac_dirichlet_apply's errors); on
 *   an error *out is empty and F partly lifted (of no use) */
int lac_assembly_digest (const lac_mesh *m, const lac_elastic *mat,
                         const lac_dirichlet *d, size_t block, double *F,
                         lac_k_digest *out);
void lac_k_digest_clear (lac_k_digest *k);    /* frees diag; NULL allowed */

#endif /* LAC_ASSEMBLY_DIGEST_H */
