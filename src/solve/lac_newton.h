/* lac_newton.h -- Algorithm 1: the generalized Newton / active-set loop
 *                                            [LAC §4.5, Alg. 1, (17)-(18)]
 *
 * ONE loop for every scene.  It knows the problem through a contact model
 * (solve/lac_contact_model.h: the linear model of small strain, the
 * large-deformation model) and solves the system (*) of each iteration
 * with a strategy (solve/lac_strategy.h).  The sign convention and (*)
 * are written once, in solve/lac_system.h; the status rule in
 * solve/lac_complementarity.h.
 *
 * One iteration, at the displacement U, with one multiplier lambda_m and
 * one status S_m per macro-element m of the slave surface:
 *
 *   1. evaluate the model at U [Alg. 1, lines 11, 25]: the out-of-balance
 *      force r(U), the columns C of the admissible macro-elements, their
 *      mean gaps d(U);
 *   2. the statuses [lines 26-33]: S_m = 1 (contact) iff
 *        lambda_m + rho_m d_m < 0,      rho_m = E / (h_m |T^m cap Gamma_C|)
 *      (lac_contact_model.h: rho_m d_m is a pressure, so the test does
 *      not depend on the units), with the values at the level of rounding
 *      taken as zero; in the first iteration of a run, S_m = [d_m <= 0]
 *      [lines 2-8];
 *   3. the test [line 10]: no status changed, the residual
 *        |r + C lambda| / (the force scale of the model, |C lambda|)
 *      (free dofs) and the mean gaps of the active macro-elements,
 *        max |d_m| / (h_m |T^m cap Gamma_C|),
 *      both below tol: the loop has converged, unless a macro-element
 *      without a multiplier is inside the master (see below);
 *   4. solve (*) for the statuses [lines 11-24] (the linearization of the
 *      model at U), U <- U + dU (or U <- the solution, for a model that
 *      gives U itself), lambda <- lambda_A (0 elsewhere).
 * Every iteration is a record in hist; the loop returns LAC_CONTINUE
 * after each solve and LAC_SUCCESS at the iteration that finds it
 * converged (at least one solve per loop).
 *
 * The rules.  Algorithm 1 alone can take many iterations, cycle, or fail
 * to start a body held by contact alone; six rules, each for a measured
 * reason, each a function of solve/lac_newton_rules.h switched by a bit
 * of opts.off: the held start, every multiplier active after a singular
 * first solve, the first contact, the cycle guard, the line search and
 * the inexact consistent step (nonlinear models).  With opts.off =
 * LAC_RULES_ALL the loop is the paper's (chapter 07 shows both).
 *
 * No silent penetration.  When the test of step 3 passes, the
 * macro-elements without a multiplier, and those that lost surface to
 * failed projections, are checked (solve/lac_newton_check.h): the model
 * pairs again with a longer reach and the loop goes on, or the loop
 * stops with an error naming the macro-element.
 *
 * Why a loop stops.  Converged: the statuses have settled and both
 * residuals of step 3 are below tol, a mean gap at the level of rounding
 * of what it was computed from (lac_snap) counting as closed.  Otherwise
 * the error says which of these failed: the statuses still change (raise
 * the iteration limit, load in more steps), the residual of equilibrium
 * or a mean gap (named) stays above tol with the statuses settled, or
 * the residual grew LAC_NEWTON_DIVERGED times above its best.
 *
 * Usage (the loop over iterations belongs to the caller, which reports):
 *   lac_newton *s = lac_newton_alloc (&model, &opts);
 *   lac_newton_begin (s);
 *   while ((st = lac_newton_iterate (s)) == LAC_CONTINUE)
 *     { report s->hist[s->nhist - 1] }
 *   lac_newton_free (s);
 * A linear system given directly (tests, small examples):
 *   lac_newton_solve_system (kind, &sys, maxit, tol, &s).
 *
 * Ownership: the model is borrowed and must outlive the workspace; the
 * workspace owns U, lambda, d, the statuses, the strategy, the history.
 */
#ifndef LAC_NEWTON_H
#define LAC_NEWTON_H

#include <stddef.h>
#include "solve/lac_contact_model.h"
#include "solve/lac_newton_rules.h"
#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

/* The defaults of the loop, defined here only. */
#define LAC_NEWTON_MAXIT 50     /* solves per loop                      */
#define LAC_NEWTON_TOL 1e-10    /* the test of step 3                   */
#define LAC_NEWTON_PEN_TOL 1e-2 /* penetration of a macro-element without
                                   a multiplier, in its sizes            */

typedef struct lac_newton_opts
{
  lac_strategy_kind kind;  /* how (*) is solved (auto: chosen from the
                              problem at the first solve)                */
  int maxit;               /* solves per loop (0: LAC_NEWTON_MAXIT)      */
  double tol;              /* of the test of step 3 (0: LAC_NEWTON_TOL)  */
  double rho;              /* > 0: rho_m = rho for all m; 0: E / (h |T|) */
  int frozen;              /* 1: no consistent correction of the step    */
  double pen_tol;          /* penetration of a macro-element without a
                              multiplier, in its sizes, above which the
                              loop pairs again or stops (0:
                              LAC_NEWTON_PEN_TOL; < 0: not checked)      */
  int off;                 /* the rules switched off (LAC_RULE_* bits of
                              solve/lac_newton_rules.h; 0: none)         */
} lac_newton_opts;

void lac_newton_opts_init (lac_newton_opts *o);

/* One iteration (one solve). */
typedef struct lac_newton_record
{
  int iter;              /* 1, 2, ... within the loop                      */
  int step;              /* load step (1, ...; set by the caller)          */
  double t;              /* its load factor (set by the caller)            */
  int cuts;              /* cuts of the load step so far (the caller's)    */
  size_t k;              /* columns: admissible macro-elements             */
  size_t nactive;        /* active multipliers of the solve                */
  size_t nchanged;       /* statuses changed by step 2 before the solve    */
  int damped;            /* the cycle guard limited those changes          */
  double residual;       /* step 3's residual at the start (before the
                            solve)                                        */
  double gap_residual;   /* and its mean gap of the active ones           */
  double max_penetration; /* max -d_m / |C(:,m)|_1 (a length)              */
  double backward_error; /* of the solve of (*) (lac_system.h)            */
  double du;             /* |dU| / |U| of the step                        */
  int backtracks;        /* line search: halvings before this iteration   */
  int factorizations;    /* numeric factorizations of the solve           */
  int factored;          /* the tangent was factored (else an older factor
                            preconditioned the consistent step)          */
  int cg_iterations;     /* conjugate-gradient iterations of the solve    */
  int krylov_iterations; /* petsc: Krylov iterations of its first solve,
                            or GMRES iterations of the consistent step    */
  double krylov_residual; /* and its final relative residual             */
  double start, seconds; /* lac_seconds () at the start, and the duration */
} lac_newton_record;

typedef struct lac_newton_work lac_newton_work;   /* the loop's state */

typedef struct lac_newton
{
  lac_contact_model model;  /* a copy (the model's data borrowed)         */
  lac_newton_opts opts;
  size_t n, nslot;
  double *U;             /* owned, n: displacement                        */
  double *U0, *lambda0;  /* owned, n and nslot: U and lambda when the loop
                            began (lac_newton_begin)                     */
  double *lambda;        /* owned, nslot: multiplier of macro-element m
                            (0: inactive or no column)                   */
  double *d;             /* owned, nslot: its mean gap at the last
                            evaluation (0 without a column)              */
  /* Coulomb friction (model.ntan > 0; NULL otherwise), solve/lac_friction.h:
   * active[m] is then the status INACTIVE, STICK or SLIP */
  int ntan;
  double *lambda_t;      /* owned, nslot ntan: tangential multipliers     */
  double *lambda0_t;     /* owned: the same when the loop began           */
  double *slip_conv;     /* owned, nslot ntan: the mean tangential jumps
                            of the last converged loop (0 at first): the
                            slip of a loop is measured from them         */
  double *dir;           /* owned, nslot ntan: the slip direction e       */
  char *active;          /* owned, nslot: status (1 = contact)            */
  int first;             /* no solve yet: statuses from the gaps [l. 2-8] */
  int predicted;         /* U, lambda were moved since begin (a load-step
                            predictor): a cell turned inside out at the
                            first evaluation goes back to the start      */
  int restarted;         /* the statuses did not hold a body: held start */
  size_t held_start;     /* then the multipliers of the smallest gaps
                            switched on                                  */
  size_t widened;        /* pairings widened (no silent penetration)     */
  size_t nhist, caphist;
  lac_newton_record *hist;   /* owned: every iteration of every loop      */
  size_t nhist0;         /* the first record of the current loop          */
  double residual;       /* step 3's residual at the last evaluation      */
  lac_strategy *strategy;    /* owned: solves (*)                         */
  lac_model_point pt;    /* the last evaluation (borrowed from the model) */
  double time_solve;     /* seconds in the solves, and of them:           */
  double time_factor;    /*   the strategy's factorizations,              */
  double time_frozen;    /*   its solves of the frozen system,            */
  double time_krylov;    /*   the consistent step                         */
  lac_newton_work *w;    /* owned: the internals of the loop              */
} lac_newton;

lac_newton *lac_newton_alloc (const lac_contact_model *m,
                              const lac_newton_opts *opts);
void lac_newton_free (lac_newton *s);      /* NULL allowed */

/* Begin a loop from the current U, lambda and statuses (the first one:
 * U = 0, lambda = 0). */
int lac_newton_begin (lac_newton *s);
/* One iteration: LAC_CONTINUE after a solve, LAC_SUCCESS when step 3
 * finds the loop converged, an error status otherwise (LAC_EMAXITER after
 * opts.maxit solves or when the residual diverges, with a message). */
int lac_newton_iterate (lac_newton *s);
/* Back to U, lambda and the statuses the loop began with (a failed load
 * step is cut and made again from there: solve/lac_loadstep.h). */
void lac_newton_restart (lac_newton *s);
/* begin, then iterate to the end. */
int lac_newton_solve (lac_newton *s);

size_t lac_newton_nactive (const lac_newton *s);
/* Iterations (solves) of the current loop. */
size_t lac_newton_iterations (const lac_newton *s);

/* The linear model over sys (solve/lac_linear_model.h), owned by the
 * workspace *out, and the loop to the end with strategy `kind`.  *out is
 * set also on failure (NULL only without memory). */
int lac_newton_solve_system (lac_strategy_kind kind,
                             const lac_contact_system *sys, int maxit,
                             double tol, lac_newton **out);

#endif /* LAC_NEWTON_H */
