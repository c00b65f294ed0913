/* lac_linalg.h -- sparse matrices and the dense/sparse solver switch
 *
 * Matrices are assembled as triplets (i, j, x; duplicates summed) and
 * compressed to CSC (column pointers p[ncol+1], row indices i[nnz] sorted in
 * each column, values x[nnz]), the layout of CSparse, UMFPACK and CHOLMOD.
 *
 * One solver interface, three back ends chosen at run time:
 *   dense    GSL LU with partial pivoting (classroom sizes, printable)
 *   umfpack  sparse LU (general, the default for saddle systems)
 *   cholmod  sparse Cholesky (symmetric positive definite matrices; the
 *            factor is kept so that repeated solves are cheap)
 * A singular matrix is reported as LAC_ESING with a message, never as
 * garbage.  Matrix Market dump of any CSC matrix.
 *
 * Ownership: every _alloc has a _free (NULL allowed).  A solver keeps its
 * own copy (or factor) of the matrix; the caller's CSC may be freed after
 * lac_solver_factor.
 */
#ifndef LAC_LINALG_H
#define LAC_LINALG_H

#include <stddef.h>
#include <stdio.h>

typedef struct lac_triplet
{
  size_t nrow, ncol;
  size_t nz, cap;
  int *i, *j;      /* owned, cap */
  double *x;       /* owned, cap */
} lac_triplet;

typedef struct lac_csc
{
  size_t nrow, ncol;
  int *p;          /* owned, ncol+1 */
  int *i;          /* owned, nnz = p[ncol] */
  double *x;       /* owned, nnz */
} lac_csc;

lac_triplet *lac_triplet_alloc (size_t nrow, size_t ncol, size_t cap);
void lac_triplet_free (lac_triplet *T);
int lac_triplet_add (lac_triplet *T, size_t i, size_t j, double x); /* grows */
/* Add a dense block: T(rows[a], cols[b]) += B[a*nc + b]. */
int lac_triplet_add_block (lac_triplet *T, size_t nr, const size_t *rows,
                           size_t nc, const size_t *cols, const double *B);

lac_csc *lac_csc_alloc (size_t nrow, size_t ncol, size_t nnz);
lac_csc *lac_csc_from_triplet (const lac_triplet *T);  /* sums duplicates */
void lac_csc_free (lac_csc *A);
int lac_csc_matvec (const lac_csc *A, const double *x, double *y); /* y = A x */
lac_csc *lac_csc_transpose (const lac_csc *A);
int lac_csc_write_mm (const lac_csc *A, const char *path);  /* Matrix Market */

typedef enum
{
  LAC_SOLVER_DENSE, LAC_SOLVER_UMFPACK, LAC_SOLVER_CHOLMOD
} lac_solver_kind;

/* "dense" | "umfpack" | "cholmod" -> kind; returns -1 if unknown. */
int lac_solver_kind_from_name (const char *name);
const char *lac_solver_kind_name (lac_solver_kind k);

typedef struct lac_solver lac_solver;   /* opaque */

lac_solver *lac_solver_alloc (lac_solver_kind kind);
void lac_solver_free (lac_solver *s);
/* Factorize the square matrix A.  LAC_ESING (message with the column or
 * pivot) if A is singular, or not positive definite for cholmod. */
int lac_solver_factor (lac_solver *s, const lac_csc *A);
/* x = A^{-1} b with the last factorization (x and b may not alias). */
int lac_solver_solve (lac_solver *s, const double *b, double *x);
/* Solve with nrhs right-hand sides stored column after column. */
int lac_solver_solve_many (lac_solver *s, size_t nrhs, const double *B,
                           double *X);

#endif /* LAC_LINALG_H */
