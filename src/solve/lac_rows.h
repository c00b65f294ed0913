/* lac_rows.h -- the equations of a contact law solved by any strategy:
 *               GMRES preconditioned by its symmetric solve
 *                                        [LAC (17), Alg. 1 l. 21; friction]
 *
 * The system of a contact law's equations (lac_contact_rows of
 * solve/lac_system.h)
 *
 *   A = [ K        -C ]        (only the free multipliers: lambda_j = 0
 *       [ -P C^T    Q ]         for the others)
 *
 * is unsymmetric where friction slips.  Its rows are of two kinds: the
 * constraints -c_j^T U = r_j (the normal rows in contact, the tangential
 * rows that stick: P is a unit row, Q zero), and the others (slip: a
 * relation between the multipliers of a macro-element, in 3D with U).
 * Without the constraints' partners, what is left is the system (*) of
 * the frictionless law with the constraints as its active multipliers, and
 * every strategy solves that, symmetric, with its own factorization or
 * Krylov method (lac_strategy_solve_rhs).  So
 *
 *   M = [ K   -C_c ]   on the constraints,   diag(Q) on the other free
 *       [ -C_c^T 0 ]   multipliers, 1 on the multipliers fixed to 0,
 *
 * differs from A by a matrix of rank at most 3 per slipping macro-element
 * (its columns and its rows), and flexible GMRES on A with M^{-1} as the
 * right preconditioner (linalg/lac_gmres.h) converges in a number of
 * iterations bounded by that rank, usually far fewer.  Each iteration is
 * one solve by the strategy (no factorization: the constraints are the
 * same for the whole solve).  The strategies with a direct solve of A
 * (solve_rows: dense, saddle, schur) do not need it; the others (split,
 * augmented, petsc) solve friction this way.
 *
 * Ownership: everything borrowed.
 */
#ifndef LAC_ROWS_H
#define LAC_ROWS_H

#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

/* U (n), lambda (k) of the system of R on sys, by the strategy st (set on
 * sys); U, lambda: the start on entry.  *its: GMRES iterations, *berr:
 * the backward error of the result (lac_system_rows_residual).
 * LAC_EMAXITER (with the residual reached) if GMRES does not converge. */
int lac_rows_gmres (lac_strategy *st, const lac_contact_system *sys,
                    const lac_contact_rows *R, double *U, double *lambda,
                    int *its, double *berr);

#endif /* LAC_ROWS_H */
