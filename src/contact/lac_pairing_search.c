/* lac_pairing_search.c -- the search of the pairing: pass 1     [LAC §4.6]
 *
 * Which (slave, master) pairs overlap: the facet lists are gathered with
 * the vertex adjacency of each side (a hash of the shared vertices), a
 * bucket grid is built over the master facets, and an advancing front
 * walks the slave facets, flooding over master neighbours while the
 * overlaps are non-empty [LAC §4.6, principles 1 and 4].  Each test is a
 * call of lac_pairing_overlap (lac_pairing_geom.c); the points are
 * computed afterwards, by lac_pairing.c.
 *
 * Reference: M. J. Gander, C. Japhet, "Algorithm 932: PANG: software for
 * nonmatching grid projections in 2D and 3D with linear complexity", ACM
 * TOMS 40 (2013), §3 (the advancing front).
 */
#include "contact/lac_pairing_search.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

#define NONE LAC_PAIRING_NONE

/* Re-raise the stored error with context (in the caller's name): the
 * stored message is copied first, since the new one is written into the
 * same buffer. */
static int
reraise (int status, const char *func, const char *what, size_t i,
         const char *extra)
{
  char why[512];
  snprintf (why, sizeof why, "%s", lac_error_message ());
  return lac_error_set (status, func, "%s facet %zu%s: %s", what, i, extra,
                        why);
}
#define RERAISE(status, what, i, extra) \
  reraise ((status), __func__, (what), (i), (extra))

/* ---- one side: facets, their nodes, vertex -> facet adjacency ----------- */

static void
side_free (lac_pairing_side *S)
{
  lac_free (S->type), lac_free (S->node), lac_free (S->vid);
  lac_free (S->vptr), lac_free (S->vfac);
  memset (S, 0, sizeof *S);
}

/* Compressed vertex ids by open addressing on the mesh node number (a hash
 * of the shared vertices: linear time whatever the size of the mesh). */
static int
side_number_vertices (lac_pairing_side *S, size_t nslots)
{
  size_t mask = 1;
  while (mask < 2 * nslots)
    mask <<= 1;
  int *key = lac_malloc (mask * sizeof *key);
  size_t *val = lac_malloc (mask * sizeof *val);
  if (!key || !val)
    {
      lac_free (key), lac_free (val);
      LAC_ERROR (LAC_ENOMEM, "vertex table of %zu slots", mask);
    }
  mask--;
  for (size_t i = 0; i <= mask; i++)
    key[i] = -1;
  S->nv = 0;
  for (size_t i = 0; i < S->f->n * 4; i++)
    {
      int nd = S->node[(i / 4) * LAC_MAX_FACE_NODES + i % 4];
      if (S->vid[i] == 0)                  /* 0 marks a vertex slot (below) */
        {
          uint64_t key64 = (uint64_t) (unsigned) nd * 0x9E3779B97F4A7C15u;
          size_t h = (size_t) (key64 >> 17) & mask;    /* Fibonacci hash */
          while (key[h] != -1 && key[h] != nd)
            h = (h + 1) & mask;                       /* linear probing */
          if (key[h] == -1)
            key[h] = nd, val[h] = S->nv++;
          S->vid[i] = val[h];
        }
    }
  lac_free (key), lac_free (val);
  return LAC_SUCCESS;
}

/* vertex -> facets, compressed rows (counting sort). */
static int
side_adjacency (lac_pairing_side *S)
{
  size_t n = S->f->n;
  S->vptr = lac_calloc (S->nv + 1, sizeof *S->vptr);
  if (!S->vptr)
    LAC_ERROR (LAC_ENOMEM, "adjacency of %zu vertices", S->nv);
  for (size_t i = 0; i < 4 * n; i++)
    if (S->vid[i] != NONE)
      S->vptr[S->vid[i] + 1]++;
  for (size_t v = 0; v < S->nv; v++)
    S->vptr[v + 1] += S->vptr[v];
  S->vfac = lac_malloc ((S->vptr[S->nv] + 1) * sizeof *S->vfac);
  size_t *next = lac_malloc ((S->nv + 1) * sizeof *next);
  if (!S->vfac || !next)
    {
      lac_free (next);
      LAC_ERROR (LAC_ENOMEM, "adjacency of %zu vertices", S->nv);
    }
  memcpy (next, S->vptr, S->nv * sizeof *next);
  for (size_t i = 0; i < 4 * n; i++)
    if (S->vid[i] != NONE)
      S->vfac[next[S->vid[i]]++] = i / 4;
  lac_free (next);
  return LAC_SUCCESS;
}

/* Gather the nodes of every facet and build the adjacency.  `what` is
 * "slave" or "master", for messages. */
static int
side_build (lac_pairing_side *S, const lac_pairing_facets *f, const char *what)
{
  int status, nodes[LAC_MAX_FACE_NODES];
  memset (S, 0, sizeof *S);
  S->f = f;
  S->sdim = f->mesh->dim;
  S->type = lac_malloc ((f->n + 1) * sizeof *S->type);
  S->node = lac_malloc ((f->n * LAC_MAX_FACE_NODES + 1) * sizeof *S->node);
  S->vid = lac_malloc ((4 * f->n + 1) * sizeof *S->vid);
  if (!S->type || !S->node || !S->vid)
    LAC_ERROR (LAC_ENOMEM, "%s side of %zu facets", what, f->n);
  for (size_t i = 0; i < f->n; i++)
    {
      int k = lac_mesh_facet_nodes (f->mesh, f->cell[i], f->face[i], nodes,
                                    S->type + i);
      if (k < 0)
        return RERAISE (-k, what, i, "");
      const lac_refelem *re = lac_refelem_get (S->type[i]);
      if (re->dim != S->sdim - 1)
        LAC_ERROR (LAC_EINVAL, "%s facet %zu is a %s in a %d-D mesh", what, i,
                   re->name, S->sdim);
      memcpy (S->node + i * LAC_MAX_FACE_NODES, nodes,
              (size_t) k * sizeof *nodes);
      for (int a = 0; a < 4; a++)
        S->vid[4 * i + (size_t) a] = a < re->nvertices ? 0 : NONE;
    }
  if ((status = side_number_vertices (S, 4 * f->n)))
    return status;
  return side_adjacency (S);
}

/* The geometry of facet i. */
int
lac_pairing_side_facet (const lac_pairing_side *S, size_t i,
                        lac_pairing_facet *F, const char *what)
{
  double xe[LAC_MAX_FACE_NODES * 3];
  const lac_refelem *re = lac_refelem_get (S->type[i]);
  const double *x = S->f->mesh->x;
  int d = S->sdim, status;
  for (int a = 0; a < re->nnodes; a++)
    for (int k = 0; k < d; k++)
      {
        size_t nd = (size_t) S->node[i * LAC_MAX_FACE_NODES + (size_t) a];
        xe[a * d + k] = x[nd * (size_t) d + (size_t) k];
      }
  if ((status = lac_pairing_facet_set (F, S->type[i], d, xe)))
    {
      char where[96];
      snprintf (where, sizeof where, " (face %d of cell tag %zu)",
                S->f->face[i], S->f->mesh->cell_tag[S->f->cell[i]]);
      return RERAISE (status, what, i, where);
    }
  return LAC_SUCCESS;
}

/* Bounding box lo[0..2], hi[3..5] of facet i (all its nodes). */
static void
side_box (const lac_pairing_side *S, size_t i, double *box)
{
  const lac_refelem *re = lac_refelem_get (S->type[i]);
  const double *x = S->f->mesh->x;
  size_t d = (size_t) S->sdim;
  for (int k = 0; k < 3; k++)
    box[k] = box[3 + k] = 0;
  for (int a = 0; a < re->nnodes; a++)
    for (size_t k = 0; k < d; k++)
      {
        size_t nd = (size_t) S->node[i * LAC_MAX_FACE_NODES + (size_t) a];
        double v = x[nd * d + k];
        box[k] = a ? fmin (box[k], v) : v;
        box[3 + k] = a ? fmax (box[3 + k], v) : v;
      }
}

/* ---- bucket grid over the master facets --------------------------------- */

static void
grid_free (lac_pairing_grid *G)
{
  lac_free (G->bptr), lac_free (G->bfac), lac_free (G->box), lac_free (G->big);
  memset (G, 0, sizeof *G);
}

static size_t
grid_bucket (const lac_pairing_grid *G, const long *c)
{
  uint64_t h = (uint64_t) c[0] * 0x9E3779B97F4A7C15u
    ^ (uint64_t) c[1] * 0xC2B2AE3D27D4EB4Fu
    ^ (uint64_t) c[2] * 0x165667B19E3779F9u;
  return (size_t) (h ^ (h >> 29)) & G->mask;
}

/* Cell range lo[k]..hi[k] covered by a box (lo[3..5]: 0 in 2D). */
static void
grid_range (const lac_pairing_grid *G, const double *box, long *lo, long *hi)
{
  for (int k = 0; k < 3; k++)
    {
      lo[k] = hi[k] = 0;
      if (k < G->sdim)
        {
          double a = floor ((box[k] - G->lo[k]) / G->hg);
          double b = floor ((box[3 + k] - G->lo[k]) / G->hg);
          lo[k] = (long) fmax (-1e15, fmin (1e15, a));   /* no overflow */
          hi[k] = (long) fmax (-1e15, fmin (1e15, b));
        }
    }
}

/* Number of grid cells a box meets. */
static double
grid_ncells (const long *lo, const long *hi)
{
  double n = 1;
  for (int k = 0; k < 3; k++)
    n *= (double) (hi[k] - lo[k] + 1);
  return n;
}

/* A spatial hash of the master facets: cells of the mean facet size, each
 * facet filed in every cell its bounding box meets, 2n buckets.  The box
 * is grown by the master's share of the gap bound, dist_abs + dist_rel
 * times its diagonal (at least the facet's diameter): a pair counts when
 * its gap is within dist_rel times the LARGER of the two diameters
 * (test_pair), so a master facet larger than its slave must be found by
 * the slave's query although it lies beyond the slave's own bound.  The
 * rare facets much larger than the mean (more than LAC_PAIRING_BIG cells,
 * on strongly graded meshes) are kept in a separate list instead. */
static int
grid_build (lac_pairing_grid *G, const lac_pairing_side *M,
            const lac_pairing_opts *o)
{
  size_t n = M->f->n, pass;
  long lo[3], hi[3], c[3];
  memset (G, 0, sizeof *G);
  G->sdim = M->sdim;
  G->box = lac_malloc (6 * n * sizeof *G->box);
  if (!G->box)
    LAC_ERROR (LAC_ENOMEM, "bounding boxes of %zu facets", n);
  double hsum = 0;
  for (size_t i = 0; i < n; i++)
    {
      double *b = G->box + 6 * i;
      side_box (M, i, b);
      for (int k = 0; k < 6; k++)
        if (!isfinite (b[k]))
          LAC_ERROR (LAC_EINVAL, "master facet %zu (face %d of cell tag %zu) "
                     "has a non-finite coordinate", i, M->f->face[i],
                     M->f->mesh->cell_tag[M->f->cell[i]]);
      for (int k = 0; k < 3; k++)
        {
          G->lo[k] = i ? fmin (G->lo[k], b[k]) : b[k];
          hsum += b[3 + k] - b[k];
        }
    }
  G->hg = hsum / (double) n / (G->sdim - 1);      /* mean facet extent */
  if (!(G->hg > 0))
    LAC_ERROR (LAC_ESING, "the %zu master facets have no extent", n);
  for (size_t i = 0; i < n; i++)                   /* the master's bound */
    {
      double *b = G->box + 6 * i, diag = 0;
      for (int k = 0; k < 3; k++)
        diag += (b[3 + k] - b[k]) * (b[3 + k] - b[k]);
      double grow = o->dist_abs + o->dist_rel * sqrt (diag);
      for (int k = 0; k < G->sdim; k++)
        b[k] -= grow, b[3 + k] += grow;
    }
  G->mask = 1;
  while (G->mask < 2 * n)
    G->mask <<= 1;
  G->mask--;
  G->bptr = lac_calloc (G->mask + 2, sizeof *G->bptr);
  G->big = lac_malloc ((n + 1) * sizeof *G->big);
  if (!G->bptr || !G->big)
    LAC_ERROR (LAC_ENOMEM, "bucket grid of %zu buckets", G->mask + 1);
  for (pass = 0; pass < 2; pass++)          /* 0: count, 1: fill */
    {
      for (size_t i = 0; i < n; i++)
        {
          grid_range (G, G->box + 6 * i, lo, hi);
          if (grid_ncells (lo, hi) > LAC_PAIRING_BIG)
            {
              if (pass == 0)
                G->big[G->nbig++] = i;
              continue;
            }
          for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++)
            for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
              for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
                {
                  size_t b = grid_bucket (G, c);
                  if (pass == 0)
                    G->bptr[b + 1]++;
                  else
                    G->bfac[G->bptr[b]++] = i;
                }
        }
      if (pass == 0)
        {
          for (size_t b = 0; b <= G->mask; b++)
            G->bptr[b + 1] += G->bptr[b];
          G->bfac = lac_malloc ((G->bptr[G->mask + 1] + 1) * sizeof *G->bfac);
          if (!G->bfac)
            LAC_ERROR (LAC_ENOMEM, "bucket grid of %zu entries",
                       G->bptr[G->mask + 1]);
        }
    }
  for (size_t b = G->mask + 1; b > 0; b--)  /* undo the fill's shift */
    G->bptr[b] = G->bptr[b - 1];
  G->bptr[0] = 0;
  return LAC_SUCCESS;
}

/* ---- the search (pass 1) ------------------------------------------------ */

void
lac_pairing_search_free (lac_pairing_search *W)
{
  side_free (&W->S), side_free (&W->M), grid_free (&W->G);
  lac_free (W->mst), lac_free (W->gst), lac_free (W->mq), lac_free (W->cand);
  lac_free (W->sq), lac_free (W->donor), lac_free (W->state);
  lac_free (W->pbeg), lac_free (W->pcnt), lac_free (W->pm);
}

static int
search_alloc (lac_pairing_search *W)
{
  size_t ns = W->S.f->n, nm = W->M.f->n;
  W->mst = lac_malloc (nm * sizeof *W->mst);
  W->gst = lac_malloc (nm * sizeof *W->gst);
  W->mq = lac_malloc (nm * sizeof *W->mq);
  W->cand = lac_malloc (nm * sizeof *W->cand);
  W->sq = lac_malloc (ns * sizeof *W->sq);
  W->donor = lac_malloc (ns * sizeof *W->donor);
  W->state = lac_calloc (ns, 1);
  W->pbeg = lac_calloc (ns, sizeof *W->pbeg);
  W->pcnt = lac_calloc (ns, sizeof *W->pcnt);
  W->cap = 4 * ns + 16;
  W->pm = lac_malloc (W->cap * sizeof *W->pm);
  if (!W->mst || !W->gst || !W->mq || !W->cand || !W->sq || !W->donor
      || !W->state || !W->pbeg || !W->pcnt || !W->pm)
    LAC_ERROR (LAC_ENOMEM, "search work space for %zu slave and %zu master "
               "facets", ns, nm);
  for (size_t m = 0; m < nm; m++)
    W->mst[m] = W->gst[m] = NONE;
  return LAC_SUCCESS;
}

/* The gap bound of the pair in work: a multiple of the larger facet (the
 * chords of curved facets of different sizes are O(h^2/R) apart). */
double
lac_pairing_gap_bound (const lac_pairing_search *W)
{
  return W->o->dist_abs + W->o->dist_rel * fmax (W->sf.h, W->mf.h);
}

/* Test master m against the slave facet in work s; record the pair if they
 * overlap.  *hit = 1 if they overlap (the front goes on from m). */
static int
test_pair (lac_pairing_search *W, size_t s, size_t m, int *hit)
{
  double poly[2 * LAC_PAIRING_MAXPOLY];
  int np, status;
  *hit = 0;
  W->mst[m] = s;
  W->ntests++;
  if ((status = lac_pairing_side_facet (&W->M, m, &W->mf, "master")))
    return status;
  int r = lac_pairing_overlap (&W->sf, &W->mf, lac_pairing_gap_bound (W),
                               W->o->facing, poly, &np);
  W->nfacing += r == LAC_PAIRING_NOT_FACING;
  W->nfar += r == LAC_PAIRING_TOO_FAR;
  if (r != LAC_PAIRING_OVERLAP)
    return LAC_SUCCESS;
  if (W->np == W->cap)
    {
      size_t *p = lac_realloc (W->pm, 2 * W->cap * sizeof *p);
      if (!p)
        LAC_ERROR (LAC_ENOMEM, "%zu pairs", 2 * W->cap);
      W->pm = p, W->cap *= 2;
    }
  W->pm[W->np++] = m;
  W->pcnt[s]++;
  W->cov += lac_pairing_overlap_fraction (&W->sf, np, poly);
  *hit = 1;
  return LAC_SUCCESS;
}

/* Masters whose boxes (grown by their share of the gap bound) meet the
 * box of slave s grown by its share (a query of the bucket grid); *nc
 * candidates in W->cand. */
static void
grid_query (lac_pairing_search *W, size_t s, size_t *nc)
{
  double b[6];
  long lo[3], hi[3], c[3];
  const lac_pairing_grid *G = &W->G;
  double dq = W->o->dist_abs + W->o->dist_rel * W->sf.h;
  side_box (&W->S, s, b);
  for (int k = 0; k < 3; k++)
    b[k] -= dq, b[3 + k] += dq;
  grid_range (G, b, lo, hi);
  W->nquery++;
  *nc = 0;
  for (size_t j = 0; j < G->nbig; j++)
    W->cand[(*nc)++] = G->big[j], W->gst[G->big[j]] = W->nquery;
  if (grid_ncells (lo, hi) > 4.0 * (double) (G->mask + 1))
    {                       /* a huge box: cheaper to scan every facet */
      for (size_t m = 0; m < W->M.f->n; m++)
        if (W->gst[m] != W->nquery)
          W->cand[(*nc)++] = m;
      return;
    }
  for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++)
    for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
      for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
        {
          size_t bk = grid_bucket (G, c);
          for (size_t j = G->bptr[bk]; j < G->bptr[bk + 1]; j++)
            {
              size_t m = G->bfac[j];
              const double *mb = G->box + 6 * m;
              if (W->gst[m] == W->nquery)
                continue;
              W->gst[m] = W->nquery;
              int apart = 0;
              for (int k = 0; k < G->sdim; k++)
                apart |= mb[k] > b[3 + k] || mb[3 + k] < b[k];
              if (!apart)
                W->cand[(*nc)++] = m;
            }
        }
}

/* Test the master neighbours of m (facets sharing a vertex) not yet
 * tested with slave s; push those that overlap s on the master front. */
static int
test_neighbours (lac_pairing_search *W, size_t s, size_t m, size_t *tail)
{
  const lac_pairing_side *M = &W->M;
  int hit, status;
  for (int a = 0; a < 4; a++)
    {
      size_t v = M->vid[4 * m + (size_t) a];
      if (v == NONE)
        continue;
      for (size_t j = M->vptr[v]; j < M->vptr[v + 1]; j++)
        {
          size_t m2 = M->vfac[j];
          if (W->mst[m2] == s)
            continue;
          if ((status = test_pair (W, s, m2, &hit)))
            return status;
          if (hit)
            W->mq[(*tail)++] = m2;
        }
    }
  return LAC_SUCCESS;
}

/* Flood over the master neighbours of the facets in the master front
 * mq[head .. *tail-1], while they overlap slave s. */
static int
flood (lac_pairing_search *W, size_t s, size_t head, size_t *tail)
{
  int status;
  for (; head < *tail; head++)
    if ((status = test_neighbours (W, s, W->mq[head], tail)))
      return status;
  return LAC_SUCCESS;
}

/* Test the candidates of the bucket grid for slave s not yet tested: all
 * of them (all = 1, robust mode, completion), or up to the first one that
 * overlaps (a seed).  Those that overlap go on the master front. */
static int
test_grid (lac_pairing_search *W, size_t s, int all, size_t *tail)
{
  size_t nc;
  int hit, status;
  W->nseeds++;
  grid_query (W, s, &nc);
  for (size_t j = 0; j < nc; j++)
    {
      size_t m = W->cand[j];
      if (W->mst[m] == s)
        continue;
      if ((status = test_pair (W, s, m, &hit)))
        return status;
      if (hit)
        {
          W->mq[(*tail)++] = m;
          if (!all)
            break;
        }
    }
  return LAC_SUCCESS;
}

/* Queue the slave neighbours of s (facets sharing a vertex) not yet
 * queued, with s as their donor, if s has pairs to hand on. */
static void
queue_neighbours (lac_pairing_search *W, size_t s)
{
  const lac_pairing_side *S = &W->S;
  if (W->pcnt[s] == 0)
    return;
  for (int a = 0; a < 4; a++)
    {
      size_t v = S->vid[4 * s + (size_t) a];
      if (v == NONE)
        continue;
      for (size_t j = S->vptr[v]; j < S->vptr[v + 1]; j++)
        {
          size_t s2 = S->vfac[j];
          if (W->state[s2] == 0)
            W->state[s2] = 1, W->donor[s2] = s, W->sq[W->sqt++] = s2;
        }
    }
}

/* Pair slave facet s.                                   [LAC §4.6, item 4]
 *
 *   Step 1: seeds.  The masters paired with the donor (a paired slave
 *           neighbour) are tested first, then, if none overlaps s, their
 *           master neighbours (on matching meshes the donor's masters only
 *           touch s).  If that fails too, or s has no donor (first facet
 *           of a contact zone), the bucket grid gives the seeds.  In robust
 *           mode every grid candidate is tested and there is no flood.
 *   Step 2: flood over master neighbours while they overlap s.
 *   Step 3: completion.  If s is only partly covered, the overlapping
 *           masters may form several groups that share no vertex (a
 *           non-conforming master surface, two master bodies); every grid
 *           candidate not yet tested is tested, and the flood resumes from
 *           those that overlap.  Only facets at the edge of a contact zone
 *           take this step, O(n^(1/2)) of them in 3D.
 *   Step 4: queue the slave neighbours of s that are not yet queued, with
 *           s as their donor (only if s has pairs to hand on).
 */
static int
pair_slave (lac_pairing_search *W, size_t s)
{
  size_t tail = 0, d = W->donor[s];
  int hit, status;
  if ((status = lac_pairing_side_facet (&W->S, s, &W->sf, "slave")))
    return status;
  W->pbeg[s] = W->np;
  W->cov = 0;
  if (!W->o->robust && d != NONE)                             /* step 1 */
    {
      for (size_t q = W->pbeg[d]; q < W->pbeg[d] + W->pcnt[d]; q++)
        {
          if (W->mst[W->pm[q]] == s)
            continue;
          if ((status = test_pair (W, s, W->pm[q], &hit)))
            return status;
          if (hit)
            W->mq[tail++] = W->pm[q];
        }
      for (size_t q = W->pbeg[d]; tail == 0 && q < W->pbeg[d] + W->pcnt[d];
           q++)
        if ((status = test_neighbours (W, s, W->pm[q], &tail)))
          return status;
    }
  if (tail == 0 && (status = test_grid (W, s, W->o->robust, &tail)))
    return status;
  if (!W->o->robust && tail > 0)
    {
      if ((status = flood (W, s, 0, &tail)))                  /* step 2 */
        return status;
      size_t head = tail;
      if (W->cov < 1 - 1e-9                                   /* step 3 */
          && ((status = test_grid (W, s, 1, &tail))
              || (status = flood (W, s, head, &tail))))
        return status;
    }
  queue_neighbours (W, s);                                    /* step 4 */
  return LAC_SUCCESS;
}

/* lac_pairing_search_init: gather both sides (facet nodes, vertex
 * adjacency), the bucket grid of the master facets, and the work arrays. */
int
lac_pairing_search_init (lac_pairing_search *W,
                         const lac_pairing_facets *slave,
                         const lac_pairing_facets *master,
                         const lac_pairing_opts *o)
{
  int status;
  W->o = o;
  if ((status = side_build (&W->S, slave, "slave"))
      || (status = side_build (&W->M, master, "master"))
      || (status = grid_build (&W->G, &W->M, W->o)))
    return status;
  return search_alloc (W);
}

/* The advancing front over all slave facets: every facet not reached by
 * the front of an earlier contact zone starts a new one (re-seeding for
 * disconnected zones).  Each slave facet is paired once. */
int
lac_pairing_search_run (lac_pairing_search *W)
{
  int status;
  for (size_t s0 = 0; s0 < W->S.f->n; s0++)
    {
      if (W->state[s0])
        continue;
      W->state[s0] = 1, W->donor[s0] = NONE;
      W->sqh = W->sqt = 0;
      W->sq[W->sqt++] = s0;
      while (W->sqh < W->sqt)
        {
          size_t s = W->sq[W->sqh++];
          if ((status = pair_slave (W, s)))
            return status;
          W->state[s] = 2;
        }
    }
  return LAC_SUCCESS;
}

