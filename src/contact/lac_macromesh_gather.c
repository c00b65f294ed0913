/* lac_macromesh_gather.c -- first macro-elements: gathering 2D segments
 *                                                 [LAC §4.4 item 1, Fig. 2]
 *
 * Step 2 of lac_macromesh_build (lac_macromesh.c): one macro-element per
 * slave facet, except for 2D linear segments, which are gathered two by
 * two along their chains:
 *
 *     chain of 5 segments:  o-----o-----o-----o-----o-----o
 *                           |    T^1    |       T^2       |
 *
 * a chain of odd length ends with one macro of three segments; a closed
 * loop is cut anywhere; an isolated segment (no neighbour) is left pending,
 * to have its cell cut at the segment's midpoint (step 3).  Chains break
 * at junctions, a node where other than two segments meet, and at
 * corners, a node where the slave curve turns by more than
 * LAC_MESH_CORNER_DEG (the corner rule of fem/lac_mesh.h): a
 * macro-element never straddles a corner, whose node would be its interior node and mix two normals in one averaged
 * condition (a quad4 cell with two slave edges at a right angle).
 */
#include "contact/lac_macromesh_gather.h"

#include <math.h>
#include <stdint.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

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
push_chain (lac_macro_list *L, const lac_group *G, const size_t *chain,
            size_t k)
{
  size_t i = 0;
  if (k == 1)
    {
      lac_macro_list_push (L, G, chain, 1, 1);
      return;
    }
  for (; i + 3 != k && i < k; i += 2)
    lac_macro_list_push (L, G, chain + i, 2, 0);
  if (i < k)
    lac_macro_list_push (L, G, chain + i, 3, 0);
}

/* 1 if the two segments e1, e2 meeting at node v turn by more than deg
 * degrees (the angle between their directions away from v is then below
 * 180 - deg). */
static int
is_corner (const lac_mesh *m, const size_t *end, size_t e1, size_t e2,
           size_t v, double deg)
{
  const double *x = m->x + 2 * v;
  const double *a = m->x + 2 * other_end (end, e1, v);
  const double *b = m->x + 2 * other_end (end, e2, v);
  double d1[2] = { a[0] - x[0], a[1] - x[1] };
  double d2[2] = { b[0] - x[0], b[1] - x[1] };
  double n1 = hypot (d1[0], d1[1]), n2 = hypot (d2[0], d2[1]);
  double c = (d1[0] * d2[0] + d1[1] * d2[1]) / (n1 * n2);
  return n1 > 0 && n2 > 0 && c > -cos (deg * 3.14159265358979323846 / 180);
}

/* Corners break chains as junctions do: deg[v] = 0 at a node of two
 * segments that turn there (next_seg then stops). */
static void
mark_corners (const lac_mesh *m, const size_t *end, size_t *deg,
              const size_t *inc)
{
  for (size_t v = 0; v < m->nnodes; v++)
    if (deg[v] == 2 && is_corner (m, end, inc[2 * v], inc[2 * v + 1], v,
                                  LAC_MESH_CORNER_DEG))
      deg[v] = 0;
}

/* Incidence of the segments to be gathered (end nodes only): end[2e],
 * end[2e+1] the ends of segment e, deg[v] the number of segments at node v
 * and inc[2v], inc[2v+1] the first two of them. */
static void
segment_incidence (const lac_mesh *m, const lac_group *G,
                   const unsigned char *kind, size_t *end, size_t *deg,
                   size_t *inc)
{
  for (size_t e = 0; e < G->n; e++)
    if (kind[e] == LAC_MACRO_GATHER)
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
}

/* The chain of segments through segment e, in order, into chain; returns
 * its length and marks its segments seen. */
static size_t
walk_chain (size_t e, const size_t *end, const size_t *deg,
            const size_t *inc, unsigned char *seen, size_t *chain)
{
  size_t cur = e, v, k = 0, s, out, nxt;
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
  return k;
}

/* lac_macromesh_start: the macro-elements before refinement, in the order
 * of the group's facets (a chain of segments is emitted where its first
 * facet appears), appended to L  [LAC §4.4, item 1]. */
int
lac_macromesh_start (const lac_mesh *m, const lac_group *G,
                     const unsigned char *kind, int corners,
                     lac_macro_list *L)
{
  size_t n = G->n, *end = NULL, *deg = NULL, *inc = NULL, *chain = NULL;
  unsigned char *seen = NULL;
  int status = LAC_SUCCESS;

  end = lac_malloc (2 * n * sizeof *end);
  deg = lac_calloc (m->nnodes, sizeof *deg);
  inc = lac_malloc (2 * m->nnodes * sizeof *inc);
  chain = lac_malloc (n * sizeof *chain);
  seen = lac_calloc (n, sizeof *seen);
  if (!end || !deg || !inc || !chain || !seen)
    {
      status = LAC_MACRO_ERRMSG (LAC_ENOMEM, "macro-elements of %zu facets",
                                 n);
      goto done;
    }
  segment_incidence (m, G, kind, end, deg, inc);
  if (corners)
    mark_corners (m, end, deg, inc);
  for (size_t e = 0; e < n; e++)
    {
      if (kind[e] != LAC_MACRO_GATHER)
        lac_macro_list_push (L, G, &e, 1, kind[e] == LAC_MACRO_CUT);
      else if (!seen[e])
        push_chain (L, G, chain, walk_chain (e, end, deg, inc, seen, chain));
    }
done:
  lac_free (end);
  lac_free (deg);
  lac_free (inc);
  lac_free (chain);
  lac_free (seen);
  return status;
}
