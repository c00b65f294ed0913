/* lac_sparse.c -- triplets, compressed sparse columns, Matrix Market dump
 *
 * A triplet list collects (i, j, x) entries in any order, duplicates
 * allowed (element matrices are added entry by entry).  lac_csc_from_triplet
 * compresses it in O(nnz + nrow + ncol) time: bucket the entries by row,
 * sum the duplicates of each row with a marker array, then transpose, which
 * leaves the row indices of every column sorted.  This is CSparse's
 * cs_compress + cs_dupl + cs_transpose, arranged so that only one
 * transpose is needed.
 *
 * References: T. A. Davis, Direct Methods for Sparse Linear Systems, SIAM
 * 2006, chapter 2 (CSparse).  Matrix Market exchange format,
 * https://math.nist.gov/MatrixMarket/formats.html
 */
#include "linalg/lac_linalg.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_file.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_tasks.h"

/* ---- triplets --------------------------------------------------------- */

lac_triplet *
lac_triplet_alloc (size_t nrow, size_t ncol, size_t cap)
{
  lac_triplet *T;
  if (nrow > INT_MAX || ncol > INT_MAX)
    LAC_ERROR_NULL (LAC_EINVAL, "%zu x %zu matrix: sizes above INT_MAX are "
                    "not supported (int indices)", nrow, ncol);
  if (cap < 16)
    cap = 16;
  T = lac_calloc (1, sizeof *T);
  if (!T)
    LAC_ERROR_NULL (LAC_ENOMEM, "triplet header");
  T->nrow = nrow;
  T->ncol = ncol;
  T->cap = cap;
  T->i = lac_malloc (cap * sizeof *T->i);
  T->j = lac_malloc (cap * sizeof *T->j);
  T->x = lac_malloc (cap * sizeof *T->x);
  if (!T->i || !T->j || !T->x)
    {
      lac_triplet_free (T);
      LAC_ERROR_NULL (LAC_ENOMEM, "triplet arrays for %zu entries", cap);
    }
  return T;
}

void
lac_triplet_free (lac_triplet *T)
{
  if (!T)
    return;
  lac_free (T->i);
  lac_free (T->j);
  lac_free (T->x);
  lac_free (T);
}

/* Make room for at least `need` entries (capacity grows geometrically). */
static int
triplet_reserve (lac_triplet *T, size_t need)
{
  size_t cap = T->cap;
  int *i, *j;
  double *x;
  if (need <= cap)
    return LAC_SUCCESS;
  while (cap < need)
    cap += cap / 2 + 16;                     /* x 1.5: less waste than x 2 */
  i = lac_realloc (T->i, cap * sizeof *i);
  if (i)
    T->i = i;
  j = lac_realloc (T->j, cap * sizeof *j);
  if (j)
    T->j = j;
  x = lac_realloc (T->x, cap * sizeof *x);
  if (x)
    T->x = x;
  if (!i || !j || !x)         /* arrays stay valid with the old capacity */
    LAC_ERROR (LAC_ENOMEM, "growing triplets from %zu to %zu entries",
               T->cap, cap);
  T->cap = cap;
  return LAC_SUCCESS;
}

int
lac_triplet_add (lac_triplet *T, size_t i, size_t j, double x)
{
  int status;
  if (i >= T->nrow || j >= T->ncol)
    LAC_ERROR (LAC_EINVAL, "entry (%zu, %zu) outside the %zu x %zu matrix",
               i, j, T->nrow, T->ncol);
  if ((status = triplet_reserve (T, T->nz + 1)))
    return status;
  T->i[T->nz] = (int) i;
  T->j[T->nz] = (int) j;
  T->x[T->nz] = x;
  T->nz++;
  return LAC_SUCCESS;
}

int
lac_triplet_add_block (lac_triplet *T, size_t nr, const size_t *rows,
                       size_t nc, const size_t *cols, const double *B)
{
  int status;
  for (size_t a = 0; a < nr; a++)
    if (rows[a] >= T->nrow)
      LAC_ERROR (LAC_EINVAL, "block row %zu: index %zu outside the %zu rows",
                 a, rows[a], T->nrow);
  for (size_t b = 0; b < nc; b++)
    if (cols[b] >= T->ncol)
      LAC_ERROR (LAC_EINVAL, "block column %zu: index %zu outside the %zu "
                 "columns", b, cols[b], T->ncol);
  if ((status = triplet_reserve (T, T->nz + nr * nc)))
    return status;
  for (size_t a = 0; a < nr; a++)
    for (size_t b = 0; b < nc; b++)
      {
        T->i[T->nz] = (int) rows[a];        /* T(rows[a], cols[b]) += B_ab */
        T->j[T->nz] = (int) cols[b];
        T->x[T->nz] = B[a * nc + b];
        T->nz++;
      }
  return LAC_SUCCESS;
}

/* ---- compressed sparse columns ----------------------------------------- */

lac_csc *
lac_csc_alloc (size_t nrow, size_t ncol, size_t nnz)
{
  lac_csc *A;
  if (nrow > INT_MAX || ncol > INT_MAX || nnz > INT_MAX)
    LAC_ERROR_NULL (LAC_EINVAL, "%zu x %zu matrix with %zu entries: sizes "
                    "above INT_MAX are not supported (int indices)",
                    nrow, ncol, nnz);
  A = lac_calloc (1, sizeof *A);
  if (!A)
    LAC_ERROR_NULL (LAC_ENOMEM, "CSC header");
  A->nrow = nrow;
  A->ncol = ncol;
  A->p = lac_calloc (ncol + 1, sizeof *A->p);
  A->i = lac_malloc (nnz * sizeof *A->i);
  A->x = lac_malloc (nnz * sizeof *A->x);
  if (!A->p || !A->i || !A->x)
    {
      lac_csc_free (A);
      LAC_ERROR_NULL (LAC_ENOMEM, "CSC arrays, %zu columns, %zu entries",
                      ncol, nnz);
    }
  return A;
}

void
lac_csc_free (lac_csc *A)
{
  if (!A)
    return;
  lac_free (A->p);
  lac_free (A->i);
  lac_free (A->x);
  lac_free (A);
}

/* p[0..n] = cumulative sum of c[0..n-1]; c is overwritten with a copy of
 * p[0..n-1] (the next free slot of each bucket).  cs_cumsum. */
static size_t
cumsum (int *p, size_t *c, size_t n)
{
  size_t nz = 0;
  for (size_t k = 0; k < n; k++)
    {
      p[k] = (int) nz;
      nz += c[k];
      c[k] = (size_t) p[k];
    }
  p[n] = (int) nz;
  return nz;
}

/* Give back the unused tail of A's arrays (a failed shrink is harmless). */
static void
shrink (lac_csc *A, size_t nnz)
{
  int *i = lac_realloc (A->i, nnz * sizeof *i);
  double *x = lac_realloc (A->x, nnz * sizeof *x);
  if (i)
    A->i = i;
  if (x)
    A->x = x;
}

/* R = rows of T (CSC of T^T), duplicates summed, column order unsorted. */
static lac_csc *
compress_rows (const lac_triplet *T)
{
  size_t *w = lac_calloc (T->nrow > T->ncol ? T->nrow : T->ncol, sizeof *w);
  lac_csc *R = lac_csc_alloc (T->ncol, T->nrow, T->nz);
  size_t nz = 0;
  if (!w || !R)
    goto fail;
  /* Step 1: bucket the entries by row (counting sort)  [cs_compress] */
  for (size_t k = 0; k < T->nz; k++)
    w[T->i[k]]++;
  cumsum (R->p, w, T->nrow);
  for (size_t k = 0; k < T->nz; k++)
    {
      size_t q = w[T->i[k]]++;
      R->i[q] = T->j[k];
      R->x[q] = T->x[k];
    }
  /* Step 2: sum duplicates; w[j] = where column j sits in the current row,
   * or a value below the row's start if not seen yet  [cs_dupl] */
  for (size_t j = 0; j < T->ncol; j++)
    w[j] = SIZE_MAX;
  for (size_t r = 0; r < T->nrow; r++)
    {
      size_t start = nz;
      for (size_t q = (size_t) R->p[r]; q < (size_t) R->p[r + 1]; q++)
        {
          size_t j = (size_t) R->i[q];
          if (w[j] != SIZE_MAX && w[j] >= start)
            R->x[w[j]] += R->x[q];                     /* R(j, r) += x */
          else
            {
              w[j] = nz;
              R->i[nz] = (int) j;
              R->x[nz++] = R->x[q];
            }
        }
      R->p[r] = (int) start;
    }
  R->p[T->nrow] = (int) nz;
  lac_free (w);
  shrink (R, nz);
  return R;
fail:
  lac_free (w);
  lac_csc_free (R);
  LAC_ERROR_NULL (LAC_ENOMEM, "compressing %zu triplets of a %zu x %zu "
                  "matrix", T->nz, T->nrow, T->ncol);
}

lac_csc *
lac_csc_from_triplet (const lac_triplet *T)
{
  lac_csc *R, *A;
  if (!T)
    LAC_ERROR_NULL (LAC_EINVAL, "no triplets");
  R = compress_rows (T);
  if (!R)
    return NULL;
  A = lac_csc_transpose (R);               /* sorts the rows of each column */
  lac_csc_free (R);
  return A;
}

/* ---- a CSC column by column ---------------------------------------------- */

lac_csc_columns *
lac_csc_columns_alloc (size_t nrow, size_t ncol)
{
  lac_csc_columns *b = lac_calloc (1, sizeof *b);
  if (!b)
    LAC_ERROR_NULL (LAC_ENOMEM, "CSC columns of %zu rows", nrow);
  b->cap = 16 * (ncol + 1);
  b->A = lac_csc_alloc (nrow, ncol, b->cap);
  b->acc = lac_calloc (nrow ? nrow : 1, sizeof *b->acc);
  b->at = lac_calloc (nrow ? nrow : 1, sizeof *b->at);
  b->rows = lac_malloc ((nrow ? nrow : 1) * sizeof *b->rows);
  if (!b->A || !b->acc || !b->at || !b->rows)
    {
      lac_csc_columns_free (b);
      LAC_ERROR_NULL (LAC_ENOMEM, "CSC columns of %zu rows", nrow);
    }
  return b;
}

void
lac_csc_columns_free (lac_csc_columns *b)
{
  if (!b)
    return;
  lac_csc_free (b->A);
  lac_free (b->acc);
  lac_free (b->at);
  lac_free (b->rows);
  lac_free (b);
}

int
lac_csc_columns_add (lac_csc_columns *b, size_t row, double x)
{
  if (!b->A)
    LAC_ERROR (LAC_EINVAL, "the matrix was taken");
  if (row >= b->A->nrow || b->j >= b->A->ncol)
    LAC_ERROR (LAC_EINVAL, "entry (%zu, %zu) outside the %zu x %zu matrix",
               row, b->j, b->A->nrow, b->A->ncol);
  if (!b->at[row])
    {
      b->at[row] = 1;
      b->rows[b->nrows++] = (int) row;
      b->acc[row] = x;
    }
  else
    b->acc[row] += x;
  return LAC_SUCCESS;
}

static int
compare_int (const void *a, const void *b)
{
  int x = *(const int *) a, y = *(const int *) b;
  return (x > y) - (x < y);
}

int
lac_csc_columns_end (lac_csc_columns *b)
{
  lac_csc *A = b->A;
  if (!A || b->j >= A->ncol)
    LAC_ERROR (LAC_EINVAL, "no column left to end");
  size_t nz = (size_t) A->p[b->j], need = nz + b->nrows;
  if (need > INT_MAX)
    LAC_ERROR (LAC_EINVAL, "more than INT_MAX entries");
  if (need > b->cap)
    {
      size_t cap = 2 * need;
      int *i = lac_realloc (A->i, cap * sizeof *i);
      if (i)
        A->i = i;
      double *x = i ? lac_realloc (A->x, cap * sizeof *x) : NULL;
      if (!x)
        LAC_ERROR (LAC_ENOMEM, "CSC column %zu, %zu entries", b->j, need);
      A->x = x;
      b->cap = cap;
    }
  qsort (b->rows, b->nrows, sizeof *b->rows, compare_int);
  for (size_t q = 0; q < b->nrows; q++)
    {
      int r = b->rows[q];
      A->i[nz + q] = r;
      A->x[nz + q] = b->acc[r];
      b->at[r] = 0;
    }
  A->p[++b->j] = (int) need;
  b->nrows = 0;
  return LAC_SUCCESS;
}

lac_csc *
lac_csc_columns_take (lac_csc_columns *b)
{
  if (!b->A)
    LAC_ERROR_NULL (LAC_EINVAL, "the matrix was taken");
  if (b->j < b->A->ncol)
    LAC_ERROR_NULL (LAC_EINVAL, "column %zu of %zu not ended", b->j,
                    b->A->ncol);
  lac_csc *A = b->A;
  shrink (A, (size_t) A->p[A->ncol] ? (size_t) A->p[A->ncol] : 1);
  b->A = NULL;
  return A;
}

int
lac_csc_matvec (const lac_csc *A, const double *x, double *y)
{
  for (size_t r = 0; r < A->nrow; r++)
    y[r] = 0;
  for (size_t j = 0; j < A->ncol; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      y[A->i[q]] += A->x[q] * x[j];                    /* y += A(:,j) x_j */
  return LAC_SUCCESS;
}

/* Columns j0 <= j < j1 of A times x into y (zeroed first). */
typedef struct matvec_piece
{
  const lac_csc *A;
  const double *x;
  double *y;
  size_t j0, j1;
} matvec_piece;

static int
matvec_columns (void *ctx)
{
  const matvec_piece *m = ctx;
  const lac_csc *A = m->A;
  for (size_t r = 0; r < A->nrow; r++)
    m->y[r] = 0;
  for (size_t j = m->j0; j < m->j1; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      m->y[A->i[q]] += A->x[q] * m->x[j];             /* y += A(:,j) x_j */
  return LAC_SUCCESS;
}

int
lac_csc_matvec_pair (const lac_csc *A, const double *x, double *y,
                     double *w)
{
  size_t mid = 0, half = (size_t) A->p[A->ncol] / 2;
  while (mid < A->ncol && (size_t) A->p[mid] < half)  /* equal entries */
    mid++;
  matvec_piece a = { A, x, y, 0, mid }, b = { A, x, w, mid, A->ncol };
  int status = lac_tasks_pair (matvec_columns, &a, matvec_columns, &b);
  for (size_t r = 0; r < A->nrow; r++)
    y[r] += w[r];
  return status;
}

double
lac_csc_diag_norm1 (const lac_csc *A, double *d)
{
  double norm = 0;
  for (size_t j = 0; j < A->ncol; j++)
    {
      double sum = 0;                              /* sum_i |a_ij| */
      if (d)
        d[j] = 0;
      for (int q = A->p[j]; q < A->p[j + 1]; q++)
        {
          sum += fabs (A->x[q]);
          if (d && (size_t) A->i[q] == j)
            d[j] = A->x[q];                        /* a_jj */
        }
      norm = fmax (norm, sum);
    }
  return norm;
}

lac_csc *
lac_csc_copy (const lac_csc *A)
{
  size_t nnz = (size_t) A->p[A->ncol];
  lac_csc *B = lac_csc_alloc (A->nrow, A->ncol, nnz);
  if (!B)
    return NULL;
  memcpy (B->p, A->p, (A->ncol + 1) * sizeof *B->p);
  memcpy (B->i, A->i, nnz * sizeof *B->i);
  memcpy (B->x, A->x, nnz * sizeof *B->x);
  return B;
}

lac_csc *
lac_csc_transpose (const lac_csc *A)
{
  size_t nnz = (size_t) A->p[A->ncol];
  size_t *w = lac_calloc (A->nrow, sizeof *w);
  lac_csc *C = lac_csc_alloc (A->ncol, A->nrow, nnz);
  if (!w || !C)
    {
      lac_free (w);
      lac_csc_free (C);
      LAC_ERROR_NULL (LAC_ENOMEM, "transpose of a %zu x %zu matrix with %zu "
                      "entries", A->nrow, A->ncol, nnz);
    }
  for (size_t q = 0; q < nnz; q++)
    w[A->i[q]]++;                                      /* row counts */
  cumsum (C->p, w, A->nrow);
  for (size_t j = 0; j < A->ncol; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      {
        size_t r = w[A->i[q]]++;                       /* C(j, i) = A(i, j) */
        C->i[r] = (int) j;
        C->x[r] = A->x[q];
      }
  lac_free (w);
  return C;
}

/* FNV-1a over the order and the pattern (p, i) of A. */
unsigned long long
lac_csc_pattern_hash (const lac_csc *A)
{
  unsigned long long h = 1469598103934665603ull;
  size_t nnz = (size_t) A->p[A->ncol];
  h = (h ^ A->nrow) * 1099511628211ull;
  h = (h ^ A->ncol) * 1099511628211ull;
  for (size_t j = 0; j <= A->ncol; j++)
    h = (h ^ (unsigned long long) A->p[j]) * 1099511628211ull;
  for (size_t q = 0; q < nnz; q++)
    h = (h ^ (unsigned long long) A->i[q]) * 1099511628211ull;
  return h;
}

/* ---- K + C W C^T ------------------------------------------------------ */

lac_csc *
lac_csc_augment_pattern (const lac_csc *K, const lac_csc *C)
{
  size_t nz = (size_t) K->p[K->ncol];
  lac_triplet *T;
  lac_csc *A = NULL;
  int status = LAC_SUCCESS;
  if (K->nrow != K->ncol || C->nrow != K->ncol)
    LAC_ERROR_NULL (LAC_EBADLEN, "K is %zu x %zu and C %zu x %zu", K->nrow,
                    K->ncol, C->nrow, C->ncol);
  for (size_t i = 0; i < C->ncol; i++)
    {
      size_t m = (size_t) (C->p[i + 1] - C->p[i]);
      nz += m * m;                             /* entries of c_i c_i^T */
    }
  if (!(T = lac_triplet_alloc (K->nrow, K->ncol, nz)))
    return NULL;
  for (size_t j = 0; !status && j < K->ncol; j++)        /* K */
    for (int q = K->p[j]; !status && q < K->p[j + 1]; q++)
      status = lac_triplet_add (T, (size_t) K->i[q], j, K->x[q]);
  for (size_t i = 0; !status && i < C->ncol; i++)        /* 0 * c_i c_i^T */
    for (int a = C->p[i]; !status && a < C->p[i + 1]; a++)
      for (int b = C->p[i]; !status && b < C->p[i + 1]; b++)
        status = lac_triplet_add (T, (size_t) C->i[a], (size_t) C->i[b], 0.0);
  if (!status)
    A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

/* Position of row r in column j of A (rows sorted), -1 if absent. */
static int
find_entry (const lac_csc *A, size_t j, int r)
{
  int lo = A->p[j], hi = A->p[j + 1] - 1;
  while (lo <= hi)
    {
      int mid = lo + (hi - lo) / 2;
      if (A->i[mid] == r)
        return mid;
      if (A->i[mid] < r)
        lo = mid + 1;
      else
        hi = mid - 1;
    }
  return -1;
}

int
lac_csc_augment (lac_csc *A, const lac_csc *K, const lac_csc *C,
                 const double *w)
{
  memset (A->x, 0, (size_t) A->p[A->ncol] * sizeof *A->x);
  for (size_t j = 0; j < K->ncol; j++)                   /* A = K */
    for (int q = K->p[j]; q < K->p[j + 1]; q++)
      {
        int e = find_entry (A, j, K->i[q]);
        if (e < 0)
          LAC_ERROR (LAC_EINVAL, "K(%d,%zu) is outside the augmented "
                     "pattern", K->i[q], j);
        A->x[e] += K->x[q];
      }
  for (size_t i = 0; i < C->ncol; i++)                   /* + w_i c_i c_i^T */
    for (int b = C->p[i]; w[i] != 0 && b < C->p[i + 1]; b++)
      for (int a = C->p[i]; a < C->p[i + 1]; a++)
        {
          int e = find_entry (A, (size_t) C->i[b], C->i[a]);
          if (e < 0)
            LAC_ERROR (LAC_EINVAL, "column %zu of C is outside the augmented"
                       " pattern", i);
          A->x[e] += w[i] * C->x[a] * C->x[b];
        }
  return LAC_SUCCESS;
}

int
lac_csc_write_mm (const lac_csc *A, const char *path)
{
  FILE *f;
  int status = lac_file_create (path, "w", &f);
  if (status)
    return status;
  fprintf (f, "%%%%MatrixMarket matrix coordinate real general\n"
           "%zu %zu %d\n", A->nrow, A->ncol, A->p[A->ncol]);
  for (size_t j = 0; !ferror (f) && j < A->ncol; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      fprintf (f, "%d %zu %.17g\n", A->i[q] + 1, j + 1, A->x[q]);
  return lac_file_close (f, path);
}
