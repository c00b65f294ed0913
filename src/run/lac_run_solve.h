/* lac_run_solve.h -- stage 5 of a linear run: the solution
 *                                             [LAC (8), §4.5, Alg. 1]
 * In:  the scene ([scene] solver; [contact] strategy, max_iterations), the
 *      system of stage 4, a strategy asked for on the command line (or
 *      LAC_STRATEGY_AUTO: the scene's).
 * Out: the displacement U; with contact, the multipliers, mean gaps,
 *      statuses and the history of the active set (solve/lac_newton.h).
 * Without contact, K U = b is solved once by the scene's solver (dense,
 * umfpack, cholmod), or by the strategy asked for on the command line
 * with no multiplier (k = 0; --strategy petsc: conjugate gradients and
 * algebraic multigrid on the MPI processes), or, with neither asked for,
 * by the one auto takes in the run ctx when it factorizes nothing (N > 1
 * MPI processes, or a factor that does not fit: petsc).  With contact,
 * the strategy is chosen from the problem and the run (solve/lac_strategy.h:
 * the MPI processes, the memory, the size, and whether a body is held by
 * contact alone) and each call does ONE active-set
 * iteration, returning LAC_CONTINUE with a progress line about it until
 * the statuses settle.
 */
#ifndef LAC_RUN_SOLVE_H
#define LAC_RUN_SOLVE_H

#include <stddef.h>
#include "io/lac_scene.h"
#include "run/lac_run_setup.h"
#include "run/lac_run_system.h"
#include "run/lac_summary.h"
#include "solve/lac_linear_model.h"
#include "solve/lac_newton.h"

typedef struct lac_run_solution
{
  double *u;                   /* owned, ndof: the displacement            */
  lac_newton *newton;          /* owned, with [contact]: Algorithm 1       */
  lac_linear_model lin;        /* its model (solve/lac_linear_model.h)     */
  lac_contact_system cs;       /* (*) as the model borrows it; points into
                                  the system of stage 4                    */
  lac_strategy_kind strategy;  /* with [contact]: the one chosen           */
  double rcond;                /* without contact: K's condition estimate   */
  int krylov;                  /* 1: by a strategy that factorizes nothing  */
  int krylov_iterations;       /* its Krylov iterations, all solves         */
  double krylov_residual;      /* the true relative residual of the last
                                  solve (before refinement)                */
  int processes;               /* MPI processes that solved                 */
  const char *why;             /* static: why auto took the strategy from
                                  the run (ctx), for the progress line;
                                  NULL when by size or asked for           */
  lac_stiffness_op kop;        /* K for the residuals when the strategy
                                  holds it (petsc): the system's K freed  */
  lac_strategy *kst;           /* borrowed: the strategy kop asks for K x
                                  and ||K||_inf, and stage 6 for the
                                  stresses on its processes (the newton's,
                                  or `plain`)                              */
  char step[96];               /* "load step k of n (...): " before the
                                  message of a failed loop, or ""         */
  lac_strategy *plain;         /* owned: the strategy of a scene without
                                  contact, kept for stage 6 when it holds
                                  the cells (lac_strategy_posts); the
                                  system it was set with is gone, so only
                                  _posts, _post and _free may be called  */
} lac_run_solution;

/* LAC_CONTINUE after an active-set iteration, LAC_SUCCESS when done.
 * The set-up's pairing and the system's contact data are replaced when
 * the loop pairs again (lac_newton.h: no silent penetration). */
int lac_run_solve (const lac_scene *sc, int strategy,
                   const lac_strategy_context *ctx, lac_run_setup *setup,
                   lac_run_system *sys, lac_run_solution *sol,
                   char *progress, size_t size);
void lac_run_solution_clear (lac_run_solution *sol);
/* 1 if the strategy lac_run_solve will take (the same choice, from the
 * system of stage 4 before its K) assembles K from the cells itself
 * (petsc: lac_strategy_own_k), so that stage 4 need not keep K
 * (lac_run_system_stiffness). */
int lac_run_solve_k_from_cells (const lac_scene *sc, int strategy,
                                const lac_strategy_context *ctx,
                                const lac_run_setup *setup,
                                const lac_run_system *sys);
/* The summary lines of a strategy that factorizes nothing (processes,
 * solver_iterations, solver_residual); nothing for the direct ones. */
int lac_run_solve_summary (const lac_run_solution *sol, lac_summary *sum);
/* The same for the strategy s of a large-deformation loop (NULL:
 * nothing). */
int lac_run_strategy_summary (const lac_strategy *s, lac_summary *sum);

#endif /* LAC_RUN_SOLVE_H */
