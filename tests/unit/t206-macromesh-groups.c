/* t206: refinement remaps every group of the mesh             [LAC §4.4]
 *
 * After lac_macromesh_build on box meshes (slave zmax, or ymax in 2D):
 *   - every side group (xmin ... zmax) still lies on its side (all facet
 *     nodes on the plane) and keeps its area: sides sharing an edge with
 *     the slave side (symmetry planes, clamps) follow the cut cells;
 *   - the cell group "body" lists every cell once, body[c] still points to
 *     it, sub-cells keep their parent's cell_tag;
 *   - a node group (dimension < dim-1) keeps its nodes;
 *   - old nodes keep their coordinates and indices.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

static double
group_area (const lac_mesh *m, const lac_group *G)
{
  double area = 0;
  for (size_t e = 0; e < G->n; e++)
    {
      int nodes[LAC_MAX_FACE_NODES], nn;
      lac_elem_type ft;
      const lac_refelem *rf;
      lac_quad *q;
      double xe[LAC_MAX_FACE_NODES * 3];
      nn = lac_mesh_facet_nodes (m, G->cell[e], G->face[e], nodes, &ft);
      rf = lac_refelem_get (ft);
      q = lac_quad_alloc (rf->shape, 4);
      for (int a = 0; a < nn; a++)
        for (int d = 0; d < m->dim; d++)
          xe[a * m->dim + d] = m->x[(size_t) nodes[a] * m->dim + d];
      for (int p = 0; p < q->n; p++)
        {
          lac_map mp;
          lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
          area += q->w[p] * mp.detJ;
        }
      lac_quad_free (q);
    }
  return area;
}

static void
run (lac_elem_type t, const lac_macro_opts *opts, const char *label)
{
  static const char *side[6] = { "xmin", "xmax", "ymin", "ymax", "zmin",
                                 "zmax" };
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 2, 2, 2 }, nn0, corner[2] = { 0, 0 };
  double L[3] = { 1, 1.5, 2 }, area0[6], *x0;
  int d = re->dim;
  const char *slave = d == 3 ? "zmax" : "ymax";
  lac_mesh *m = NULL;
  lac_macro *M = NULL;
  size_t *tag0;
  char what[64];

  snprintf (what, sizeof what, "%s %s", re->name, label);
  check_status (lac_mesh_box (t, n, L, 0.2, &m), LAC_SUCCESS, "%s: box",
                what);
  if (!m)
    return;
  for (int s = 0; s < 2 * d; s++)
    area0[s] = group_area (m, lac_mesh_group (m, side[s]));
  /* a node group: the first nodes of the slave side */
  corner[0] = lac_mesh_group (m, slave)->node[0];
  corner[1] = lac_mesh_group (m, slave)->node[1];
  lac_mesh_add_node_group (m, "corner", 0, 7, 2, corner);
  nn0 = m->nnodes;
  x0 = malloc (nn0 * (size_t) d * sizeof *x0);
  memcpy (x0, m->x, nn0 * (size_t) d * sizeof *x0);
  tag0 = malloc (m->ncells * sizeof *tag0);
  memcpy (tag0, m->cell_tag, m->ncells * sizeof *tag0);

  check_status (lac_macromesh_build (&m, slave, opts, &M), LAC_SUCCESS,
                "%s: build", what);
  check_true (m->nnodes > nn0 || t == LAC_HEX27 || re->order == 2,
              "%s: refined", what);
  check_true (!memcmp (x0, m->x, nn0 * (size_t) d * sizeof *x0),
              "%s: old nodes unchanged", what);

  for (int s = 0; s < 2 * d; s++)
    {
      const lac_group *G = lac_mesh_group (m, side[s]);
      int axis = s / 2, off = 0;
      double plane = s % 2 ? L[axis] : 0;
      for (size_t e = 0; e < G->n; e++)
        {
          int nodes[LAC_MAX_FACE_NODES];
          int k = lac_mesh_facet_nodes (m, G->cell[e], G->face[e], nodes,
                                        NULL);
          for (int a = 0; a < k; a++)
            off |= fabs (m->x[(size_t) nodes[a] * d + axis] - plane) > 1e-13;
        }
      check_true (!off, "%s: group %s on its side", what, side[s]);
      check_rel (group_area (m, G), area0[s], 1e-13, "%s: group %s area",
                 what, side[s]);
      for (size_t i = 0; i < G->nnodes; i++)
        off |= fabs (m->x[G->node[i] * d + axis] - plane) > 1e-13;
      check_true (!off, "%s: group %s node list on its side", what,
                  side[s]);
    }
  {
    const lac_group *B = lac_mesh_group (m, "body");
    int ok = B && B->n == m->ncells;
    for (size_t e = 0; ok && e < B->n; e++)
      ok = B->cell[e] == e && m->body[e] >= 0
           && &m->group[m->body[e]] == B;
    check_true (ok, "%s: body group and body[] cover the new cells", what);
  }
  {
    const lac_group *C = lac_mesh_group (m, "corner");
    check_true (C && C->dim == 0 && C->tag == 7 && C->nnodes == 2
                && C->node[0] == corner[0] && C->node[1] == corner[1],
                "%s: node group kept", what);
  }
  {
    /* cells appear in parent order: tags never decrease, and every old
     * tag is still there */
    int ok = 1;
    for (size_t c = 1; c < m->ncells; c++)
      ok &= m->cell_tag[c] >= m->cell_tag[c - 1];
    ok &= m->cell_tag[0] == tag0[0];
    check_true (ok, "%s: sub-cells keep their parent's tag, in order", what);
  }
  free (x0);
  free (tag0);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 }, cut2d = { 0, 1 };
  lac_init ();
  run (LAC_TET4, NULL, "");
  run (LAC_TET10, NULL, "");
  run (LAC_HEX8, NULL, "pyramids");
  run (LAC_HEX8, &six, "six");
  run (LAC_HEX20, NULL, "six");
  run (LAC_HEX27, NULL, "");
  run (LAC_TRI3, &cut2d, "cut");
  run (LAC_QUAD4, &cut2d, "cut");
  run (LAC_TRI6, NULL, "");
  lac_finalize ();
  return check_summary ();
}
