/* lac_linalg.h -- sparse matrices and the dense/sparse solver switch
 *
 * Matrices are assembled as triplets (i, j, x; duplicates summed) and
 * compressed to CSC (column pointers p[ncol+1], row indices i[nnz] sorted in
 * each column, values x[nnz]), the layout of CSparse, UMFPACK and CHOLMOD.
 *
 * One solver interface, three back ends chosen at run time:
 *   dense    LU with partial pivoting (classroom sizes, printable)
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
/* y = A x on two cores (linalg/lac_tasks.h): the columns cut in two
 * pieces of equal entries, each piece adds into its own vector (y, and
 * the scratch w of A->nrow doubles), then y += w.  The same bits whether
 * the pieces run side by side or one after the other. */
int lac_csc_matvec_pair (const lac_csc *A, const double *x, double *y,
                         double *w);
lac_csc *lac_csc_transpose (const lac_csc *A);

/* A CSC made one column after the other, when the entries come column by
 * column (the LAC columns of C: one macro-element after the other): the
 * adds to the current column are summed in a dense accumulator of nrow
 * values, in the order of the adds -- the sums lac_csc_from_triplet
 * would make of the same adds -- and written, rows sorted, when the
 * column ends.  Memory: the matrix, and 16 bytes per row; no triplets. */
typedef struct lac_csc_columns
{
  lac_csc *A;            /* owned until lac_csc_columns_take: columns 0 ..
                            j-1 done                                       */
  size_t j, cap;         /* the current column; room for cap entries      */
  double *acc;           /* owned, nrow: the current column's sums        */
  int *at;               /* owned, nrow: 1 if the row has an entry in it  */
  int *rows;             /* owned, nrow: its rows, in the order first met */
  size_t nrows;
} lac_csc_columns;

lac_csc_columns *lac_csc_columns_alloc (size_t nrow, size_t ncol);
void lac_csc_columns_free (lac_csc_columns *b);       /* NULL allowed */
/* A(row, j) += x for the current column j; LAC_EINVAL outside. */
int lac_csc_columns_add (lac_csc_columns *b, size_t row, double x);
/* The current column is complete: write it, go to the next one.
 * LAC_ENOMEM (the columns made so far kept) or LAC_EINVAL after the
 * last column. */
int lac_csc_columns_end (lac_csc_columns *b);
/* The matrix, once every column ended (else NULL, LAC_EINVAL); b keeps
 * nothing of it. */
lac_csc *lac_csc_columns_take (lac_csc_columns *b);
lac_csc *lac_csc_copy (const lac_csc *A);
int lac_csc_write_mm (const lac_csc *A, const char *path);  /* Matrix Market */
/* The diagonal of a square A into d (ncol entries, 0 where none is
 * stored; d may be NULL) and its 1-norm, the largest column sum of
 * |a_ij| (the infinity norm too when A is symmetric, as K is). */
double lac_csc_diag_norm1 (const lac_csc *A, double *d);
/* The augmented matrix K + C W C^T of the contact solves [LAC (17)]:
 * the pattern of K + C C^T with the values of K (zeros elsewhere), made
 * once; then A = K + C diag(w) C^T in that pattern (w_i = 0: column i
 * left out), the pattern unchanged so that a factorization can keep its
 * analysis (lac_solver_refactor). */
/* A checksum of the order and pattern of A (FNV-1a over p and i): equal
 * patterns, equal sums; used to reuse an analysis made for a pattern. */
unsigned long long lac_csc_pattern_hash (const lac_csc *A);
lac_csc *lac_csc_augment_pattern (const lac_csc *K, const lac_csc *C);
int lac_csc_augment (lac_csc *A, const lac_csc *K, const lac_csc *C,
                     const double *w);

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
/* Factorize A again when only its numbers have changed (a Newton tangent
 * of a fixed mesh): the fill-reducing ordering and the symbolic analysis
 * of the last factorization of s are reused if A has the same order and
 * pattern (checked by a checksum of p and i), only the numbers are
 * factored; otherwise, or for dense, it is lac_solver_factor.  The same
 * checks and messages as lac_solver_factor. */
int lac_solver_refactor (lac_solver *s, const lac_csc *A);
/* threads = 1: the factorizations and solves of s keep the BLAS on one
 * thread (another factorization runs beside them, linalg/lac_tasks.h);
 * 0, the default: every core inside them (linalg/lac_blas.h). */
void lac_solver_set_threads (lac_solver *s, int threads);
/* x = A^{-1} b with the last factorization (x and b may not alias). */
int lac_solver_solve (lac_solver *s, const double *b, double *x);
/* Solve with nrhs right-hand sides stored column after column. */
int lac_solver_solve_many (lac_solver *s, size_t nrhs, const double *B,
                           double *X);
/* A solve in two halves, with a Cholesky factor P A P^T = L L^T (P the
 * fill-reducing permutation):
 *   A^{-1} b = P^T L^{-T} (L^{-1} P b),  so  b^T A^{-1} c = y_b^T y_c
 * with y = L^{-1} P b: the forward half alone gives the products
 * C^T A^{-1} C (solve/lac_schur.c).  lac_solver_halves says whether s
 * has such a factor (cholmod, supernodal or simplicial L L^T; not its
 * simplicial L D L^T, nor the LU of dense and umfpack); the other two
 * refuse (LAC_EINVAL) when it has not.  Y = L^{-1} P B for nrhs columns
 * stored column after column; x = P^T L^{-T} y. */
int lac_solver_halves (const lac_solver *s);
int lac_solver_forward_many (lac_solver *s, size_t nrhs, const double *B,
                             double *Y);
int lac_solver_backward (lac_solver *s, const double *y, double *x);

/* Singularity tests, the same for the three back ends.  A factorization
 * is refused (LAC_ESING) if
 * (1) a pivot is tiny: the smallest pivot is below LAC_PIVOT_RTOL times the
 *     largest (names the column):
 *       dense    min_k |U_kk| <= LAC_PIVOT_RTOL * max_ij |A_ij|
 *       umfpack  zero pivot, or Info[UMFPACK_RCOND] = min |U_kk| / max |U_kk|
 *                < LAC_PIVOT_RTOL (U of the row-scaled matrix)
 *       cholmod  d_k <= 0 (L->minor, CHOLMOD_NOT_POSDEF), or min d_k / max d_k
 *                < LAC_PIVOT_RTOL, d_k = L_kk^2 (LL') or D_kk (LDL');
 * (2) or the condition number is too large: rcond = 1 / (||A||_inf *
 *     est ||A^-1||_inf) < LAC_RCOND_MIN, the norm of the inverse estimated
 *     from two steps of inverse iteration with a pseudo-random start (two
 *     extra solves).  The message names the dof where the near-null vector
 *     is largest.
 * Test (1) alone is not enough: for a body without enough Dirichlet
 * conditions the rigid-mode pivots are rounding noise of size about
 * n * eps * max pivot, which exceeds 1e-14 from a few thousand unknowns on,
 * whereas its condition number stays near 1/eps (rounding perturbs a zero
 * eigenvalue by about eps ||A||, whatever n).  Stiffness matrices of fixed
 * bodies have rcond ~ h^2 (1e-4 .. 1e-9 in practice).  A Dirichlet row
 * scaled by 1 while the stiffness is ~1e12 lowers rcond too: scale such rows
 * like the diagonal of K. */
#define LAC_PIVOT_RTOL 1e-14
#define LAC_RCOND_MIN 1e-13
/* The dense back end refuses larger orders (n^2 doubles: 3.2 GB). */
#define LAC_DENSE_NMAX 20000

/* What the last factorization cost and found (for benchmarks and reports). */
typedef struct lac_solver_info
{
  size_t n;              /* order of the factored matrix                  */
  double nnz_factor;     /* entries of the factors: dense n^2, umfpack
                            nnz(L)+nnz(U)-n, cholmod nnz(L)              */
  double pivot_ratio;    /* the quantity tested against LAC_PIVOT_RTOL    */
  double rcond;          /* the estimate tested against LAC_RCOND_MIN      */
  double peak_bytes;     /* peak memory of the factorization as reported
                            by the back end (dense: the n^2 copy)          */
  double flops;          /* floating-point operations of the factorization */
  const char *method;    /* e.g. "supernodal LL'" (static string)         */
  const char *ordering;  /* fill-reducing ordering, "" for dense          */
  int analysis_reused;   /* 1: lac_solver_refactor kept the analysis      */
} lac_solver_info;

/* Fill *info from the last successful factorization (LAC_EINVAL if none). */
int lac_solver_get_info (const lac_solver *s, lac_solver_info *info);
/* Symbolic analysis only (no numbers are factored): the predicted
 * nnz_factor, flops and peak_bytes of factoring A with back end `kind`, to
 * decide whether it fits in memory.  CHOLMOD: exact counts from
 * cholmod_analyze (peak_bytes = 8 (xsize + ssize) of the supernodal
 * factor); UMFPACK: the upper-bound estimates of umfpack_symbolic; dense:
 * n^2.  pivot_ratio and rcond are 0. */
int lac_solver_estimate (lac_solver_kind kind, const lac_csc *A,
                         lac_solver_info *info);

#endif /* LAC_LINALG_H */
