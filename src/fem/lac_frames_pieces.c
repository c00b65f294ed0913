/* lac_frames_pieces.c -- the smooth pieces of the rollers' faces at their
 *                        nodes (see lac_frames.h)        [LAC (4), (8)]
 *
 * Every facet of the groups meets each of its nodes once: an incidence
 * (node, group, the facet's unit normal at the node).  At a node the
 * incidences within LAC_MESH_CORNER_DEG of each other are joined
 * (union-find: a chain of such facets is one piece, whatever its order),
 * and each class is a piece.  A piece's tilt looks across its facets: the
 * pieces the same facets belong to at their other nodes.  Whether it ends
 * at the node: each facet's boundary through the node (two edges of a
 * face at its vertex, one at a node inside an edge, the node itself for
 * a segment) is shared by two facets of the piece where they surround
 * the node, by one where the piece ends.
 */
#include "fem/lac_frames.h"

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

#define PI 3.14159265358979323846

/* The incidences, facet after facet in the order of the groups. */
typedef struct incidences
{
  size_t n;
  size_t *node, *group, *first;  /* first: its facet's first incidence   */
  int *count;                    /* its facet's nodes                    */
  size_t *key;                   /* 4 n: its facet's boundary through the
                                    node, two pairs of nodes (SIZE_MAX:
                                    none)                                */
  double *normal;                /* 3 n                                  */
  size_t *piece;                 /* its piece                            */
  size_t *order, *at;            /* by node (stable): order[at[a] ..
                                    at[a + 1]) are node a's; at: nnodes+1 */
  size_t *up;                    /* union-find over the positions        */
} incidences;

static void
incidences_free (incidences *I)
{
  lac_free (I->node), lac_free (I->group), lac_free (I->first);
  lac_free (I->count), lac_free (I->normal), lac_free (I->piece);
  lac_free (I->key);
  lac_free (I->order), lac_free (I->at), lac_free (I->up);
}

/* Room for cap incidences on a mesh of nnodes nodes. */
static int
incidences_alloc (incidences *I, size_t cap, size_t nnodes)
{
  memset (I, 0, sizeof *I);
  I->node = lac_malloc (cap * sizeof *I->node);
  I->group = lac_malloc (cap * sizeof *I->group);
  I->first = lac_malloc (cap * sizeof *I->first);
  I->count = lac_malloc (cap * sizeof *I->count);
  I->key = lac_malloc (4 * cap * sizeof *I->key);
  I->normal = lac_malloc (3 * cap * sizeof *I->normal);
  I->piece = lac_malloc (cap * sizeof *I->piece);
  I->order = lac_malloc (cap * sizeof *I->order);
  I->up = lac_malloc (cap * sizeof *I->up);
  I->at = lac_calloc (nnodes + 1, sizeof *I->at);
  if (!I->node || !I->group || !I->first || !I->count || !I->key
      || !I->normal
      || !I->piece || !I->order || !I->up || !I->at)
    LAC_ERROR (LAC_ENOMEM, "facet normals at %zu nodes", nnodes);
  return LAC_SUCCESS;
}

/* The pair (u, v) as a key, the smaller first. */
static void
pair_key (int u, int v, size_t *key)
{
  key[0] = (size_t) (u < v ? u : v);
  key[1] = (size_t) (u < v ? v : u);
}

/* The boundary of a facet (type rf, nodes fn) through its node a: the two
 * edges through a vertex of a face, the edge a node of an edge lies on,
 * a segment's end node itself; nothing through a node inside the facet
 * (SIZE_MAX).  Mid-edge nodes follow the vertices, edge after edge. */
static void
boundary_keys (const lac_refelem *rf, const int *fn, int a, size_t *key)
{
  int nv = rf->nvertices;
  for (int i = 0; i < 4; i++)
    key[i] = SIZE_MAX;
  if (rf->dim == 1 && a < 2)
    pair_key (fn[a], fn[a], key);
  else if (rf->dim == 2 && a < nv)
    {
      pair_key (fn[a], fn[(a + nv - 1) % nv], key);
      pair_key (fn[a], fn[(a + 1) % nv], key + 2);
    }
  else if (rf->dim == 2 && a < 2 * nv)
    pair_key (fn[a - nv], fn[(a - nv + 1) % nv], key);
}

/* The incidences of facet e of group g (index gi): its unit normal at
 * each of its nodes, and its boundary there. */
static int
facet_incidences (const lac_mesh *m, const lac_group *g, size_t gi,
                  size_t e, incidences *I)
{
  int fn[LAC_MAX_FACE_NODES], dim = m->dim;
  double xe[LAC_MAX_FACE_NODES * 3];
  lac_elem_type ft;
  lac_map mp;
  int nf = lac_mesh_facet_nodes (m, g->cell[e], g->face[e], fn, &ft);
  const lac_refelem *rf = nf > 0 ? lac_refelem_get (ft) : NULL;
  size_t first = I->n;
  if (!rf || rf->dim != dim - 1)
    LAC_ERROR (LAC_EINVAL, "group '%s': facet %zu is not a facet of cell "
               "%zu", g->name, e + 1, m->cell_tag[g->cell[e]]);
  for (int a = 0; a < nf; a++)
    for (int i = 0; i < dim; i++)
      xe[a * dim + i] = m->x[(size_t) dim * (size_t) fn[a] + (size_t) i];
  for (int a = 0; a < nf; a++)
    {
      size_t k = I->n++;
      if (lac_map_face (rf, dim, xe, rf->xi + a * rf->dim, &mp))
        LAC_ERROR (LAC_ESING, "group '%s': the facet of cell %zu at node "
                   "%zu is degenerate", g->name, m->cell_tag[g->cell[e]],
                   m->node_tag[fn[a]]);
      I->node[k] = (size_t) fn[a], I->group[k] = gi, I->first[k] = first;
      I->count[k] = nf;
      boundary_keys (rf, fn, a, I->key + 4 * k);
      for (int i = 0; i < 3; i++)
        I->normal[3 * k + (size_t) i] = i < dim ? mp.normal[i] : 0;
    }
  return LAC_SUCCESS;
}

/* The positions sorted by node, stably (a counting sort). */
static void
sort_by_node (incidences *I, size_t nnodes)
{
  for (size_t k = 0; k < I->n; k++)
    I->at[I->node[k] + 1]++;
  for (size_t a = 0; a < nnodes; a++)
    I->at[a + 1] += I->at[a];
  for (size_t k = 0; k < I->n; k++)
    I->order[I->at[I->node[k]]++] = k;
  for (size_t a = nnodes; a > 0; a--)
    I->at[a] = I->at[a - 1];
  I->at[0] = 0;
}

static size_t
root (size_t *up, size_t i)
{
  while (up[i] != i)
    i = up[i] = up[up[i]];
  return i;
}

/* The pieces at node a: positions within the corner angle joined (the
 * root of a class its first position), numbered from *np on in the order
 * of their first incidence. */
static void
join_at_node (incidences *I, size_t a, double cmin, size_t *np)
{
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    I->up[i] = i;
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    for (size_t j = i + 1; j < I->at[a + 1]; j++)
      if (lac_vec_dot (3, I->normal + 3 * I->order[i],
                       I->normal + 3 * I->order[j]) >= cmin)
        {
          size_t ri = root (I->up, i), rj = root (I->up, j);
          if (ri < rj)
            I->up[rj] = ri;
          else
            I->up[ri] = rj;
        }
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    if (root (I->up, i) == i)
      I->piece[I->order[i]] = (*np)++;
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    I->piece[I->order[i]] = I->piece[I->order[root (I->up, i)]];
}

/* out's arrays for at most n pieces. */
static int
pieces_alloc (lac_face_pieces *P, size_t nnodes, size_t n)
{
  P->nnodes = nnodes;
  P->ptr = lac_calloc (nnodes + 1, sizeof *P->ptr);
  P->normal = lac_calloc (3 * n + 1, sizeof *P->normal);
  P->tilt = lac_calloc (n + 1, sizeof *P->tilt);
  P->end = lac_calloc (n + 1, 1);
  P->gptr = lac_calloc (n + 2, sizeof *P->gptr);
  P->grp = lac_malloc ((n + 1) * sizeof *P->grp);
  if (!P->ptr || !P->normal || !P->tilt || !P->end || !P->gptr || !P->grp)
    LAC_ERROR (LAC_ENOMEM, "%zu pieces of faces", n);
  return LAC_SUCCESS;
}

/* How many incidences of piece p at node a have the boundary key
 * (u, v). */
static size_t
key_count (const incidences *I, size_t a, size_t p, const size_t *key)
{
  size_t c = 0;
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    {
      const size_t *k = I->key + 4 * I->order[i];
      if (I->piece[I->order[i]] == p)
        c += (k[0] == key[0] && k[1] == key[1])
             + (k[2] == key[0] && k[3] == key[1]);
    }
  return c;
}

/* Does piece p end at node a: a boundary key of one facet only? */
static int
piece_ends (const incidences *I, size_t a, size_t p)
{
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    for (int h = 0; I->piece[I->order[i]] == p && h < 4; h += 2)
      {
        const size_t *k = I->key + 4 * I->order[i] + h;
        if (k[0] != SIZE_MAX && key_count (I, a, p, k) == 1)
          return 1;
      }
  return 0;
}

/* Piece p's normal (the normalized sum) and groups, at node a. */
static int
make_piece (const incidences *I, size_t a, size_t p, lac_face_pieces *P)
{
  double *n = P->normal + 3 * p, s;
  size_t ng = P->gptr[p];
  for (size_t i = I->at[a]; i < I->at[a + 1]; i++)
    {
      size_t k = I->order[i];
      if (I->piece[k] != p)
        continue;
      for (int c = 0; c < 3; c++)
        n[c] += I->normal[3 * k + (size_t) c];
      if (ng == P->gptr[p] || P->grp[ng - 1] != I->group[k])
        P->grp[ng++] = I->group[k];       /* the groups come in order */
    }
  P->gptr[p + 1] = ng;
  P->end[p] = (char) piece_ends (I, a, p);
  if (!((s = lac_vec_norm (3, n)) > 1e-6))   /* within the corner angle */
    LAC_ERROR (LAC_ESANITY, "the normals of one piece cancel");
  for (int c = 0; c < 3; c++)
    n[c] /= s;
  return LAC_SUCCESS;
}

/* The tilts: the sine of the largest angle between a piece's normal and
 * that of the piece of one of its facets at another node (1 beyond 90
 * degrees; 0 up to LAC_FRAMES_DEPENDENT: a flat face, to rounding). */
static void
tilts (const incidences *I, lac_face_pieces *P)
{
  for (size_t k = 0; k < I->n; k++)
    for (size_t j = I->first[k]; j < I->first[k] + (size_t) I->count[k];
         j++)
      {
        const double *u = P->normal + 3 * I->piece[k];
        const double *v = P->normal + 3 * I->piece[j];
        double w[3], s;
        lac_vec_cross (u, v, w);
        s = lac_vec_dot (3, u, v) > 0 ? fmin (lac_vec_norm (3, w), 1) : 1;
        if (s > LAC_FRAMES_DEPENDENT)
          P->tilt[I->piece[k]] = fmax (P->tilt[I->piece[k]], s);
      }
}

/* The incidences of every facet of the groups. */
static int
all_incidences (const lac_mesh *m, size_t ng, const lac_group *const *g,
                incidences *I, lac_face_pieces *out)
{
  size_t cap = 0;
  int status;
  for (size_t gi = 0; gi < ng; gi++)
    {
      out->failed = gi;
      if (g[gi]->dim != m->dim - 1 || g[gi]->n == 0)
        LAC_ERROR (LAC_EINVAL, "group '%s' has no facets: a normal needs a "
                   "group of boundary facets (dimension %d)", g[gi]->name,
                   m->dim - 1);
      cap += g[gi]->n * LAC_MAX_FACE_NODES;
    }
  if ((status = incidences_alloc (I, cap + 1, m->nnodes)))
    return status;
  for (size_t gi = 0; gi < ng; gi++)
    {
      out->failed = gi;
      for (size_t e = 0; e < g[gi]->n; e++)
        if ((status = facet_incidences (m, g[gi], gi, e, I)))
          return status;
    }
  return LAC_SUCCESS;
}

int
lac_frames_pieces (const lac_mesh *m, size_t ng, const lac_group *const *g,
                   lac_face_pieces *out)
{
  incidences I;
  double cmin = cos (LAC_MESH_CORNER_DEG * PI / 180);
  int status;
  memset (out, 0, sizeof *out);
  memset (&I, 0, sizeof I);
  if (!(status = all_incidences (m, ng, g, &I, out)))
    {
      sort_by_node (&I, m->nnodes);
      status = pieces_alloc (out, m->nnodes, I.n);
    }
  for (size_t a = 0; !status && a < m->nnodes; a++)
    {
      size_t p0 = out->n;
      join_at_node (&I, a, cmin, &out->n);
      out->ptr[a + 1] = out->n;
      for (size_t p = p0; !status && p < out->n; p++)
        status = make_piece (&I, a, p, out);
    }
  if (!status)
    tilts (&I, out);
  incidences_free (&I);
  if (status)
    {
      size_t failed = out->failed;
      lac_face_pieces_clear (out);
      out->failed = failed;
    }
  return status;
}

void
lac_face_pieces_clear (lac_face_pieces *p)
{
  lac_free (p->ptr);
  lac_free (p->normal);
  lac_free (p->tilt);
  lac_free (p->end);
  lac_free (p->gptr);
  lac_free (p->grp);
  memset (p, 0, sizeof *p);
}
