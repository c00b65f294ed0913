/* lac_assembly_dist.h -- the assembly of K_W = K + C W C^T on the MPI
 *                        processes of PETSc                 [LAC (8), (17)]
 *
 * Each process assembles what it owns into PETSc's distributed matrices,
 * and PETSc adds the entries of rows owned by another process
 * (MatSetValues with ADD_VALUES, then MatAssembly):
 *
 *   cells     the root (process 0) reads the mesh and broadcasts it once;
 *             the cells are cut in N parts by PETSc's partitioner
 *             (MatPartitioning: PT-Scotch when PETSc has it, or what
 *             -lac_part_mat_partitioning_type names) on the dual graph of
 *             the mesh (cells sharing dim nodes);
 *   rows      a node belongs to the process of its first cell; the
 *             processes' nodes are numbered in turn (PETSc's rows: whole
 *             nodes, contiguous per process), row[dof] on every process;
 *   K         each process adds the element matrices of its cells
 *             (fem/lac_assembly.h), the Dirichlet elimination of
 *             lac_dirichlet_apply made at the insertion (a fixed dof's row
 *             and column zero but the diagonal), so that K is never whole
 *             on one process;
 *   contact   C (n x k, small: the slave surface) is broadcast; column i
 *             belongs to the process owning its first node (a node of the
 *             slave macro-element), which adds w_i c_i c_i^T to K_W and
 *             inserts -c_i (or zeros, inactive) in B = -C_A.
 *
 * Without a mesh (a system given by its matrices: rigid plates, the
 * tangent of large deformation, the unit tests) the rows are the dofs in
 * N contiguous ranges of whole nodes and the root adds K's entries, which
 * PETSc sends to their processes.
 *
 * Every function is collective.  A failure on one process (an element
 * with det J <= 0, memory) is agreed on by all before the next collective
 * call (lac_petsc_agree): every process returns it, with the message of
 * the process that failed.  A build compiled with LAC_TEST_FAULTS fails on
 * purpose in the assembly of the cells on the process named by the
 * environment variable LAC_TEST_FAIL_RANK, and scales the first own
 * cell's matrix in PETSc's K (not in lac_dist_k_mult) by the factor
 * LAC_TEST_SCALE_CELL (tests/cases-petsc.sh).
 *
 * Ownership: lac_dist_alloc/lac_dist_free; the root's mesh, material and
 * matrices are borrowed during each call only.
 */
#ifndef LAC_ASSEMBLY_DIST_H
#define LAC_ASSEMBLY_DIST_H

#include <stddef.h>
#include "fem/lac_assembly.h"

/* The root's cells of K (NULL, or mesh NULL: K is given whole). */
typedef struct lac_dist_source
{
  const lac_mesh *mesh;       /* NULL: K                                  */
  const lac_elastic *mat;     /* with mesh                                */
  const char *fixed;          /* with mesh: n, the Dirichlet dofs         */
} lac_dist_source;

typedef struct lac_dist lac_dist;

#ifdef LAC_HAVE_PETSC
/* PETSc's matrices, without its headers (which bring <complex.h> and its
 * macro I to every includer); rows are int (PetscInt: lac_petsc.c). */
typedef struct _p_Mat *lac_dist_mat;

/* The rows of n dofs in blocks of bs for the root's source src (the
 * other processes: NULL); *d: new, every process's. */
int lac_dist_alloc (const lac_dist_source *src, size_t n, int bs,
                    lac_dist **d);
void lac_dist_free (lac_dist *d);
/* The own rows [*r0, *r1) of this process. */
void lac_dist_rows (const lac_dist *d, int *r0, int *r1);
/* row[j], the PETSc row of dof j (NULL: j itself). */
const int *lac_dist_row (const lac_dist *d);
/* The mesh and material K was assembled from (the root's or this
 * process's copy; NULL: K was given whole), and this process's cells:
 * mine[c] = 1 for the cells it owns, 0 for the others (ncells). */
const lac_mesh *lac_dist_mesh (const lac_dist *d);
const lac_elastic *lac_dist_material (const lac_dist *d);
void lac_dist_own_cells (const lac_dist *d, char *mine);
/* The copy of C the contact terms were added from (NULL: none). */
const lac_csc *lac_dist_c (const lac_dist *d);
/* The root's C (n x k; others NULL) to every process: its pattern and
 * values (pattern = 1) or its values (0: the pattern is the last one). */
int lac_dist_set_c (lac_dist *d, const lac_csc *C, int pattern);
/* The patterns of K_W (n x n) and B (n x k) into the preallocators Pk,
 * Pb (MATPREALLOCATOR; Pb may be NULL), assembled.  K: the root's when
 * the source had no mesh (else and elsewhere NULL). */
int lac_dist_pattern (lac_dist *d, const lac_csc *K, lac_dist_mat Pk,
                      lac_dist_mat Pb);
/* K_W += K / kappa, from the own cells (or the root's K); not assembled. */
int lac_dist_add_stiffness (lac_dist *d, const lac_csc *K, lac_dist_mat Kw,
                            double kappa);
/* After lac_dist_add_stiffness from the cells and the assembly of Kw
 * (holding K / kappa, nothing else yet): *err = |Kw x - y|_inf /
 * |Kw|_inf for a probe x without structure (|x|_inf <= 1) and y the sum
 * over the cells of their element matrices times x, which
 * lac_dist_add_stiffness made from the same element matrices, in lac's
 * numbering of the dofs: rounding (1e-15) if PETSc's matrix is the
 * cells' K, whatever the partition and the numbering of the rows. */
int lac_dist_check_stiffness (lac_dist *d, lac_dist_mat Kw, double *err);
/* K_W += sum_i dw_i c_i c_i^T over the own columns (dw: k, the same on
 * every process); not assembled. */
int lac_dist_add_contact (lac_dist *d, lac_dist_mat Kw, const double *dw);
/* B's own columns: -c_i if on[i], zeros otherwise; not assembled. */
int lac_dist_set_b (lac_dist *d, lac_dist_mat B, const char *on);
#endif

#endif /* LAC_ASSEMBLY_DIST_H */
