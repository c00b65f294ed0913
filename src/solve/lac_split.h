/* lac_split.h -- the augmented system on the bodies held by contact alone
 *                only: one Cholesky factor per part, the multipliers by
 *                GMRES                            [LAC (17), Alg. 1 l. 21]
 *
 * Strategy (b') of solve/lac_strategy.h, for a scene where some bodies
 * are held by their Dirichlet conditions (the dofs H) and others by
 * contact alone (the dofs S: the bodies that the rigid motions N of
 * solve/lac_system.h move).  K has no entry between two bodies, so
 *
 *   K = [ K_HH   0   ]      C = [ C_H ]      (rows of H, rows of S).
 *       [  0   K_SS  ]          [ C_S ]
 *
 * Strategy (b) adds C_A W_A times the constraint C_A^T U = G_A to every
 * equation of the equilibrium; K + C_A W C_A^T then couples the two
 * bodies of every contact and its Cholesky factor is that of one body
 * twice as large (measured in chapter 07: 76 % more flops than the two
 * bodies apart on the 3D patch test).  Adding it to the equations of S
 * only keeps the bodies apart.  Since C_S^T U_S = G - C_H^T U_H on the
 * active multipliers, the equilibrium of (*) (solve/lac_system.h) reads
 *
 *   K_HH U_H                                   = F_H + C_H,A lambda_A
 *   K~_SS U_S + C_S,A W_A C_H,A^T U_H          = F_S + C_S,A (W_A G_A
 *                                                      + lambda_A),
 *   K~_SS = K_SS + C_S,A W_A C_S,A^T,
 *
 * a block lower-triangular system: U_H by the factor of K_HH, then U_S
 * by the factor of K~_SS.  K_HH is positive definite (held bodies) and
 * factorized once per set; K~_SS is positive definite as soon as the
 * active multipliers hold the bodies of S (the condition of (b)) and is
 * factorized again when the statuses change.  The two share nothing: the
 * first solve after set factorizes them at the same time, one core each,
 * when each part has 2,000 unknowns or more (linalg/lac_tasks.h; 2.7 s
 * instead of 4.5 s at 141k dofs, chapter 07).
 * The multipliers solve
 *
 *   A lambda_A = G_A - C_A^T U(0),   A v = C_A^T U_0(v),
 *
 * U(lambda) the solution of the triangular system above, U_0 the same
 * with F = 0 and G = 0.  A is not symmetric (the triangular system is
 * not), so GMRES (linalg/lac_gmres.h) replaces the conjugate gradients of
 * (b), with the same preconditioner W_A: A W_A = (I + omega S_S)^{-1}
 * omega (S_S + S_H) (S_P = C_P,A^T K_PP^{-1} C_P,A), whose eigenvalues
 * are 1 on the rigid motions of S and about 1 + eig(S_H S_S^{-1}) on the
 * rest when omega is large: the number of iterations does not grow with
 * the mesh.  Each iteration is one forward and back substitution with
 * each factor.
 *
 * The operations of the type split of solve/lac_strategy.h (omega =
 * LAC_AUGMENT_OMEGA): set finds the parts H and S from the connected
 * components of K and from N and makes the pattern of K_SS + C_S C_S^T
 * (nothing is factorized before the first solve); solve starts GMRES
 * from the given lambda_A; factor_failed: the last error was a
 * factorization (not positive definite).
 */
#ifndef LAC_SPLIT_H
#define LAC_SPLIT_H

#include "solve/lac_system.h"

extern const lac_strategy_ops lac_split_ops;

#endif /* LAC_SPLIT_H */
