/* lac_contact_facet.c -- the map of one contact facet at a point
 *                                                  [LAC (16)-(18), Def. 1]
 *
 * The facet's nodes from its cell (lac_mesh_facet_nodes, oriented
 * outward), their coordinates, then the face map of its element at xi
 * (lac_map_face).
 */
#include "contact/lac_contact_facet.h"

#include "base/lac_status.h"

int
lac_contact_facet_eval (const lac_mesh *mesh, size_t cell, int face,
                        const double *xi, int *nodes, lac_map *m)
{
  lac_elem_type ft;
  double xe[LAC_MAX_FACE_NODES * 3];
  int dim = mesh->dim;
  int nn = lac_mesh_facet_nodes (mesh, cell, face, nodes, &ft);
  const lac_refelem *re = lac_refelem_get (ft);
  if (nn <= 0 || !re)
    return -LAC_ERRMSG (LAC_ESANITY, "cell %zu has no face %d", cell, face);
  for (int a = 0; a < nn; a++)
    for (int k = 0; k < dim; k++)
      xe[a * dim + k] = mesh->x[(size_t) nodes[a] * dim + k];
  int st = lac_map_face (re, dim, xe, xi, m);
  return st ? -st : nn;
}
