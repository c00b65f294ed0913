/* t437: the schur strategy as the preconditioner of a consistent step:
 *       reset and keep (solve/lac_strategy.h)
 *
 * K: the 7-point Laplacian of a 6^3 grid plus I (positive definite); C1
 * and C2: k = 5 sparse columns of pseudo-random weights on the same rows
 * (C2 = C1 moved a little, as a pairing moves between two Newton
 * iterations); F, G and F', G' two pairs of right-hand sides.
 *   1. set on (K, C1): the solve of (*) for an active set has residuals
 *      below 1e-12 (the reference);
 *   2. reset on (K', C2) with same_columns = 0: the factorization of K is
 *      kept, C2 is used: the solve is that of (K, C2) (residual of the
 *      system with K and C2 below 1e-12);
 *   3. set on (K, C1) again, then reset on (K', C2, F', G') with
 *      same_columns = 1: C1 is kept with the columns of its Schur
 *      complement, and the solve with F', G' is that of (K, C1): the same
 *      U and lambda as a set on (K, C1, F', G') to 1e-12, by one solve
 *      with the factor per right-hand side (the kept K^-1 C1 columns);
 *   4. a solve for an active set with a column the kept system had not
 *      made yet (its column of S made then, with C1) is that of (K, C1).
 * Twice: on the 6^3 grid CHOLMOD's factor is simplicial L D L^T and S is
 * C^T (K^{-1} C) from whole solves; on the 14^3 grid it is supernodal
 * L L^T and S = Y^T Y from the forward halves Y = L^{-1} P C
 * (linalg/lac_linalg.h, lac_solver_halves), and each solve takes one
 * solve with the factor instead of two (the count of substitutions).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_strategy.h"

#define K 5

static double
rnd (unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 65535.0;
}

static lac_csc *
laplacian (int M, double shift)
{
  size_t n = (size_t) (M * M * M);
  lac_triplet *T = lac_triplet_alloc (n, n, 7 * n);
  for (int z = 0; z < M; z++)
    for (int y = 0; y < M; y++)
      for (int x = 0; x < M; x++)
        {
          size_t i = (size_t) (x + M * (y + M * z));
          lac_triplet_add (T, i, i, 7.0 + shift);
          if (x > 0)
            lac_triplet_add (T, i, i - 1, -1.0);
          if (x < M - 1)
            lac_triplet_add (T, i, i + 1, -1.0);
          if (y > 0)
            lac_triplet_add (T, i, i - M, -1.0);
          if (y < M - 1)
            lac_triplet_add (T, i, i + M, -1.0);
          if (z > 0)
            lac_triplet_add (T, i, i - M * M, -1.0);
          if (z < M - 1)
            lac_triplet_add (T, i, i + M * M, -1.0);
        }
  lac_csc *A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

/* k columns of 4 rows each on the top face z = M - 1, weights + move. */
static lac_csc *
columns (int M, double move)
{
  size_t n = (size_t) (M * M * M);
  unsigned seed = 7;
  lac_triplet *T = lac_triplet_alloc (n, K, 4 * K);
  for (size_t i = 0; i < K; i++)
    for (int q = 0; q < 4; q++)
      {
        size_t r = (size_t) (M * M * (M - 1)) + 5 * i + (size_t) q;
        lac_triplet_add (T, r, i, 0.25 + rnd (&seed) + move * (double) q);
      }
  lac_csc *C = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return C;
}

/* max of |F - K U + C_A lambda_A| and |G_A - C_A^T U| */
static double
residual (const lac_csc *Km, const lac_csc *C, const double *F,
          const double *G, const char *act, const double *U,
          const double *lam)
{
  size_t n = Km->ncol;
  double *r = malloc (n * sizeof *r), e = 0;
  lac_csc_matvec (Km, U, r);
  for (size_t j = 0; j < n; j++)
    r[j] = F[j] - r[j];
  for (size_t i = 0; i < C->ncol; i++)
    {
      double g = G[i];
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        {
          r[C->i[p]] += act[i] ? C->x[p] * lam[i] : 0.0;
          g -= C->x[p] * U[C->i[p]];
        }
      e = fmax (e, act[i] ? fabs (g) : fabs (lam[i]));
    }
  for (size_t j = 0; j < n; j++)
    e = fmax (e, fabs (r[j]));
  free (r);
  return e;
}

static double
diff (size_t n, const double *a, const double *b)
{
  double e = 0;
  for (size_t j = 0; j < n; j++)
    e = fmax (e, fabs (a[j] - b[j]));
  return e;
}

/* Parts 1-4 on the M^3 grid; halves: the factor is L L^T. */
static void
run (int M, int halves)
{
  size_t n = (size_t) (M * M * M);
  lac_csc *K1 = laplacian (M, 0), *K2 = laplacian (M, 0.5);
  lac_csc *C1 = columns (M, 0), *C2 = columns (M, 0.05);
  double *F = calloc (n, sizeof *F), *F2 = calloc (n, sizeof *F2);
  double G[K] = { -0.1, -0.2, 0.05, -0.3, -0.1 }, G2[K];
  double *U = calloc (n, sizeof *U), *Ur = calloc (n, sizeof *Ur);
  double lam[K], lamr[K];
  char act[K] = { 1, 1, 0, 1, 0 }, act2[K] = { 1, 1, 1, 1, 0 };
  unsigned seed = 3;
  for (size_t j = 0; j < n; j++)
    F[j] = rnd (&seed) - 0.5, F2[j] = rnd (&seed) - 0.5;
  for (int i = 0; i < K; i++)
    G2[i] = G[i] - 0.05 * i;
  lac_contact_system s1 = { K1, F, C1, G, NULL, 0, NULL, NULL, NULL };
  lac_contact_system s2 = { K2, F, C2, G, NULL, 0, NULL, NULL, NULL };
  lac_contact_system s3 = { K2, F2, C2, G2, NULL, 0, NULL, NULL, NULL };
  lac_contact_system s4 = { K1, F2, C1, G2, NULL, 0, NULL, NULL, NULL };
  lac_strategy *st = lac_strategy_alloc (LAC_STRATEGY_SCHUR);
  int kept = -1;
  lac_strategy_counts c;
  check_true (st != NULL, "schur strategy: %s", lac_error_message ());
  if (!st)
    return;

  /* 1. the reference */
  check_status (lac_strategy_set (st, &s1), LAC_SUCCESS, "set (K, C1)");
  check_status (lac_strategy_solve_rhs (st, act, F, G, U, lam), LAC_SUCCESS,
                "solve (K, C1)");
  double e = residual (K1, C1, F, G, act, U, lam);
  check_true (e < 1e-12, "1. %d^3: residual of (K, C1): %.2e", M, e);
  lac_strategy_get_counts (st, &c);  /* 2 of the condition estimate, 3 */
  check_true (c.substitutions == (halves ? 6 : 7), "1. %d^3: %d "  /* of S, */
              "substitutions, %d expected", M, c.substitutions,  /* then U */
              halves ? 6 : 7);

  /* 2. reset: the factor of K kept, C2 used */
  check_status (lac_strategy_reset (st, &s2, 0, &kept), LAC_SUCCESS,
                "reset (K', C2)");
  check_true (kept == 1, "2. the factorization is kept (%d)", kept);
  check_status (lac_strategy_solve_rhs (st, act, F, G, U, lam), LAC_SUCCESS,
                "solve after reset");
  e = residual (K1, C2, F, G, act, U, lam);
  check_true (e < 1e-12, "2. residual of (K, C2) after reset: %.2e", e);

  /* 3. keep: C1 and its Schur columns kept, only F', G' new */
  check_status (lac_strategy_set (st, &s1), LAC_SUCCESS, "set (K, C1) again");
  check_status (lac_strategy_solve_rhs (st, act, F, G, U, lam), LAC_SUCCESS,
                "solve (K, C1) again");
  check_status (lac_strategy_reset (st, &s3, 1, &kept), LAC_SUCCESS,
                "keep (K', C2, F', G')");
  check_status (lac_strategy_solve_rhs (st, act, F2, G2, U, lam),
                LAC_SUCCESS, "solve kept");
  lac_strategy *ref = lac_strategy_alloc (LAC_STRATEGY_SCHUR);
  check_status (lac_strategy_set (ref, &s4), LAC_SUCCESS, "set (K, C1, F', "
                "G')");
  check_status (lac_strategy_solve_rhs (ref, act, F2, G2, Ur, lamr),
                LAC_SUCCESS, "reference solve");
  e = fmax (diff (n, U, Ur), diff (K, lam, lamr));
  check_true (e < 1e-12, "3. kept solve against (K, C1): %.2e", e);
  e = residual (K1, C1, F2, G2, act, U, lam);
  check_true (e < 1e-12, "3. residual of (K, C1, F', G'): %.2e", e);

  /* 4. a column of S not made before the keep: made with C1 */
  check_status (lac_strategy_solve_rhs (st, act2, F2, G2, U, lam),
                LAC_SUCCESS, "solve kept, one more active");
  check_status (lac_strategy_solve_rhs (ref, act2, F2, G2, Ur, lamr),
                LAC_SUCCESS, "reference, one more active");
  e = fmax (diff (n, U, Ur), diff (K, lam, lamr));
  check_true (e < 1e-12, "4. kept solve, new column, against (K, C1): %.2e",
              e);

  lac_strategy_free (st);
  lac_strategy_free (ref);
  lac_csc_free (K1), lac_csc_free (K2), lac_csc_free (C1), lac_csc_free (C2);
  free (F), free (F2), free (U), free (Ur);
}

int
main (void)
{
  lac_init ();
  run (6, 0);
  run (14, 1);
  lac_finalize ();
  return check_summary ();
}
