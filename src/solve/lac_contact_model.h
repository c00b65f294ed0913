/* lac_contact_model.h -- what Algorithm 1 asks of a contact problem
 *                                               [LAC §4.5, Alg. 1, (16)-(18)]
 *
 * The loop of Algorithm 1 (solve/lac_newton.h) knows the problem only
 * through this interface, a small table of operations in the manner of
 * the solve strategies (solve/lac_strategy.h):
 *
 *   evaluate   at a displacement U: the out-of-balance force
 *                r(U) = F - F_int(U)                    [Alg. 1, line 11]
 *              and the contact data of U: one column of C per admissible
 *              macro-element, its mean gap d(U) = int g(U) over T^m cap
 *              Gamma_C, the measure of T^m cap Gamma_C with and without
 *              the axisymmetric weight               [Alg. 1, line 25]
 *   linearize  the saddle-point system (*) of solve/lac_system.h for the
 *              step from U: the tangent, the right-hand sides, the
 *              Dirichlet values                       [Alg. 1, lines 11-20]
 *   consistent (optional) the frozen step corrected into the exact Newton
 *              step of a model whose C and d move with U
 *   uncovered  how deep the macro-elements WITHOUT a multiplier penetrate
 *              the master at U (no silent penetration)
 *   widen      pair again with a longer reach (after uncovered found one)
 *
 * Two implementations:
 *   - the linear model (solve/lac_linear_model.h): small strain, K, F, C
 *     and the initial gaps G constant, d(U) = G - C^T U; its (*) gives U
 *     itself, so one solve per active set is exact;
 *   - the large-deformation model (solve/lac_nonlinear.h): hyperelastic
 *     F_int and K_T(U), the pairing on the current coordinates at every
 *     evaluation; its (*) gives a Newton increment.
 * A contact law with friction would be a third.
 *
 * THE INDEX SPACE OF THE MULTIPLIERS.  The loop keeps one multiplier and
 * one status per macro-element of the slave surface ("slot" m = 0 ..
 * nslot - 1), whatever the columns of the moment: a model whose pairing
 * moves (large deformations) gains and loses columns, the multiplier of
 * a macro-element stays where it is.  Column i of an evaluation belongs
 * to slot slot[i].
 *
 * Units.  d_i is a mean gap times a measure (a volume in 3D), lambda_i a
 * pressure; the loop makes them comparable with
 *   rho_i = E / (h_i |T^m cap Gamma_C|)     h_i = size_i (2D), sqrt(size_i) (3D)
 * (E: the model's reference Young modulus; size_i the measure without the
 * weight 2 pi r, so h_i is a length in the axisymmetric model too):
 * rho_i d_i is the pressure that pushes a layer of depth h_i in by the
 * mean gap d_i / |T^m cap Gamma_C|.
 *
 * Ownership: what a model returns is borrowed from it until its next call.
 */
#ifndef LAC_CONTACT_MODEL_H
#define LAC_CONTACT_MODEL_H

#include <math.h>
#include <stddef.h>
#include "contact/lac_contact_pair.h"
#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

enum { LAC_MODEL_SAME, LAC_MODEL_NEW_C, LAC_MODEL_NEW_K };

/* The model at U (evaluate). */
typedef struct lac_model_point
{
  /* contact: k = 0 when no macro-element is paired and admissible */
  size_t k;
  const lac_csc *C;      /* n x k (rows of the Dirichlet dofs zero)        */
  const double *d;       /* k: mean gaps at U, > 0 open        [LAC (18)]  */
  const double *area;    /* k: |T^m cap Gamma_C| (NULL: 1)                 */
  const double *size;    /* k: the same without the weight 2 pi r (NULL: 1) */
  const size_t *slot;    /* k: the macro-element of column i (NULL: i)     */
  const double *lost;    /* k: measure of T^m cap Gamma_C (no weight) lost
                            to failed projections (NULL: none)            */
  const double *rho;     /* k: rho of the status test, given (NULL: E / (h
                            |T^m cap Gamma_C|), below)                    */
  /* equilibrium: the loop tests |r + C lambda| on the free dofs */
  const double *r;       /* n: F - F_int(U)                                */
  const char *fixed;     /* n: Dirichlet dofs (NULL: none)                 */
  double fscale;         /* > 0: the size of the forces in r, the scale of
                            the residual (with |C lambda|)                 */
} lac_model_point;

/* The macro-element (slot) of column i of p. */
static inline size_t
lac_model_slot (const lac_model_point *p, size_t i)
{
  return p->slot ? p->slot[i] : i;
}

/* The penetration of column i as a length: -d_i / |C(:,i)|_1, the mean
 * gap per unit weight of the column (0 for an empty column). */
static inline double
lac_model_penetration (const lac_model_point *p, size_t i)
{
  double csum = 0;
  for (int q = p->C->p[i]; q < p->C->p[i + 1]; q++)
    csum += fabs (p->C->x[q]);
  return csum > 0 ? -p->d[i] / csum : 0.0;
}

/* h_i of column i, the size of T^m cap Gamma_C as a length: size_i in
 * 2D, sqrt(size_i) in 3D (1 without sizes). */
static inline double
lac_model_h (const lac_model_point *p, size_t i, int dim)
{
  if (!p->size)
    return 1.0;
  return dim == 3 ? sqrt (p->size[i]) : p->size[i];
}

typedef struct lac_contact_model_type
{
  const char *name;
  /* 0: K, C and G do not depend on U, (*) gives U itself (a linear
   * model: no line search); 1: (*) gives the Newton increment dU */
  int nonlinear;
  /* At U; tangent = 0: the tangent may be left out (linearize makes it). */
  int (*evaluate) (void *self, const double *U, int tangent,
                   lac_model_point *p);
  /* The system (*) of the step from the last evaluation: *sys (the
   * model's, with the bodies held by contact alone, N; it stays where it
   * is, the strategy borrows it) and *news, what changed
   * since the previous call: LAC_MODEL_SAME, LAC_MODEL_NEW_C (C and G,
   * K is the same: the strategy keeps a factorization of K) or
   * LAC_MODEL_NEW_K. */
  int (*linearize) (void *self, const double *U,
                    const lac_contact_system **sys, int *news);
  /* NULL, or: from the solution dU, lambda (k columns) of the frozen
   * system, the exact Newton step to relative accuracy eta, with the
   * strategy as the preconditioner (solve/lac_consistent.h); lam_lin: the
   * multipliers of the linearization point; *its: GMRES iterations,
   * *res: its final relative residual. */
  int (*consistent) (void *self, lac_strategy *st, const char *active,
                     const double *lam_lin, double eta, double *dU,
                     double *lambda, int *its, double *res);
  /* The macro-elements without a column at U that penetrate the master by
   * more than tol h_m (contact/lac_contact_pair.h; u->macro is the slot),
   * looked for as deep as the nodes moved since the pairing that left
   * them out. */
  int (*uncovered) (void *self, const double *U, double tol,
                    lac_contact_uncovered *u);
  /* Pair again with `reach` (a length) added to the pairing distance;
   * *more: the number of macro-elements that have a column now and had
   * none (NULL: the model cannot). */
  int (*widen) (void *self, const double *U, double reach, size_t *more);
} lac_contact_model_type;

/* A model: its operations and its data. */
typedef struct lac_contact_model
{
  const lac_contact_model_type *type;
  void *self;            /* the model's data, borrowed                     */
  size_t n;              /* displacements                                  */
  size_t nslot;          /* macro-elements: the multipliers' index space   */
  double E;              /* reference Young modulus of rho (> 0)           */
  int dim;               /* 2 or 3: h_i from size_i                        */
} lac_contact_model;

#endif /* LAC_CONTACT_MODEL_H */
