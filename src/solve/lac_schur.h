/* lac_schur.h -- the multipliers of one active set through the Schur
 *                complement of K                  [LAC (17), Alg. 1 l. 21]
 *
 * Strategy (a) of solve/lac_strategy.h, for bodies all held by their
 * Dirichlet conditions (K symmetric positive definite):
 *
 *   K = L L^T (CHOLMOD), once per matrix;
 *   S(:, i) = C^T K^{-1} c_i for every multiplier i that is active, the
 *     first time it is (blocks of LAC_SCHUR_BLOCK right-hand sides), kept:
 *     a later active set only adds the columns of its new members;
 *   S_AA lambda_A = g_A - C_A^T K^{-1} f    (dense Cholesky, k_A x k_A);
 *   U = K^{-1} (f + C_A lambda_A).
 *
 * With a factor P K P^T = L L^T that solves in halves (supernodal; the
 * small simplicial L D L^T does not, linalg/lac_linalg.h), only the
 * forward halves y_i = L^{-1} P c_i are made, half the work of whole
 * solves, and kept sparse: y_i is zero but on the rows of the elimination
 * tree above those of c_i (5 % of them on the fine ring of chapter 10).
 * S(j, i) = y_j^T y_i, and a solve is one forward and one back
 * substitution:
 *   w = L^{-1} P f,  S_AA lambda_A = g_A - Y_A^T w,
 *   U = P^T L^{-T} (w + Y_A lambda_A).
 *
 * A linear scene factorizes K once and pays for each column of S once,
 * whatever the number of active-set iterations; a large-deformation step
 * (a new K every iteration) pays for the active columns at every
 * iteration.  Chapter 07 compares it with the augmented strategy (b).
 *
 * The operations of the type schur of solve/lac_strategy.h: set factors
 * K (a K that is not positive definite: LAC_ESING, and factor_failed
 * says so), reset keeps that factorization for another C (only the
 * columns of S are forgotten), keep keeps the C as well, with the columns
 * of S made and the columns behind them (y_i, or without the halves
 * K^{-1} c_i when they take no more room than the factor): the solves are
 * those of the older system, the preconditioner of a consistent Newton
 * step (solve/lac_consistent.h), one solve with the factor each (without
 * the halves U = K^{-1} f + K^{-1} C_A lambda_A).
 */
#ifndef LAC_SCHUR_H
#define LAC_SCHUR_H

#include "solve/lac_system.h"

#define LAC_SCHUR_BLOCK 64

extern const lac_strategy_ops lac_schur_ops;

#endif /* LAC_SCHUR_H */
