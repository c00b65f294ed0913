/* lac_saddle.c -- LU of the whole saddle-point system (see lac_saddle.h)
 *                                                 [LAC (17), Alg. 1 l. 21]
 *
 * D A D y = D b, x = D y with the symmetric scaling D of saddle_scaling;
 * A has a fixed pattern: K, every column of C and its transpose, and the
 * diagonal of the multiplier block (1 for inactive multipliers, an
 * explicit 0 for the active ones).
 */
#include "solve/lac_saddle.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

typedef struct lac_saddle
{
  const lac_contact_system *sys;   /* borrowed                            */
  size_t n, k;
  lac_solver *solver;              /* owned: the factors of D A D          */
  char *factored_for;              /* owned, k: statuses of the factors    */
  int have_factor;
  double *D;                       /* owned, n + k: the scaling            */
  double *work;                    /* owned, 2 (n + k)                     */
  lac_solve_counts counts;         /* factorizations (solves: not counted) */
  double *rows_for;                /* owned, 2 k q + k: the P, Q and free
                                      of the factors of a law's equations
                                      (solve_rows; NULL: none)           */
} lac_saddle;

static void *
saddle_alloc (lac_solver_kind kind)
{
  lac_saddle *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "saddle-point solver");
  if (!(s->solver = lac_solver_alloc (kind)))
    {
      lac_free (s);
      return NULL;
    }
  return s;
}

static void *
saddle_alloc_dense (void)
{
  return saddle_alloc (LAC_SOLVER_DENSE);
}

static void *
saddle_alloc_lu (void)
{
  return saddle_alloc (LAC_SOLVER_UMFPACK);
}

static void
saddle_free (void *w)
{
  lac_saddle *s = w;
  if (!s)
    return;
  lac_solver_free (s->solver);
  lac_free (s->factored_for);
  lac_free (s->D);
  lac_free (s->work);
  lac_free (s->rows_for);
  lac_free (s);
}

static int
saddle_set (void *w, const lac_contact_system *sys)
{
  lac_saddle *s = w;
  size_t n = sys->K->ncol, k = sys->C->ncol;
  if (s->n != n || s->k != k || !s->D)
    {
      lac_free (s->factored_for);
      lac_free (s->D);
      lac_free (s->work);
      s->factored_for = lac_calloc (k ? k : 1, 1);
      s->D = lac_malloc ((n + k) * sizeof *s->D);
      s->work = lac_malloc (2 * (n + k) * sizeof *s->work);
      if (!s->factored_for || !s->D || !s->work)
        LAC_ERROR (LAC_ENOMEM, "saddle-point system of %zu unknowns", n + k);
    }
  s->sys = sys;
  s->n = n;
  s->k = k;
  s->have_factor = 0;               /* new numbers: factorize again */
  lac_free (s->rows_for);
  s->rows_for = NULL;
  return LAC_SUCCESS;
}

/* The scaling D: diag(K)^-1/2 on the displacements and, on multiplier i,
 * 1 / max_r |D_r C_ri|.  Without it a partly covered macro-element (its
 * column of C scales with the covered fraction delta) or a contrast of
 * Young's moduli between the bodies would make the matrix look singular
 * to the solvers' condition test although the problem is well posed. */
static void
saddle_scaling (const lac_saddle *s, const char *active)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  double *D = s->D;
  lac_csc_diag_norm1 (K, D);                       /* D = diag(K) */
  for (size_t j = 0; j < s->n; j++)
    D[j] = D[j] != 0 ? 1 / sqrt (fabs (D[j])) : 1.0;
  for (size_t i = 0; i < s->k; i++)
    {
      double cmax = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        cmax = fmax (cmax, fabs (D[C->i[p]] * C->x[p]));
      D[s->n + i] = active[i] && cmax > 0 ? 1 / cmax : 1.0;
    }
}

/* T = D K D, the displacement block of both systems below. */
static int
add_dkd (const lac_saddle *s, lac_triplet *T)
{
  const lac_csc *K = s->sys->K;
  const double *D = s->D;
  int status = LAC_SUCCESS;
  for (size_t j = 0; !status && j < s->n; j++)
    for (int p = K->p[j]; !status && p < K->p[j + 1]; p++)
      status = lac_triplet_add (T, (size_t) K->i[p], j,
                                D[K->i[p]] * K->x[p] * D[j]);
  return status;
}

/* D A D for the statuses `active` [LAC Alg. 1, lines 13-21], in the
 * fixed pattern of the header. */
static lac_csc *
saddle_matrix (const lac_saddle *s, const char *active)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  const double *D = s->D;
  size_t n = s->n, k = s->k, nnzC = (size_t) C->p[k];
  lac_triplet *T = lac_triplet_alloc (n + k, n + k,
                                      (size_t) K->p[n] + 2 * nnzC + k);
  lac_csc *A = NULL;
  int status = T ? LAC_SUCCESS : LAC_ENOMEM;
  if (!status)
    status = add_dkd (s, T);
  for (size_t i = 0; !status && i < k; i++)
    {
      status = lac_triplet_add (T, n + i, n + i, active[i] ? 0.0 : 1.0);
      for (int p = C->p[i]; !status && p < C->p[i + 1]; p++)
        {
          double c = active[i] ? -D[C->i[p]] * C->x[p] * D[n + i] : 0.0;
          status = lac_triplet_add (T, (size_t) C->i[p], n + i, c);
          if (!status)
            status = lac_triplet_add (T, n + i, (size_t) C->i[p], c);
        }
    }
  if (!status)
    A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

static int
factorize (lac_saddle *s, const char *active)
{
  lac_csc *A;
  int status;
  saddle_scaling (s, active);
  if (!(A = saddle_matrix (s, active)))
    return LAC_ENOMEM;
  status = lac_solve_counts_factor (&s->counts, s->solver, A);
  lac_csc_free (A);
  if (status == LAC_ESING)
    {
      size_t na = 0;
      for (size_t i = 0; i < s->k; i++)
        na += active[i] != 0;
      return LAC_ERRMSG (LAC_ESING, "the saddle-point system with %zu active"
                         " multipliers is singular: check the Dirichlet "
                         "conditions and the inf-sup condition [LAC (10)] "
                         "(%s)", na, lac_error_message ());
    }
  if (status)
    return status;
  memcpy (s->factored_for, active, s->k);
  s->have_factor = 1;
  lac_free (s->rows_for);           /* the factors of (*), not of a law's */
  s->rows_for = NULL;
  return LAC_SUCCESS;
}

/* Solve the factored system for the scaled right-hand side in s->work and
 * scale back: x = D y, lambda_i = 0 where `free' is not set. */
static int
solve_scaled (lac_saddle *s, const char *free, double *U, double *lambda)
{
  size_t n = s->n, k = s->k;
  const double *rhs = s->work, *D = s->D;
  double *sol = s->work + n + k;
  int status = lac_solver_solve (s->solver, rhs, sol);
  if (status)
    return status;
  for (size_t j = 0; j < n; j++)
    U[j] = D[j] * sol[j];                               /* x = D y */
  for (size_t i = 0; i < k; i++)
    lambda[i] = free[i] ? D[n + i] * sol[n + i] : 0.0;
  return LAC_SUCCESS;
}

static int
saddle_solve (void *w, const char *active, const double *f, const double *g,
              double rtol, double *U, double *lambda)
{
  lac_saddle *s = w;
  size_t n = s->n, k = s->k;
  double *rhs = s->work;
  const double *D = s->D;
  int status = LAC_SUCCESS;
  (void) rtol;
  if (!s->have_factor || s->rows_for
      || memcmp (active, s->factored_for, k) != 0)
    status = factorize (s, active);
  if (status)
    return status;
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  for (size_t j = 0; j < n; j++)                        /* D [F; -G_A; 0] */
    rhs[j] = D[j] * f[j];
  for (size_t i = 0; i < k; i++)
    rhs[n + i] = active[i] ? -D[n + i] * g[i] : 0.0;
  return solve_scaled (s, active, U, lambda);
}

/* ---- the equations of a contact law (friction) ---------------------------- */

/* The scale Dr_j of row j of a law's equations: 1 / its largest entry
 * once the columns are scaled by D (P C^T D on the displacements, Q D on
 * the multipliers).  A row of Q alone (the slip of friction: lambda_t + mu
 * e lambda_n = 0) would otherwise carry entries D_j^2, far from the
 * others, and look singular to the solver's condition test. */
static double
rows_scale (const lac_saddle *s, const lac_contact_rows *R, size_t j)
{
  const lac_csc *C = s->sys->C;
  const double *D = s->D;
  size_t n = s->n, q = (size_t) R->q, g = j / q;
  double m = 0;
  for (size_t b = 0; b < q; b++)
    {
      size_t i = g * q + b;
      double pj = fabs (R->P[j * q + b]), qj = fabs (R->Q[j * q + b]);
      for (int p = C->p[i]; pj != 0 && p < C->p[i + 1]; p++)
        m = fmax (m, pj * fabs (C->x[p] * D[C->i[p]]));
      if (R->free[i])
        m = fmax (m, qj * D[n + i]);
    }
  return m > 0 ? 1 / m : 1.0;
}

/* The entries of row j of a law's equations (lac_contact_rows), scaled by
 * Dr_j and the columns' D: -P C^T on the displacements, Q on the
 * multipliers of its group. */
static int
rows_row (const lac_saddle *s, const lac_contact_rows *R, size_t j,
          double dr, lac_triplet *T)
{
  const lac_csc *C = s->sys->C;
  const double *D = s->D;
  size_t n = s->n, q = (size_t) R->q, g = j / q;
  int status = LAC_SUCCESS;
  for (size_t b = 0; !status && b < q; b++)
    {
      size_t i = g * q + b;
      double pj = R->P[j * q + b], qj = R->Q[j * q + b];
      for (int p = C->p[i]; !status && pj != 0 && p < C->p[i + 1]; p++)
        status = lac_triplet_add (T, n + j, (size_t) C->i[p],
                                  -dr * pj * C->x[p] * D[C->i[p]]);
      if (!status && qj != 0 && R->free[i])
        status = lac_triplet_add (T, n + j, n + i, dr * qj * D[n + i]);
    }
  return status;
}

/* [D; Dr] A D of a law's equations: K, -C on the free multipliers, their
 * rows; lambda_j = 0 for the others. */
static lac_csc *
rows_matrix (const lac_saddle *s, const lac_contact_rows *R)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  const double *D = s->D;
  size_t n = s->n, k = s->k, q = (size_t) R->q;
  lac_triplet *T = lac_triplet_alloc (n + k, n + k, (size_t) K->p[n]
                                      + (2 * q + 1) * (size_t) C->p[k] + k
                                      * (q + 1));
  lac_csc *A = NULL;
  int status = T ? LAC_SUCCESS : LAC_ENOMEM;
  if (!status)
    status = add_dkd (s, T);
  for (size_t i = 0; !status && i < k; i++)
    {
      if (!R->free[i])
        {
          status = lac_triplet_add (T, n + i, n + i, 1.0);
          continue;
        }
      for (int p = C->p[i]; !status && p < C->p[i + 1]; p++)   /* -C */
        status = lac_triplet_add (T, (size_t) C->i[p], n + i,
                                  -D[C->i[p]] * C->x[p] * D[n + i]);
      if (!status)
        status = rows_row (s, R, i, s->rows_for[2 * k * q + i], T);
    }
  if (!status)
    A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

/* Factorize the system of R unless its factors are those of R already. */
static int
rows_factorize (lac_saddle *s, const lac_contact_rows *R)
{
  size_t k = s->k, kq = k * (size_t) R->q;
  if (s->rows_for && s->have_factor
      && !memcmp (s->rows_for, R->P, kq * sizeof *R->P)
      && !memcmp (s->rows_for + kq, R->Q, kq * sizeof *R->Q)
      && !memcmp (s->factored_for, R->free, k))
    return LAC_SUCCESS;
  if (!s->rows_for && !(s->rows_for = lac_malloc ((2 * kq + k + 1)
                                                  * sizeof *s->rows_for)))
    LAC_ERROR (LAC_ENOMEM, "equations of %zu multipliers", k);
  s->have_factor = 0;
  saddle_scaling (s, R->free);
  for (size_t j = 0; j < k; j++)                 /* the rows' scales Dr */
    s->rows_for[2 * kq + j] = R->free[j] ? rows_scale (s, R, j) : 1.0;
  lac_csc *A = rows_matrix (s, R);
  if (!A)
    return LAC_ENOMEM;
  int status = lac_solve_counts_factor (&s->counts, s->solver, A);
  lac_csc_free (A);
  if (status == LAC_ESING)
    return LAC_ERRMSG (LAC_ESING, "the system of the contact law's "
                       "equations is singular (%s)", lac_error_message ());
  if (status)
    return status;
  memcpy (s->rows_for, R->P, kq * sizeof *R->P);
  memcpy (s->rows_for + kq, R->Q, kq * sizeof *R->Q);
  memcpy (s->factored_for, R->free, k);
  s->have_factor = 1;
  return LAC_SUCCESS;
}

static int
saddle_solve_rows (void *w, const lac_contact_rows *R, const double *f,
                   const double *r, double *U, double *lambda)
{
  lac_saddle *s = w;
  size_t n = s->n, k = s->k;
  double *rhs = s->work;
  const double *D = s->D;
  int status = rows_factorize (s, R);
  if (status)
    return status;
  const double *Dr = s->rows_for + 2 * k * (size_t) R->q;
  f = f ? f : s->sys->F;
  r = r ? r : R->r;
  for (size_t j = 0; j < n; j++)                        /* [D F; Dr r] */
    rhs[j] = D[j] * f[j];
  for (size_t i = 0; i < k; i++)
    rhs[n + i] = R->free[i] ? Dr[i] * r[i] : 0.0;
  return solve_scaled (s, R->free, U, lambda);
}

static void
saddle_get_counts (const void *w, lac_solve_counts *c)
{
  *c = ((const lac_saddle *) w)->counts;
  c->solves = 0;                    /* substitutions of the LU: not counted */
}

const lac_strategy_ops lac_saddle_dense_ops = {
  .alloc = saddle_alloc_dense, .free = saddle_free, .set = saddle_set,
  .solve = saddle_solve, .get_counts = saddle_get_counts,
  .solve_rows = saddle_solve_rows
};
const lac_strategy_ops lac_saddle_lu_ops = {
  .alloc = saddle_alloc_lu, .free = saddle_free, .set = saddle_set,
  .solve = saddle_solve, .get_counts = saddle_get_counts,
  .solve_rows = saddle_solve_rows
};
