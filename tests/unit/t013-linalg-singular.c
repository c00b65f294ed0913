/* t013: singular matrices are refused by every back end with LAC_ESING and
 * a message (never garbage): a pure-Neumann Laplacian, a floating 2D truss
 * (rigid modes), a truss with only one node fixed (rotation left), a zero
 * column, dependent rows; CHOLMOD on an indefinite matrix. */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "linalg/lac_linalg.h"
#include "base/lac_status.h"

/* Pure-Neumann 5-point Laplacian on m x m: rows sum to zero, the
 * constants are its kernel.  shift is added to the diagonal. */
static lac_csc *
neumann_2d (size_t m, double shift)
{
  size_t n = m * m;
  lac_triplet *T = lac_triplet_alloc (n, n, 5 * n);
  lac_csc *A;
  for (size_t a = 0; a < m; a++)
    for (size_t b = 0; b < m; b++)
      {
        size_t k = a * m + b, nb[4], c = 0;
        if (a > 0)
          nb[c++] = k - m;
        if (a + 1 < m)
          nb[c++] = k + m;
        if (b > 0)
          nb[c++] = k - 1;
        if (b + 1 < m)
          nb[c++] = k + 1;
        lac_triplet_add (T, k, k, (double) c + shift);
        for (size_t q = 0; q < c; q++)
          lac_triplet_add (T, k, nb[q], -1);
      }
  A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

/* Bar from node a to node b of a 2D truss: K += k/L (n n^T) [1 -1; -1 1]. */
static void
add_bar (lac_triplet *T, const double *xy, size_t a, size_t b)
{
  double dx = xy[2 * b] - xy[2 * a], dy = xy[2 * b + 1] - xy[2 * a + 1];
  double L = hypot (dx, dy), n[2] = { dx / L, dy / L }, Ke[16];
  size_t idx[4] = { 2 * a, 2 * a + 1, 2 * b, 2 * b + 1 };
  for (int r = 0; r < 4; r++)
    for (int c = 0; c < 4; c++)
      Ke[4 * r + c] = 210e3 / L * n[r % 2] * n[c % 2]
                      * ((r < 2) == (c < 2) ? 1 : -1);
  lac_triplet_add_block (T, 4, idx, 4, idx, Ke);
}

/* A rigid m x m truss (bars along the grid lines and both diagonals, a
 * slightly irregular grid); the first nfix nodes of the bottom row are
 * clamped by symmetric elimination (row and column zeroed, diagonal = the
 * mean stiffness diagonal). */
static lac_csc *
truss_2d (size_t m, size_t nfix)
{
  size_t nn = m * m, n = 2 * nn;
  double *xy = malloc (2 * nn * sizeof *xy), dmean = 0;
  lac_triplet *T = lac_triplet_alloc (n, n, 64 * nn);
  lac_csc *A;
  for (size_t a = 0; a < m; a++)
    for (size_t b = 0; b < m; b++)
      {
        xy[2 * (a * m + b)] = (double) b + 0.1 * sin ((double) (7 * a + b));
        xy[2 * (a * m + b) + 1] = (double) a
                                  + 0.1 * cos ((double) (a + 5 * b));
      }
  for (size_t a = 0; a < m; a++)
    for (size_t b = 0; b < m; b++)
      {
        size_t k = a * m + b;
        if (b + 1 < m)
          add_bar (T, xy, k, k + 1);
        if (a + 1 < m)
          add_bar (T, xy, k, k + m);
        if (a + 1 < m && b + 1 < m)
          {
            add_bar (T, xy, k, k + m + 1);
            add_bar (T, xy, k + 1, k + m);
          }
      }
  A = lac_csc_from_triplet (T);
  for (size_t j = 0; j < n; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      if ((size_t) A->i[q] == j)
        dmean += A->x[q] / (double) n;
  for (size_t j = 0; j < n; j++)                      /* clamp dofs < 2 nfix */
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      if (j < 2 * nfix || (size_t) A->i[q] < 2 * nfix)
        A->x[q] = (size_t) A->i[q] == j ? dmean : 0;
  lac_triplet_free (T);
  free (xy);
  return A;
}

/* Every kind in kinds[0..nk-1] must give `want` on A. */
static void
expect (const char *what, const lac_csc *A, int nk, const int *kinds,
        int want, const char *needle)
{
  for (int s = 0; s < nk; s++)
    {
      lac_solver *S = lac_solver_alloc ((lac_solver_kind) kinds[s]);
      const char *name = lac_solver_kind_name ((lac_solver_kind) kinds[s]);
      double *b = calloc (A->ncol, sizeof *b);
      double *x = calloc (A->ncol, sizeof *x);
      lac_error_clear ();
      check_status (lac_solver_factor (S, A), want, "%s: %s", what, name);
      if (want != LAC_SUCCESS)
        {
          check_message (needle, "%s: %s message", what, name);
          check_status (lac_solver_solve (S, b, x), LAC_EINVAL,
                        "%s: %s no solve after failure", what, name);
        }
      free (b);
      free (x);
      lac_solver_free (S);
    }
}

int
main (void)
{
  const int all[3] = { LAC_SOLVER_DENSE, LAC_SOLVER_UMFPACK,
                       LAC_SOLVER_CHOLMOD };
  lac_csc *A;
  lac_init ();

  A = neumann_2d (12, 0);
  expect ("neumann laplacian", A, 3, all, LAC_ESING, "singular");
  lac_csc_free (A);
  A = neumann_2d (12, 1e-3);                  /* the same, made regular */
  expect ("shifted laplacian", A, 3, all, LAC_SUCCESS, "");
  lac_csc_free (A);

  for (size_t m = 3; m <= 15; m += 6)
    {
      A = truss_2d (m, 0);                     /* floating: 3 rigid modes */
      expect ("floating truss", A, 3, all, LAC_ESING, "rigid motion");
      lac_csc_free (A);
      A = truss_2d (m, 1);                     /* one node: rotation free */
      expect ("truss on one node", A, 3, all, LAC_ESING, "rigid motion");
      lac_csc_free (A);
      A = truss_2d (m, 2);                     /* two nodes: fixed */
      expect ("truss on two nodes", A, 3, all, LAC_SUCCESS, "");
      lac_csc_free (A);
    }

  /* A structurally singular matrix: column 2 of a 4 x 4 is empty. */
  {
    lac_triplet *T = lac_triplet_alloc (4, 4, 8);
    lac_triplet_add (T, 0, 0, 2);
    lac_triplet_add (T, 1, 1, 3);
    lac_triplet_add (T, 3, 3, 4);
    lac_triplet_add (T, 0, 1, 1);
    lac_triplet_add (T, 1, 0, 1);
    A = lac_csc_from_triplet (T);
    expect ("zero column", A, 3, all, LAC_ESING, "column 2");
    lac_csc_free (A);
    lac_triplet_free (T);
  }

  /* Nonsymmetric, row 2 = row 0 + row 1 (dense and UMFPACK only). */
  {
    const double R[3][3] = { { 1, 2, 3 }, { -4, 5, 0.5 }, { -3, 7, 3.5 } };
    lac_triplet *T = lac_triplet_alloc (3, 3, 9);
    for (size_t i = 0; i < 3; i++)
      for (size_t j = 0; j < 3; j++)
        lac_triplet_add (T, i, j, R[i][j]);
    A = lac_csc_from_triplet (T);
    expect ("dependent rows", A, 2, all, LAC_ESING, "singular");
    lac_csc_free (A);
    lac_triplet_free (T);
  }

  /* Symmetric indefinite: Laplacian shifted by -1 (eigenvalues 4 sin^2 ...
   * - 1 of both signs) is regular for LU but not for Cholesky. */
  A = neumann_2d (10, -1.0);
  expect ("indefinite", A, 2, all, LAC_SUCCESS, "");
  expect ("indefinite", A, 1, all + 2, LAC_ESING, "not positive definite");
  lac_csc_free (A);
  return check_summary ();
}
