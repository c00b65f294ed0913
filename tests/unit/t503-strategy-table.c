/* t503: the strategies are a table of types; a type of one's own goes
 *       through the same machinery                [LAC (17), Alg. 1; ch. 07]
 *
 * solve/lac_strategy.h: a strategy is a type (its operations and its
 * properties), and a new one is one file and one row.  Checked:
 *   - a strategy of this file, "gauss" (the unscaled saddle-point matrix
 *     of one active set, dense, by GSL's LU: a few dozen lines), solves a
 *     small contact problem -- the chain of springs against obstacles of
 *     t501, by the active-set rule of solve/lac_complementarity.h --
 *     through lac_strategy_alloc_type, with the same statuses, iterations,
 *     U and lambda (1e-12) as the saddle strategy of the table;
 *   - every type of the table solves a system without contact (k = 0:
 *     K U = F), split included (petsc: t510, which starts MPI);
 *   - the fallback is the table's: a type whose factorization fails falls
 *     back to saddle once and says so when its falls_back property says so,
 *     reports the error otherwise unless lac_strategy_allow_fallback; schur
 *     on a K that is not positive definite: LAC_ESING, or saddle's answer
 *     once allowed;
 *   - the choice reads the properties: auto, the refusals and their
 *     message, the names.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "check.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_complementarity.h"
#include "solve/lac_strategy.h"

enum { N = 40, KC = 6 };

/* ---- the strategy "gauss": one file's worth ------------------------------ */

typedef struct
{
  const lac_contact_system *sys;   /* borrowed */
  int fail;                        /* pretend the factorization fails */
  lac_solve_counts counts;
} gauss;

static void *
gauss_alloc (void)
{
  return lac_calloc (1, sizeof (gauss));
}

static void *
failing_alloc (void)
{
  gauss *s = lac_calloc (1, sizeof *s);
  if (s)
    s->fail = 1;
  return s;
}

static void
gauss_free (void *w)
{
  lac_free (w);
}

static int
gauss_set (void *w, const lac_contact_system *sys)
{
  ((gauss *) w)->sys = sys;
  return LAC_SUCCESS;
}

/* [K -C_A; -C_A^T 0] (identity rows for the inactive) [U; lambda] =
 * [f; -g_A], by an LU with partial pivoting. */
static int
gauss_solve (void *w, const char *active, const double *f, const double *g,
             double rtol, double *U, double *lambda)
{
  gauss *s = w;
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  size_t n = K->ncol, k = C->ncol, m = n + k;
  int sign;
  (void) rtol;
  if (s->fail)
    return lac_error_set (LAC_ESING, "gauss", "pretended failure");
  gsl_matrix *A = gsl_matrix_calloc (m, m);
  gsl_vector *b = gsl_vector_alloc (m), *x = gsl_vector_alloc (m);
  gsl_permutation *P = gsl_permutation_alloc (m);
  for (size_t j = 0; j < n; j++)
    {
      for (int p = K->p[j]; p < K->p[j + 1]; p++)
        gsl_matrix_set (A, (size_t) K->i[p], j, K->x[p]);
      gsl_vector_set (b, j, f ? f[j] : s->sys->F[j]);
    }
  for (size_t i = 0; i < k; i++)
    {
      for (int p = C->p[i]; active[i] && p < C->p[i + 1]; p++)
        {
          gsl_matrix_set (A, (size_t) C->i[p], n + i, -C->x[p]);
          gsl_matrix_set (A, n + i, (size_t) C->i[p], -C->x[p]);
        }
      gsl_matrix_set (A, n + i, n + i, active[i] ? 0.0 : 1.0);
      gsl_vector_set (b, n + i, active[i] ? -(g ? g[i] : s->sys->G[i]) : 0);
    }
  gsl_linalg_LU_decomp (A, P, &sign);
  gsl_linalg_LU_solve (A, P, b, x);
  s->counts.factorizations++;
  for (size_t j = 0; j < n; j++)
    U[j] = gsl_vector_get (x, j);
  for (size_t i = 0; i < k; i++)
    lambda[i] = gsl_vector_get (x, n + i);
  gsl_permutation_free (P);
  gsl_vector_free (x);
  gsl_vector_free (b);
  gsl_matrix_free (A);
  return LAC_SUCCESS;
}

static void
gauss_get_counts (const void *w, lac_solve_counts *c)
{
  *c = ((const gauss *) w)->counts;
}

static int
failing_factor_failed (const void *w)
{
  return ((const gauss *) w)->fail;
}

static const lac_strategy_ops gauss_ops = {
  .alloc = gauss_alloc, .free = gauss_free, .set = gauss_set,
  .solve = gauss_solve, .get_counts = gauss_get_counts
};
static const lac_strategy_type gauss_type = {
  "gauss", &gauss_ops, LAC_BODIES_ANY, 0, LAC_FACTOR_DENSE, 0, 0, { 0, 0 }
};

/* "failing": a Cholesky that always fails, falling back unasked or not. */
static const lac_strategy_ops failing_ops = {
  .alloc = failing_alloc, .free = gauss_free, .set = gauss_set,
  .solve = gauss_solve, .get_counts = gauss_get_counts,
  .factor_failed = failing_factor_failed
};
static const lac_strategy_type failing_type = {
  "failing", &failing_ops, LAC_BODIES_ANY, 0, LAC_FACTOR_CHOLESKY, 1, 0, { 0, 0 }
};
static const lac_strategy_type failing_asked_type = {
  "failing", &failing_ops, LAC_BODIES_ANY, 0, LAC_FACTOR_CHOLESKY, 0, 0, { 0, 0 }
};

/* ---- a small contact problem: t501's chain of springs ------------------- */

/* K: springs 100 between dofs 1..N-1, dof 0 fixed (diagonal 1), shift
 * added to the diagonal of dof N/2 (negative: K indefinite); F = 1 on
 * the free dofs; obstacles u_j <= g_j at six dofs. */
static void
build (double shift, lac_csc **K, double *F, lac_csc **C, double *G)
{
  static const int dof[KC] = { 5, 12, 20, 27, 33, 39 };
  static const double gap[KC] = { 10.0, 0.3, 2.0, 0.9, 5.0, 1.2 };
  lac_triplet *T = lac_triplet_alloc (N, N, 3 * N);
  lac_triplet_add (T, 0, 0, 1.0);
  for (int j = 1; j < N; j++)
    {
      lac_triplet_add (T, j, j, (j == N - 1 ? 100.0 : 200.0)
                       + (j == N / 2 ? shift : 0.0));
      if (j + 1 < N)
        {
          lac_triplet_add (T, j, j + 1, -100.0);
          lac_triplet_add (T, j + 1, j, -100.0);
        }
    }
  *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  for (int j = 0; j < N; j++)
    F[j] = j == 0 ? 0.0 : 1.0;
  T = lac_triplet_alloc (N, KC, KC);
  for (int i = 0; i < KC; i++)
    {
      lac_triplet_add (T, dof[i], i, 1.0);
      G[i] = gap[i];
    }
  *C = lac_csc_from_triplet (T);
  lac_triplet_free (T);
}

/* Algorithm 1 with the strategy s: statuses from G <= 0, solve, the
 * rule, until no status changes.  Returns the iterations (-1: failed). */
static int
active_set (lac_strategy *s, const lac_contact_system *sys, char *active,
            double *U, double *lambda)
{
  double d[KC];
  for (int i = 0; i < KC; i++)
    active[i] = sys->G[i] <= 0, lambda[i] = 0;
  memset (U, 0, N * sizeof *U);
  if (lac_strategy_set (s, sys))
    return -1;
  for (int it = 1; it <= 20; it++)
    {
      int changed = 0;
      if (lac_strategy_solve (s, active, U, lambda))
        return -1;
      lac_system_gaps (sys, U, d);
      double lmax = lac_complementarity_lmax (KC, lambda);
      for (int i = 0; i < KC; i++)
        {
          char a = (char) lac_complementarity_active (lambda[i], d[i], 1.0,
                                                      lmax, fabs (sys->G[i]));
          changed += a != active[i];
          active[i] = a;
        }
      if (!changed)
        return it;
    }
  return -1;
}

static double
rel_diff (size_t n, const double *x, const double *ref)
{
  double d = 0, m = 0;
  for (size_t i = 0; i < n; i++)
    {
      d = fmax (d, fabs (x[i] - ref[i]));
      m = fmax (m, fabs (ref[i]));
    }
  return m > 0 ? d / m : d;
}

/* ---- the checks ----------------------------------------------------------- */

/* gauss against saddle on the chain: same statuses, iterations, answer. */
static void
own_type (const lac_contact_system *sys)
{
  lac_strategy *a = lac_strategy_alloc_type (&gauss_type);
  lac_strategy *b = lac_strategy_alloc (LAC_STRATEGY_SADDLE);
  double Ua[N], Ub[N], la[KC], lb[KC];
  char sa[KC], sb[KC];
  int ita = active_set (a, sys, sa, Ua, la), itb = active_set (b, sys, sb, Ub,
                                                               lb);
  lac_strategy_counts c;
  check_true (ita > 1 && ita == itb, "gauss: %d iterations, saddle %d", ita,
              itb);
  check_true (memcmp (sa, sb, KC) == 0 && sa[1], "gauss: the statuses");
  check_true (rel_diff (N, Ua, Ub) <= 1e-12, "gauss: U %.1e",
              rel_diff (N, Ua, Ub));
  check_true (rel_diff (KC, la, lb) <= 1e-12, "gauss: lambda %.1e",
              rel_diff (KC, la, lb));
  check_true (strcmp (lac_strategy_method (a), "gauss") == 0,
              "gauss: its name");
  check_int (lac_strategy_kind_of (a), LAC_NSTRATEGIES, "gauss: not a row");
  lac_strategy_get_counts (a, &c);
  check_int (c.factorizations, c.solves + c.refinements, "gauss: counts");
  check_true (c.backward_error <= LAC_STRATEGY_TOL, "gauss: refined, %.1e",
              c.backward_error);
  lac_strategy_free (a);
  lac_strategy_free (b);
}

/* k = 0 by every type of the table against gauss. */
static void
no_contact (const lac_contact_system *with)
{
  lac_csc *C0 = lac_csc_alloc (N, 0, 0);
  lac_contact_system sys = { with->K, with->F, C0, with->G, NULL, 0, NULL,
                             NULL, NULL };
  double Uref[N] = { 0 }, U[N], lambda[1];
  lac_strategy *ref = lac_strategy_alloc_type (&gauss_type);
  check_status (lac_strategy_set (ref, &sys), LAC_SUCCESS, "k = 0: set");
  check_status (lac_strategy_solve (ref, "", Uref, lambda), LAC_SUCCESS,
                "k = 0: gauss");
  for (int k = 1; lac_strategy_table[k].name; k++)
    {
      const lac_strategy_type *t = &lac_strategy_table[k];
      if (t->processes)
        continue;                       /* MPI: t510 checks k = 0 */
      lac_strategy *s = lac_strategy_alloc (k);
      memset (U, 0, sizeof U);
      check_status (s ? lac_strategy_set (s, &sys) : LAC_ENOMEM, LAC_SUCCESS,
                    "k = 0: %s set", t->name);
      check_status (lac_strategy_solve (s, "", U, lambda), LAC_SUCCESS,
                    "k = 0: %s", t->name);
      check_true (rel_diff (N, U, Uref) <= (t->factor ? 1e-13 : 1e-8),
                  "k = 0: %s, U %.1e", t->name, rel_diff (N, U, Uref));
      lac_strategy_free (s);
    }
  lac_strategy_free (ref);
  lac_csc_free (C0);
}

/* The fallback of the table: unasked, refused, allowed; schur. */
static void
fallback (const lac_contact_system *sys, const lac_contact_system *indef)
{
  double U[N], lambda[KC], Uref[N], lref[KC];
  char active[KC];
  lac_strategy *ref = lac_strategy_alloc (LAC_STRATEGY_SADDLE);
  lac_strategy *s = lac_strategy_alloc_type (&failing_type);
  active_set (ref, sys, active, Uref, lref);
  check_true (active_set (s, sys, active, U, lambda) > 0
              && rel_diff (N, U, Uref) <= 1e-12, "falls back unasked");
  check_true (lac_strategy_fallback (s)
              && strstr (lac_strategy_fallback (s), "failing: "
                         "pretended failure; the LU of the saddle-point "
                         "system (saddle)"), "says so: %s",
              lac_strategy_fallback (s));
  check_int (lac_strategy_kind_of (s), LAC_STRATEGY_SADDLE, "saddle now");
  lac_strategy_free (s);
  s = lac_strategy_alloc_type (&failing_asked_type);
  check_true (active_set (s, sys, active, U, lambda) < 0
              && !lac_strategy_fallback (s), "no fallback unless allowed");
  check_message ("pretended failure", "the error is reported");
  lac_strategy_allow_fallback (s, 1);
  check_true (active_set (s, sys, active, U, lambda) > 0
              && lac_strategy_fallback (s), "allowed: falls back");
  lac_strategy_free (s);
  /* schur on an indefinite K: refused, or saddle's answer once allowed */
  s = lac_strategy_alloc (LAC_STRATEGY_SCHUR);
  check_status (lac_strategy_set (s, indef), LAC_ESING, "schur, indefinite");
  lac_strategy_allow_fallback (s, 1);
  check_true (active_set (s, indef, active, U, lambda) > 0
              && lac_strategy_kind_of (s) == LAC_STRATEGY_SADDLE,
              "schur falls back when allowed: %s", lac_error_message ());
  check_true (active_set (ref, indef, active, Uref, lref) > 0
              && rel_diff (N, U, Uref) <= 1e-12, "schur's fallback: U");
  lac_strategy_free (s);
  lac_strategy_free (ref);
}

/* The choice from the properties. */
static void
choice (void)
{
  check_int (lac_strategy_choose (LAC_STRATEGY_AUTO, 500, 100, 1),
             LAC_STRATEGY_DENSE, "auto: dense up to 600");
  check_int (lac_strategy_choose (LAC_STRATEGY_AUTO, 600, 1, 0),
             LAC_STRATEGY_SCHUR, "auto: schur, every body held");
  check_int (lac_strategy_choose (LAC_STRATEGY_AUTO, 600, 1, 2),
             LAC_STRATEGY_SPLIT, "auto: split, a floating body");
  check_int (lac_strategy_choose (LAC_STRATEGY_SCHUR, 10, 1, 1),
             LAC_NSTRATEGIES, "schur refused");
  check_message ("strategy schur needs every body held by its Dirichlet "
                 "conditions (K positive definite); 1 rigid motion is held "
                 "by contact alone: use dense, augmented, saddle, petsc, "
                 "split", "schur's refusal names the others");
  check_int (lac_strategy_choose (LAC_STRATEGY_SPLIT, 10, 1, 0),
             LAC_NSTRATEGIES, "split refused");
  check_message ("needs a body held by contact alone", "split's refusal");
  check_int (lac_strategy_choose (LAC_STRATEGY_AUGMENTED, 10, 1, 3),
             LAC_STRATEGY_AUGMENTED, "augmented: any");
  check_int (lac_strategy_choose (LAC_STRATEGY_SPLIT, 10, 0, 0),
             LAC_STRATEGY_SPLIT, "without contact, split too");
  {
    /* the run: processes, factor fits, dim, order, Cholesky bytes */
    const double big = LAC_STRATEGY_ITERATIVE_BYTES;
    const lac_strategy_context mpi = { 2, 1, 3, 1, 0 },
      nofit = { 1, 0, 3, 1, 0 }, one = { 1, 1, 3, 1, 0 },
      big3 = { 1, 1, 3, 1, big }, below = { 1, 1, 3, 1, 0.99 * big },
      big2 = { 1, 1, 2, 1, big }, quad3 = { 1, 1, 3, 2, 4 * big },
      big3mpi = { 2, 1, 3, 1, big };
    const struct
    {
      lac_strategy_kind want;
      size_t n, k, nfree;
      const lac_strategy_context *ctx;
      lac_strategy_kind expect;
      const char *what;
    } cases[] = {
      { LAC_STRATEGY_AUTO, 500, 100, 1, &mpi, LAC_STRATEGY_PETSC,
        "auto on 2 processes: petsc" },
      { LAC_STRATEGY_AUTO, 9000, 1, 0, &nofit, LAC_STRATEGY_PETSC,
        "auto, no factor fits: petsc" },
      { LAC_STRATEGY_AUTO, 9000, 0, 0, &nofit, LAC_STRATEGY_PETSC,
        "auto, no factor fits, no contact" },
      { LAC_STRATEGY_AUTO, 9000, 1, 2, &one, LAC_STRATEGY_SPLIT,
        "auto, one process, fits: by size" },
      { LAC_STRATEGY_SCHUR, 9000, 1, 0, &mpi, LAC_STRATEGY_SCHUR,
        "asked for: kept on 2 processes" },
      { LAC_STRATEGY_AUTO, 9000, 1, 2, &big3, LAC_STRATEGY_PETSC,
        "auto, 3D, a factor above the crossover: petsc" },
      { LAC_STRATEGY_AUTO, 9000, 0, 0, &big3, LAC_STRATEGY_PETSC,
        "... without contact too" },
      { LAC_STRATEGY_AUTO, 9000, 1, 2, &below, LAC_STRATEGY_SPLIT,
        "auto, 3D, below the crossover: by size" },
      { LAC_STRATEGY_AUTO, 9000, 1, 0, &big2, LAC_STRATEGY_SCHUR,
        "auto, 2D: by size whatever the factor" },
      { LAC_STRATEGY_AUTO, 9000, 1, 0, &quad3, LAC_STRATEGY_SCHUR,
        "auto, 3D quadratic cells: by size" },
      { LAC_STRATEGY_AUTO, 9000, 1, 0, &big3mpi, LAC_STRATEGY_PETSC,
        "auto, 2 processes: petsc" },
      { LAC_STRATEGY_SPLIT, 9000, 1, 2, &big3, LAC_STRATEGY_SPLIT,
        "asked for: kept above the crossover" },
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
      check_int (lac_strategy_choose_in (cases[c].want, cases[c].n,
                                         cases[c].k, cases[c].nfree,
                                         cases[c].ctx),
                 cases[c].expect, "%s", cases[c].what);
  }
  for (int k = 0; k < LAC_NSTRATEGIES; k++)
    check_int (lac_strategy_from_name (lac_strategy_name (k)), k,
               "name of %d", k);
  check_true (lac_strategy_type_of (LAC_STRATEGY_AUTO) == NULL
              && lac_strategy_alloc (LAC_STRATEGY_AUTO) == NULL,
              "auto is a choice, not a type");
}

int
main (void)
{
  lac_csc *K, *Ki, *C, *Ci;
  double F[N], G[KC];
  lac_init ();
  build (-250.0, &Ki, F, &Ci, G);
  build (0.0, &K, F, &C, G);
  lac_contact_system sys = { K, F, C, G, NULL, 0, NULL, NULL, NULL };
  lac_contact_system indef = { Ki, F, C, G, NULL, 0, NULL, NULL, NULL };
  own_type (&sys);
  no_contact (&sys);
  fallback (&sys, &indef);
  choice ();
  lac_csc_free (K);
  lac_csc_free (Ki);
  lac_csc_free (C);
  lac_csc_free (Ci);
  lac_finalize ();
  return check_summary ();
}
