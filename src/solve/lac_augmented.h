/* lac_augmented.h -- the multipliers of one active set by conjugate
 *                    gradients on the Schur complement of the augmented
 *                    system                       [LAC (17), Alg. 1 l. 21]
 *
 * Strategy (b) of solve/lac_strategy.h.  Adding C_A W_A times the
 * constraint C_A^T U = G_A to the equilibrium of (*) (solve/lac_system.h)
 * changes neither U nor lambda:
 *
 *   K_W U - C_A lambda_A = F + C_A W_A G_A,   K_W = K + C_A W_A C_A^T,
 *
 * and eliminating U leaves the multipliers alone:
 *
 *   S_W lambda_A = G_A - C_A^T U_0,   S_W = C_A^T K_W^{-1} C_A,
 *   U_0 = K_W^{-1} (F + C_A W_A G_A),   U = U_0 + K_W^{-1} C_A lambda_A.
 *
 * S_W is symmetric positive definite and is never formed: it is solved by
 * preconditioned conjugate gradients (linalg/lac_pcg.h), each product one
 * forward and back substitution with the Cholesky factor of K_W (CHOLMOD).
 *
 * W_i = omega / s_i on the active multipliers, s_i = c_i^T diag(K)^{-1}
 * c_i: then S_W = (S^{-1} + W)^{-1} (S = C_A^T K^{-1} C_A) has its
 * eigenvalues between 1 / (w_i + 1 / s_min) and 1 / w_i, and conjugate
 * gradients preconditioned by W converge in about ten iterations whatever
 * the mesh, where S alone needs 80 to more than 100 (chapter 07).  K_W is
 * positive definite when the active multipliers hold every body, also
 * those that the Dirichlet conditions leave free.  Its pattern, that of
 * K + C C^T (every potential contact coupling), is analysed once; the
 * numbers are factorized again when the statuses change.
 *
 * omega trades the iterations (about 18, 9, 6 for omega = 1, 10, 100 on
 * the 3D spheres; 26, 13, 9 with the refinement on the 3D patch test of
 * 53k dofs for omega = 10, 100, 1000) against the condition number of K_W
 * (omega times that of K): the strategy's refinement step
 * (solve/lac_strategy.c) recovers the digits that LAC_AUGMENT_OMEGA = 100
 * costs (lambda exact to 1e-13 on that patch test all the same).
 *
 * The operations of the type augmented of solve/lac_strategy.h: set makes
 * the pattern of K + C C^T (kept while the patterns of K and C stay),
 * solve factorizes K_W when the statuses changed and starts the
 * conjugate gradients from the given lambda_A; factor_failed tells a
 * failed factorization of K_W (not positive definite) from conjugate
 * gradients that did not converge (dependent constraints).
 */
#ifndef LAC_AUGMENTED_H
#define LAC_AUGMENTED_H

#include "solve/lac_system.h"

#define LAC_AUGMENT_OMEGA 100.0

extern const lac_strategy_ops lac_augmented_ops;

#endif /* LAC_AUGMENTED_H */
