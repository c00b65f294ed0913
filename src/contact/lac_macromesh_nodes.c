/* lac_macromesh_nodes.c -- measures and interior nodes of T^M
 *                                      [LAC §4.4, Remark 1, Definition 1]
 *
 * Step 4 of lac_macromesh_build (lac_macromesh.c), and the interior nodes
 * of a patch behind the public lac_macromesh_interior.  For each
 * macro-element T^m (a patch of sub-facets of the refined mesh):
 *
 *   - its measure |T^m| and the integrals int_{T^m} phi_i of the nodal
 *     basis functions of its nodes (Gauss rules of order 6 on the
 *     sub-facets);
 *   - its interior nodes: nodes of its sub-facets that are on no boundary
 *     edge (3D) or end (2D) of the patch, i.e. on no edge that only one
 *     sub-facet has, and on no other macro-element;
 *   - the designated one x_{m*+1}: the interior node of largest integral,
 *     lowest index on ties [LAC Remark 1].
 */
#include "contact/lac_macromesh_nodes.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "base/lac_mem.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

/* ---- the nodes of a patch of sub-facets --------------------------------- */

/* Nodes and edges of a patch under examination. */
typedef struct patch
{
  int fn[LAC_MACRO_MAXSUBF][LAC_MAX_FACE_NODES]; /* nodes of each sub-facet */
  size_t ekey[LAC_MACRO_MAXSUBF * 4][2];         /* edges: sorted end nodes */
  int ecount[LAC_MACRO_MAXSUBF * 4], ne;         /* sub-facets per edge     */
} patch;

/* The sorted end nodes (a, b) of edge e of a sub-facet of type rf with
 * nodes fn; in 2D the "edge" is end e, and a = b. */
static void
edge_key (const lac_refelem *rf, const int *fn, int e, size_t *a, size_t *b)
{
  if (rf->dim == 1)
    {
      *a = *b = (size_t) fn[e];
      return;
    }
  *a = (size_t) fn[rf->face_node[e][0]];
  *b = (size_t) fn[rf->face_node[e][1]];
  if (*a > *b)
    {
      size_t t = *a;
      *a = *b;
      *b = t;
    }
}

/* The face type of sub-facet (cell, face) and its number of edges (ends). */
static const lac_refelem *
subfacet_type (const lac_mesh *m, size_t cell, int face, int *nedge)
{
  const lac_refelem *re = lac_refelem_get (m->type[cell]);
  const lac_refelem *rf = lac_refelem_get (re->face_type[face]);
  *nedge = rf->dim == 1 ? 2 : rf->nfaces;
  return rf;
}

/* Count, for each edge (end in 2D) of the patch, the sub-facets having it. */
static void
count_edges (const lac_mesh *m, const size_t *cell, const int *face,
             size_t nsub, patch *P)
{
  P->ne = 0;
  for (size_t j = 0; j < nsub; j++)
    {
      int nedge;
      const lac_refelem *rf = subfacet_type (m, cell[j], face[j], &nedge);
      for (int e = 0; e < nedge; e++)
        {
          size_t a, b;
          int i = 0;
          edge_key (rf, P->fn[j], e, &a, &b);
          while (i < P->ne && !(P->ekey[i][0] == a && P->ekey[i][1] == b))
            i++;
          if (i == P->ne)
            P->ekey[P->ne][0] = a, P->ekey[P->ne][1] = b,
              P->ecount[P->ne++] = 0;
          P->ecount[i]++;
        }
    }
}

/* inter[k] = 0 for the nodes of the boundary edges of the patch: those
 * that only one sub-facet has. */
static void
mark_boundary (const lac_mesh *m, const size_t *cell, const int *face,
               size_t nsub, const patch *P, const size_t *node, size_t nn,
               int *inter)
{
  for (size_t j = 0; j < nsub; j++)
    {
      int nedge;
      const lac_refelem *rf = subfacet_type (m, cell[j], face[j], &nedge);
      for (int e = 0; e < nedge; e++)
        {
          const lac_refelem *rd = rf->dim == 1 ? NULL
                                  : lac_refelem_get (rf->face_type[e]);
          int nen = rd ? rd->nnodes : 1;
          size_t a, b;
          int i = 0;
          edge_key (rf, P->fn[j], e, &a, &b);
          while (!(P->ekey[i][0] == a && P->ekey[i][1] == b))
            i++;
          if (P->ecount[i] != 1)
            continue;
          for (int q = 0; q < nen; q++)       /* the edge's nodes: boundary */
            {
              size_t v = (size_t) P->fn[j][rd ? rf->face_node[e][q] : e];
              for (size_t k = 0; k < nn; k++)
                if (node[k] == v)
                  inter[k] = 0;
            }
        }
    }
}

/* The distinct nodes of the patch of sub-facets (cell[j], face[j]), j <
 * nsub, and which of them are interior: not on an edge (3D) or end (2D)
 * that only one sub-facet of the patch has.  Returns the number of nodes,
 * or 0 if the patch is too large. */
static size_t
patch_nodes (const lac_mesh *m, const size_t *cell, const int *face,
             size_t nsub, size_t *node, int *inter)
{
  patch P;
  size_t nn = 0;

  if (nsub > LAC_MACRO_MAXSUBF)
    return 0;
  for (size_t j = 0; j < nsub; j++)
    {
      int nfn = lac_mesh_facet_nodes (m, cell[j], face[j], P.fn[j], NULL);
      if (nfn <= 0)
        return 0;
      for (int a = 0; a < nfn; a++)
        {
          size_t v = (size_t) P.fn[j][a], i = 0;
          while (i < nn && node[i] != v)
            i++;
          if (i == nn)
            node[nn] = v, inter[nn++] = 1;
        }
    }
  count_edges (m, cell, face, nsub, &P);
  mark_boundary (m, cell, face, nsub, &P, node, nn, inter);
  return nn;
}

/* ---- step 4: measures and the designated nodes -------------------------- */

enum { LINE, TRI, QUAD };   /* the quadrature rules of the sub-facets */

static const size_t NONE = SIZE_MAX, SEVERAL = SIZE_MAX - 1;

/* owner[i]: the macro-element whose facets hold node i, SEVERAL if more
 * than one, NONE if none. */
static void
node_owners (const lac_mesh *m, const lac_macro_list *L, size_t *owner)
{
  for (size_t i = 0; i < m->nnodes; i++)
    owner[i] = NONE;
  for (size_t k = 0; k < L->n; k++)
    for (size_t j = L->ptr[k]; j < L->ptr[k + 1]; j++)
      {
        int fn[LAC_MAX_FACE_NODES];
        int nf = lac_mesh_facet_nodes (m, L->cell[j], L->face[j], fn, NULL);
        for (int a = 0; a < nf; a++)
          {
            size_t *o = &owner[fn[a]];
            *o = *o == NONE || *o == k ? k : SEVERAL;
          }
      }
}

/* |T^k| = sum int 1 and int_{T^k} phi_i = sum int N_a (i = node a) over the
 * sub-facets of T^k, whose nn nodes are node[]; integ[i] for node[i]. */
static int
macro_integrals (const lac_mesh *m, const lac_macro_list *L, size_t k,
                 lac_quad *const *rule, const size_t *node, size_t nn,
                 double *integ, double *meas)
{
  for (size_t i = 0; i < nn; i++)
    integ[i] = 0;
  *meas = 0;
  for (size_t j = L->ptr[k]; j < L->ptr[k + 1]; j++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[L->cell[j]]);
      const lac_refelem *rf = lac_refelem_get (re->face_type[L->face[j]]);
      const lac_quad *q = rule[rf->shape == LAC_SHAPE_LINE ? LINE
                               : rf->shape == LAC_SHAPE_TRI ? TRI : QUAD];
      int fn[LAC_MAX_FACE_NODES], slot[LAC_MAX_FACE_NODES];
      double xe[LAC_MAX_FACE_NODES * 3];
      lac_mesh_facet_nodes (m, L->cell[j], L->face[j], fn, NULL);
      for (int a = 0; a < rf->nnodes; a++)
        {
          size_t i = 0;
          while (node[i] != (size_t) fn[a])
            i++;
          slot[a] = (int) i;
          for (int d = 0; d < m->dim; d++)
            xe[a * m->dim + d] = m->x[(size_t) fn[a] * (size_t) m->dim
                                      + (size_t) d];
        }
      for (int p = 0; p < q->n; p++)
        {
          lac_map mp;
          int status = lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
          if (status)
            return status;
          *meas += q->w[p] * mp.detJ;
          for (int a = 0; a < rf->nnodes; a++)
            integ[slot[a]] += q->w[p] * mp.N[a] * mp.detJ;
        }
    }
  return LAC_SUCCESS;
}

/* x_{m*+1} of T^k: the interior node (of T^k only) of largest integral,
 * lowest index on ties  [LAC Remark 1].  Returns 0 if there is none. */
static int
designated_node (size_t k, const size_t *node, const int *inter,
                 const double *integ, size_t nn, const size_t *owner,
                 size_t *best)
{
  int found = 0;
  *best = 0;
  for (size_t i = 0; i < nn; i++)
    {
      double tie = 1e-12 * fabs (integ[*best]);
      int better;
      if (!inter[i] || owner[node[i]] != k)
        continue;
      better = !found || integ[i] > integ[*best] + tie
               || (fabs (integ[i] - integ[*best]) <= tie
                   && node[i] < node[*best]);
      if (better)
        *best = i, found = 1;
    }
  return found;
}

/* lac_macromesh_finish: meas, inode, phi of every macro-element. */
int
lac_macromesh_finish (const lac_mesh *m, const lac_macro_list *L,
                      size_t *inode, double *meas, double *phi)
{
  lac_quad *rule[3] = { NULL, NULL, NULL };
  size_t *owner = lac_malloc (m->nnodes * sizeof *owner);
  int status = LAC_SUCCESS;

  rule[LINE] = lac_quad_alloc (LAC_SHAPE_LINE, 6);
  rule[TRI] = lac_quad_alloc (LAC_SHAPE_TRI, 6);
  rule[QUAD] = lac_quad_alloc (LAC_SHAPE_QUAD, 6);
  if (!owner || !rule[LINE] || !rule[TRI] || !rule[QUAD])
    {
      status = LAC_MACRO_ERRMSG (LAC_ENOMEM, "quadrature for macro-elements");
      goto done;
    }
  node_owners (m, L, owner);
  for (size_t k = 0; k < L->n && !status; k++)
    {
      size_t node[LAC_MACRO_MAXPATCH], nsub = L->ptr[k + 1] - L->ptr[k];
      size_t nn, best;
      int inter[LAC_MACRO_MAXPATCH];
      double integ[LAC_MACRO_MAXPATCH], mk;

      nn = patch_nodes (m, L->cell + L->ptr[k], L->face + L->ptr[k], nsub,
                        node, inter);
      if (nn == 0)
        {
          status = LAC_MACRO_ERRMSG (LAC_ESANITY, "macro-element %zu: %zu "
                                     "sub-facets, bad or too many", k, nsub);
          break;
        }
      status = macro_integrals (m, L, k, rule, node, nn, integ, &mk);
      if (status)
        break;
      if (!designated_node (k, node, inter, integ, nn, owner, &best))
        {
          status = LAC_MACRO_ERRMSG (LAC_ESANITY, "macro-element %zu (cell "
                                     "%zu, face %d) has no interior node", k,
                                     L->cell[L->ptr[k]], L->face[L->ptr[k]]);
          break;
        }
      inode[k] = node[best];
      phi[k] = integ[best];
      meas[k] = mk;
    }
done:
  lac_free (owner);
  for (int s = 0; s < 3; s++)
    lac_quad_free (rule[s]);
  return status;
}

/* ---- public ------------------------------------------------------------- */

static int
cmp_size (const void *a, const void *b)
{
  size_t x = *(const size_t *) a, y = *(const size_t *) b;
  return x < y ? -1 : x > y;
}

/* lac_macromesh_patch_interior: the interior nodes of a patch, sorted. */
size_t
lac_macromesh_patch_interior (const lac_mesh *m, const size_t *cell,
                              const int *face, size_t nsub, size_t *nodes,
                              size_t nmax)
{
  size_t node[LAC_MACRO_MAXPATCH], nn, count = 0;
  int inter[LAC_MACRO_MAXPATCH];

  nn = patch_nodes (m, cell, face, nsub, node, inter);
  for (size_t i = 0; i < nn; i++)
    if (inter[i])
      node[count++] = node[i];
  qsort (node, count, sizeof *node, cmp_size);
  for (size_t i = 0; i < count && i < nmax; i++)
    nodes[i] = node[i];
  return count;
}
