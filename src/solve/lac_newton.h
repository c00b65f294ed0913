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
 *   4. solve (*) for the statuses [lines 11-23] (the linearization of the
 *      model at U), U <- U + dU (or U <- the solution, for a model that
 *      gives U itself), lambda <- lambda_A (0 elsewhere).
 * Every iteration is a record in hist; the loop returns LAC_CONTINUE
 * after each solve and LAC_SUCCESS at the iteration that finds it
 * converged (at least one solve per loop).
 *
 * Heuristics, each for a measured reason:
 *   - held start: when the statuses of the first iteration of a loop do
 *     not hold a body held by contact alone (its stiffness alone is
 *     singular), the multipliers of the smallest gaps are switched on, 1,
 *     2, 4, ... of them until they hold every body (restarted,
 *     held_start); from every multiplier active, the rule released the
 *     elements in tension a ring at a time: 19/22/24 iterations for the
 *     sphere on a rigid flat of chapter 10 (tet10 levels 0/1/2) against
 *     3/5/5;
 *   - first contact: when the first solve of a loop had no active
 *     multiplier (bodies apart), or only those of a held start, only the
 *     elements that penetrate by at least LAC_NEWTON_FIRST_CONTACT
 *     (LAC_NEWTON_HELD_CONTACT) times the deepest penetration are
 *     switched on: for a pressed paraboloid the contact radius is where
 *     the overlap is half the deepest (Hertz), so the overlap, wider than
 *     the contact zone, is not taken whole and released half an excess
 *     per iteration;
 *   - cycle guard: the statuses of every iteration are remembered (a
 *     checksum); when the rule would return to statuses already tried,
 *     only the most violated half of its changes is made (damped);
 *   - line search (a nonlinear model only): a Newton step that turns a
 *     cell inside out, or that was made on settled statuses and does not
 *     lower max(residual, gap residual), is halved, up to
 *     LAC_NEWTON_HALVINGS times; a residual LAC_NEWTON_DIVERGED times
 *     above the best of the loop is a failure;
 *   - inexact consistent step (a model with a consistent op): the step is
 *     accurate to eta = 1e-2 times the residual (in [1e-12, 1e-3]; 1e-5
 *     in the first iteration of a loop), and the factorization of an
 *     earlier tangent is kept (schur) while GMRES needs at most
 *     LAC_NEWTON_LAG iterations (about half a factorization).
 *
 * No silent penetration.  When the test of step 3 passes, the model says
 * how deep the macro-elements WITHOUT a multiplier (not paired, or not
 * admissible) are inside the master at U (lac_contact_model.h,
 * uncovered).  Deeper than opts.pen_tol times their size: the model pairs
 * again with a reach of 2 max |U| + that depth (widen) and the loop goes
 * on with the new multipliers; if that gains nothing, the loop stops with
 * an error naming the macro-element, where it is and how deep.  Likewise
 * an active macro-element that lost part of its surface to failed
 * projections of the pairing is an error.
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
#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

/* Fraction of the deepest penetration switched on at the first contact. */
#define LAC_NEWTON_FIRST_CONTACT 0.5
/* The same after a held start: the first solve pressed the bodies on a
 * few elements, its penetrations are those of a load concentrated there,
 * not of a rigid approach; the zone is grown from its deepest elements
 * instead (measured on chapter 10's sphere on a rigid flat, tet10 levels
 * 0/1/2: 7/10/- active-set iterations with 0.5, 4/6/8 with 0.9, 3/5/5
 * with 0.95, 7/6/5 with 0.99). */
#define LAC_NEWTON_HELD_CONTACT 0.95
#define LAC_NEWTON_HALVINGS 4   /* line search: a step halved at most   */
#define LAC_NEWTON_DIVERGED 1e3 /* residual / the loop's best: failure  */
#define LAC_NEWTON_LAG 6        /* GMRES iterations that keep an older
                                   factorization: about half of one (one
                                   costs 12 iterations on the coarse hex20
                                   ring, 13 on the fine one)             */

typedef struct lac_newton_opts
{
  lac_strategy_kind kind;  /* how (*) is solved (auto: chosen from the
                              problem at the first solve)                */
  int maxit;               /* solves per loop (0: 50)                    */
  double tol;              /* of the test of step 3 (0: 1e-10)           */
  double rho;              /* > 0: rho_m = rho for all m; 0: E / (h |T|) */
  int frozen;              /* 1: no consistent correction of the step    */
  double pen_tol;          /* penetration of a macro-element without a
                              multiplier, in its sizes, above which the
                              loop pairs again or stops (0: 1e-2; < 0:
                              not checked)                               */
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
