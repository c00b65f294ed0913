/* lac_contact_facet.h -- the map of one contact facet at a point
 *                                                  [LAC (16)-(18), Def. 1]
 *
 * Every integral over the slave surface (the measures of Definition 1, the
 * columns of C and the mean gaps, node-to-segment, the obstacle's points)
 * evaluates a facet (cell, local face) of a mesh at a reference point of
 * the face: its point x, its shape functions, its unit outward normal and
 * its surface element.  A pure function of the mesh (lac_contact_facet.c).
 */
#ifndef LAC_CONTACT_FACET_H
#define LAC_CONTACT_FACET_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "fem/lac_spaces.h"

/* Geometry of one facet (cell, face) of a mesh at reference point xi:
 * fills m (x, N, unit outward normal, detJ) and the facet's global nodes
 * (returns their number, or a negative status: -LAC_ESANITY for a cell
 * without that face, minus the status of lac_map_face). */
int lac_contact_facet_eval (const lac_mesh *mesh, size_t cell, int face,
                            const double *xi, int *nodes, lac_map *m);

#endif /* LAC_CONTACT_FACET_H */
