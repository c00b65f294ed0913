/* t012: dense, UMFPACK and CHOLMOD agree (1e-10 relative) with small
 * residuals (< 1e-12) on an SPD 2D Laplacian-like matrix and, for dense and
 * UMFPACK, on a random nonsymmetric well-conditioned matrix; several
 * right-hand sides, refactoring (and lac_solver_refactor's reuse of the
 * analysis), names, info and argument errors; CHOLMOD refuses a matrix
 * whose upper part differs from its lower part, naming the entry; the
 * solve in halves (lac_solver_halves) of a supernodal L L^T: forward and
 * back are a solve, y_b^T y_c = b^T A^{-1} c, and the LU and L D L^T
 * factors refuse it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* 5-point Laplacian on an m x m grid (Dirichlet outside) plus 0.1 I,
 * with the unknowns in a scrambled order so that the pattern is not banded. */
static lac_csc *
laplacian_2d (size_t m)
{
  size_t n = m * m;
  size_t *map = malloc (n * sizeof *map);
  lac_triplet *T = lac_triplet_alloc (n, n, 5 * n);
  lac_csc *A;
  for (size_t k = 0; k < n; k++)
    map[k] = (k * 37) % n;                 /* 37 is prime to n (m = 20) */
  for (size_t a = 0; a < m; a++)
    for (size_t b = 0; b < m; b++)
      {
        size_t k = map[a * m + b];
        lac_triplet_add (T, k, k, 4.1);
        if (a > 0)
          lac_triplet_add (T, k, map[(a - 1) * m + b], -1);
        if (a + 1 < m)
          lac_triplet_add (T, k, map[(a + 1) * m + b], -1);
        if (b > 0)
          lac_triplet_add (T, k, map[a * m + b - 1], -1);
        if (b + 1 < m)
          lac_triplet_add (T, k, map[a * m + b + 1], -1);
      }
  A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  free (map);
  return A;
}

/* Random sparse nonsymmetric matrix, 6 entries per row in [-1,1], with a
 * diagonal 8 (diagonally dominant, so well conditioned). */
static lac_csc *
random_nonsym (size_t n)
{
  lac_triplet *T = lac_triplet_alloc (n, n, 7 * n);
  lac_csc *A;
  srand (2024);
  for (size_t i = 0; i < n; i++)
    {
      lac_triplet_add (T, i, i, 8.0);
      for (int k = 0; k < 6; k++)
        lac_triplet_add (T, i, (size_t) rand () % n,
                         2.0 * rand () / RAND_MAX - 1.0);
    }
  A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

/* ||b - A x||_inf / ||b||_inf */
static double
relres (const lac_csc *A, const double *x, const double *b)
{
  size_t n = A->nrow;
  double *r = malloc (n * sizeof *r), num = 0, den = 0;
  lac_csc_matvec (A, x, r);
  for (size_t i = 0; i < n; i++)
    {
      num = fmax (num, fabs (b[i] - r[i]));
      den = fmax (den, fabs (b[i]));
    }
  free (r);
  return num / den;
}

static double
reldiff (size_t n, const double *x, const double *y)
{
  double num = 0, den = 0;
  for (size_t i = 0; i < n; i++)
    {
      num = fmax (num, fabs (x[i] - y[i]));
      den = fmax (den, fabs (y[i]));
    }
  return num / den;
}

/* Solve A X = B (nrhs columns) with each back end in kinds[0..nk-1]; compare
 * with the first. */
static void
compare (const char *what, const lac_csc *A, const int *kinds, int nk)
{
  enum { NRHS = 3 };
  size_t n = A->ncol;
  double *B = malloc (NRHS * n * sizeof *B);
  double *X[3];
  for (size_t k = 0; k < NRHS * n; k++)
    B[k] = sin (0.37 * (double) k) + (k % 7 == 0);
  for (int s = 0; s < nk; s++)
    {
      lac_solver *S = lac_solver_alloc ((lac_solver_kind) kinds[s]);
      const char *name = lac_solver_kind_name ((lac_solver_kind) kinds[s]);
      lac_solver_info info;
      X[s] = calloc (NRHS * n, sizeof *X[s]);
      check_status (lac_solver_factor (S, A), LAC_SUCCESS, "%s: %s factor",
                    what, name);
      check_status (lac_solver_solve_many (S, NRHS, B, X[s]), LAC_SUCCESS,
                    "%s: %s solve_many", what, name);
      for (int r = 0; r < NRHS; r++)
        check_true (relres (A, X[s] + r * n, B + r * n) < 1e-12,
                    "%s: %s residual %.3g, rhs %d", what, name,
                    relres (A, X[s] + r * n, B + r * n), r);
      check_status (lac_solver_get_info (S, &info), LAC_SUCCESS, "info");
      check_int ((long) info.n, (long) n, "%s: info.n", name);
      check_true (info.nnz_factor >= (double) n && info.peak_bytes > 0
                  && info.pivot_ratio >= LAC_PIVOT_RTOL && info.method,
                  "%s: info filled (%s, %s)", name, info.method,
                  info.ordering);
      {
        lac_solver_info est;
        check_status (lac_solver_estimate ((lac_solver_kind) kinds[s], A,
                                           &est), LAC_SUCCESS, "estimate");
        /* exact for dense and CHOLMOD, an upper bound for UMFPACK */
        double hi = kinds[s] == LAC_SOLVER_UMFPACK ? 4 : 1;
        check_true (est.nnz_factor >= info.nnz_factor
                    && est.nnz_factor <= hi * info.nnz_factor
                    && est.flops > 0 && est.peak_bytes > 0,
                    "%s: %s estimate nnz %.6g vs factor %.6g", what, name,
                    est.nnz_factor, info.nnz_factor);
      }
      if (s > 0)
        check_true (reldiff (NRHS * n, X[s], X[0]) < 1e-10,
                    "%s: %s vs %s differ by %.3g", what, name,
                    lac_solver_kind_name ((lac_solver_kind) kinds[0]),
                    reldiff (NRHS * n, X[s], X[0]));
      lac_solver_free (S);
    }
  for (int s = 0; s < nk; s++)
    free (X[s]);
  free (B);
}

/* One solver object factors twice; single solve equals solve_many. */
static void
test_refactor (const lac_csc *A1, const lac_csc *A2)
{
  size_t n = A1->ncol;
  double *b = malloc (n * sizeof *b), *x = malloc (n * sizeof *x);
  for (int kind = 0; kind < 3; kind++)
    {
      lac_solver *S = lac_solver_alloc ((lac_solver_kind) kind);
      const lac_csc *As[2] = { A1, A2 };
      check_status (lac_solver_solve (S, b, x), LAC_EINVAL,
                    "%d: solve before factor", kind);
      for (int t = 0; t < 2; t++)
        {
          if (kind == LAC_SOLVER_CHOLMOD && t == 1)
            break;                                   /* A2 nonsymmetric */
          for (size_t i = 0; i < n; i++)
            b[i] = 1.0 + (double) (i % 3);
          check_status (lac_solver_factor (S, As[t]), LAC_SUCCESS,
                        "%d: factor %d", kind, t);
          check_status (lac_solver_solve (S, b, x), LAC_SUCCESS,
                        "%d: solve %d", kind, t);
          check_true (relres (As[t], x, b) < 1e-12, "%d: refactor %d", kind,
                      t);
        }
      lac_solver_free (S);
    }
  free (b);
  free (x);
}

/* lac_solver_refactor: new numbers on the same pattern reuse the analysis
 * (info.analysis_reused) and solve as well as a fresh factorization; a
 * different pattern is analysed again; a singular matrix is refused and
 * the next refactor starts afresh. */
static void
test_reuse (const lac_csc *A, const lac_csc *Other)
{
  size_t n = A->ncol, nnz = (size_t) A->p[n];
  lac_csc *A2 = lac_csc_alloc (n, n, nnz), *Z = lac_csc_alloc (n, n, nnz);
  double *b = malloc (n * sizeof *b), *x = malloc (n * sizeof *x);
  double *y = malloc (n * sizeof *y);
  memcpy (A2->p, A->p, (n + 1) * sizeof *A->p);
  memcpy (Z->p, A->p, (n + 1) * sizeof *A->p);
  memcpy (A2->i, A->i, nnz * sizeof *A->i);
  memcpy (Z->i, A->i, nnz * sizeof *A->i);
  for (size_t j = 0; j < n; j++)           /* A2 = A + diag(j % 5), SPD */
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      {
        A2->x[q] = A->x[q] + ((size_t) A->i[q] == j ? (double) (j % 5) : 0);
        Z->x[q] = 0;                        /* the zero matrix: singular */
      }
  for (size_t i = 0; i < n; i++)
    b[i] = cos (0.3 * (double) i);
  for (int kind = 1; kind < 3; kind++)
    {
      lac_solver *S = lac_solver_alloc ((lac_solver_kind) kind);
      lac_solver *F = lac_solver_alloc ((lac_solver_kind) kind);
      lac_solver_info info;
      check_status (lac_solver_refactor (S, A), LAC_SUCCESS, "%d: first", kind);
      lac_solver_get_info (S, &info);
      check_int (info.analysis_reused, 0, "%d: nothing to reuse at first",
                 kind);
      check_status (lac_solver_refactor (S, A2), LAC_SUCCESS, "%d: same "
                    "pattern", kind);
      lac_solver_get_info (S, &info);
      check_int (info.analysis_reused, 1, "%d: analysis reused", kind);
      check_status (lac_solver_solve (S, b, x), LAC_SUCCESS, "solve");
      lac_solver_factor (F, A2);
      lac_solver_solve (F, b, y);
      check_true (relres (A2, x, b) < 1e-12 && reldiff (n, x, y) < 1e-12,
                  "%d: refactor residual %.3g, vs factor %.3g", kind,
                  relres (A2, x, b), reldiff (n, x, y));
      if (kind == LAC_SOLVER_UMFPACK)
        {
          check_status (lac_solver_refactor (S, Other), LAC_SUCCESS,
                        "%d: other pattern", kind);
          lac_solver_get_info (S, &info);
          check_int (info.analysis_reused, 0, "%d: other pattern analysed",
                     kind);
          check_status (lac_solver_refactor (S, A), LAC_SUCCESS, "back");
        }
      check_status (lac_solver_refactor (S, Z), LAC_ESING, "%d: singular",
                    kind);
      check_status (lac_solver_solve (S, b, x), LAC_EINVAL, "%d: nothing "
                    "stored after a failure", kind);
      check_status (lac_solver_refactor (S, A2), LAC_SUCCESS, "%d: again",
                    kind);
      lac_solver_get_info (S, &info);
      check_int (info.analysis_reused, 0, "%d: analysed afresh", kind);
      lac_solver_solve (S, b, x);
      check_true (reldiff (n, x, y) < 1e-12, "%d: after failure", kind);
      lac_solver_free (S);
      lac_solver_free (F);
    }
  lac_csc_free (A2);
  lac_csc_free (Z);
  free (b);
  free (x);
  free (y);
}

static void
test_errors (const lac_csc *Ansym)
{
  lac_solver *S = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  lac_csc *R = lac_csc_alloc (3, 2, 0);
  lac_csc *big = lac_csc_alloc (LAC_DENSE_NMAX + 1, LAC_DENSE_NMAX + 1, 0);
  check_status (lac_solver_factor (S, Ansym), LAC_EINVAL, "cholmod, nonsym");
  check_message ("symmetric", "message says symmetric");
  check_status (lac_solver_factor (S, R), LAC_EBADLEN, "3 x 2");
  lac_solver_free (S);
  S = lac_solver_alloc (LAC_SOLVER_DENSE);
  check_status (lac_solver_factor (S, big), LAC_EINVAL, "dense too large");
  check_message ("umfpack or cholmod", "message suggests sparse");
  lac_solver_free (S);
  lac_solver_free (NULL);
  check_true (lac_solver_alloc ((lac_solver_kind) 7) == NULL, "bad kind");
  check_int (lac_solver_kind_from_name ("cholmod"), LAC_SOLVER_CHOLMOD,
             "name cholmod");
  check_int (lac_solver_kind_from_name ("umfpack"), LAC_SOLVER_UMFPACK,
             "name umfpack");
  check_int (lac_solver_kind_from_name ("dense"), LAC_SOLVER_DENSE, "dense");
  check_int (lac_solver_kind_from_name ("mumps"), -1, "unknown name");
  check_true (!strcmp (lac_solver_kind_name (LAC_SOLVER_UMFPACK), "umfpack"),
              "kind name");
  lac_csc_free (R);
  lac_csc_free (big);
}

/* A copy of A with entry (i, j), i < j, of the upper part set to v (added
 * to the pattern if it is not there): CHOLMOD must refuse it, naming
 * (i, j), unless v equals A(j, i). */
static void
check_one_sided (const lac_csc *A, size_t i, size_t j, double v, int bad)
{
  lac_triplet *T = lac_triplet_alloc (A->nrow, A->ncol, 0);
  int found = 0;
  for (size_t c = 0; c < A->ncol; c++)
    for (int q = A->p[c]; q < A->p[c + 1]; q++)
      {
        int here = (size_t) A->i[q] == i && c == j;
        found |= here;
        lac_triplet_add (T, (size_t) A->i[q], c, here ? v : A->x[q]);
      }
  if (!found)
    lac_triplet_add (T, i, j, v);
  lac_csc *B = lac_csc_from_triplet (T);
  lac_solver *S = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  char at[64];
  snprintf (at, sizeof at, "A(%zu,%zu)", i, j);
  lac_error_clear ();
  check_status (lac_solver_factor (S, B), bad ? LAC_EINVAL : LAC_SUCCESS,
                "one-sided %s = %g", at, v);
  if (bad)
    check_message (at, "the message names %s", at);
  lac_solver_free (S);
  lac_csc_free (B);
  lac_triplet_free (T);
}

/* The symmetry check of every entry of the upper part, the first and the
 * last columns included. */
static void
test_symmetry_check (const lac_csc *L)
{
  size_t n = L->ncol, i = (size_t) -1, j = 0;
  for (size_t c = n; c-- > 0 && i == (size_t) -1;)   /* the last off-diagonal */
    for (int q = L->p[c]; q < L->p[c + 1]; q++)       /* upper entry */
      if ((size_t) L->i[q] < c)
        i = (size_t) L->i[q], j = c;
  check_one_sided (L, i, j, -1.0, 0);            /* the same value: fine */
  check_one_sided (L, i, j, -1.5, 1);            /* changed */
  check_one_sided (L, 0, n - 1, 0.25, 1);        /* not in the lower part */
  check_one_sided (L, 0, 1, 0.0, 0);             /* an explicit zero */
}

/* Make the k-th allocation fail, k = 0, 1, ...: every step either works or
 * returns LAC_ENOMEM with a message; nothing leaks (checked under ASan). */
static void
test_alloc_failures (void)
{
  for (int kind = 0; kind < 3; kind++)
    {
      int done = 0;
      for (long k = 0; !done && k < 100; k++)
        {
          lac_triplet *T;
          lac_csc *A = NULL;
          lac_solver *S = NULL;
          double b[30], x[30];
          int st = LAC_ENOMEM;
          for (int i = 0; i < 30; i++)
            b[i] = 1;
          lac_error_clear ();
          lac_mem_fail_after (k);
          T = lac_triplet_alloc (30, 30, 0);
          for (size_t i = 0; T && i < 30; i++)
            {
              st = lac_triplet_add (T, i, i, 3.0);
              if (!st && i > 0)
                st = lac_triplet_add (T, i, i - 1, -1.0);
              if (!st && i > 0)
                st = lac_triplet_add (T, i - 1, i, -1.0);
              if (st)
                break;
            }
          if (T && !st)
            A = lac_csc_from_triplet (T);
          if (A)
            S = lac_solver_alloc ((lac_solver_kind) kind);
          st = S ? lac_solver_factor (S, A) : LAC_ENOMEM;
          if (!st)
            st = lac_solver_solve (S, b, x);
          lac_mem_fail_after (-1);
          check_true (st == LAC_SUCCESS || st == LAC_ENOMEM, "kind %d, fail "
                      "at %ld: status %d", kind, k, st);
          if (st == LAC_ENOMEM)
            check_true (lac_error_message ()[0] != 0, "kind %d, fail at %ld:"
                        " message", kind, k);
          done = st == LAC_SUCCESS;
          lac_solver_free (S);
          lac_csc_free (A);
          lac_triplet_free (T);
        }
      check_true (done, "kind %d: succeeds once allocations work", kind);
    }
}

/* 7-point Laplacian of an m^3 grid plus 0.1 I: CHOLMOD factors it
 * supernodal from m = 14 on. */
static lac_csc *
laplacian_3d (size_t m)
{
  size_t n = m * m * m;
  lac_triplet *T = lac_triplet_alloc (n, n, 7 * n);
  for (size_t k = 0; k < n; k++)
    {
      size_t x = k % m, y = k / m % m, z = k / (m * m);
      lac_triplet_add (T, k, k, 6.1);
      if (x > 0) lac_triplet_add (T, k, k - 1, -1);
      if (x + 1 < m) lac_triplet_add (T, k, k + 1, -1);
      if (y > 0) lac_triplet_add (T, k, k - m, -1);
      if (y + 1 < m) lac_triplet_add (T, k, k + m, -1);
      if (z > 0) lac_triplet_add (T, k, k - m * m, -1);
      if (z + 1 < m) lac_triplet_add (T, k, k + m * m, -1);
    }
  lac_csc *A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

/* The halves of a solve: P^T L^-T (L^-1 P b) = A^-1 b, and y_b^T y_c =
 * b^T A^-1 c; refused by the LU and by the small 2D matrix L (simplicial
 * L D L^T). */
static void
test_halves (const lac_csc *L2)
{
  lac_csc *A = laplacian_3d (14);
  size_t n = A->nrow;
  double *B = malloc (2 * n * sizeof *B), *Y = malloc (2 * n * sizeof *Y);
  double *x = malloc (n * sizeof *x), *xr = malloc (n * sizeof *xr);
  for (size_t i = 0; i < 2 * n; i++)
    B[i] = sin (0.37 * (double) i) + (i < n ? 0.0 : 0.5);
  lac_solver *s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  check_status (lac_solver_factor (s, A), LAC_SUCCESS, "halves: factor");
  check_true (lac_solver_halves (s), "halves: the 14^3 Laplacian's factor "
              "is L L^T");
  check_status (lac_solver_forward_many (s, 2, B, Y), LAC_SUCCESS,
                "forward halves");
  check_status (lac_solver_backward (s, Y, x), LAC_SUCCESS, "back half");
  check_status (lac_solver_solve (s, B, xr), LAC_SUCCESS, "whole solve");
  double e = reldiff (n, x, xr);
  check_true (e < 1e-12, "halves: back(forward(b)) against a solve: %.2e",
              e);
  check_status (lac_solver_solve (s, B + n, xr), LAC_SUCCESS, "solve c");
  double yy = 0, bx = 0;
  for (size_t i = 0; i < n; i++)
    yy += Y[i] * Y[n + i], bx += B[i] * xr[i];
  check_true (fabs (yy - bx) < 1e-12 * fabs (bx), "halves: y_b^T y_c = "
              "%.15g, b^T A^-1 c = %.15g", yy, bx);
  for (int kind = LAC_SOLVER_DENSE; kind <= LAC_SOLVER_CHOLMOD; kind++)
    {
      lac_solver *t = lac_solver_alloc ((lac_solver_kind) kind);
      check_status (lac_solver_factor (t, L2), LAC_SUCCESS, "factor L2");
      check_true (!lac_solver_halves (t), "halves: %s of the 20 x 20 grid "
                  "has none", lac_solver_kind_name ((lac_solver_kind) kind));
      check_status (lac_solver_forward_many (t, 1, B, Y), LAC_EINVAL,
                    "forward half refused (%s)",
                    lac_solver_kind_name ((lac_solver_kind) kind));
      lac_error_clear ();
      lac_solver_free (t);
    }
  lac_solver_free (s);
  lac_csc_free (A);
  free (B), free (Y), free (x), free (xr);
}

int
main (void)
{
  const int all[3] = { LAC_SOLVER_DENSE, LAC_SOLVER_UMFPACK,
                       LAC_SOLVER_CHOLMOD };
  lac_csc *L, *N;
  lac_init ();
  L = laplacian_2d (20);
  N = random_nonsym (300);
  compare ("laplacian", L, all, 3);
  compare ("nonsymmetric", N, all, 2);
  test_refactor (L, L);
  test_reuse (L, N);
  test_errors (N);
  test_symmetry_check (L);
  test_halves (L);
  test_alloc_failures ();
  lac_csc_free (L);
  lac_csc_free (N);
  return check_summary ();
}
