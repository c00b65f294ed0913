/* lac_petsc_saddle.h -- a stiffness under linear constraints, solved by
 *                       Krylov methods and algebraic multigrid (PETSc)
 *                                                          [chapter 13]
 *
 *   [ K    B ] [u]   [f]     K  n x n, symmetric positive definite, its
 *   [ B^T  D ] [l] = [g]        near-null space set (the rigid motions);
 *                            B  n x k, a zero column where D = 1;
 *                            D  k x k diagonal: 0 where multiplier l_i
 *                               constrains u (B_i^T u = g_i), 1 where it
 *                               is free (then l_i = g_i, usually 0).
 *
 * Three methods, distributed over the MPI processes as K and B are:
 *
 *   K alone      (B = NULL, k = 0) conjugate gradients, preconditioned by
 *                one V-cycle of PETSc's GAMG on K (options prefix elast_);
 *   projected    conjugate gradients on the null space of B^T: with the
 *                l2-orthogonal projection P = I - B (B^T B + D)^-1 B^T,
 *                u = u0 + x, B^T u0 = g, and P K x = P (f - K u0), each
 *                iteration preconditioned by z = P_Z M P_Z^T r, M one
 *                V-cycle of multigrid on K (lac_petsc_mg.h; prefix
 *                elast_), P_Z = I - Z (B^T Z + D)^-1 B^T
 *                with Z ~ K^-1 B after -lac_projection_steps Jacobi
 *                steps from diag(K)^-1 B (default 1; 0: P_Z = P); the
 *                multipliers after, l = (B^T B + D)^-1 B^T (f - K u).
 *                B^T B + D and B^T Z + D (k x k) are factored by LU, on
 *                every process (prefixes gram_, gramz_; gram_local_,
 *                gramz_local_ on N > 1 processes);
 *   fieldsplit   GMRES on the whole system, preconditioned by PETSc's
 *                PCFIELDSPLIT (Schur complement, upper factorization):
 *                GAMG on K (prefix fieldsplit_u_; the threshold as the
 *                projected CG's, by default), the diagonal Sp given
 *                for the Schur complement (fieldsplit_lambda_: Jacobi).
 *
 * Every PETSc option of those prefixes is read (-ksp_type, -pc_type of
 * the outer solver have no prefix), and wins over lac's settings.
 * PETSc's types appear only in the implementation: the header names its
 * matrices and vectors by their structs, as fem/lac_assembly_dist.h
 * does.
 */
#ifndef LAC_PETSC_SADDLE_H
#define LAC_PETSC_SADDLE_H

#include <stddef.h>

#ifdef LAC_HAVE_PETSC

typedef struct _p_Mat *lac_saddle_mat;
typedef struct _p_Vec *lac_saddle_vec;

typedef enum { LAC_SADDLE_PROJECTED, LAC_SADDLE_FIELDSPLIT }
lac_saddle_method;

typedef struct lac_petsc_saddle lac_petsc_saddle;

/* What one solve did: Krylov iterations, solves (GMRES and its
 * correction: 2), the relative true residual (see lac_petsc_saddle_solve). */
typedef struct
{
  int iterations, solves;
  double residual;
} lac_saddle_counts;

/* The solvers of K (and B: NULL for K alone) by `method`; K and B are
 * borrowed and keep their patterns (new values: _update).  threshold:
 * projected CG, the multigrid of K is lac's (lac_petsc_mg.h), whose
 * graph leaves out the couplings below it at a contact node (a node with
 * a row of B; < 0: none), unless -elast_pc_type names another; with
 * -pc_type none no multigrid.  fieldsplit: PCGAMG's threshold on the
 * finest level (0 on the coarser ones; < 0: PETSc's default), unless
 * -fieldsplit_u_pc_gamg_threshold is given.  The user's -ksp_rtol,
 * -ksp_atol, -ksp_max_it (with the Krylov method's prefix) replace the
 * tolerance and limit of every solve.  Collective. */
int lac_petsc_saddle_create (lac_saddle_method method, lac_saddle_mat K,
                             lac_saddle_mat B, double threshold,
                             lac_petsc_saddle **out);
void lac_petsc_saddle_free (lac_petsc_saddle *sv);
/* After new values of K and B: D's diagonal d and (fieldsplit) the
 * Schur preconditioner's diagonal sp, both k, in the layout of B's
 * columns (NULL for K alone).  Collective. */
int lac_petsc_saddle_update (lac_petsc_saddle *sv, lac_saddle_vec d,
                             lac_saddle_vec sp);
/* Solve with (u, l) as the start and the solution (l: not read by the
 * projected CG; NULL for K alone), to the relative residual rtol: of the
 * forces f - K u - B l against f (K alone, projected), of the whole
 * system (fieldsplit).  c: the counts, also on failure; c->residual is
 * the true relative residual, for the projected CG the larger of the
 * forces' (2-norms) and the constraints' g - B^T u against |g| + |B^T|
 * |u| (max-norms).  A Krylov failure is LAC_EMAXITER (LAC_ESING if
 * indefinite) with `what` in the message.  Collective. */
int lac_petsc_saddle_solve (lac_petsc_saddle *sv, lac_saddle_vec f,
                            lac_saddle_vec g, double rtol, const char *what,
                            lac_saddle_vec u, lac_saddle_vec l,
                            lac_saddle_counts *c);
/* "projected cg + gamg" style names: the Krylov method, the
 * preconditioner of K (fieldsplit: of its block u). */
int lac_petsc_saddle_types (const lac_petsc_saddle *sv, char *krylov,
                            char *pc, size_t size);

#endif /* LAC_HAVE_PETSC */

#endif /* LAC_PETSC_SADDLE_H */
