/* lac_macromesh.c -- the macro-mesh T^M of the slave contact boundary
 *                                                 [LAC Hyp. 1, §4.4, Fig. 2]
 *
 * Builds T^M in four steps (conventions and ownership in lac_macromesh.h):
 *
 *   1. check the slave group: it exists, is a non-empty facet group, lists
 *      no facet twice, and every facet is on the boundary (a cut would
 *      otherwise break conformity with the cell on the other side);
 *   2. start the macro-elements: one per facet, except for 2D linear
 *      segments, which are gathered two by two along their chains
 *      [LAC §4.4, item 1]:
 *
 *          chain of 5 segments:  o-----o-----o-----o-----o-----o
 *                                |    T^1    |       T^2       |
 *                                      ^            ^     (^)
 *                                  interior node    interior nodes: the
 *                                                   one with the largest
 *                                                   integral is fixed
 *
 *      a chain of odd length ends with one macro of three segments; a
 *      closed loop is cut anywhere; an isolated segment (no neighbour) has
 *      its cell cut at the segment's midpoint instead;
 *   3. cut, in rounds, the cells owning a facet that has no interior node
 *      (lac_refine.c): a round cuts at most one facet per cell, then every
 *      macro-element's facet list is remapped to the new mesh;
 *   4. for each T^m: its measure, its interior nodes (nodes of its
 *      sub-facets that are on no boundary edge of T^m and on no other
 *      macro-element), and the designated one x_{m*+1}: the largest
 *      int_{T^m} phi_i [LAC Remark 1, Def. 1].
 */
#include "lac_macromesh.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lac_mem.h"
#include "lac_quadrature.h"
#include "lac_status.h"

/* Messages from the static helpers carry the public function's name. */
#define MM_ERRMSG(status, ...) \
  lac_error_set ((status), "lac_macromesh_build", __VA_ARGS__)
#define MM_ERROR(status, ...) return MM_ERRMSG ((status), __VA_ARGS__)

#define MAXSUBF 16   /* sub-facets of one macro-element (5 at most here) */
#define MAXPATCH (MAXSUBF * LAC_MAX_FACE_NODES)

enum { KEEP, CUT, GATHER };   /* what a slave facet needs */

/* Macro-elements under construction: T^k has the facets ptr[k]..ptr[k+1]-1;
 * pending[k]: its single (whole) facet still has to be cut. */
typedef struct mlist
{
  size_t n;
  size_t *ptr, *cell;          /* owned */
  int *face;                   /* owned */
  unsigned char *pending;      /* owned */
} mlist;

static void
mlist_clear (mlist *L)
{
  lac_free (L->ptr);
  lac_free (L->cell);
  lac_free (L->face);
  lac_free (L->pending);
  memset (L, 0, sizeof *L);
}

/* ---- step 1: the slave group ------------------------------------------- */

typedef struct fkey
{
  int v[4];      /* vertex nodes of the facet, sorted, padded with -1 */
  size_t e;      /* entry of the group                                 */
} fkey;

static int
cmp_fkey (const void *a, const void *b)
{
  const fkey *p = a, *q = b;
  for (int i = 0; i < 4; i++)
    if (p->v[i] != q->v[i])
      return p->v[i] < q->v[i] ? -1 : 1;
  return 0;
}

static void
make_key (const lac_mesh *m, size_t c, int f, fkey *k)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  for (int i = 0; i < 4; i++)
    k->v[i] = i < nv ? m->conn[m->ptr[c] + (size_t) re->face_node[f][i]] : -1;
  for (int i = 1; i < nv; i++)               /* insertion sort, nv <= 4 */
    for (int j = i; j > 0 && k->v[j - 1] > k->v[j]; j--)
      {
        int t = k->v[j];
        k->v[j] = k->v[j - 1];
        k->v[j - 1] = t;
      }
}

/* What facet e of G needs, from its face type. */
static int
classify (const lac_mesh *m, const lac_group *G, size_t e,
          const lac_macro_opts *opts, unsigned char *kind)
{
  const lac_refelem *re, *rf;
  int hex_cut = opts ? opts->hex_cut : LAC_MACRO_HEX_DEFAULT;

  if (G->cell[e] >= m->ncells)
    MM_ERROR (LAC_EINVAL, "facet %zu of group '%s': cell %zu out of range",
              e, G->name, G->cell[e]);
  re = lac_refelem_get (m->type[G->cell[e]]);
  if (!re || re->dim != m->dim || G->face[e] < 0 || G->face[e] >= re->nfaces)
    MM_ERROR (LAC_EINVAL, "facet %zu of group '%s': cell %zu (tag %zu) has "
              "no face %d", e, G->name, G->cell[e],
              m->cell_tag[G->cell[e]], G->face[e]);
  rf = lac_refelem_get (re->face_type[G->face[e]]);
  switch (rf->type)
    {
    case LAC_SEG2:                           /* tri3, quad4 */
      *kind = opts && opts->cut_2d ? CUT : GATHER;
      return LAC_SUCCESS;
    case LAC_SEG3: case LAC_QUAD9:           /* mid / centre node exists */
      *kind = KEEP;
      return LAC_SUCCESS;
    case LAC_TRI3: case LAC_QUAD4: case LAC_TRI6:
      *kind = CUT;
      return LAC_SUCCESS;
    case LAC_QUAD8:
      if (hex_cut == LAC_MACRO_HEX_PYRAMIDS)
        MM_ERROR (LAC_EINVAL, "facet %zu of group '%s': a %s cannot be cut "
                  "into pyramids (its quad8 face would need pyramid13 "
                  "cells, which lac does not have); use LAC_MACRO_HEX_SIX",
                  e, G->name, re->name);
      *kind = CUT;
      return LAC_SUCCESS;
    default:
      MM_ERROR (LAC_EINVAL, "facet %zu of group '%s': %s faces of %s cells "
                "cannot be made into macro-elements", e, G->name, rf->name,
                re->name);
    }
}

/* No facet twice, and none shared with another cell: the slave facets must
 * lie on the boundary (sorting the slave keys, then looking every face of
 * the mesh up among them). */
static int
check_boundary (const lac_mesh *m, const lac_group *G)
{
  fkey *key = lac_malloc (G->n * sizeof *key);
  int status = LAC_SUCCESS;

  if (!key)
    MM_ERROR (LAC_ENOMEM, "keys of %zu slave facets", G->n);
  for (size_t e = 0; e < G->n; e++)
    {
      make_key (m, G->cell[e], G->face[e], &key[e]);
      key[e].e = e;
    }
  qsort (key, G->n, sizeof *key, cmp_fkey);
  for (size_t e = 1; e < G->n && !status; e++)
    if (cmp_fkey (&key[e - 1], &key[e]) == 0)
      {
        size_t a = key[e - 1].e, b = key[e].e;
        if (G->cell[a] == G->cell[b])
          status = MM_ERRMSG (LAC_EINVAL, "group '%s' lists facet (cell %zu, "
                              "face %d) twice (entries %zu and %zu)",
                              G->name, G->cell[a], G->face[a], a, b);
        else
          status = MM_ERRMSG (LAC_EINVAL, "group '%s': facet %zu (cell %zu) "
                              "and facet %zu (cell %zu) are the same face, "
                              "interior to the mesh; a contact boundary "
                              "must lie on the boundary", G->name, a,
                              G->cell[a], b, G->cell[b]);
      }
  for (size_t c = 0; c < m->ncells && !status; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      for (int f = 0; f < re->nfaces && !status; f++)
        {
          fkey k;
          const fkey *hit;
          make_key (m, c, f, &k);
          hit = bsearch (&k, key, G->n, sizeof *key, cmp_fkey);
          if (hit && !(G->cell[hit->e] == c && G->face[hit->e] == f))
            status = MM_ERRMSG (LAC_EINVAL, "facet %zu of group '%s' (cell "
                                "%zu, face %d) is shared with cell %zu "
                                "(tag %zu): it is interior, a contact "
                                "boundary must lie on the boundary", hit->e,
                                G->name, G->cell[hit->e], G->face[hit->e],
                                c, m->cell_tag[c]);
        }
    }
  lac_free (key);
  return status;
}

/* ---- step 2: first macro-elements, gathering 2D segments --------------- */

static void
push_macro (mlist *L, const lac_group *G, const size_t *e, size_t n,
            int pending)
{
  size_t j = L->ptr[L->n];
  for (size_t i = 0; i < n; i++, j++)
    {
      L->cell[j] = G->cell[e[i]];
      L->face[j] = G->face[e[i]];
    }
  L->pending[L->n] = (unsigned char) pending;
  L->ptr[++L->n] = j;
}

/* The other end of segment e (ends end[2e], end[2e+1]) than node v. */
static size_t
other_end (const size_t *end, size_t e, size_t v)
{
  return end[2 * e] == v ? end[2 * e + 1] : end[2 * e];
}

/* The segment after e through node v: none (SIZE_MAX) unless exactly two
 * segments meet at v (ends of chains and junctions break chains). */
static size_t
next_seg (const size_t *deg, const size_t *inc, size_t e, size_t v)
{
  if (deg[v] != 2)
    return SIZE_MAX;
  return inc[2 * v] == e ? inc[2 * v + 1] : inc[2 * v];
}

/* Split a chain of k segments into macro-elements of 2 (the last of 3 if k
 * is odd); a lone segment is left to be cut  [LAC §4.4, item 1]. */
static void
push_chain (mlist *L, const lac_group *G, const size_t *chain, size_t k)
{
  size_t i = 0;
  if (k == 1)
    {
      push_macro (L, G, chain, 1, 1);
      return;
    }
  for (; i + 3 != k && i < k; i += 2)
    push_macro (L, G, chain + i, 2, 0);
  if (i < k)
    push_macro (L, G, chain + i, 3, 0);
}

/* The macro-elements before refinement, in the order of the group's facets
 * (a chain of segments is emitted where its first facet appears). */
static int
start_macros (const lac_mesh *m, const lac_group *G, const unsigned char *kind,
              mlist *L)
{
  size_t n = G->n, *end = NULL, *deg = NULL, *inc = NULL, *chain = NULL;
  unsigned char *seen = NULL;
  int status = LAC_SUCCESS;

  L->ptr = lac_malloc ((n + 1) * sizeof *L->ptr);
  L->cell = lac_malloc (n * sizeof *L->cell);
  L->face = lac_malloc (n * sizeof *L->face);
  L->pending = lac_malloc (n * sizeof *L->pending);
  end = lac_malloc (2 * n * sizeof *end);
  deg = lac_calloc (m->nnodes, sizeof *deg);
  inc = lac_malloc (2 * m->nnodes * sizeof *inc);
  chain = lac_malloc (n * sizeof *chain);
  seen = lac_calloc (n, sizeof *seen);
  if (!L->ptr || !L->cell || !L->face || !L->pending || !end || !deg || !inc
      || !chain || !seen)
    {
      status = MM_ERRMSG (LAC_ENOMEM, "macro-elements of %zu facets", n);
      goto done;
    }
  L->n = 0;
  L->ptr[0] = 0;

  /* Incidence of the segments to be gathered (end nodes only). */
  for (size_t e = 0; e < n; e++)
    if (kind[e] == GATHER)
      {
        int nodes[LAC_MAX_FACE_NODES];
        lac_mesh_facet_nodes (m, G->cell[e], G->face[e], nodes, NULL);
        for (int i = 0; i < 2; i++)
          {
            size_t v = (size_t) nodes[i];
            end[2 * e + (size_t) i] = v;
            if (deg[v] < 2)
              inc[2 * v + deg[v]] = e;
            deg[v]++;
          }
      }

  for (size_t e = 0; e < n; e++)
    {
      size_t cur = e, v, k = 0, s, out, nxt;
      if (kind[e] != GATHER)
        {
          push_macro (L, G, &e, 1, kind[e] == CUT);
          continue;
        }
      if (seen[e])
        continue;
      /* Walk back through the first end to the start of the chain (or
       * around a closed loop back to e). */
      v = end[2 * e];
      while ((nxt = next_seg (deg, inc, cur, v)) != SIZE_MAX && nxt != e)
        {
          v = other_end (end, nxt, v);
          cur = nxt;
        }
      /* Walk forward from there, collecting the chain. */
      s = cur;
      out = other_end (end, s, v);
      while (s != SIZE_MAX && !seen[s])
        {
          seen[s] = 1;
          chain[k++] = s;
          nxt = next_seg (deg, inc, s, out);
          if (nxt != SIZE_MAX)
            out = other_end (end, nxt, out);
          s = nxt;
        }
      push_chain (L, G, chain, k);
    }
done:
  lac_free (end);
  lac_free (deg);
  lac_free (inc);
  lac_free (chain);
  lac_free (seen);
  return status;
}

/* ---- step 3: refinement rounds ----------------------------------------- */

/* Facet lists of L through the map of one round. */
static int
remap_macros (mlist *L, const lac_refine_map *map)
{
  size_t n = 0, *cell, *ptr = L->ptr;
  int *face;

  for (size_t j = 0; j < ptr[L->n]; j++)
    {
      size_t q = L->cell[j] * LAC_MAX_FACES + (size_t) L->face[j];
      n += map->fptr[q + 1] - map->fptr[q];
    }
  cell = lac_malloc (n * sizeof *cell);
  face = lac_malloc (n * sizeof *face);
  if (!cell || !face)
    {
      lac_free (cell);
      lac_free (face);
      MM_ERROR (LAC_ENOMEM, "macro-element facets (%zu)", n);
    }
  n = 0;
  for (size_t k = 0; k < L->n; k++)
    {
      size_t j0 = ptr[k], j1 = ptr[k + 1];
      ptr[k] = n;
      for (size_t j = j0; j < j1; j++)
        {
          size_t q = L->cell[j] * LAC_MAX_FACES + (size_t) L->face[j];
          for (size_t p = map->fptr[q]; p < map->fptr[q + 1]; p++, n++)
            {
              cell[n] = map->fcell[p];
              face[n] = map->fface[p];
            }
        }
    }
  ptr[L->n] = n;
  lac_free (L->cell);
  lac_free (L->face);
  L->cell = cell;
  L->face = face;
  return LAC_SUCCESS;
}

/* Cut the pending facets, at most one per cell and round  [LAC §4.4]. *cur
 * is replaced by each new mesh; meshes other than `orig` are freed. */
static int
refine_rounds (lac_mesh **cur, const lac_mesh *orig, mlist *L,
               const lac_macro_opts *opts, lac_macro *M)
{
  int status = LAC_SUCCESS;

  for (;;)
    {
      lac_mesh *m = *cur, *next = NULL;
      lac_refine_map *map = NULL;
      int *cut;
      size_t ncut = 0;

      for (size_t k = 0; k < L->n; k++)
        ncut += L->pending[k];
      if (!ncut)
        break;
      cut = lac_malloc (m->ncells * sizeof *cut);
      if (!cut)
        MM_ERROR (LAC_ENOMEM, "refinement round %d", M->nrounds + 1);
      for (size_t c = 0; c < m->ncells; c++)
        cut[c] = -1;
      for (size_t k = 0; k < L->n; k++)
        {
          size_t c = L->cell[L->ptr[k]];
          if (L->pending[k] && cut[c] < 0)
            {
              cut[c] = L->face[L->ptr[k]];
              L->pending[k] = 0;
              M->ncut++;
            }
        }
      status = lac_refine_cut (m, cut, opts, &next, &map);
      lac_free (cut);
      if (!status)
        status = remap_macros (L, map);
      lac_refine_map_free (map);
      if (status)
        {
          lac_mesh_free (next);
          return status;
        }
      M->nnew += next->nnodes - m->nnodes;
      M->nrounds++;
      if (m != orig)
        lac_mesh_free (m);
      *cur = next;
    }
  return status;
}

/* ---- step 4: measures and interior nodes ------------------------------- */

/* The distinct nodes of the patch of sub-facets (cell[j], face[j]), j <
 * nsub, and which of them are interior: not on an edge (3D) or end (2D)
 * that only one sub-facet of the patch has.  Returns the number of nodes,
 * or 0 if the patch is too large. */
static size_t
patch_nodes (const lac_mesh *m, const size_t *cell, const int *face,
             size_t nsub, size_t *node, int *inter)
{
  int fn[MAXSUBF][LAC_MAX_FACE_NODES], nfn[MAXSUBF];
  size_t nn = 0, ekey[MAXSUBF * 4][2];
  int ecount[MAXSUBF * 4], ne = 0;

  if (nsub > MAXSUBF)
    return 0;
  for (size_t j = 0; j < nsub; j++)
    {
      nfn[j] = lac_mesh_facet_nodes (m, cell[j], face[j], fn[j], NULL);
      if (nfn[j] <= 0)
        return 0;
      for (int a = 0; a < nfn[j]; a++)
        {
          size_t v = (size_t) fn[j][a], i = 0;
          while (i < nn && node[i] != v)
            i++;
          if (i == nn)
            node[nn] = v, inter[nn++] = 1;
        }
    }
  /* Boundary edges (ends in 2D) of the patch: those seen only once. */
  for (size_t j = 0; j < nsub; j++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[cell[j]]);
      const lac_refelem *rf = lac_refelem_get (re->face_type[face[j]]);
      int nedge = rf->dim == 1 ? 2 : rf->nfaces;
      for (int e = 0; e < nedge; e++)
        {
          size_t a, b;
          int i = 0;
          if (rf->dim == 1)
            a = b = (size_t) fn[j][e];
          else
            {
              a = (size_t) fn[j][rf->face_node[e][0]];
              b = (size_t) fn[j][rf->face_node[e][1]];
              if (a > b)
                {
                  size_t t = a;
                  a = b;
                  b = t;
                }
            }
          while (i < ne && !(ekey[i][0] == a && ekey[i][1] == b))
            i++;
          if (i == ne)
            ekey[ne][0] = a, ekey[ne][1] = b, ecount[ne++] = 0;
          ecount[i]++;
        }
    }
  for (size_t j = 0; j < nsub; j++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[cell[j]]);
      const lac_refelem *rf = lac_refelem_get (re->face_type[face[j]]);
      int nedge = rf->dim == 1 ? 2 : rf->nfaces;
      for (int e = 0; e < nedge; e++)
        {
          const lac_refelem *rd = rf->dim == 1 ? NULL
                                  : lac_refelem_get (rf->face_type[e]);
          int nen = rd ? rd->nnodes : 1;
          size_t a = (size_t) fn[j][rd ? rf->face_node[e][0] : e];
          size_t b = rd ? (size_t) fn[j][rf->face_node[e][1]] : a;
          int i = 0;
          if (a > b)
            {
              size_t t = a;
              a = b;
              b = t;
            }
          while (!(ekey[i][0] == a && ekey[i][1] == b))
            i++;
          if (ecount[i] != 1)
            continue;
          for (int q = 0; q < nen; q++)       /* the edge's nodes: boundary */
            {
              size_t v = (size_t) fn[j][rd ? rf->face_node[e][q] : e];
              for (size_t k = 0; k < nn; k++)
                if (node[k] == v)
                  inter[k] = 0;
            }
        }
    }
  return nn;
}

static int
cmp_size (const void *a, const void *b)
{
  size_t x = *(const size_t *) a, y = *(const size_t *) b;
  return x < y ? -1 : x > y;
}

/* meas, inode, phi of every macro-element. */
static int
finish (const lac_mesh *m, const mlist *L, lac_macro *M)
{
  enum { LINE, TRI, QUAD };
  lac_quad *rule[3] = { NULL, NULL, NULL };
  size_t *owner = NULL;
  int status = LAC_SUCCESS;
  const size_t none = SIZE_MAX, several = SIZE_MAX - 1;

  owner = lac_malloc (m->nnodes * sizeof *owner);
  rule[LINE] = lac_quad_alloc (LAC_SHAPE_LINE, 6);
  rule[TRI] = lac_quad_alloc (LAC_SHAPE_TRI, 6);
  rule[QUAD] = lac_quad_alloc (LAC_SHAPE_QUAD, 6);
  if (!owner || !rule[LINE] || !rule[TRI] || !rule[QUAD])
    {
      status = MM_ERRMSG (LAC_ENOMEM, "quadrature for macro-elements");
      goto done;
    }
  /* owner[i]: the macro-element whose facets hold node i, or `several`. */
  for (size_t i = 0; i < m->nnodes; i++)
    owner[i] = none;
  for (size_t k = 0; k < L->n; k++)
    for (size_t j = L->ptr[k]; j < L->ptr[k + 1]; j++)
      {
        int fn[LAC_MAX_FACE_NODES];
        int nf = lac_mesh_facet_nodes (m, L->cell[j], L->face[j], fn, NULL);
        for (int a = 0; a < nf; a++)
          {
            size_t *o = &owner[fn[a]];
            *o = *o == none || *o == k ? k : several;
          }
      }

  for (size_t k = 0; k < L->n && !status; k++)
    {
      size_t node[MAXPATCH], nsub = L->ptr[k + 1] - L->ptr[k], nn, best = 0;
      int inter[MAXPATCH], found = 0;
      double integ[MAXPATCH], meas = 0;

      nn = patch_nodes (m, L->cell + L->ptr[k], L->face + L->ptr[k], nsub,
                        node, inter);
      if (nn == 0)
        {
          status = MM_ERRMSG (LAC_ESANITY, "macro-element %zu: %zu "
                              "sub-facets, bad or too many", k, nsub);
          break;
        }
      for (size_t i = 0; i < nn; i++)
        integ[i] = 0;
      /* |T^m| = sum int 1,  int_{T^m} phi_i = sum int N_a  (i = node a) */
      for (size_t j = L->ptr[k]; j < L->ptr[k + 1] && !status; j++)
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
              status = lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
              if (status)
                break;
              meas += q->w[p] * mp.detJ;
              for (int a = 0; a < rf->nnodes; a++)
                integ[slot[a]] += q->w[p] * mp.N[a] * mp.detJ;
            }
        }
      if (status)
        break;
      /* x_{m*+1}: the interior node of largest integral, lowest index on
       * ties  [LAC Remark 1]. */
      for (size_t i = 0; i < nn; i++)
        {
          double tie = 1e-12 * fabs (integ[best]);
          int better;
          if (!inter[i] || owner[node[i]] != k)
            continue;
          better = !found || integ[i] > integ[best] + tie
                   || (fabs (integ[i] - integ[best]) <= tie
                       && node[i] < node[best]);
          if (better)
            best = i, found = 1;
        }
      if (!found)
        {
          status = MM_ERRMSG (LAC_ESANITY, "macro-element %zu (cell %zu, "
                              "face %d) has no interior node", k,
                              L->cell[L->ptr[k]], L->face[L->ptr[k]]);
          break;
        }
      M->inode[k] = node[best];
      M->phi[k] = integ[best];
      M->meas[k] = meas;
    }
done:
  lac_free (owner);
  for (int s = 0; s < 3; s++)
    lac_quad_free (rule[s]);
  return status;
}

/* ---- public ------------------------------------------------------------ */

void
lac_macromesh_free (lac_macro *M)
{
  if (!M)
    return;
  lac_free (M->ptr);
  lac_free (M->cell);
  lac_free (M->face);
  lac_free (M->inode);
  lac_free (M->meas);
  lac_free (M->phi);
  lac_free (M);
}

/* lac_macromesh_build: T^M on the facet group `slave`  [LAC Hyp. 1, §4.4].
 *
 *   [in,out] mesh   *mesh is replaced by the refined mesh on success (the
 *                   old one is freed); unchanged on failure
 *   [in]     slave  name of the slave facet group
 *   [in]     opts   NULL or the template choice (lac_macromesh.h)
 *   [out]    out    the macro-mesh (free with lac_macromesh_free)
 *   returns LAC_SUCCESS, LAC_EINVAL (message names the group, facet, cell
 *   or element type), LAC_ENOMEM, LAC_ESANITY */
int
lac_macromesh_build (lac_mesh **mesh, const char *slave,
                     const lac_macro_opts *opts, lac_macro **out)
{
  lac_mesh *cur = NULL;
  const lac_group *G;
  unsigned char *kind = NULL;
  mlist L = { 0 };
  lac_macro *M = NULL;
  int status = LAC_SUCCESS;

  if (!out)
    MM_ERROR (LAC_EINVAL, "no output pointer");
  *out = NULL;
  if (!mesh || !*mesh || !slave)
    MM_ERROR (LAC_EINVAL, "no mesh or no slave group name");
  if (opts && (opts->hex_cut < LAC_MACRO_HEX_DEFAULT
               || opts->hex_cut > LAC_MACRO_HEX_SIX
               || (opts->cut_2d != 0 && opts->cut_2d != 1)))
    MM_ERROR (LAC_EINVAL, "options hex_cut = %d, cut_2d = %d out of range",
              opts->hex_cut, opts->cut_2d);
  cur = *mesh;

  /* Step 1: the slave group. */
  G = lac_mesh_group (cur, slave);
  if (!G)
    {
      char msg[768];
      const char *p = strstr (lac_error_message (), ": ");
      snprintf (msg, sizeof msg, "%s", p ? p + 2 : lac_error_message ());
      MM_ERROR (LAC_EINVAL, "slave contact group: %s", msg);
    }
  if (G->dim != cur->dim - 1)
    MM_ERROR (LAC_EINVAL, "slave contact group '%s' has dimension %d; it "
              "must be a group of boundary facets (dimension %d)", slave,
              G->dim, cur->dim - 1);
  if (G->n == 0)
    MM_ERROR (LAC_EINVAL, "slave contact group '%s' is empty", slave);
  kind = lac_malloc (G->n * sizeof *kind);
  M = lac_calloc (1, sizeof *M);
  if (!kind || !M)
    {
      status = MM_ERRMSG (LAC_ENOMEM, "macro-mesh of %zu facets", G->n);
      goto done;
    }
  for (size_t e = 0; e < G->n && !status; e++)
    status = classify (cur, G, e, opts, &kind[e]);
  if (!status)
    status = check_boundary (cur, G);

  /* Step 2: first macro-elements; step 3: cut what has to be cut. */
  if (!status)
    status = start_macros (cur, G, kind, &L);
  if (!status)
    status = refine_rounds (&cur, *mesh, &L, opts, M);
  if (status)
    goto done;

  /* Step 4: measures and interior nodes, moved into M. */
  M->n = L.n;
  M->inode = lac_malloc (L.n * sizeof *M->inode);
  M->meas = lac_malloc (L.n * sizeof *M->meas);
  M->phi = lac_malloc (L.n * sizeof *M->phi);
  if (!M->inode || !M->meas || !M->phi)
    {
      status = MM_ERRMSG (LAC_ENOMEM, "macro-mesh of %zu elements", L.n);
      goto done;
    }
  status = finish (cur, &L, M);
  if (status)
    goto done;
  M->ptr = L.ptr;
  M->cell = L.cell;
  M->face = L.face;
  L.ptr = L.cell = NULL;
  L.face = NULL;

done:
  lac_free (kind);
  mlist_clear (&L);
  if (status)
    {
      if (cur != *mesh)
        lac_mesh_free (cur);
      lac_macromesh_free (M);
      return status;
    }
  if (cur != *mesh)
    {
      lac_mesh_free (*mesh);
      *mesh = cur;
    }
  *out = M;
  return LAC_SUCCESS;
}

/* lac_macromesh_interior: the interior nodes of T^m, sorted. */
size_t
lac_macromesh_interior (const lac_mesh *mesh, const lac_macro *M, size_t m,
                        size_t *nodes, size_t nmax)
{
  size_t node[MAXPATCH], nn, count = 0;
  int inter[MAXPATCH];

  if (!mesh || !M || m >= M->n)
    return 0;
  nn = patch_nodes (mesh, M->cell + M->ptr[m], M->face + M->ptr[m],
                    M->ptr[m + 1] - M->ptr[m], node, inter);
  for (size_t i = 0; i < nn; i++)
    if (inter[i])
      node[count++] = node[i];
  qsort (node, count, sizeof *node, cmp_size);
  for (size_t i = 0; i < count && i < nmax; i++)
    nodes[i] = node[i];
  return count;
}

/* lac_macromesh_trace: the raw trace mesh as "macro-mesh": one element per
 * slave facet, nothing gathered or refined (the P0 multipliers of [LAC
 * §4.2], which violate Hypothesis 1 for linear elements: used only to
 * compare with LAC).  inode = (size_t) -1 where the facet has no interior
 * node; meas = |T^s|, phi = 0. */
int
lac_macromesh_trace (const lac_mesh *mesh, const char *slave, lac_macro **out)
{
  const lac_group *G = mesh ? lac_mesh_group (mesh, slave) : NULL;
  *out = NULL;
  if (!G)
    MM_ERROR (LAC_EINVAL, "slave contact group '%s' not found", slave);
  if (G->dim != mesh->dim - 1 || G->n == 0)
    MM_ERROR (LAC_EINVAL, "slave contact group '%s' is not a non-empty "
              "group of boundary facets", slave);
  lac_macro *M = lac_calloc (1, sizeof *M);
  size_t n = G->n;
  if (M)
    {
      M->n = n;
      M->ptr = lac_malloc ((n + 1) * sizeof *M->ptr);
      M->cell = lac_malloc (n * sizeof *M->cell);
      M->face = lac_malloc (n * sizeof *M->face);
      M->inode = lac_malloc (n * sizeof *M->inode);
      M->meas = lac_calloc (n, sizeof *M->meas);
      M->phi = lac_calloc (n, sizeof *M->phi);
    }
  if (!M || !M->ptr || !M->cell || !M->face || !M->inode || !M->meas
      || !M->phi)
    {
      lac_macromesh_free (M);
      MM_ERROR (LAC_ENOMEM, "trace macro-mesh of %zu facets", n);
    }
  M->ptr[0] = 0;
  for (size_t e = 0; e < n; e++)
    {
      M->ptr[e + 1] = e + 1;
      M->cell[e] = G->cell[e];
      M->face[e] = G->face[e];
      size_t in[MAXPATCH];
      M->inode[e] = lac_macromesh_interior (mesh, M, e, in, MAXPATCH) > 0
                    ? in[0] : (size_t) -1;
    }
  *out = M;
  return LAC_SUCCESS;
}
