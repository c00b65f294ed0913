/* lac_strategy.c -- solve the LAC system for a given active set
 *                   (see lac_strategy.h)          [LAC (17), Alg. 1 l. 21]
 *
 * The choice of the strategy, the dispatch to solve/lac_saddle.c (dense,
 * saddle), solve/lac_schur.c, solve/lac_augmented.c, solve/lac_split.c
 * and solve/lac_petsc.c, the check that the
 * active multipliers hold the bodies held by contact alone, the
 * refinement of every solve, and the fallback to the LU of the whole
 * system when a Cholesky factorization fails.
 */
#include "solve/lac_strategy.h"

#include <math.h>
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
#define MAX_REFINE_KRYLOV 2  /* petsc: a step costs half a solve, ...  */
#define TOL_KRYLOV 1e-11     /* ... so only above this backward error    */

struct lac_strategy
{
  lac_strategy_kind kind;          /* in use (saddle after a fallback)    */
  const lac_contact_system *sys;   /* borrowed                            */
  lac_saddle *saddle;              /* owned: dense, saddle, fallback      */
  lac_schur *schur;                /* owned: schur                        */
  lac_augmented *aug;              /* owned: augmented                    */
  lac_split *split;                /* owned: split                        */
  lac_petsc *petsc;                /* owned: petsc                        */
  double *r, *g, *dU, *dl;         /* owned: residuals and corrections    */
  size_t n, k;
  char fallback[512];              /* why the fallback happened, or ""    */
  lac_strategy_counts counts;
  lac_solve_counts before;         /* counts of a Cholesky solver replaced
                                      by saddle                           */
};

static const char *const names[LAC_NSTRATEGIES] =
  { "auto", "dense", "schur", "augmented", "saddle", "petsc", "split" };

int
lac_strategy_from_name (const char *name)
{
  for (int k = 0; name && k < LAC_NSTRATEGIES; k++)
    if (strcmp (name, names[k]) == 0)
      return k;
  return -1;
}

const char *
lac_strategy_name (lac_strategy_kind kind)
{
  return (unsigned) kind < LAC_NSTRATEGIES ? names[kind] : "unknown";
}

lac_strategy_kind
lac_strategy_choose (lac_strategy_kind want, size_t n, size_t k,
                     size_t nfree)
{
  if (want == LAC_STRATEGY_SCHUR && nfree > 0)
    {
      lac_error_set (LAC_EINVAL, "lac_strategy_choose", "strategy schur "
                     "needs every body held by its Dirichlet conditions (K "
                     "positive definite); %zu rigid motion%s held by contact "
                     "alone: use split, augmented, saddle or dense", nfree,
                     nfree == 1 ? " is" : "s are");
      return LAC_NSTRATEGIES;
    }
  if (want == LAC_STRATEGY_SPLIT && nfree == 0)
    {
      lac_error_set (LAC_EINVAL, "lac_strategy_choose", "strategy split "
                     "needs a body held by contact alone (it augments the "
                     "equations of those bodies only); every body is held "
                     "by its Dirichlet conditions: use schur, augmented, "
                     "saddle or dense");
      return LAC_NSTRATEGIES;
    }
  if (want != LAC_STRATEGY_AUTO)
    return want;
  if (n + k <= LAC_STRATEGY_DENSE_MAX)
    return LAC_STRATEGY_DENSE;
  return nfree == 0 ? LAC_STRATEGY_SCHUR : LAC_STRATEGY_SPLIT;
}

static int fall_back (lac_strategy *s);

/* ---- alloc / set / free ------------------------------------------------- */

lac_strategy *
lac_strategy_alloc (lac_strategy_kind kind)
{
  lac_strategy *s;
  if (kind <= LAC_STRATEGY_AUTO || kind >= LAC_NSTRATEGIES)
    LAC_ERROR_NULL (LAC_EINVAL, "strategy %d: choose one first "
                    "(lac_strategy_choose)", (int) kind);
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR_NULL (LAC_ENOMEM, "strategy");
  s->kind = kind;
  if (kind == LAC_STRATEGY_DENSE || kind == LAC_STRATEGY_SADDLE)
    s->saddle = lac_saddle_alloc (kind == LAC_STRATEGY_DENSE
                                  ? LAC_SOLVER_DENSE : LAC_SOLVER_UMFPACK);
  else if (kind == LAC_STRATEGY_SCHUR)
    s->schur = lac_schur_alloc ();
  else if (kind == LAC_STRATEGY_PETSC)
    s->petsc = lac_petsc_alloc (LAC_PETSC_OMEGA);
  else if (kind == LAC_STRATEGY_SPLIT)
    s->split = lac_split_alloc (LAC_AUGMENT_OMEGA);
  else
    s->aug = lac_augmented_alloc (LAC_AUGMENT_OMEGA);
  if (!s->saddle && !s->schur && !s->aug && !s->petsc && !s->split)
    {
      lac_free (s);
      return NULL;
    }
  return s;
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
  lac_saddle_free (s->saddle);
  lac_schur_free (s->schur);
  lac_augmented_free (s->aug);
  lac_split_free (s->split);
  lac_petsc_free (s->petsc);
  lac_free (s);
}

void
lac_strategy_set_coordinates (lac_strategy *s, int dim, const double *x)
{
  if (s->petsc)
    lac_petsc_set_coordinates (s->petsc, dim, x);
}

int
lac_strategy_set (lac_strategy *s, const lac_contact_system *sys)
{
  size_t n = sys->K->ncol, k = sys->C->ncol;
  double t0 = lac_seconds ();
  int status;
  if (!s->r || s->n != n || s->k != k)
    {
      free_work (s);
      s->r = lac_malloc (n * sizeof *s->r);
      s->dU = lac_malloc (n * sizeof *s->dU);
      s->g = lac_malloc ((k ? k : 1) * sizeof *s->g);
      s->dl = lac_malloc ((k ? k : 1) * sizeof *s->dl);
      if (!s->r || !s->dU || !s->g || !s->dl)
        LAC_ERROR (LAC_ENOMEM, "strategy work arrays, n = %zu", n);
      s->n = n;
      s->k = k;
    }
  s->sys = sys;
  status = s->saddle ? lac_saddle_set (s->saddle, sys)
           : s->schur ? lac_schur_set (s->schur, sys)
           : s->petsc ? lac_petsc_set (s->petsc, sys)
           : s->split ? lac_split_set (s->split, sys)
           : lac_augmented_set (s->aug, sys);
  s->counts.time_factor += lac_seconds () - t0;
  return status;
}

int
lac_strategy_reset (lac_strategy *s, const lac_contact_system *sys,
                    int *kept)
{
  *kept = s->schur && s->sys && s->n == sys->K->ncol;
  if (!*kept)
    return lac_strategy_set (s, sys);
  double t0 = lac_seconds ();
  size_t k = sys->C->ncol;
  if (s->k != k)
    {
      lac_free (s->g);
      lac_free (s->dl);
      s->g = lac_malloc ((k ? k : 1) * sizeof *s->g);
      s->dl = lac_malloc ((k ? k : 1) * sizeof *s->dl);
      if (!s->g || !s->dl)
        LAC_ERROR (LAC_ENOMEM, "strategy work arrays, k = %zu", k);
      s->k = k;
    }
  s->sys = sys;
  int status = lac_schur_reset (s->schur, sys);
  s->counts.time_solve += lac_seconds () - t0;
  return status;
}

/* ---- solve -------------------------------------------------------------- */

/* One solve of (*) with right-hand sides f, g (NULL: F, G); rtol: the
 * conjugate gradients' tolerance (augmented). */
static int
solve_once (lac_strategy *s, const char *active, const double *f,
            const double *g, double rtol, double *U, double *lambda)
{
  if (s->saddle)
    return lac_saddle_solve (s->saddle, active, f, g, U, lambda);
  if (s->schur)
    return lac_schur_solve (s->schur, active, f, g, U, lambda);
  if (s->petsc)
    return lac_petsc_solve (s->petsc, active, f, g, rtol, U, lambda);
  if (s->split)
    return lac_split_solve (s->split, active, f, g, rtol, U, lambda);
  return lac_augmented_solve (s->aug, active, f, g, rtol, U, lambda);
}

/* The factorization of K_W failed although the bodies are held: go on
 * with the LU of the whole system. */
static int
fall_back (lac_strategy *s)
{
  snprintf (s->fallback, sizeof s->fallback, "%s: %s; the LU of the "
            "saddle-point system (saddle) from now on",
            names[s->kind], lac_error_message ());
  lac_error_clear ();
  if (s->schur)
    lac_schur_get_counts (s->schur, &s->before);
  else if (s->split)
    lac_split_get_counts (s->split, &s->before);
  else
    lac_augmented_get_counts (s->aug, &s->before);
  lac_schur_free (s->schur);
  lac_augmented_free (s->aug);
  lac_split_free (s->split);
  s->schur = NULL;
  s->aug = NULL;
  s->split = NULL;
  s->kind = LAC_STRATEGY_SADDLE;
  if (!(s->saddle = lac_saddle_alloc (LAC_SOLVER_UMFPACK)))
    return LAC_ENOMEM;
  return lac_saddle_set (s->saddle, s->sys);
}

/* The counts of the Cholesky-based solver in use into *sc (unchanged
 * without one: the saddle-point LU counts apart). */
static void
inner_counts (const lac_strategy *s, lac_solve_counts *sc)
{
  if (s->schur)
    lac_schur_get_counts (s->schur, sc);
  if (s->aug)
    lac_augmented_get_counts (s->aug, sc);
  if (s->split)
    lac_split_get_counts (s->split, sc);
  if (s->petsc)
    lac_petsc_get_counts (s->petsc, sc);
}

/* Up to MAX_REFINE steps of iterative refinement on the residual of (*):
 * U += dU, lambda += dlambda while the backward error decreases. */
static int
refine (lac_strategy *s, const char *active, double *U, double *lambda)
{
  double be = lac_system_residual (s->sys, active, U, lambda, s->r, s->g);
  int steps = s->petsc ? MAX_REFINE_KRYLOV : MAX_REFINE;
  double tol = s->petsc ? TOL_KRYLOV : LAC_STRATEGY_TOL;
  for (int step = 0; step < steps && be > tol; step++)
    {
      double bnew;
      int status;
      memset (s->dU, 0, s->n * sizeof *s->dU);
      memset (s->dl, 0, s->k * sizeof *s->dl);
      if ((status = solve_once (s, active, s->r, s->g, CG_RTOL_REFINE,
                                s->dU, s->dl)))
        return status;
      for (size_t j = 0; j < s->n; j++)
        s->dU[j] += U[j];                         /* trial U + dU */
      for (size_t i = 0; i < s->k; i++)
        s->dl[i] += lambda[i];
      bnew = lac_system_residual (s->sys, active, s->dU, s->dl, s->r, s->g);
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
  if (status == LAC_ESING && ((s->aug && lac_augmented_factor_failed (s->aug))
                              || (s->split
                                  && lac_split_factor_failed (s->split))))
    {
      if (!(status = fall_back (s)))
        status = solve_once (s, active, NULL, NULL, CG_RTOL, U, lambda);
    }
  if (!status)
    {
      lac_solve_counts sc = { 0 };
      inner_counts (s, &sc);
      s->counts.last_iterations = sc.last_iterations;  /* before refine */
      s->counts.last_residual = sc.last_residual;
      status = refine (s, active, U, lambda);
    }
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

const char *
lac_strategy_method (const lac_strategy *s)
{
  return s->petsc ? lac_petsc_method (s->petsc) : names[s->kind];
}

lac_strategy_kind
lac_strategy_kind_of (const lac_strategy *s)
{
  return s->kind;
}

const char *
lac_strategy_fallback (const lac_strategy *s)
{
  return s->fallback[0] ? s->fallback : NULL;
}

void
lac_strategy_get_counts (const lac_strategy *s, lac_strategy_counts *c)
{
  lac_solve_counts sc = s->before;
  *c = s->counts;
  inner_counts (s, &sc);
  c->substitutions = sc.solves;
  c->iterations = sc.iterations;
  c->factorizations = sc.factorizations;
  c->analyses = sc.analyses;
  c->rcond = sc.rcond;
  c->time_factor = sc.time_factor;
  c->flops = sc.flops;
  if (s->saddle)
    {
      lac_solve_counts sd;
      lac_saddle_get_counts (s->saddle, &sd);
      c->factorizations += sd.factorizations;
      c->analyses += sd.analyses;
      c->rcond = sd.rcond;
      c->time_factor += sd.time_factor;
      c->flops += sd.flops;
    }
  c->time_solve = s->counts.time_solve + s->counts.time_factor
                  - c->time_factor;
}
