/* lac_macromesh_nodes.h -- measures and interior nodes of T^M
 *                                      [LAC §4.4, Remark 1, Definition 1]
 *
 * Step 4 of lac_macromesh_build (lac_macromesh.c), and the interior nodes
 * of one patch of sub-facets behind lac_macromesh_interior.  An interior
 * node of a patch is a node of its sub-facets that is on no boundary edge
 * (3D) or end (2D) of the patch; for T^m it must also be on no other
 * macro-element, so that its trace basis function is supported in T^m
 * [LAC Hyp. 1].  The method is in lac_macromesh_nodes.c.
 */
#ifndef LAC_MACROMESH_NODES_H
#define LAC_MACROMESH_NODES_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "contact/lac_macro_list.h"

/* For every macro-element k of L on mesh m: meas[k] = |T^k|, inode[k] the
 * designated interior node x_{k*+1} (the largest int_{T^k} phi_i, lowest
 * index on ties [LAC Remark 1]) and phi[k] = int_{T^k} phi_{inode[k]}
 * (arrays of L->n entries).  LAC_ESANITY (a macro-element with no interior
 * node, or too many sub-facets), LAC_ENOMEM. */
int lac_macromesh_finish (const lac_mesh *m, const lac_macro_list *L,
                          size_t *inode, double *meas, double *phi);

/* The interior nodes of the patch of sub-facets (cell[j], face[j]), j <
 * nsub, sorted; writes at most nmax of them and returns how many there are
 * (0 for a bad or too large patch). */
size_t lac_macromesh_patch_interior (const lac_mesh *m, const size_t *cell,
                                     const int *face, size_t nsub,
                                     size_t *nodes, size_t nmax);

#endif /* LAC_MACROMESH_NODES_H */
