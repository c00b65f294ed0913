/* lac_strategy.c -- solve the LAC system for a given active set
 *                   (see lac_strategy.h)          [LAC (17), Alg. 1 l. 21]
 *
 * The table of the types, the choice, and what every type shares: the
 * check that the active multipliers hold the bodies held by contact
 * alone, the refinement of every solve, the counts, and the fallback to
 * the LU of the whole system when a Cholesky factorization fails.  The
 * operations of each type are in its own file (solve/lac_saddle.c,
 * lac_schur.c, lac_augmented.c, lac_split.c, lac_petsc.c).
 */
#include "solve/lac_strategy.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "solve/lac_saddle.h"
#include "solve/lac_augmented.h"
#include "solve/lac_schur.h"
#include "solve/lac_split.h"
#include "solve/lac_petsc.h"

#define CG_RTOL 1e-10     /* relative residual of the conjugate gradients */
#define CG_RTOL_REFINE 1e-3  /* ... in a refinement step (a correction) */
#define MAX_REFINE 3
#define MAX_REFINE_KRYLOV 2  /* no factorization: a step costs half a  */
#define TOL_KRYLOV 1e-11     /* solve, so only above this backward error */

/* Each row: name, operations, the scenes it applies to, the size up to
 * which auto takes it; what it factorizes, falls back unasked, solves on
 * the MPI processes (lac_strategy_type); every row solves both loops,
 * small strain and large deformation.  Auto takes the first row that
 * applies: on N > 1 MPI processes, or when no factor fits in memory, by
 * the properties processes and factor (lac_strategy_choose_in); in 3D
 * when a Cholesky factor would cost far more memory than the time it
 * saves over the Krylov solve, by auto_from_bytes
 * (LAC_STRATEGY_ITERATIVE_BYTES, measured in chapter 13); else by size. */
const lac_strategy_type lac_strategy_table[] = {  /* lac_strategy_kind order */
  { "auto", NULL, LAC_BODIES_ANY, 0,
    LAC_FACTOR_NONE, 0, 0, { 0, 0 } },
  { "dense", &lac_saddle_dense_ops, LAC_BODIES_ANY, LAC_STRATEGY_DENSE_MAX,
    LAC_FACTOR_DENSE, 0, 0, { 0, 0 } },
  { "schur", &lac_schur_ops, LAC_BODIES_HELD, SIZE_MAX,
    LAC_FACTOR_CHOLESKY, 0, 0, { 0, 0 } },
  { "augmented", &lac_augmented_ops, LAC_BODIES_ANY, 0,
    LAC_FACTOR_CHOLESKY, 1, 0, { 0, 0 } },
  { "saddle", &lac_saddle_lu_ops, LAC_BODIES_ANY, 0,
    LAC_FACTOR_LU, 0, 0, { 0, 0 } },
  { "petsc", &lac_petsc_ops, LAC_BODIES_ANY, 0,
    LAC_FACTOR_NONE, 0, 1, { LAC_STRATEGY_ITERATIVE_BYTES, 0 } },
  { "split", &lac_split_ops, LAC_BODIES_FLOATING, SIZE_MAX,
    LAC_FACTOR_CHOLESKY, 1, 0, { 0, 0 } },
  { NULL, NULL, LAC_BODIES_ANY, 0, LAC_FACTOR_NONE, 0, 0, { 0, 0 } }
};

/* The type every failed Cholesky factorization falls back to. */
#define FALLBACK (&lac_strategy_table[LAC_STRATEGY_SADDLE])

struct lac_strategy
{
  const lac_strategy_type *type;   /* borrowed: in use (the fallback's)   */
  void *w;                         /* owned: the type's workspace         */
  int allow_fallback;              /* also for types that do not unasked  */
  const lac_contact_system *sys;   /* borrowed                            */
  double *r, *g, *dU, *dl;         /* owned: residuals and corrections    */
  size_t n, k;
  char fallback[512];              /* why the fallback happened, or ""    */
  lac_strategy_counts counts;
  lac_solve_counts before;         /* counts of the type replaced by the
                                      fallback                            */
};

/* ---- the table ---------------------------------------------------------- */

int
lac_strategy_from_name (const char *name)
{
  for (int k = 0; name && k < LAC_NSTRATEGIES; k++)
    if (strcmp (name, lac_strategy_table[k].name) == 0)
      return k;
  return -1;
}

const char *
lac_strategy_name (lac_strategy_kind kind)
{
  return (unsigned) kind < LAC_NSTRATEGIES ? lac_strategy_table[kind].name
                                           : "unknown";
}

const lac_strategy_type *
lac_strategy_type_of (int kind)
{
  return kind > LAC_STRATEGY_AUTO && kind < LAC_NSTRATEGIES
         ? &lac_strategy_table[kind] : NULL;
}

/* Does type t solve a system with nfree rigid motions left free? */
static int
applies (const lac_strategy_type *t, size_t nfree)
{
  return t->bodies == LAC_BODIES_ANY
         || (t->bodies == LAC_BODIES_HELD) == (nfree == 0);
}

/* t refused for nfree rigid motions; the message names those that do. */
static lac_strategy_kind
refuse (const lac_strategy_type *t, size_t nfree)
{
  char use[200] = "";
  for (int k = 1; k < LAC_NSTRATEGIES; k++)
    if (applies (&lac_strategy_table[k], nfree))
      snprintf (use + strlen (use), sizeof use - strlen (use), "%s%s",
                *use ? ", " : "", lac_strategy_table[k].name);
  if (t->bodies == LAC_BODIES_HELD)
    lac_error_set (LAC_EINVAL, "lac_strategy_choose", "strategy %s needs "
                   "every body held by its Dirichlet conditions (K positive"
                   " definite); %zu rigid motion%s held by contact alone: "
                   "use %s", t->name, nfree, nfree == 1 ? " is" : "s are",
                   use);
  else
    lac_error_set (LAC_EINVAL, "lac_strategy_choose", "strategy %s needs a "
                   "body held by contact alone (it augments the equations "
                   "of those bodies only); every body is held by its "
                   "Dirichlet conditions: use %s", t->name, use);
  return LAC_NSTRATEGIES;
}

/* Does the run ctx take row t before the sizes: on N > 1 processes, a
 * row that solves on them; when no factor fits, one that factorizes
 * nothing; in 3D, one whose auto_from_bytes for the cells' order the
 * estimated Cholesky run reaches? */
static int
run_takes (const lac_strategy_type *t, const lac_strategy_context *ctx)
{
  if (ctx->processes > 1)
    return t->processes;
  if (!ctx->factor_fits)
    return t->factor == LAC_FACTOR_NONE;
  double from = ctx->order == 1 || ctx->order == 2
                ? t->auto_from_bytes[ctx->order - 1] : 0;
  return ctx->dim == 3 && from > 0 && ctx->cholesky_bytes >= from;
}

/* Auto in the run ctx: the first row that applies and the run takes
 * (run_takes); -1 if none (or no ctx). */
static int
choose_for_run (size_t k, size_t nfree, const lac_strategy_context *ctx)
{
  for (int j = 1; ctx && j < LAC_NSTRATEGIES; j++)
    {
      const lac_strategy_type *t = &lac_strategy_table[j];
      if ((k == 0 || applies (t, nfree)) && run_takes (t, ctx))
        return j;
    }
  return -1;
}

lac_strategy_kind
lac_strategy_choose (lac_strategy_kind want, size_t n, size_t k,
                     size_t nfree)
{
  return lac_strategy_choose_in (want, n, k, nfree, NULL);
}

lac_strategy_kind
lac_strategy_choose_in (lac_strategy_kind want, size_t n, size_t k,
                        size_t nfree, const lac_strategy_context *ctx)
{
  const lac_strategy_type *t = lac_strategy_type_of (want);
  int j;
  if (t)                         /* without contact (k = 0) any type */
    return k == 0 || applies (t, nfree) ? want : refuse (t, nfree);
  if (want != LAC_STRATEGY_AUTO)
    return want;
  if ((j = choose_for_run (k, nfree, ctx)) > 0)
    return (lac_strategy_kind) j;
  for (j = 1; j < LAC_NSTRATEGIES; j++)
    if (n + k <= lac_strategy_table[j].auto_upto
        && applies (&lac_strategy_table[j], nfree))
      return (lac_strategy_kind) j;
  return LAC_STRATEGY_SADDLE;          /* not reached with the table above */
}

lac_strategy_kind
lac_strategy_choose_factor (lac_strategy_factor factor, size_t nfree)
{
  for (int j = 1; j < LAC_NSTRATEGIES; j++)
    if (lac_strategy_table[j].factor == factor
        && applies (&lac_strategy_table[j], nfree))
      return (lac_strategy_kind) j;
  return LAC_STRATEGY_SADDLE;
}

/* ---- alloc / set / free ------------------------------------------------- */

lac_strategy *
lac_strategy_alloc_type (const lac_strategy_type *type)
{
  lac_strategy *s;
  if (!type || !type->ops)
    LAC_ERROR_NULL (LAC_EINVAL, "strategy %s: choose one first "
                    "(lac_strategy_choose)", type ? type->name : "NULL");
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR_NULL (LAC_ENOMEM, "strategy");
  s->type = type;
  if (!(s->w = type->ops->alloc ()))
    {
      lac_free (s);
      return NULL;
    }
  return s;
}

lac_strategy *
lac_strategy_alloc (lac_strategy_kind kind)
{
  const lac_strategy_type *t = lac_strategy_type_of (kind);
  if (!t)
    LAC_ERROR_NULL (LAC_EINVAL, "strategy %d: choose one first "
                    "(lac_strategy_choose)", (int) kind);
  return lac_strategy_alloc_type (t);
}

void
lac_strategy_allow_fallback (lac_strategy *s, int allow)
{
  s->allow_fallback = allow;
}

static void
free_work (lac_strategy *s)
{
  lac_free (s->r);
  lac_free (s->g);
  lac_free (s->dU);
  lac_free (s->dl);
  s->r = s->g = s->dU = s->dl = NULL;
}

void
lac_strategy_free (lac_strategy *s)
{
  if (!s)
    return;
  free_work (s);
  s->type->ops->free (s->w);
  lac_free (s);
}

void
lac_strategy_set_coordinates (lac_strategy *s, int dim, const double *x)
{
  if (s->type->ops->set_coordinates)
    s->type->ops->set_coordinates (s->w, dim, x);
}

void
lac_strategy_set_mesh (lac_strategy *s, const struct lac_dist_source *src)
{
  if (s->type->ops->set_mesh)
    s->type->ops->set_mesh (s->w, src);
}

int
lac_strategy_kmul (lac_strategy *s, size_t n, const double *x, double *y)
{
  int zero = 1;
  for (size_t j = 0; zero && j < n; j++)
    zero = x[j] == 0;
  if (zero)                 /* K 0 = 0, before any set too (U = 0) */
    {
      memset (y, 0, n * sizeof *y);
      return LAC_SUCCESS;
    }
  if (!s->type->ops->kmul)
    LAC_ERROR (LAC_EINVAL, "the strategy %s holds no K", s->type->name);
  return s->type->ops->kmul (s->w, x, y);
}

int
lac_strategy_knorm (const lac_strategy *s, double *norm)
{
  *norm = 0;
  if (!s->type->ops->knorm)
    LAC_ERROR (LAC_EINVAL, "the strategy %s holds no K", s->type->name);
  return s->type->ops->knorm (s->w, norm);
}

int
lac_strategy_posts (const lac_strategy *s)
{
  lac_strategy_counts c;
  if (!s->type->ops->post || !s->type->ops->own_k)
    return 0;
  lac_strategy_get_counts (s, &c);
  return c.processes > 1 && s->type->ops->own_k (s->w, s->n);
}

int
lac_strategy_post (lac_strategy *s, struct lac_post_request *p)
{
  if (!lac_strategy_posts (s))
    LAC_ERROR (LAC_EINVAL, "the strategy %s holds no cells on several "
               "processes", s->type->name);
  return s->type->ops->post (s->w, p);
}

int
lac_strategy_own_k (const lac_strategy *s, size_t n)
{
  return s->type->ops->kmul && s->type->ops->knorm && s->type->ops->own_k
         && s->type->ops->own_k (s->w, n);
}

/* The residuals and corrections for n displacements, k multipliers. */
static int
work_arrays (lac_strategy *s, size_t n, size_t k)
{
  if (s->r && s->n == n && s->k == k)
    return LAC_SUCCESS;
  free_work (s);
  s->r = lac_malloc (n * sizeof *s->r);
  s->dU = lac_malloc (n * sizeof *s->dU);
  s->g = lac_malloc ((k ? k : 1) * sizeof *s->g);
  s->dl = lac_malloc ((k ? k : 1) * sizeof *s->dl);
  if (!s->r || !s->dU || !s->g || !s->dl)
    LAC_ERROR (LAC_ENOMEM, "strategy work arrays, n = %zu, k = %zu", n, k);
  s->n = n;
  s->k = k;
  return LAC_SUCCESS;
}

/* Did the last error come from a Cholesky factorization that may fall
 * back (the type does it unasked, or the caller allowed it)? */
static int
may_fall_back (const lac_strategy *s, int status)
{
  const lac_strategy_ops *ops = s->type->ops;
  return status == LAC_ESING && ops->factor_failed
         && (s->type->falls_back || s->allow_fallback)
         && ops->factor_failed (s->w);
}

/* The factorization failed although the bodies are held: go on with
 * the LU of the whole system, set on the system. */
static int
fall_back (lac_strategy *s)
{
  void *w;
  snprintf (s->fallback, sizeof s->fallback, "%s: %s; the LU of the "
            "saddle-point system (%s) from now on", s->type->name,
            lac_error_message (), FALLBACK->name);
  lac_error_clear ();
  if (!(w = FALLBACK->ops->alloc ()))
    return LAC_ENOMEM;
  s->type->ops->get_counts (s->w, &s->before);
  s->type->ops->free (s->w);
  s->type = FALLBACK;
  s->w = w;
  return s->type->ops->set (s->w, s->sys);
}

int
lac_strategy_set (lac_strategy *s, const lac_contact_system *sys)
{
  double t0 = lac_seconds ();
  int status = work_arrays (s, lac_system_n (sys), sys->C->ncol);
  if (status)
    return status;
  s->sys = sys;
  status = s->type->ops->set (s->w, sys);
  if (may_fall_back (s, status))
    status = fall_back (s);
  s->counts.time_factor += lac_seconds () - t0;
  return status;
}

int
lac_strategy_reset (lac_strategy *s, const lac_contact_system *sys,
                    int same_columns, int *kept)
{
  *kept = s->type->ops->reset && s->sys && s->n == lac_system_n (sys);
  if (!*kept)
    return lac_strategy_set (s, sys);
  int keep = same_columns && s->type->ops->keep && s->k == sys->C->ncol;
  double t0 = lac_seconds ();
  int status = work_arrays (s, lac_system_n (sys), sys->C->ncol);
  s->sys = sys;
  if (!status)
    status = keep ? s->type->ops->keep (s->w, sys)
                  : s->type->ops->reset (s->w, sys);
  s->counts.time_solve += lac_seconds () - t0;
  return status;
}

/* ---- solve -------------------------------------------------------------- */

/* One solve of (*) by the type, right-hand sides f, g (NULL: F, G);
 * rtol: the tolerance of an inner Krylov method. */
static int
solve_once (lac_strategy *s, const char *active, const double *f,
            const double *g, double rtol, double *U, double *lambda)
{
  return s->type->ops->solve (s->w, active, f, g, rtol, U, lambda);
}

/* Up to MAX_REFINE steps of iterative refinement on the residual of (*):
 * U += dU, lambda += dlambda while the backward error decreases. */
static int
refine (lac_strategy *s, const char *active, double *U, double *lambda)
{
  double be;
  int status = lac_system_residual (s->sys, active, U, lambda, s->r, s->g,
                                    &be);
  if (status)
    return status;
  int krylov = s->type->factor == LAC_FACTOR_NONE;
  int steps = krylov ? MAX_REFINE_KRYLOV : MAX_REFINE;
  double tol = krylov ? TOL_KRYLOV : LAC_STRATEGY_TOL;
  for (int step = 0; step < steps && be > tol; step++)
    {
      double bnew;
      memset (s->dU, 0, s->n * sizeof *s->dU);
      memset (s->dl, 0, s->k * sizeof *s->dl);
      if ((status = solve_once (s, active, s->r, s->g, CG_RTOL_REFINE,
                                s->dU, s->dl)))
        return status;
      for (size_t j = 0; j < s->n; j++)
        s->dU[j] += U[j];                         /* trial U + dU */
      for (size_t i = 0; i < s->k; i++)
        s->dl[i] += lambda[i];
      if ((status = lac_system_residual (s->sys, active, s->dU, s->dl, s->r,
                                         s->g, &bnew)))
        return status;
      s->counts.refinements++;
      if (!(bnew < be))
        break;                                    /* no better: keep U */
      memcpy (U, s->dU, s->n * sizeof *U);
      memcpy (lambda, s->dl, s->k * sizeof *lambda);
      be = bnew;
    }
  s->counts.backward_error = be;
  return LAC_SUCCESS;
}

int
lac_strategy_solve (lac_strategy *s, const char *active, double *U,
                    double *lambda)
{
  double t0 = lac_seconds ();
  int status;
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_strategy_set was not called");
  if ((status = lac_system_check_held (s->sys, active)))
    return status;
  s->counts.solves++;
  status = solve_once (s, active, NULL, NULL, CG_RTOL, U, lambda);
  if (may_fall_back (s, status) && !(status = fall_back (s)))
    status = solve_once (s, active, NULL, NULL, CG_RTOL, U, lambda);
  if (!status)
    {
      lac_solve_counts sc;
      s->type->ops->get_counts (s->w, &sc);
      s->counts.last_iterations = sc.last_iterations;  /* before refine */
      s->counts.last_residual = sc.last_residual;
      status = refine (s, active, U, lambda);
    }
  s->counts.time_solve += lac_seconds () - t0;
  return status;
}

int
lac_strategy_solves_rows (lac_strategy_kind kind)
{
  return kind > LAC_STRATEGY_AUTO && kind < LAC_NSTRATEGIES
         && lac_strategy_table[kind].ops->solve_rows != NULL;
}

/* The names of the types that solve the equations of a contact law. */
static void
rows_types (char *buf, size_t size)
{
  size_t n = 0;
  buf[0] = '\0';
  for (int k = 1; k < LAC_NSTRATEGIES; k++)
    if (lac_strategy_solves_rows ((lac_strategy_kind) k) && n < size)
      n += (size_t) snprintf (buf + n, size - n, "%s%s", n ? ", " : "",
                              lac_strategy_table[k].name);
}

/* Refinement of a solve of the equations R, as refine (). */
static int
refine_rows (lac_strategy *s, const lac_contact_rows *R, double *U,
             double *lambda)
{
  double be;
  int status = lac_system_rows_residual (s->sys, R, U, lambda, s->r, s->g,
                                         &be);
  for (int step = 0; !status && step < MAX_REFINE
                     && be > LAC_STRATEGY_TOL; step++)
    {
      double bnew;
      memset (s->dU, 0, s->n * sizeof *s->dU);
      memset (s->dl, 0, s->k * sizeof *s->dl);
      if ((status = s->type->ops->solve_rows (s->w, R, s->r, s->g, s->dU,
                                              s->dl)))
        return status;
      for (size_t j = 0; j < s->n; j++)
        s->dU[j] += U[j];
      for (size_t i = 0; i < s->k; i++)
        s->dl[i] += lambda[i];
      if ((status = lac_system_rows_residual (s->sys, R, s->dU, s->dl, s->r,
                                              s->g, &bnew)))
        return status;
      s->counts.refinements++;
      if (!(bnew < be))
        break;
      memcpy (U, s->dU, s->n * sizeof *U);
      memcpy (lambda, s->dl, s->k * sizeof *lambda);
      be = bnew;
    }
  s->counts.backward_error = be;
  return status;
}

int
lac_strategy_solve_rows (lac_strategy *s, const lac_contact_rows *R,
                         double *U, double *lambda)
{
  double t0 = lac_seconds ();
  char names[128];
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_strategy_set was not called");
  if (!s->type->ops->solve_rows)
    {
      rows_types (names, sizeof names);
      LAC_ERROR (LAC_EINVAL, "the strategy %s does not solve the equations "
                 "of friction (its slip makes the system unsymmetric): "
                 "take %s", s->type->name, names);
    }
  s->counts.solves++;
  int status = s->type->ops->solve_rows (s->w, R, NULL, NULL, U, lambda);
  if (!status)
    status = refine_rows (s, R, U, lambda);
  s->counts.time_solve += lac_seconds () - t0;
  return status;
}

int
lac_strategy_solve_rhs (lac_strategy *s, const char *active, const double *f,
                        const double *g, double *U, double *lambda)
{
  double t0 = lac_seconds ();
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_strategy_set was not called");
  s->counts.solves++;
  int status = solve_once (s, active, f, g, CG_RTOL, U, lambda);
  s->counts.time_solve += lac_seconds () - t0;
  return status;
}

/* ---- what it is, what it did -------------------------------------------- */

const char *
lac_strategy_method (const lac_strategy *s)
{
  return s->type->ops->method ? s->type->ops->method (s->w) : s->type->name;
}

const lac_strategy_type *
lac_strategy_get_type (const lac_strategy *s)
{
  return s->type;
}

lac_strategy_kind
lac_strategy_kind_of (const lac_strategy *s)
{
  for (int k = 1; k < LAC_NSTRATEGIES; k++)
    if (s->type == &lac_strategy_table[k])
      return (lac_strategy_kind) k;
  return LAC_NSTRATEGIES;
}

const char *
lac_strategy_fallback (const lac_strategy *s)
{
  return s->fallback[0] ? s->fallback : NULL;
}

void
lac_strategy_get_counts (const lac_strategy *s, lac_strategy_counts *c)
{
  const lac_solve_counts *b = &s->before;
  lac_solve_counts sc;
  s->type->ops->get_counts (s->w, &sc);
  *c = s->counts;
  c->substitutions = b->solves + sc.solves;
  c->iterations = b->iterations + sc.iterations;
  c->factorizations = b->factorizations + sc.factorizations;
  c->analyses = b->analyses + sc.analyses;
  c->rcond = sc.rcond;
  c->time_factor = b->time_factor + sc.time_factor;
  c->flops = b->flops + sc.flops;
  c->processes = sc.processes > 0 ? sc.processes : 1;
  c->time_solve = s->counts.time_solve + s->counts.time_factor
                  - c->time_factor;
}
