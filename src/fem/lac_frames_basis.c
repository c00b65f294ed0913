/* lac_frames_basis.c -- the frame of the conditions at a node, and the
 *                       nodal normals of a facet group (see lac_frames.h)
 *                                                        [LAC (4), (8)]
 */
#include "fem/lac_frames.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* ---- the frame of the conditions at a node ------------------------------ */

/* Column k of R (row-major 3 x 3) into q, and back. */
static void
column_get (const double *R, int k, double *q)
{
  for (int i = 0; i < 3; i++)
    q[i] = R[3 * i + k];
}

static void
column_set (double *R, int k, const double *q)
{
  for (int i = 0; i < 3; i++)
    R[3 * i + k] = q[i];
}

/* w = d minus its components along the first r columns of R (twice, for
 * the orthogonality of nearly dependent directions); L[k] = d . q_k. */
static double
orthogonalize (const double *R, int r, const double *d, double *w, double *L)
{
  memcpy (w, d, 3 * sizeof *w);
  for (int k = 0; k < r; k++)
    L[k] = 0;
  for (int pass = 0; pass < 2; pass++)
    for (int k = 0; k < r; k++)
      {
        double q[3], s;
        column_get (R, k, q);
        s = lac_vec_dot (3, w, q);
        L[k] += s;
        for (int i = 0; i < 3; i++)
          w[i] -= s * q[i];
      }
  return lac_vec_norm (3, w);
}

/* The free axes: R's columns r .. dim-1 orthonormal to the first r. */
static void
complete (int dim, int r, double *R)
{
  for (int k = r; k < dim; k++)
    {
      double best[3] = { 0, 0, 0 }, nb = -1, L[3];
      for (int c = 0; c < dim; c++)     /* the axis least in the span */
        {
          double e[3] = { 0, 0, 0 }, w[3];
          e[c] = 1;
          double nw = orthogonalize (R, k, e, w, L);
          if (nw > nb + 1e-3)
            nb = nw, memcpy (best, w, sizeof w);
        }
      for (int i = 0; i < 3; i++)
        best[i] /= nb;
      column_set (R, k, best);
    }
  for (int k = dim; k < 3; k++)
    {
      double e[3] = { 0, 0, 0 };
      e[k] = 1;
      column_set (R, k, e);
    }
}

int
lac_frames_basis (int dim, size_t n, const double *d, const double *v,
                  double *R, double *w, char *indep, int *rank,
                  size_t *bad, size_t *with)
{
  int r = 0;
  memset (R, 0, 9 * sizeof *R);
  memset (w, 0, 3 * sizeof *w);
  *bad = *with = (size_t) -1;
  for (size_t j = 0; j < n; j++)
    {
      double res[3], L[3], s = 0, scale = fabs (v[j]);
      double nr = orthogonalize (R, r, d + 3 * j, res, L);
      if (r == dim)                   /* every axis fixed: nothing new */
        nr = 0;
      for (int k = 0; k < r; k++)
        s += L[k] * w[k], scale = fmax (scale, fabs (w[k]));
      indep[j] = nr > LAC_FRAMES_DEPENDENT;
      if (indep[j])                   /* a new axis: q_r . u = w_r */
        {
          for (int i = 0; i < 3; i++)
            res[i] /= nr;
          column_set (R, r, res);
          w[r++] = (v[j] - s) / nr;
        }
      else if (fabs (v[j] - s) > 1e-9 * scale)     /* d_j . u = v_j ? */
        {
          *bad = j;
          for (size_t i = 0; i < j && *with == (size_t) -1; i++)
            if (fabs (lac_vec_dot (3, d + 3 * i, d + 3 * j)) > LAC_FRAMES_DEPENDENT)
              *with = i;
          return LAC_EINVAL;
        }
    }
  complete (dim, r, R);
  *rank = r;
  return LAC_SUCCESS;
}

/* ---- nodal normals ------------------------------------------------------- */

static int
cmp_node (const void *a, const void *b)
{
  size_t x = *(const size_t *) a, y = *(const size_t *) b;
  return (x > y) - (x < y);
}

/* Add the unit normal of facet e of g at each of its nodes to n. */
static int
facet_normals (const lac_mesh *m, const lac_group *g, size_t e, double *n)
{
  int fn[LAC_MAX_FACE_NODES], dim = m->dim;
  double xe[LAC_MAX_FACE_NODES * 3];
  lac_elem_type ft;
  lac_map mp;
  int nf = lac_mesh_facet_nodes (m, g->cell[e], g->face[e], fn, &ft);
  const lac_refelem *rf = nf > 0 ? lac_refelem_get (ft) : NULL;
  if (!rf || rf->dim != dim - 1)
    LAC_ERROR (LAC_EINVAL, "group '%s': facet %zu is not a facet of cell "
               "%zu", g->name, e + 1, m->cell_tag[g->cell[e]]);
  for (int a = 0; a < nf; a++)
    for (int i = 0; i < dim; i++)
      xe[a * dim + i] = m->x[(size_t) dim * (size_t) fn[a] + (size_t) i];
  for (int a = 0; a < nf; a++)
    {
      size_t node = (size_t) fn[a];
      const size_t *k = bsearch (&node, g->node, g->nnodes, sizeof node,
                                 cmp_node);
      if (lac_map_face (rf, dim, xe, rf->xi + a * rf->dim, &mp) || !k)
        LAC_ERROR (LAC_ESING, "group '%s': the facet of cell %zu at node "
                   "%zu is degenerate", g->name, m->cell_tag[g->cell[e]],
                   m->node_tag[node]);
      for (int i = 0; i < dim; i++)
        n[3 * (size_t) (k - g->node) + (size_t) i] += mp.normal[i];
    }
  return LAC_SUCCESS;
}

int
lac_frames_normals (const lac_mesh *m, const lac_group *g, double *n)
{
  int status = LAC_SUCCESS;
  if (g->dim != m->dim - 1 || g->n == 0)
    LAC_ERROR (LAC_EINVAL, "group '%s' has no facets: a normal needs a "
               "group of boundary facets (dimension %d)", g->name,
               m->dim - 1);
  memset (n, 0, 3 * g->nnodes * sizeof *n);
  for (size_t e = 0; e < g->n && !status; e++)
    status = facet_normals (m, g, e, n);
  for (size_t k = 0; k < g->nnodes && !status; k++)
    {
      double *nk = n + 3 * k, s = lac_vec_norm (3, nk);   /* of unit normals */
      if (!(s > 1e-6))
        LAC_ERROR (LAC_ESING, "group '%s': the normals of its facets at "
                   "node %zu cancel (facets on both sides of a sheet?)",
                   g->name, m->node_tag[g->node[k]]);
      for (int i = 0; i < 3; i++)
        nk[i] /= s;
    }
  return status;
}
