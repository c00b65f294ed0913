/* t010: triplets -> CSC: duplicates summed, rows sorted, transpose, matvec
 * (one core and two) against a dense reference, diagonal and 1-norm, growth
 * and argument errors; a CSC made column by column (lac_csc_columns) is the
 * one of the same adds as triplets, bit for bit. */
#include <stdlib.h>
#include "check.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

enum { NR = 7, NC = 5, NADD = 400 };

/* Columns have strictly increasing rows and p is consistent. */
static int
csc_is_sorted (const lac_csc *A)
{
  if (A->p[0] != 0)
    return 0;
  for (size_t j = 0; j < A->ncol; j++)
    {
      if (A->p[j] > A->p[j + 1])
        return 0;
      for (int q = A->p[j]; q < A->p[j + 1]; q++)
        if (A->i[q] < 0 || (size_t) A->i[q] >= A->nrow
            || (q > A->p[j] && A->i[q] <= A->i[q - 1]))
          return 0;
    }
  return 1;
}

/* Dense value A(i,j) looked up in the CSC. */
static double
csc_get (const lac_csc *A, size_t i, size_t j)
{
  for (int q = A->p[j]; q < A->p[j + 1]; q++)
    if ((size_t) A->i[q] == i)
      return A->x[q];
  return 0;
}

static void
test_random (void)
{
  double D[NR][NC] = { { 0 } }, x[NC], y[NR], yt[NC], yd[NR], z[NR];
  lac_triplet *T = lac_triplet_alloc (NR, NC, 0);     /* grows from 16 */
  lac_csc *A, *At;
  srand (12345);
  for (int k = 0; k < NADD; k++)          /* many duplicates, random order */
    {
      size_t i = (size_t) rand () % NR, j = (size_t) rand () % NC;
      double v = rand () / (double) RAND_MAX - 0.5;
      if (i == 3)
        continue;                                     /* an empty row */
      if (j == 2)
        continue;                                     /* an empty column */
      D[i][j] += v;
      check_status (lac_triplet_add (T, i, j, v), LAC_SUCCESS, "add");
    }
  check_true (T->cap >= T->nz && T->nz > 16, "triplets grew: nz %zu", T->nz);
  A = lac_csc_from_triplet (T);
  check_true (A != NULL, "compress");
  if (!A)
    return;
  check_true (csc_is_sorted (A), "rows sorted, unique");
  check_int (A->p[2 + 1] - A->p[2], 0, "empty column stays empty");
  for (size_t i = 0; i < NR; i++)
    for (size_t j = 0; j < NC; j++)
      check_rel (csc_get (A, i, j), D[i][j], 1e-14, "A(%zu,%zu)", i, j);
  check_true (A->p[NC] <= NR * NC, "nnz %d <= %d", A->p[NC], NR * NC);

  for (size_t j = 0; j < NC; j++)
    x[j] = 1.0 + 0.25 * (double) j;
  for (size_t i = 0; i < NR; i++)
    z[i] = 2.0 - 0.5 * (double) i;
  lac_csc_matvec (A, x, y);
  for (size_t i = 0; i < NR; i++)
    {
      yd[i] = 0;
      for (size_t j = 0; j < NC; j++)
        yd[i] += D[i][j] * x[j];
      check_abs (y[i], yd[i], 1e-13, "y = A x, row %zu", i);
    }
  double yp[NR], wp[NR], yq[NR], wq[NR];                /* on two cores */
  check_status (lac_csc_matvec_pair (A, x, yp, wp), LAC_SUCCESS, "pair");
  check_status (lac_csc_matvec_pair (A, x, yq, wq), LAC_SUCCESS, "again");
  for (size_t i = 0; i < NR; i++)
    {
      check_abs (yp[i], yd[i], 1e-13, "y = A x on two cores, row %zu", i);
      check_true (yp[i] == yq[i], "the same bits twice, row %zu", i);
    }

  At = lac_csc_transpose (A);
  check_true (At && At->nrow == NC && At->ncol == NR, "transpose sizes");
  if (At)
    {
      check_true (csc_is_sorted (At), "transpose rows sorted");
      lac_csc_matvec (At, z, yt);
      for (size_t j = 0; j < NC; j++)
        {
          double w = 0;
          for (size_t i = 0; i < NR; i++)
            w += D[i][j] * z[i];
          check_abs (yt[j], w, 1e-13, "A^T z, row %zu", j);
        }
    }
  lac_csc_free (At);
  lac_csc_free (A);
  lac_triplet_free (T);
}

/* add_block: a 1D bar of 4 two-node elements, K = k [1 -1; -1 1]. */
static void
test_block (void)
{
  const double Ke[4] = { 1, -1, -1, 1 };
  const double want[5][5] = { { 1, -1, 0, 0, 0 }, { -1, 2, -1, 0, 0 },
                              { 0, -1, 2, -1, 0 }, { 0, 0, -1, 2, -1 },
                              { 0, 0, 0, -1, 1 } };
  lac_triplet *T = lac_triplet_alloc (5, 5, 4);
  lac_csc *K;
  for (size_t e = 0; e < 4; e++)
    {
      size_t idx[2] = { e, e + 1 };
      check_status (lac_triplet_add_block (T, 2, idx, 2, idx, Ke),
                    LAC_SUCCESS, "block %zu", e);
    }
  check_int ((long) T->nz, 16, "16 triplets");
  K = lac_csc_from_triplet (T);
  check_true (K != NULL, "compress bar");
  if (K)
    {
      check_int (K->p[5], 13, "tridiagonal 5x5: 13 entries");
      double d[5];
      for (size_t i = 0; i < 5; i++)
        for (size_t j = 0; j < 5; j++)
          check_abs (csc_get (K, i, j), want[i][j], 0, "K(%zu,%zu)", i, j);
      /* diag(K) = (1 2 2 2 1), ||K||_1 = |-1| + 2 + |-1| = 4 */
      check_abs (lac_csc_diag_norm1 (K, d), 4, 0, "||K||_1");
      for (size_t j = 0; j < 5; j++)
        check_abs (d[j], want[j][j], 0, "diag(K)_%zu", j);
      check_abs (lac_csc_diag_norm1 (K, NULL), 4, 0, "||K||_1, no diag");
    }
  lac_csc_free (K);
  lac_triplet_free (T);
}

static void
test_errors (void)
{
  lac_triplet *T = lac_triplet_alloc (3, 2, 4);
  size_t rows[2] = { 0, 3 }, cols[2] = { 0, 1 };
  double B[4] = { 1, 2, 3, 4 };
  check_status (lac_triplet_add (T, 3, 0, 1.0), LAC_EINVAL, "row 3 of 3");
  check_message ("outside", "message names the problem");
  check_status (lac_triplet_add (T, 0, 2, 1.0), LAC_EINVAL, "column 2 of 2");
  check_status (lac_triplet_add_block (T, 2, rows, 2, cols, B), LAC_EINVAL,
                "block with row 3");
  check_int ((long) T->nz, 0, "nothing added on error");
  lac_triplet_free (T);
  lac_triplet_free (NULL);
  lac_csc_free (NULL);

  /* Allocation failure while growing: message, triplets intact. */
  T = lac_triplet_alloc (4, 4, 16);
  for (size_t k = 0; k < 16; k++)
    lac_triplet_add (T, k % 4, k / 4, 1.0);
  lac_mem_fail_after (0);
  check_status (lac_triplet_add (T, 0, 0, 1.0), LAC_ENOMEM, "grow fails");
  lac_mem_fail_after (-1);
  check_int ((long) T->nz, 16, "entries kept after failed growth");
  check_status (lac_triplet_add (T, 0, 0, 1.0), LAC_SUCCESS, "grow again");
  lac_triplet_free (T);
}

/* The same adds, column after column, as triplets and by columns: the
 * same p, rows and values to the last bit (sums in the order of the adds);
 * an empty column; the errors. */
static void
test_columns (void)
{
  enum { R = 50, K = 6 };
  lac_triplet *T = lac_triplet_alloc (R, K, 0);
  lac_csc_columns *b = lac_csc_columns_alloc (R, K);
  srand (777);
  for (size_t j = 0; j < K; j++)
    {
      for (int a = 0; j != 2 && a < 300; a++)       /* column 2 stays empty */
        {
          size_t i = (size_t) rand () % R;
          double v = rand () / (double) RAND_MAX - 0.3;
          lac_triplet_add (T, i, j, v);
          check_status (lac_csc_columns_add (b, i, v), LAC_SUCCESS, "add");
        }
      check_status (lac_csc_columns_end (b), LAC_SUCCESS, "column %zu", j);
    }
  lac_csc *A = lac_csc_from_triplet (T), *B = lac_csc_columns_take (b);
  check_true (A && B, "both made");
  if (A && B)
    {
      int same = A->p[K] == B->p[K];
      for (size_t j = 0; same && j <= K; j++)
        same = A->p[j] == B->p[j];
      for (int q = 0; same && q < A->p[K]; q++)
        same = A->i[q] == B->i[q] && A->x[q] == B->x[q];
      check_true (same, "by columns = from triplets, bit for bit (%d entries)",
                  A->p[K]);
      check_true (csc_is_sorted (B), "rows sorted");
      check_int (B->p[3] - B->p[2], 0, "empty column");
    }
  check_status (lac_csc_columns_end (b), LAC_EINVAL, "no column left");
  check_true (lac_csc_columns_take (b) == NULL, "taken once");
  lac_csc_columns_free (b);
  b = lac_csc_columns_alloc (4, 2);
  check_status (lac_csc_columns_add (b, 4, 1.0), LAC_EINVAL, "row 4 of 4");
  check_message ("outside", "message names the problem");
  check_true (lac_csc_columns_take (b) == NULL, "not every column ended");
  lac_csc_columns_free (b);
  lac_csc_columns_free (NULL);
  lac_csc_free (A);
  lac_csc_free (B);
  lac_triplet_free (T);
}

int
main (void)
{
  lac_init ();
  test_random ();
  test_columns ();
  test_block ();
  test_errors ();
  return check_summary ();
}
