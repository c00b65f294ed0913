/* lac_pairing_internal.h -- internal: shared by the lac_pairing_*.c kernels
 *                                                                 [LAC §4.6]
 * Not part of the public interface.  lac_pairing_project.c (projection onto
 * a face map) and lac_pairing_geom.c (facets, overlap, points) measure their
 * residuals against the same length scale of a face.
 */
#ifndef LAC_PAIRING_INTERNAL_H
#define LAC_PAIRING_INTERNAL_H

#include "fem/lac_spaces.h"

/* Diameter of the vertex set of a face (the length scale of residuals):
 * max over vertex pairs of |x_a - x_b| (lac_pairing_project.c). */
double lac_pairing_face_diameter (const lac_refelem *re, int sdim,
                                  const double *xe);

#endif /* LAC_PAIRING_INTERNAL_H */
