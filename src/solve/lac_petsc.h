/* lac_petsc.h -- the LAC system of one active set by Krylov methods and
 *                algebraic multigrid (PETSc), on one or N processes
 *                                                 [LAC (17), Alg. 1 l. 21]
 *
 * Strategy (e) of solve/lac_strategy.h, for the 3D meshes whose Cholesky
 * factor does not fit in memory (a 1,029,000-dof hex8 cube needs 20.5 GB,
 * chapter 10).  It solves the augmented form of (*) of
 * solve/lac_system.h (solve/lac_augmented.h: adding C_A W_A times the
 * constraint changes neither U nor lambda),
 *
 *   [ K_W    -C_A ] [ U        ]   [ f + C_A W_A g_A ]
 *   [ -C_A^T   0  ] [ lambda_A ] = [ -g_A            ],           (*W)
 *
 *   K_W = K + C_A W_A C_A^T,   W_i = omega / s_i,  s_i = c_i^T diag(K)^-1 c_i,
 *
 * where K_W is positive definite as soon as the active multipliers hold
 * every body (lac_system_check_held), with no dense Schur complement:
 *
 *   fieldsplit (default)  flexible GMRES on the whole of (*W), right
 *      preconditioned by the block factorization of PCFIELDSPLIT (Schur
 *      type, "upper"): K_W by one V-cycle of smoothed-aggregation
 *      multigrid (PCGAMG), the Schur complement S_W = C_A^T K_W^-1 C_A
 *      by W_A^-1: S_W^-1 = S^-1 + W_A lies between W_A and W_A + 1/s_min
 *      (lac_augmented.h), so W_A is a good inverse when omega is not
 *      small.  The inactive multipliers are rows lambda_i = 0, so that
 *      the matrices keep their size and pattern when the statuses change
 *      and the multigrid hierarchy is rebuilt only in its coarse
 *      operators (-pc_gamg_reuse_interpolation).
 *   nested  the conjugate gradients of lac_augmented.c on the multipliers
 *      (preconditioner W_A), each product one solve of K_W by conjugate
 *      gradients and GAMG to 1e-2 times the outer tolerance: the
 *      comparison of chapter 11 (option -lac_contact nested).
 *
 * Without multipliers (k = 0, plain elasticity) K U = f is solved by
 * conjugate gradients and GAMG.  The near-null space of the multigrid is
 * the rigid motions of the nodal coordinates (MatNullSpaceCreateRigidBody:
 * 3 in 2D, 6 in 3D) when they are given (lac_petsc_set_coordinates), the
 * constants of each component otherwise (the axisymmetric model, whose
 * only rigid motion is the translation along the axis).  Tolerances are
 * on the unpreconditioned residual; the true residual ||b - A x|| / ||b||
 * of (*W) and the iterations are reported for every solve.
 *
 * Distribution: the nodes are cut in N contiguous ranges, one per MPI
 * process, and the multipliers in N ranges (PETSC_DECIDE).  Every process
 * holds the whole system (the assembly stays serial and is repeated on
 * every process) and inserts only its own rows; after each solve U and
 * lambda are gathered on every process, so that the active-set loop, the
 * refinement and the output are the same on all.  Every process must make
 * the same calls (PETSc's are collective).
 *
 * Options: PETSc's, from the string given to lac_petsc_initialize and from
 * the environment variable PETSC_OPTIONS.  The saddle solver has no
 * prefix (-ksp_type, -pc_fieldsplit_schur_fact_type), its blocks
 * -fieldsplit_u_ and -fieldsplit_lambda_ (-fieldsplit_u_pc_type hypre:
 * BoomerAMG); the solver of K_W alone (k = 0, nested) has the prefix
 * -elast_ (-elast_pc_type hypre).  The defaults are those of an elastic
 * body, nothing to tune.  The tolerances are the strategy's.
 *
 * A build without PETSc (no LAC_HAVE_PETSC, chapter 11) compiles the same
 * interface: every function then fails with LAC_EDEP and the apt-get line.
 *
 * Ownership: the system and the coordinates are borrowed from set until
 * the next set or lac_petsc_free.
 */
#ifndef LAC_PETSC_H
#define LAC_PETSC_H

#include "solve/lac_system.h"

#define LAC_PETSC_INSTALL "apt-get install -y --no-install-recommends " \
  "libpetsc-real-dev, then make clean && make"

/* 1 if lac was built with PETSc. */
int lac_petsc_available (void);
/* Initialize MPI (if nobody did) and PETSc (if nobody did), then add the
 * options (a string "-key value ...", NULL or "" for none).  Called by
 * every process before the first strategy, and again to add options;
 * lac_petsc_alloc initializes alone when it was not called. */
int lac_petsc_initialize (const char *options);
/* Finalize PETSc (and MPI) if lac_petsc_initialize or lac_petsc_alloc
 * initialized them; nothing otherwise.  Last call of main(). */
void lac_petsc_finalize (void);
/* This process and the number of processes: 0 and 1 without MPI or
 * before lac_petsc_initialize. */
void lac_petsc_rank (int *rank, int *size);

typedef struct lac_petsc lac_petsc;     /* opaque */

lac_petsc *lac_petsc_alloc (double omega);
void lac_petsc_free (lac_petsc *s);      /* NULL allowed */
/* The nodal coordinates (dof = dim*node + comp, the mesh's x; borrowed,
 * n entries) for the rigid motions; NULL: constants per component.
 * Before lac_petsc_set. */
void lac_petsc_set_coordinates (lac_petsc *s, int dim, const double *x);
/* Borrow the system; distribute K_W's pattern (kept while the patterns of
 * K and C stay; new numbers: set again). */
int lac_petsc_set (lac_petsc *s, const lac_contact_system *sys);
/* U, lambda of (*) for the statuses `active`, right-hand sides f, g
 * (NULL: F, G); U and lambda are the start (warm start) on entry, the
 * solution on every process on return (lambda = 0 where inactive).
 * rtol: relative unpreconditioned residual of (*W). */
int lac_petsc_solve (lac_petsc *s, const char *active, const double *f,
                     const double *g, double rtol, double *U, double *lambda);
void lac_petsc_get_counts (const lac_petsc *s, lac_solve_counts *c);
/* What is solved, e.g. "fgmres + fieldsplit(gamg, W), 2 processes". */
const char *lac_petsc_method (const lac_petsc *s);

#endif /* LAC_PETSC_H */
