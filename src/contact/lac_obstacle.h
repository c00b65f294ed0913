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
 * covered, its integration points are those of its own rule, and the
 * initial gap at a point is obtained exactly: x_s + g n_s lies on the graph,
 * which is a quadratic equation in g (the root of smallest |g|; g > 0 when
 * open).  lac_obstacle_pairing returns a lac_pairing with nmaster = 0 and
 * master[p] = LAC_OBSTACLE_MASTER for every point, so that C has no master
 * part (C^M = 0) and the mean gaps G are exact integrals of the gap.
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
} lac_obstacle;

/* h(w) for the horizontal coordinates w of x (x has dim components). */
double lac_obstacle_height (const lac_obstacle *o, const double *x);

/* The gap g along the unit direction n: x + g n is on the graph (the root
 * of smallest |g|).  LAC_EINVAL if the line never meets the graph. */
int lac_obstacle_gap (const lac_obstacle *o, const double *x,
                      const double *n, double *g);

/* Integration points of every slave facet (a rule of the given exact
 * degree, 0: as lac_pairing_opts_init) with their exact gaps. */
int lac_obstacle_pairing (const lac_pairing_facets *slave,
                          const lac_obstacle *o, int degree,
                          lac_pairing **out);

#endif /* LAC_OBSTACLE_H */
