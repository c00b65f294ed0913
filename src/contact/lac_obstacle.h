/* lac_obstacle.h -- a rigid analytic obstacle as the master side
 *                                                  [LAC §4.3, (18); §5.3]
 *
 * The master body can be a rigid foundation given by a formula: the region
 * below the graph
 *
 *   v <= h(w) = height + sum_k curv_k (w_k - center_k)^2,
 *
 * with v the last coordinate (y in 2D, z in 3D) and w the others (x; x, y).
 * The paper's manufactured solutions [LAC §5.3] press a square onto
 * y <= -0.05 (x - 0.5)^2 and a cube onto z <= -0.2 (1 + x^2 + y^2) - 0.3.
 *
 * Against a rigid master the pairing is trivial: every slave facet is fully
 * covered and its integration points are those of its own rule.  The gap
 * and the direction of the constraint are the obstacle's, as is usual for
 * a rigid foundation (P. Wriggers, Computational Contact Mechanics, 2006;
 * T. A. Laursen, Computational Contact and Impact Mechanics, 2002): x_s is projected to the closest point x^O of
 * the graph, the gap is the signed distance g = (x_s - x^O).n^O (n^O the
 * obstacle's unit outward normal at x^O, g > 0 when open) and the
 * constraint acts along nu = -n^O, the direction in which the slave
 * point must move to close the gap: g(x_s + u) = g - u.nu to first order.
 * For two deformable bodies lac keeps the paper's slave normal n^S
 * [LAC (16)-(18)]; chapter 06 (section "Which normal") compares the two.
 * With slave_normal = 1 the obstacle too is met along n^S: g solves
 * x_s + g n^S on the graph (a quadratic equation, the root of smallest
 * |g|) and P->normal is NULL.  The paper's manufactured solutions are
 * built for that formulation (their deformed bottom lies on the graph
 * point by point vertically); along n^O they are exact only to second
 * order in the gap, which stops their convergence at about 1e-3.
 * The closest point solves (x_s - x^O(w)).t_k(w) = 0, t_k = e_k + dh/dw_k
 * e_v, by Newton on w from the vertical projection (the graph is
 * quadratic, so the Newton matrix A is exact).  lac_obstacle_pairing
 * returns a lac_pairing with nmaster = 0, master[p] = LAC_OBSTACLE_MASTER
 * and the directions nu in P->normal, so that C has no master part
 * (C^M = 0) and the mean gaps G are exact integrals of the distance.
 *
 * Ownership: the result is freed with lac_pairing_free.
 */
#ifndef LAC_OBSTACLE_H
#define LAC_OBSTACLE_H

#include <stddef.h>
#include <stdint.h>
#include "contact/lac_pairing.h"

#define LAC_OBSTACLE_MASTER SIZE_MAX   /* master index of obstacle points */

typedef struct lac_obstacle
{
  int dim;            /* 2 or 3                                           */
  double height;      /* h at the centre                                  */
  double curv[2];     /* curvature coefficients per horizontal direction */
  double center[2];   /* horizontal position of the apex                 */
  int slave_normal;   /* 0: gap and constraint along the obstacle's
                         normal; 1: along the slave normal n^S, the
                         formulation for which the paper's manufactured
                         solutions [LAC §5.3] are exact                   */
} lac_obstacle;

/* h(w) for the horizontal coordinates w of x (x has dim components). */
double lac_obstacle_height (const lac_obstacle *o, const double *x);

/* The closest point projection of x onto the graph: the signed distance
 * g (> 0 above the graph), the unit outward normal n of the obstacle at
 * the closest point (dim components) and, if dndx is not NULL, its
 * derivative dn_r/dx_c at dndx[r dim + c] (the derivative of g is n).
 * LAC_EINVAL if the projection does not converge or x lies beyond the
 * centre of curvature of a hollow obstacle (no unique closest point). */
int lac_obstacle_project (const lac_obstacle *o, const double *x, double *g,
                          double *n, double *dndx);

/* The gap g along the unit direction n: x + g n is on the graph (the root
 * of smallest |g|).  LAC_EINVAL if the line never meets the graph. */
int lac_obstacle_gap (const lac_obstacle *o, const double *x,
                      const double *n, double *g);

/* Integration points of every slave facet (a rule of the given exact
 * degree, 0: as lac_pairing_opts_init) with their exact gaps (signed
 * distances) and the directions nu = -n^O of the constraint. */
int lac_obstacle_pairing (const lac_pairing_facets *slave,
                          const lac_obstacle *o, int degree,
                          lac_pairing **out);

#endif /* LAC_OBSTACLE_H */
