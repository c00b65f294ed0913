/* lac_mesh_check.c -- a mesh that can be trusted (see lac_mesh_check.h)
 *
 * Validation walks the arrays once.  The topology checks take one cell
 * at a time:
 *
 *   - flat cells: the measure of the straight-sided cell from its faces,
 *     (1/d) sum_f a_f . o_f (divergence theorem: a_f the area vector of
 *     face f, o_f the centre of its vertices), against its diameter^d;
 *   - faces: every face of every cell goes into a hash table keyed by its
 *     sorted vertices.  A face met a third time is a face of three cells.
 *     A face met a second time is interior: its two cells must not have
 *     the same vertices (a cell listed twice, under the same tag or
 *     another) and must lie on opposite sides of it: the centroids of
 *     their vertices give signed distances of opposite signs to the plane
 *     (the line, in 2D) of the face's vertices; and they must share all
 *     its nodes, not its vertices only (a tri6 beside a tri3, or two
 *     quadratic cells with mid-edge nodes of their own, are not
 *     conforming: the displacement would jump across the face).
 *
 * Why face by face: summed over a mesh whose cells are all positively
 * oriented, the measures of the cells always equal the volume enclosed by
 * the boundary faces (the interior faces cancel), even when two cells are
 * folded over each other; what the divergence theorem does see is the
 * pair of cells on the same side of their common face, which the region
 * covers twice, and that is checked here with the cells named.
 */
#include "fem/lac_mesh_check.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* ---------------------------------------------------------------------- */
/* validation                                                              */
/* ---------------------------------------------------------------------- */

static int
validate_nodes (const lac_mesh *m)
{
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; i < m->dim; i++)
      {
        double x = m->x[a * (size_t) m->dim + (size_t) i];
        if (!isfinite (x) || fabs (x) > LAC_MESH_COORD_MAX)
          LAC_ERROR (LAC_EINVAL, "node %zu has coordinate %c = %g (expected "
                     "a finite number of magnitude at most %g)",
                     m->node_tag ? m->node_tag[a] : a + 1, "xyz"[i], x,
                     LAC_MESH_COORD_MAX);
      }
  return LAC_SUCCESS;
}

static int
validate_cells (const lac_mesh *m)
{
  if (m->ptr[0] != 0)
    LAC_ERROR (LAC_EINVAL, "connectivity does not start at 0");
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      size_t tag = m->cell_tag ? m->cell_tag[c] : c + 1;
      if (!re || re->dim != m->dim)
        LAC_ERROR (LAC_EINVAL, "cell %zu: %s in a %dD mesh", tag,
                   re ? re->name : "no known type", m->dim);
      if (m->ptr[c + 1] < m->ptr[c]
          || m->ptr[c + 1] - m->ptr[c] != (size_t) re->nnodes)
        LAC_ERROR (LAC_EINVAL, "cell %zu (%s) has %zu nodes, a %s has %d",
                   tag, re->name, m->ptr[c + 1] < m->ptr[c] ? 0
                   : m->ptr[c + 1] - m->ptr[c], re->name, re->nnodes);
      for (size_t k = m->ptr[c]; k < m->ptr[c + 1]; k++)
        if (m->conn[k] < 0 || (size_t) m->conn[k] >= m->nnodes)
          LAC_ERROR (LAC_EINVAL, "cell %zu (%s): node index %d out of range "
                     "(%zu nodes)", tag, re->name, m->conn[k], m->nnodes);
      if (m->body && (m->body[c] < -1 || m->body[c] >= (int) m->ngroups))
        LAC_ERROR (LAC_EINVAL, "cell %zu: body %d out of range", tag,
                   m->body[c]);
    }
  return LAC_SUCCESS;
}

static int
validate_group (const lac_mesh *m, const lac_group *G)
{
  if (!G->name || !G->name[0] || G->dim < 0 || G->dim > m->dim)
    LAC_ERROR (LAC_EINVAL, "a group without a name or of dimension %d",
               G->dim);
  for (size_t e = 0; G->dim >= m->dim - 1 && e < G->n; e++)
    {
      const lac_refelem *re;
      if (G->cell[e] >= m->ncells)
        LAC_ERROR (LAC_EINVAL, "group '%s': cell index %zu out of range",
                   G->name, G->cell[e]);
      re = lac_refelem_get (m->type[G->cell[e]]);
      if (G->dim == m->dim - 1
          && (!G->face || G->face[e] < 0 || G->face[e] >= re->nfaces))
        LAC_ERROR (LAC_EINVAL, "group '%s': cell %zu has no face %d",
                   G->name, m->cell_tag[G->cell[e]], G->face ? G->face[e]
                   : -1);
    }
  for (size_t k = 0; k < G->nnodes; k++)
    if (G->node[k] >= m->nnodes || (k > 0 && G->node[k] <= G->node[k - 1]))
      LAC_ERROR (LAC_EINVAL, "group '%s': node list not sorted or out of "
                 "range", G->name);
  return LAC_SUCCESS;
}

/* lac_mesh_validate: see lac_mesh_check.h. */
int
lac_mesh_validate (const lac_mesh *m)
{
  int status;
  if (!m || (m->dim != 2 && m->dim != 3) || !m->ptr
      || (m->nnodes && !m->x) || (m->ncells && (!m->type || !m->conn)))
    LAC_ERROR (LAC_EINVAL, "not a mesh (no arrays or dimension %d)",
               m ? m->dim : 0);
  if ((status = validate_nodes (m)) || (status = validate_cells (m)))
    return status;
  for (size_t g = 0; g < m->ngroups; g++)
    if ((status = validate_group (m, &m->group[g])))
      return status;
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* faces, in a hash table keyed by their sorted vertices                   */
/* ---------------------------------------------------------------------- */

typedef struct slot
{
  int v[4];            /* sorted vertices, padded with -1; v[0] < 0: empty */
  int face;            /* the local face of the first cell                 */
  size_t cell, cell2;  /* the first and second cell (SIZE_MAX: none yet)   */
} slot;

/* Centroid of the vertices of cell c. */
static void
cell_centroid (const lac_mesh *m, size_t c, double *g)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  size_t d = (size_t) m->dim;
  g[0] = g[1] = g[2] = 0;
  for (int a = 0; a < re->nvertices; a++)
    for (size_t i = 0; i < d; i++)
      g[i] += m->x[(size_t) m->conn[m->ptr[c] + (size_t) a] * d + i]
              / re->nvertices;
}

/* Area vector (2D: the edge's normal, its length; 3D: twice the area for
 * a triangle, the product of the diagonals for a quadrangle) and centre
 * of the vertices of face f of cell c. */
static void
face_plane (const lac_mesh *m, size_t c, int f, double *n, double *o)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  double p[4][3] = { { 0 } };
  size_t d = (size_t) m->dim;
  o[0] = o[1] = o[2] = 0;
  for (int a = 0; a < nv; a++)
    for (size_t i = 0; i < d; i++)
      {
        p[a][i] = m->x[(size_t) m->conn[m->ptr[c] + (size_t)
                                        re->face_node[f][a]] * d + i];
        o[i] += p[a][i] / nv;
      }
  if (d == 2)
    {
      n[0] = p[1][1] - p[0][1];
      n[1] = p[0][0] - p[1][0];
      n[2] = 0;
      return;
    }
  double u[3], v[3];
  for (int i = 0; i < 3; i++)
    {
      u[i] = p[nv == 4 ? 2 : 1][i] - p[0][i];
      v[i] = nv == 4 ? p[3][i] - p[1][i] : p[2][i] - p[0][i];
    }
  lac_vec_cross (u, v, n);
}

/* Do cells a and b lie on the same side of face fa of a? */
static int
folded (const lac_mesh *m, size_t a, int fa, size_t b)
{
  double n[3], o[3], ga[3], gb[3], sa = 0, sb = 0, scale = 0;
  face_plane (m, a, fa, n, o);
  cell_centroid (m, a, ga);
  cell_centroid (m, b, gb);
  for (int i = 0; i < 3; i++)
    {
      sa += n[i] * (ga[i] - o[i]);
      sb += n[i] * (gb[i] - o[i]);
      scale += fabs (n[i]) * (fabs (ga[i] - o[i]) + fabs (gb[i] - o[i]));
    }
  return sa * sb > 0 && fabs (sa) > 1e-12 * scale && fabs (sb) > 1e-12 * scale;
}

/* The vertices of cell c, sorted, padded with -1. */
static void
cell_key (const lac_mesh *m, size_t c, int *v)
{
  int nv = lac_refelem_get (m->type[c])->nvertices;
  for (int i = 0; i < LAC_MAX_NODES; i++)
    v[i] = i < nv ? m->conn[m->ptr[c] + (size_t) i] : INT_MAX;
  for (int i = 1; i < nv; i++)
    for (int j = i; j > 0 && v[j - 1] > v[j]; j--)
      {
        int t = v[j];
        v[j] = v[j - 1];
        v[j - 1] = t;
      }
}

/* Two cells with a common face: the same cell twice? */
static int
check_twice (const lac_mesh *m, size_t a, size_t b)
{
  int ka[LAC_MAX_NODES], kb[LAC_MAX_NODES];
  cell_key (m, a, ka);
  cell_key (m, b, kb);
  if (!memcmp (ka, kb, sizeof ka) && m->cell_tag[a] == m->cell_tag[b])
    LAC_ERROR (LAC_EINVAL, "cell %zu is listed twice", m->cell_tag[a]);
  if (!memcmp (ka, kb, sizeof ka))
    LAC_ERROR (LAC_EINVAL, "cells %zu and %zu have the same vertices (a cell"
               " listed twice)", m->cell_tag[a < b ? a : b],
               m->cell_tag[a < b ? b : a]);
  return LAC_SUCCESS;
}

/* The nodes of face f of cell c, sorted; returns their number. */
static int
face_nodes_sorted (const lac_mesh *m, size_t c, int f, int *v)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int n = lac_refelem_get (re->face_type[f])->nnodes;
  for (int a = 0; a < n; a++)
    v[a] = m->conn[m->ptr[c] + (size_t) re->face_node[f][a]];
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && v[j - 1] > v[j]; j--)
      {
        int t = v[j];
        v[j] = v[j - 1];
        v[j - 1] = t;
      }
  return n;
}

/* Cells a and b, which share the vertices of face fa of a and fb of b,
 * share all its nodes. */
static int
check_conforming (const lac_mesh *m, size_t a, int fa, size_t b, int fb)
{
  int va[LAC_MAX_NODES], vb[LAC_MAX_NODES];
  int na = face_nodes_sorted (m, a, fa, va), nb = face_nodes_sorted (m, b, fb,
                                                                     vb);
  if (na == nb && !memcmp (va, vb, (size_t) na * sizeof *va))
    return LAC_SUCCESS;
  LAC_ERROR (LAC_EINVAL, "cells %zu (%s) and %zu (%s) share the vertices of "
             "a face but not all its nodes (%d and %d nodes): the mesh is "
             "not conforming there, the displacement would jump across the "
             "face (cells of one order, sharing their edge and face nodes)",
             m->cell_tag[a], lac_refelem_get (m->type[a])->name,
             m->cell_tag[b], lac_refelem_get (m->type[b])->name, na, nb);
}

/* Two cells that share a face: the same cell twice, folded, or not
 * conforming? */
static int
check_pair (const lac_mesh *m, size_t a, int fa, size_t b, int fb)
{
  int status = check_twice (m, a, b);
  if (status || (status = check_conforming (m, a, fa, b, fb)))
    return status;
  if (folded (m, a, fa, b))
    LAC_ERROR (LAC_EINVAL, "cells %zu and %zu overlap: both lie on the same "
               "side of their common face", m->cell_tag[a < b ? a : b],
               m->cell_tag[a < b ? b : a]);
  return LAC_SUCCESS;
}

static size_t
face_hash (const int *v)
{
  uint64_t h = 0;
  for (int i = 0; i < 4; i++)
    {
      h = (h ^ (uint32_t) v[i]) * 0x9e3779b97f4a7c15u;
      h ^= h >> 32;
    }
  return (size_t) h;
}

/* Face f of cell c into the table (cap slots, a power of 2): a face met
 * for the second time is checked as a pair, a third time is an error. */
static int
add_face (const lac_mesh *m, slot *t, size_t cap, size_t c, int f)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int v[4] = { -1, -1, -1, -1 };
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  size_t h;
  for (int a = 0; a < nv; a++)
    v[a] = m->conn[m->ptr[c] + (size_t) re->face_node[f][a]];
  for (int i = 1; i < nv; i++)
    for (int j = i; j > 0 && v[j - 1] > v[j]; j--)
      {
        int tmp = v[j];
        v[j] = v[j - 1];
        v[j - 1] = tmp;
      }
  for (h = face_hash (v) & (cap - 1); t[h].v[0] >= 0; h = (h + 1) & (cap - 1))
    if (!memcmp (t[h].v, v, sizeof v))
      break;
  if (t[h].v[0] < 0)
    {
      memcpy (t[h].v, v, sizeof v);
      t[h].face = f;
      t[h].cell = c;
      t[h].cell2 = SIZE_MAX;
      return LAC_SUCCESS;
    }
  if (t[h].cell2 != SIZE_MAX)
    {
      int status = check_twice (m, t[h].cell, c);
      if (status || (status = check_twice (m, t[h].cell2, c)))
        return status;
    }
  if (t[h].cell2 != SIZE_MAX)
    LAC_ERROR (LAC_EINVAL, "cells %zu, %zu and %zu share a face (a face "
               "belongs to two cells at most)", m->cell_tag[t[h].cell],
               m->cell_tag[t[h].cell2], m->cell_tag[c]);
  t[h].cell2 = c;
  return check_pair (m, t[h].cell, t[h].face, c, f);
}

static int
check_faces (const lac_mesh *m)
{
  size_t n = 0, cap = 16;
  int status = LAC_SUCCESS;
  slot *t;
  for (size_t c = 0; c < m->ncells; c++)
    n += (size_t) lac_refelem_get (m->type[c])->nfaces;
  while (cap < 2 * n)
    cap *= 2;
  if (!(t = lac_malloc (cap * sizeof *t)))
    LAC_ERROR (LAC_ENOMEM, "a table of %zu faces", n);
  for (size_t h = 0; h < cap; h++)
    t[h].v[0] = -1;
  for (size_t c = 0; c < m->ncells && !status; c++)
    for (int f = 0; f < lac_refelem_get (m->type[c])->nfaces && !status; f++)
      status = add_face (m, t, cap, c, f);
  lac_free (t);
  return status;
}

/* ---------------------------------------------------------------------- */
/* degenerate cells                                                        */
/* ---------------------------------------------------------------------- */

/* The measure of cell c from its faces, (1/d) sum_f a_f . o_f (divergence
 * theorem on the straight-sided cell; a_f the area vector of face f, o_f
 * the centre of its vertices), and the largest distance between two of
 * its vertices. */
static void
cell_size (const lac_mesh *m, size_t c, double *measure, double *diam)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  const int *v = m->conn + m->ptr[c];
  size_t d = (size_t) m->dim;
  double sum = 0;
  for (int f = 0; f < re->nfaces; f++)
    {
      double n[3], o[3];
      face_plane (m, c, f, n, o);
      for (size_t i = 0; i < d; i++)
        sum += n[i] * o[i] / (d == 3 ? 2.0 : 1.0);
    }
  *measure = fabs (sum) / (double) d;
  *diam = 0;
  for (int a = 0; a < re->nvertices; a++)
    for (int b = a + 1; b < re->nvertices; b++)
      *diam = fmax (*diam, lac_vec_dist (d, m->x + (size_t) v[a] * d,
                                         m->x + (size_t) v[b] * d));
}

/* A cell whose measure is nothing next to its size: vertices at one
 * point, on one line (2D) or in one plane (3D). */
static int
check_degenerate (const lac_mesh *m)
{
  for (size_t c = 0; c < m->ncells; c++)
    {
      double measure, diam;
      cell_size (m, c, &measure, &diam);
      if (!(measure > LAC_MESH_FLAT * pow (diam, m->dim)))
        LAC_ERROR (LAC_EINVAL, "cell %zu (%s) is degenerate: its %s is %g "
                   "for a diameter of %g (vertices at one point or %s)",
                   m->cell_tag[c], lac_refelem_get (m->type[c])->name,
                   m->dim == 2 ? "area" : "volume", measure, diam,
                   m->dim == 2 ? "on one line" : "in one plane");
    }
  return LAC_SUCCESS;
}

/* lac_mesh_flattest: see lac_mesh_check.h. */
double
lac_mesh_flattest (const lac_mesh *m, size_t *cell, double *thick,
                   double *diam)
{
  double best = 1;
  *cell = 0, *thick = *diam = 0;
  for (size_t c = 0; c < m->ncells; c++)
    {
      double measure, d, t;
      cell_size (m, c, &measure, &d);
      t = d > 0 ? measure / pow (d, m->dim - 1) : 0;
      if (d > 0 && t / d < best)
        best = t / d, *cell = c, *thick = t, *diam = d;
    }
  return best;
}

/* lac_mesh_check_topology: see lac_mesh_check.h. */
int
lac_mesh_check_topology (const lac_mesh *m)
{
  int status = check_degenerate (m);
  return status ? status : check_faces (m);
}
