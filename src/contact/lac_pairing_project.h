/* lac_pairing_project.h -- projection of a point onto a face map
 *                                                      [LAC §4.6, item 2]
 *
 * A pure function of one (possibly curved) face and a point: the point of
 * the face hit along a direction, or the closest one, in the face's
 * reference coordinates (the method is in lac_pairing_project.c).  Used by
 * the pairing's integration points (lac_pairing_geom.h) and by the
 * node-to-segment method (lac_nts.c).
 */
#ifndef LAC_PAIRING_PROJECT_H
#define LAC_PAIRING_PROJECT_H

#include "fem/lac_spaces.h"

/* Projection onto a face map x = X(xi) (re: a seg/tri/quad face element,
 * sdim = re->dim + 1, xe: its nodes).  With dir != NULL, solve
 *   X(xi) = x + t dir                         (projection along dir)
 * by Newton's method with line search in (xi, t); with dir == NULL, find
 * the closest point, (X(xi) - x).dX/dxi_k = 0 (Gauss-Newton), and return
 * t = (x - X(xi)).n(xi).  xi is the starting point on input.
 * Returns LAC_SUCCESS, LAC_EMAXITER (no convergence, or xi left the
 * neighbourhood |xi| <= 100 of the reference cell), LAC_ESING (dir tangent
 * to the face, or degenerate face); never loops more than 50 iterations. */
int lac_pairing_project (const lac_refelem *re, int sdim, const double *xe,
                         const double *x, const double *dir, double *xi,
                         double *t);

/* Diameter of the vertex set of a face, max over vertex pairs of
 * |x_a - x_b|: the length scale against which the projection and the
 * overlaps (lac_pairing_geom.c) measure their residuals. */
double lac_pairing_face_diameter (const lac_refelem *re, int sdim,
                                  const double *xe);

#endif /* LAC_PAIRING_PROJECT_H */
