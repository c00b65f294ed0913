/* lac_petsc.h -- the LAC system of one active set by Krylov methods and
 *                algebraic multigrid (PETSc), on one or N processes
 *                                                 [LAC (17), Alg. 1 l. 21]
 *
 * Strategy (e) of solve/lac_strategy.h, for the 3D meshes whose Cholesky
 * factor does not fit in memory (a 1,029,000-dof hex8 cube needs 20.5 GB,
 * chapter 13).  It solves the augmented form of (*) of
 * solve/lac_system.h (solve/lac_augmented.h: adding C_A W_A times the
 * constraint changes neither U nor lambda),
 *
 *   [ K_W    -C_A ] [ U        ]   [ f_W ]     f_W = f + C_A W_A g_A,
 *   [ -C_A^T   0  ] [ lambda_A ] = [ -g_A ],                       (*W)
 *
 *   K_W = K + C_A W_A C_A^T,   W_i = omega / s_i,  s_i = c_i^T diag(K)^-1 c_i,
 *
 * where K_W is positive definite as soon as the active multipliers hold
 * every body (lac_system_check_held), with no dense Schur complement and
 * no factorization of a matrix of size n:
 *
 *   projected (default)  conjugate gradients on the null space of C_A^T
 *      (Gould, Hribar and Nocedal, SIAM J. Sci. Comput. 23 (2001)): with
 *      the projection P = I - C_A (C_A^T C_A)^-1 C_A^T (C_A^T C_A is k x
 *      k and sparse: LU on every process), U = u0 + x with C_A^T u0 = g_A
 *      and x = P x solving P K_W x = P (f_W - K_W u0), preconditioned by
 *      P M, M one V-cycle of smoothed-aggregation multigrid on K_W;
 *      then lambda_A = (C_A^T C_A)^-1 C_A^T (K_W U - f_W).  On the null
 *      space K_W is K: W only makes K_W positive definite for the
 *      multigrid (omega = LAC_PETSC_OMEGA, smaller than the augmented
 *      strategy's: a stiffer K_W is harder for the multigrid).  The
 *      multigrid's finest level is lac's (linalg/lac_petsc_mg.h: its
 *      aggregates leave out the couplings of the contact nodes below
 *      LAC_PETSC_CONTACT_THRESHOLD, and have no single nodes), PETSc's
 *      GAMG the coarser ones: about 1.2 times the CG iterations of the
 *      cube without contact (chapter 13, section 1).
 *   fieldsplit  GMRES on the whole of (*W), right preconditioned by the
 *      block factorization of PCFIELDSPLIT (Schur type, "upper"): K_W by
 *      one V-cycle of GAMG, the Schur complement S_W = C_A^T K_W^-1 C_A
 *      by W_A^-1 (S_W^-1 = S^-1 + W_A lies between W_A and W_A + 1/s_min,
 *      lac_augmented.h).  GMRES meets C_A^T U = g_A only to its tolerance,
 *      relative to the forces: one correction solve follows.  The
 *      comparison of chapter 13 (option -lac_contact fieldsplit).
 *
 * The inactive multipliers keep their rows (lambda_i = 0), so that the
 * matrices keep their size and pattern when the statuses change and the
 * multigrid keeps its interpolation (-pc_gamg_reuse_interpolation).
 * Without multipliers (k = 0, plain elasticity) K U = f is solved by
 * conjugate gradients and GAMG.  The near-null space of the multigrid is
 * the rigid motions of the nodal coordinates (MatNullSpaceCreateRigidBody:
 * 3 in 2D, 6 in 3D) when they are given (lac_strategy_set_coordinates:
 * centred on their mean and divided by their largest distance from it
 * first), the constants of each component otherwise (the axisymmetric
 * model, whose only rigid motion is the translation along the axis).
 * Tolerances are on the true, unpreconditioned residual ||b - A x|| /
 * ||b||: of K U = f when k = 0; of the forces of (*W) for the projected
 * CG, whose constraint rows hold to rounding, so that no tolerance adds
 * forces to gaps and nothing depends on the units (the same scene in mm
 * and MPa or in m and Pa: chapter 13); fieldsplit's GMRES takes the norm
 * of the whole of (*W), forces and gaps together.  The residual reported
 * with the iterations of every solve is, for the projected CG, the larger
 * of the relative residuals of the two rows of (*W), each in its unit.
 *
 * Processes.  The rows of the matrices and vectors are cut in N parts,
 * whole nodes for U, one per MPI process, and the multipliers in N
 * contiguous ranges.  Process 0 (the root) runs the scene -- mesh, active
 * set, output -- and the others run lac_petsc_serve: they follow the
 * root's commands (build, new values, solve, free, memory, quit; one
 * broadcast each).  K_W is assembled where the cells are
 * (fem/lac_assembly_dist.h): the root broadcasts the mesh once (given by
 * set_mesh), PETSc's partitioner cuts the cells, each process adds its
 * cells' element matrices and the contact terms of the columns it owns,
 * PETSc adds the entries of the other processes' rows.  The K so
 * assembled is checked against its cells (K x against the sum of the
 * element matrices times x, for a probe x: lac_dist_check_stiffness)
 * before it is used, so that the root's residuals, which take K x from
 * it (kmul), judge the cells' system.  Without a mesh (rigid plates,
 * large deformation) the root adds K's entries.  The solution comes back
 * to the root alone.  An error on any process ends the command on every
 * process with that process's message: each command ends with the
 * agreement of every process on its status.  One petsc strategy at a
 * time exists on the root when N > 1.
 *
 * Options: PETSc's, from the environment variable PETSC_OPTIONS and then
 * from the string given to lac_petsc_initialize (which wins).  The
 * multigrid of K_W (and the solver of K when k = 0) has the prefix
 * -elast_ (-elast_pc_type hypre: BoomerAMG instead of lac's; lac's
 * coarse GAMG: -elast_mg_coarse_), the projected CG none (-ksp_monitor;
 * -pc_type none: the projections without the multigrid, another type
 * is refused), C_A^T C_A -gram_; fieldsplit: no prefix for GMRES,
 * -fieldsplit_u_ and -fieldsplit_lambda_ for the blocks.  The user's
 * options win over lac's settings, as in PETSc: -ksp_rtol, -ksp_atol,
 * -ksp_max_it of a Krylov method replace the strategy's tolerance and
 * limit (the root's residuals still decide when Algorithm 1 stops).
 * lac's own: -lac_contact projected|fieldsplit, -lac_omega W (finite, >
 * 0), -lac_contact_threshold T (finite; < 0: no coupling left out),
 * -lac_projection_steps N.  The defaults are those of an elastic body:
 * nothing to tune.
 *
 * The operations of the type petsc of solve/lac_strategy.h: alloc starts
 * MPI and PETSc if nobody did (lac_petsc_initialize) and reads
 * -lac_contact, -lac_omega and -lac_contact_threshold (their build
 * command carries them to the others); set_coordinates (before set)
 * gives the rigid motions; set_mesh (before set) the cells K comes from;
 * set builds K_W's pattern (kept while the patterns of K and C stay; new
 * numbers: set again); solve's rtol is the relative unpreconditioned
 * residual of (*W); method says what solves, e.g.
 * "projected cg + lac-sa + gamg on K_W, 2 processes"; the counts give
 * the processes.  A build without PETSc (no LAC_HAVE_PETSC, chapter 13)
 * compiles the same: alloc and lac_petsc_serve fail with LAC_EDEP and the
 * apt-get line.
 */
#ifndef LAC_PETSC_H
#define LAC_PETSC_H

#include "linalg/lac_petsc_env.h"
#include "solve/lac_system.h"

#define LAC_PETSC_OMEGA 1.0   /* omega of K_W (chapter 13: 1 against 10) */
#define LAC_PETSC_OMEGA_MAX 1e6   /* -lac_omega at most (lac_petsc.c) */
/* The multigrid's threshold on the couplings of the contact nodes of
 * K_W's finest level (-lac_contact_threshold; chapter 13) */
#define LAC_PETSC_CONTACT_THRESHOLD 0.1

/* The processes other than the root: follow the root's commands until it
 * finalizes (lac_petsc_finalize).  LAC_SUCCESS then; an error if called
 * on the root. */
int lac_petsc_serve (void);

extern const lac_strategy_ops lac_petsc_ops;

#endif /* LAC_PETSC_H */
