/* lac_split.c -- the augmented system on the bodies held by contact alone
 *                only (see lac_split.h)           [LAC (17), Alg. 1 l. 21]
 *
 * set:   the parts H and S (connected components of K, S where N moves
 *        them), K_HH, K_SS, C_H, C_S renumbered, the pattern of
 *        K_SS + C_S C_S^T;
 * solve: 1. K_HH = L L^T once per set, K~_SS for the statuses when they
 *           changed; both at the same time when both are due (the first
 *           solve after set: linalg/lac_tasks.h);
 *        2. b = G_A - C_A^T U(0);
 *        3. A lambda_A = b by GMRES preconditioned by W_A, from the given
 *           lambda_A;
 *        4. U = U(lambda_A).
 */
#include "solve/lac_split.h"

#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_gmres.h"
#include "linalg/lac_tasks.h"
#include "solve/lac_active.h"
#include "solve/lac_augmented.h"

#define GMRES_RESTART 50
#define GMRES_MAXIT 300     /* about ten are needed (lac_split.h) */
/* Unknowns in each part from which the two factorizations run side by
 * side: below, each takes milliseconds and they run one after the other
 * in the calling thread, without starting a thread for so little. */
#define SIDE_BY_SIDE_MIN 2000

/* One part of the unknowns: its dofs, its block of K, its rows of C, the
 * factor, and two vectors of its size. */
typedef struct part
{
  size_t n;                /* unknowns of the part                       */
  size_t *dof;             /* owned, n: global dof of each local one     */
  lac_csc *K, *C;          /* owned: K_PP, C_P (n x k)                   */
  lac_solver *chol;        /* owned                                      */
  double *x, *y;           /* owned, n: scratch                          */
} part;

typedef struct lac_split
{
  const lac_contact_system *sys;   /* borrowed                            */
  size_t n;
  part H, S;
  lac_csc *KS;             /* owned: K~_SS in the pattern of K_SS + C_S C_S^T */
  lac_active act;          /* owned: W and the factor of K~_SS             */
  int H_factored;          /* K_HH factorized since the last set           */
  int factor_failed;
  double *v;               /* owned, k: scratch                            */
  double *U0;              /* owned, n: U of the current product           */
  lac_solve_counts counts;
} lac_split;

static void split_free (void *w);

static void *
split_alloc (void)
{
  lac_split *s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "split solver");
  s->act.omega = LAC_AUGMENT_OMEGA;
  s->H.chol = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  s->S.chol = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  if (!s->H.chol || !s->S.chol)
    {
      split_free (s);
      return NULL;
    }
  return s;
}

static void
part_clear (part *P)
{
  lac_free (P->dof);
  lac_csc_free (P->K);
  lac_csc_free (P->C);
  lac_free (P->x);
  lac_free (P->y);
  P->dof = NULL;
  P->K = P->C = NULL;
  P->x = P->y = NULL;
  P->n = 0;
}

static void
free_arrays (lac_split *s)
{
  part_clear (&s->H);
  part_clear (&s->S);
  lac_csc_free (s->KS);
  s->KS = NULL;
  lac_active_clear (&s->act);
  lac_free (s->v);
  lac_free (s->U0);
  s->v = s->U0 = NULL;
}

static void
split_free (void *w)
{
  lac_split *s = w;
  if (!s)
    return;
  free_arrays (s);
  lac_solver_free (s->H.chol);
  lac_solver_free (s->S.chol);
  lac_free (s);
}

static void
split_get_counts (const void *w, lac_solve_counts *c)
{
  *c = ((const lac_split *) w)->counts;
}

static int
split_factor_failed (const void *w)
{
  return ((const lac_split *) w)->factor_failed;
}

/* ---- the parts ---------------------------------------------------------- */

static size_t
find_root (size_t *up, size_t j)
{
  while (up[j] != j)
    j = up[j] = up[up[j]];                        /* path halving */
  return j;
}

/* in_S[j] = 1 for the dofs of the connected components of K's graph that
 * a free rigid motion moves (the bodies held by contact alone). */
static int
floating_dofs (const lac_contact_system *sys, char *in_S)
{
  size_t n = sys->K->ncol;
  size_t *up = lac_malloc (n * sizeof *up);
  char *moved = lac_calloc (n, 1);
  if (!up || !moved)
    {
      lac_free (up);
      lac_free (moved);
      LAC_ERROR (LAC_ENOMEM, "components of K, n = %zu", n);
    }
  for (size_t j = 0; j < n; j++)
    up[j] = j;
  for (size_t j = 0; j < n; j++)                  /* union of K's edges */
    for (int p = sys->K->p[j]; p < sys->K->p[j + 1]; p++)
      {
        size_t a = find_root (up, j), b = find_root (up, sys->K->i[p]);
        if (a != b)
          up[a] = b;
      }
  for (size_t m = 0; m < sys->nfree; m++)
    for (size_t j = 0; j < n; j++)
      if (sys->N[m * n + j] != 0)
        moved[find_root (up, j)] = 1;
  for (size_t j = 0; j < n; j++)
    in_S[j] = moved[find_root (up, j)];
  lac_free (up);
  lac_free (moved);
  return LAC_SUCCESS;
}

/* The rows `loc` >= 0 of A's columns `cols` (ncols of them), renumbered:
 * loc[j] is the local index of global row j, -1 if not in the part. */
static lac_csc *
submatrix (const lac_csc *A, const long *loc, size_t nrow,
           const size_t *cols, size_t ncols)
{
  size_t nnz = 0, q = 0;
  lac_csc *B;
  for (size_t c = 0; c < ncols; c++)
    for (int p = A->p[cols ? cols[c] : c]; p < A->p[(cols ? cols[c] : c) + 1]; p++)
      nnz += loc[A->i[p]] >= 0;
  if (!(B = lac_csc_alloc (nrow, ncols, nnz ? nnz : 1)))
    return NULL;
  for (size_t c = 0; c < ncols; c++)
    {
      size_t j = cols ? cols[c] : c;
      for (int p = A->p[j]; p < A->p[j + 1]; p++)
        if (loc[A->i[p]] >= 0)
          {
            B->i[q] = (int) loc[A->i[p]];
            B->x[q++] = A->x[p];
          }
      B->p[c + 1] = (int) q;
    }
  return B;
}

/* The part of the dofs with in_S[j] == want: dofs, K_PP, C_P, vectors. */
static int
make_part (part *P, const lac_contact_system *sys, const char *in_S,
           char want, long *loc)
{
  size_t n = sys->K->ncol;
  P->n = 0;
  for (size_t j = 0; j < n; j++)
    loc[j] = in_S[j] == want ? (long) P->n++ : -1;
  P->dof = lac_malloc ((P->n ? P->n : 1) * sizeof *P->dof);
  P->x = lac_malloc ((P->n ? P->n : 1) * sizeof *P->x);
  P->y = lac_malloc ((P->n ? P->n : 1) * sizeof *P->y);
  if (!P->dof || !P->x || !P->y)
    LAC_ERROR (LAC_ENOMEM, "split solver, part of %zu unknowns", P->n);
  for (size_t j = 0; j < n; j++)
    if (loc[j] >= 0)
      P->dof[loc[j]] = j;
  P->K = submatrix (sys->K, loc, P->n, P->dof, P->n);
  P->C = P->K ? submatrix (sys->C, loc, P->n, NULL, sys->C->ncol) : NULL;
  return P->K && P->C ? LAC_SUCCESS : LAC_ENOMEM;
}

static int
alloc_arrays (lac_split *s, size_t n, size_t k)
{
  int status;
  free_arrays (s);
  if ((status = lac_active_init (&s->act, k)))
    return status;
  s->v = lac_malloc ((k ? k : 1) * sizeof *s->v);
  s->U0 = lac_malloc (n * sizeof *s->U0);
  if (!s->v || !s->U0)
    LAC_ERROR (LAC_ENOMEM, "split solver, n = %zu, k = %zu", n, k);
  s->n = n;
  return LAC_SUCCESS;
}

static int
factor (lac_split *s, lac_solver *chol, const lac_csc *A)
{
  int status = lac_solve_counts_factor (&s->counts, chol, A);
  s->factor_failed = status != LAC_SUCCESS;
  return status;
}

static int
split_set (void *w, const lac_contact_system *sys)
{
  lac_split *s = w;
  size_t n = sys->K->ncol, k = sys->C->ncol;
  char *in_S;
  long *loc;
  int status = alloc_arrays (s, n, k);
  if (status)
    return status;
  s->sys = sys;
  s->factor_failed = s->H_factored = 0;
  in_S = lac_malloc (n ? n : 1);
  loc = lac_malloc ((n ? n : 1) * sizeof *loc);
  status = !in_S || !loc ? LAC_ERRMSG (LAC_ENOMEM, "split solver, n = %zu",
                                       n)
           : floating_dofs (sys, in_S);
  if (!status)
    status = make_part (&s->H, sys, in_S, 0, loc);
  if (!status)
    status = make_part (&s->S, sys, in_S, 1, loc);
  lac_free (in_S);
  lac_free (loc);
  if (status)
    return status;
  lac_system_column_scales (sys, s->U0, s->act.s);
  if (s->S.n && !(s->KS = lac_csc_augment_pattern (s->S.K, s->S.C)))
    return LAC_ENOMEM;
  return LAC_SUCCESS;
}

/* ---- solve -------------------------------------------------------------- */

/* One factorization, a task of lac_tasks_pair. */
typedef struct
{
  lac_solver *chol;
  const lac_csc *A;
} factor_job;

static int
factor_task (void *ctx)
{
  factor_job *j = ctx;
  return lac_solver_refactor (j->chol, j->A);
}

/* K_HH and K~_SS at the same time, one core each; both counted. */
static int
factor_both (lac_split *s)
{
  factor_job h = { s->H.chol, s->H.K }, f = { s->S.chol, s->KS };
  double t0 = lac_seconds ();
  int status;
  lac_solver_set_threads (s->H.chol, 1);
  lac_solver_set_threads (s->S.chol, 1);
  status = lac_tasks_pair (factor_task, &h, factor_task, &f);
  lac_solver_set_threads (s->H.chol, 0);
  lac_solver_set_threads (s->S.chol, 0);
  s->counts.time_factor += lac_seconds () - t0;
  s->factor_failed = status != LAC_SUCCESS;
  if (status)
    return status;
  lac_solve_counts_factored (&s->counts, s->H.chol);
  lac_solve_counts_factored (&s->counts, s->S.chol);
  return LAC_SUCCESS;
}

/* 1. K_HH once per set; K~_SS = K_SS + C_S,A W_A C_S,A^T if the statuses
 *    changed; side by side when both are due and large enough. */
static int
factor_parts (lac_split *s, const char *active)
{
  int due_H = s->H.n && !s->H_factored;
  int due_S = s->S.n && lac_active_weights (&s->act, active);
  int status = LAC_SUCCESS;
  if (due_S && (status = lac_csc_augment (s->KS, s->S.K, s->S.C, s->act.w)))
    return status;
  if (due_H && due_S && s->H.n >= SIDE_BY_SIDE_MIN
      && s->S.n >= SIDE_BY_SIDE_MIN)
    status = factor_both (s);
  else
    {
      if (due_H)
        status = factor (s, s->H.chol, s->H.K);
      if (!status && due_S)
        status = factor (s, s->S.chol, s->KS);
    }
  if (status)
    return status;
  s->H_factored = s->H_factored || due_H;
  if (due_S)
    lac_active_factored (&s->act, active);
  return LAC_SUCCESS;
}

/* U = U(lambda_A) of the triangular system of lac_split.h, with the
 * right-hand sides f, g (both NULL: the homogeneous map U_0). */
static int
triangular_solve (lac_split *s, const double *f, const double *g,
                  const double *lamA, double *U)
{
  part *H = &s->H, *S = &s->S;
  const lac_active *act = &s->act;
  int status;
  for (size_t j = 0; j < H->n; j++)                      /* U_H */
    H->x[j] = f ? f[H->dof[j]] : 0.0;
  lac_active_add_C (act, H->C, lamA, H->x);
  if (H->n && (s->counts.solves++,
               (status = lac_solver_solve (H->chol, H->x, H->y))))
    return status;
  for (size_t j = 0; j < H->n; j++)
    U[H->dof[j]] = H->y[j];
  for (size_t a = 0; a < act->na; a++) /* W_A (g_A - C_H,A^T U_H) + lambda_A */
    {
      size_t i = act->idx[a];
      double cu = 0;
      for (int p = H->C->p[i]; p < H->C->p[i + 1]; p++)
        cu += H->C->x[p] * H->y[H->C->i[p]];
      s->v[a] = act->w[i] * ((g ? g[i] : 0.0) - cu) + lamA[a];
    }
  for (size_t j = 0; j < S->n; j++)                      /* U_S */
    S->x[j] = f ? f[S->dof[j]] : 0.0;
  lac_active_add_C (act, S->C, s->v, S->x);
  if (S->n && (s->counts.solves++,
               (status = lac_solver_solve (S->chol, S->x, S->y))))
    return status;
  for (size_t j = 0; j < S->n; j++)
    U[S->dof[j]] = S->y[j];
  return LAC_SUCCESS;
}

/* q = A v = C_A^T U_0(v): GMRES's operator. */
static int
product (void *ctx, const double *v, double *q)
{
  lac_split *s = ctx;
  int status = triangular_solve (s, NULL, NULL, v, s->U0);
  if (!status)
    lac_active_Ct (&s->act, s->sys->C, s->U0, q);
  return status;
}

/* z = W_A r (the column scales alone if there is no S). */
static int
precondition (void *ctx, const double *r, double *z)
{
  const lac_active *act = &((const lac_split *) ctx)->act;
  for (size_t a = 0; a < act->na; a++)
    {
      size_t i = act->idx[a];
      z[a] = act->w[i] > 0 ? act->w[i] * r[a]
             : act->s[i] > 0 ? act->omega * r[a] / act->s[i] : r[a];
    }
  return LAC_SUCCESS;
}

static int
split_solve (void *w, const char *active, const double *f, const double *g,
             double rtol, double *U, double *lambda)
{
  lac_split *s = w;
  lac_active *act = &s->act;
  lac_gmres_info info;
  int status;
  s->factor_failed = 0;
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  if ((status = factor_parts (s, active)))                /* 1. */
    return status;
  lac_active_gather (act, active, lambda);
  memset (s->v, 0, act->k * sizeof *s->v);
  if ((status = triangular_solve (s, f, g, s->v, U)))     /* 2. U(0) */
    return status;
  lac_active_rhs (act, s->sys->C, g, U);
  status = lac_gmres (act->na, product, precondition, s, act->b, act->lamA,
                      rtol, GMRES_RESTART, GMRES_MAXIT, &info);  /* 3. */
  if ((status = lac_solve_counts_krylov (&s->counts, status, info.iterations,
                                         info.residual, act->na)))
    return status;
  lac_active_scatter (act, lambda);
  return triangular_solve (s, f, g, act->lamA, U);          /* 4. */
}

const lac_strategy_ops lac_split_ops = {
  .alloc = split_alloc, .free = split_free, .set = split_set,
  .solve = split_solve, .get_counts = split_get_counts,
  .factor_failed = split_factor_failed
};
