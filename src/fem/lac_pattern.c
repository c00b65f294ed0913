/* lac_pattern.c -- the stiffness pattern and the scatter map
 *                  (see lac_pattern.h)                         [LAC (17)]
 *
 * 1. node -> cells (the cells kept), 2. each node's sorted neighbours,
 * 3. the CSC (dim columns per node, dim rows per neighbour), 4. the map.
 */
#include "fem/lac_pattern.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* Node -> cells as a CSR list (ptr: nnodes+1, cell). */
typedef struct graph
{
  size_t *ptr;
  size_t *idx;
} graph;

static void
graph_free (graph *g)
{
  lac_free (g->ptr);
  lac_free (g->idx);
  g->ptr = g->idx = NULL;
}

static int
node_cells (const lac_mesh *m, const char *cells, graph *g)
{
  g->ptr = lac_calloc (m->nnodes + 1, sizeof *g->ptr);
  if (!g->ptr)
    return LAC_ENOMEM;
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t q = m->ptr[c]; (!cells || cells[c]) && q < m->ptr[c + 1]; q++)
      g->ptr[m->conn[q] + 1]++;
  for (size_t a = 0; a < m->nnodes; a++)
    g->ptr[a + 1] += g->ptr[a];
  size_t *fill = lac_malloc ((m->nnodes + 1) * sizeof *fill);
  g->idx = lac_malloc ((g->ptr[m->nnodes] + 1) * sizeof *g->idx);
  if (!fill || !g->idx)
    {
      lac_free (fill);
      return LAC_ENOMEM;
    }
  memcpy (fill, g->ptr, m->nnodes * sizeof *fill);
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t q = m->ptr[c]; (!cells || cells[c]) && q < m->ptr[c + 1]; q++)
      g->idx[fill[m->conn[q]]++] = c;
  lac_free (fill);
  return LAC_SUCCESS;
}

static int
cmp_size (const void *x, const void *y)
{
  size_t a = *(const size_t *) x, b = *(const size_t *) y;
  return (a > b) - (a < b);
}

/* The neighbours of node b (the nodes of the cells around it, given by
 * ptr and idx, itself included) into out (NULL: only counted), in the
 * order met; mark[]: SIZE_MAX or another node's number on entry, b on
 * return for each neighbour.  Their number. */
static size_t
node_neighbours (const lac_mesh *m, const size_t *ptr, const size_t *idx,
                 size_t b, size_t *mark, size_t *out)
{
  size_t deg = 0;
  for (size_t q = ptr[b]; q < ptr[b + 1]; q++)
    for (size_t r = m->ptr[idx[q]]; r < m->ptr[idx[q] + 1]; r++)
      if (mark[m->conn[r]] != b)
        {
          mark[m->conn[r]] = b;
          if (out)
            out[deg] = (size_t) m->conn[r];
          deg++;
        }
  return deg;
}

/* Node -> its neighbours, sorted; two passes with a marker per node. */
static int
neighbours (const lac_mesh *m, const graph *nc, graph *nb)
{
  size_t n = m->nnodes;
  size_t *mark = lac_malloc ((n + 1) * sizeof *mark);
  nb->ptr = lac_calloc (n + 1, sizeof *nb->ptr);
  if (!mark || !nb->ptr)
    {
      lac_free (mark);
      return LAC_ENOMEM;
    }
  for (int pass = 0; pass < 2; pass++)
    {
      for (size_t a = 0; a <= n; a++)
        mark[a] = SIZE_MAX;
      for (size_t b = 0; b < n; b++)
        {
          size_t deg = node_neighbours (m, nc->ptr, nc->idx, b, mark,
                                        pass ? nb->idx + nb->ptr[b] : NULL);
          if (!pass)
            nb->ptr[b + 1] = nb->ptr[b] + deg;
          else
            qsort (nb->idx + nb->ptr[b], deg, sizeof *nb->idx, cmp_size);
        }
      if (!pass && !(nb->idx = lac_malloc ((nb->ptr[n] + 1)
                                           * sizeof *nb->idx)))
        {
          lac_free (mark);
          return LAC_ENOMEM;
        }
    }
  lac_free (mark);
  return LAC_SUCCESS;
}

/* The CSC: column dim b + k holds rows dim a + i, a among b's neighbours. */
static int
csc_of (const graph *nb, size_t nnodes, int dim, lac_csc **out)
{
  size_t d = (size_t) dim, nnz = nb->ptr[nnodes] * d * d;
  if (nnz > INT_MAX)
    LAC_ERROR (LAC_EINVAL, "%zu entries in the pattern: more than INT_MAX "
               "(int indices)", nnz);
  lac_csc *K = *out = lac_csc_alloc (d * nnodes, d * nnodes, nnz);
  if (!K)
    return LAC_ENOMEM;
  size_t q = 0;
  for (size_t b = 0; b < nnodes; b++)
    for (size_t k = 0; k < d; k++)
      {
        for (size_t t = nb->ptr[b]; t < nb->ptr[b + 1]; t++)
          for (size_t i = 0; i < d; i++)
            K->i[q++] = (int) (nb->idx[t] * d + i);
        K->p[b * d + k + 1] = (int) q;
      }
  memset (K->x, 0, nnz * sizeof *K->x);
  return LAC_SUCCESS;
}

/* Position of node a in b's sorted neighbours. */
static int
position (const graph *nb, size_t b, size_t a)
{
  const size_t *x = nb->idx + nb->ptr[b];
  size_t lo = 0, hi = nb->ptr[b + 1] - nb->ptr[b];
  while (hi - lo > 1)
    {
      size_t mid = (lo + hi) / 2;
      if (x[mid] <= a)
        lo = mid;
      else
        hi = mid;
    }
  return (int) lo;
}

static int
make_map (lac_pattern *p, const lac_mesh *m, const char *cells,
          const graph *nb)
{
  p->cptr = lac_calloc (m->ncells + 1, sizeof *p->cptr);
  if (!p->cptr)
    return LAC_ENOMEM;
  for (size_t c = 0; c < m->ncells; c++)
    {
      size_t nen = m->ptr[c + 1] - m->ptr[c];
      p->cptr[c + 1] = p->cptr[c] + (!cells || cells[c] ? nen * nen : 0);
    }
  if (!(p->pos = lac_malloc ((p->cptr[m->ncells] + 1) * sizeof *p->pos)))
    return LAC_ENOMEM;
  for (size_t c = 0; c < m->ncells; c++)
    {
      const int *conn = m->conn + m->ptr[c];
      size_t nen = m->ptr[c + 1] - m->ptr[c];
      int *pos = p->pos + p->cptr[c];
      for (size_t a = 0; p->cptr[c + 1] > p->cptr[c] && a < nen; a++)
        for (size_t b = 0; b < nen; b++)
          pos[a * nen + b] = position (nb, (size_t) conn[b], (size_t) conn[a]);
    }
  return LAC_SUCCESS;
}

/* ---- the slabs (lac_pattern.h) ----------------------------------------- */

typedef struct keyed
{
  double key;
  size_t cell;
} keyed;

static int
cmp_key (const void *x, const void *y)
{
  const keyed *a = x, *b = y;
  if (a->key != b->key)
    return a->key < b->key ? -1 : 1;
  return a->cell < b->cell ? -1 : a->cell > b->cell;
}

/* The axis along which the mesh's nodes spread most. */
static int
longest_axis (const lac_mesh *m)
{
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
  int d = m->dim, best = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    for (int k = 0; k < d; k++)
      {
        double x = m->x[a * (size_t) d + (size_t) k];
        lo[k] = a == 0 || x < lo[k] ? x : lo[k];
        hi[k] = a == 0 || x > hi[k] ? x : hi[k];
      }
  for (int k = 1; k < d; k++)
    if (hi[k] - lo[k] > hi[best] - lo[best])
      best = k;
  return best;
}

/* slab[c] = 1 + the slab of cell c of the pattern (0: not in it): the
 * cells sorted by their centres along the longest axis, nslab equal
 * shares of that order.  LAC_ENOMEM. */
static int
cut_slabs (const lac_pattern *p, const lac_mesh *m, size_t nslab,
           size_t *slab)
{
  size_t n = 0;
  int axis = longest_axis (m), d = m->dim;
  keyed *kc = lac_malloc ((m->ncells + 1) * sizeof *kc);
  if (!kc)
    return LAC_ENOMEM;
  for (size_t c = 0; c < m->ncells; c++)
    {
      double s = 0;
      slab[c] = 0;
      if (p->cptr[c + 1] == p->cptr[c])
        continue;                                  /* not in the pattern */
      for (size_t q = m->ptr[c]; q < m->ptr[c + 1]; q++)
        s += m->x[(size_t) m->conn[q] * (size_t) d + (size_t) axis];
      kc[n++] = (keyed) { s / (double) (m->ptr[c + 1] - m->ptr[c]), c };
    }
  qsort (kc, n, sizeof *kc, cmp_key);
  for (size_t j = 0; j < n; j++)                  /* share j nslab / n */
    slab[kc[j].cell] = 1 + j * nslab / n;
  lac_free (kc);
  return LAC_SUCCESS;
}

/* From slabs to runs: run[c] = 1 + the slab of cell c on entry (0: not
 * in the pattern, as cut_slabs leaves it), its run on return (SIZE_MAX:
 * not in the pattern): slab s even, run s / 2; odd, the count of even
 * slabs + s / 2; the last run, nslab, for a cell with a node that a cell
 * of another slab of the same parity has.  Found node by node:
 * owner[2 a + parity] = 1 + the first slab of that parity met at node a,
 * bad[a] has bit (1 << parity) once another one meets it.  LAC_ENOMEM. */
static int
runs_of_cells (const lac_mesh *m, size_t nslab, size_t *run)
{
  size_t *owner = lac_calloc (2 * m->nnodes + 1, sizeof *owner);
  unsigned char *bad = lac_calloc (m->nnodes + 1, 1);
  if (!owner || !bad)
    {
      lac_free (owner), lac_free (bad);
      return LAC_ENOMEM;
    }
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t q = m->ptr[c]; run[c] && q < m->ptr[c + 1]; q++)
      {
        size_t par = (run[c] - 1) % 2, *o = owner + 2 * (size_t) m->conn[q];
        if (!o[par])
          o[par] = run[c];
        else if (o[par] != run[c])
          bad[m->conn[q]] |= (unsigned char) (1u << par);
      }
  for (size_t c = 0; c < m->ncells; c++)
    {
      if (!run[c])
        {
          run[c] = SIZE_MAX;                       /* not in the pattern */
          continue;
        }
      size_t s = run[c] - 1, par = s % 2;
      int shared = 0;
      for (size_t q = m->ptr[c]; q < m->ptr[c + 1]; q++)
        shared |= bad[m->conn[q]] >> par & 1;
      run[c] = shared ? nslab : par ? (nslab + 1) / 2 + s / 2 : s / 2;
    }
  lac_free (owner), lac_free (bad);
  return LAC_SUCCESS;
}

/* p->order, p->run, p->nrun, p->phase from the run of every cell (the
 * cells of a run in the cells' order).  LAC_ENOMEM (nothing kept). */
static int
fill_runs (lac_pattern *p, const lac_mesh *m, size_t nslab, const size_t *run)
{
  size_t nrun = nslab + 1;
  p->order = lac_malloc ((m->ncells + 1) * sizeof *p->order);
  p->run = lac_calloc (nrun + 1, sizeof *p->run);
  if (!p->order || !p->run)
    {
      lac_free (p->order), lac_free (p->run);
      p->order = NULL, p->run = NULL;
      return LAC_ENOMEM;
    }
  for (size_t c = 0; c < m->ncells; c++)
    if (run[c] != SIZE_MAX)
      p->run[run[c] + 1]++;
  for (size_t r = 0; r < nrun; r++)
    p->run[r + 1] += p->run[r];
  for (size_t c = 0; c < m->ncells; c++)          /* in the cells' order */
    if (run[c] != SIZE_MAX)
      p->order[p->run[run[c]]++] = c;
  for (size_t r = nrun; r > 0; r--)               /* back to the starts */
    p->run[r] = p->run[r - 1];
  p->run[0] = 0;
  p->nrun = nrun;
  p->phase[0] = 0;
  p->phase[1] = (nslab + 1) / 2;                  /* the even slabs */
  p->phase[2] = nslab;                            /* the odd ones */
  p->phase[3] = nrun;                             /* the shared cells */
  return LAC_SUCCESS;
}

lac_pattern *
lac_pattern_build (const lac_mesh *m, const char *cells)
{
  graph nc = { NULL, NULL }, nb = { NULL, NULL };
  lac_pattern *p = lac_calloc (1, sizeof *p);
  int status = p ? node_cells (m, cells, &nc)
                 : LAC_ERRMSG (LAC_ENOMEM, "the pattern of K");
  if (!status)
    status = neighbours (m, &nc, &nb);
  graph_free (&nc);
  if (!status)
    {
      p->dim = m->dim;
      p->ncells = m->ncells;
      p->ndof = (size_t) m->dim * m->nnodes;
      status = csc_of (&nb, m->nnodes, m->dim, &p->K);
    }
  if (!status)
    status = make_map (p, m, cells, &nb);
  graph_free (&nb);
  if (status)
    {
      lac_pattern_free (p);
      if (status == LAC_ENOMEM)
        LAC_ERROR_NULL (LAC_ENOMEM, "pattern of the stiffness of %zu nodes",
                        m->nnodes);
      return NULL;
    }
  return p;
}

int
lac_pattern_slabs (lac_pattern *p, const lac_mesh *m, size_t nslab)
{
  if (p->order && p->nrun == nslab + 1)
    return LAC_SUCCESS;                          /* made by an earlier call */
  if (p->ncells != m->ncells || p->ndof != (size_t) m->dim * m->nnodes)
    LAC_ERROR (LAC_EINVAL, "the pattern of %zu cells and %zu dofs is not "
               "that of the mesh (%zu cells, %zu dofs)", p->ncells, p->ndof,
               m->ncells, (size_t) m->dim * m->nnodes);
  if (nslab < 1)
    LAC_ERROR (LAC_EINVAL, "%zu slabs: at least one is needed", nslab);
  lac_free (p->order), lac_free (p->run);          /* another count's */
  p->order = NULL, p->run = NULL;
  p->nrun = 0;
  size_t *run = lac_malloc ((m->ncells + 1) * sizeof *run);
  int status = run ? cut_slabs (p, m, nslab, run) : LAC_ENOMEM;
  if (!status)
    status = runs_of_cells (m, nslab, run);
  if (!status)
    status = fill_runs (p, m, nslab, run);
  lac_free (run);
  if (status)
    LAC_ERROR (status, "%zu slabs of %zu cells", nslab, m->ncells);
  return LAC_SUCCESS;
}

int
lac_pattern_node_cells (const lac_mesh *m, const char *cells, size_t **ptr,
                        size_t **idx)
{
  graph g = { NULL, NULL };
  int status = node_cells (m, cells, &g);
  if (status)
    {
      graph_free (&g);
      LAC_ERROR (status, "the cells around %zu nodes", m->nnodes);
    }
  *ptr = g.ptr;
  *idx = g.idx;
  return LAC_SUCCESS;
}

int
lac_pattern_count (const lac_mesh *m, const size_t *ptr, const size_t *idx,
                   size_t *nnz)
{
  size_t d = (size_t) m->dim;
  size_t *mark = lac_malloc ((m->nnodes + 1) * sizeof *mark);
  *nnz = 0;
  if (!mark)
    LAC_ERROR (LAC_ENOMEM, "the pattern's count of %zu nodes", m->nnodes);
  for (size_t a = 0; a < m->nnodes; a++)
    mark[a] = SIZE_MAX;
  for (size_t b = 0; b < m->nnodes; b++)
    *nnz += d * d * node_neighbours (m, ptr, idx, b, mark, NULL);
  lac_free (mark);
  return LAC_SUCCESS;
}

void
lac_pattern_free (lac_pattern *p)
{
  if (!p)
    return;
  lac_csc_free (p->K);
  lac_free (p->cptr);
  lac_free (p->pos);
  lac_free (p->order);
  lac_free (p->run);
  lac_free (p);
}

void
lac_pattern_zero (lac_pattern *p)
{
  memset (p->K->x, 0, (size_t) p->K->p[p->K->ncol] * sizeof *p->K->x);
}

void
lac_pattern_add (lac_pattern *p, const lac_mesh *m, size_t c,
                 const double *Ke)
{
  const int *conn = m->conn + m->ptr[c], *pos = p->pos + p->cptr[c];
  const int *cp = p->K->p;
  size_t nen = m->ptr[c + 1] - m->ptr[c], d = (size_t) p->dim;
  size_t nc = nen * d;
  double *x = p->K->x;
  for (size_t b = 0; b < nen; b++)
    for (size_t k = 0; k < d; k++)
      {
        size_t col = b * d + k;
        double *xc = x + cp[(size_t) conn[b] * d + k];
        for (size_t a = 0; a < nen; a++)
          {
            double *xa = xc + (size_t) pos[a * nen + b] * d;
            for (size_t i = 0; i < d; i++)
              xa[i] += Ke[(a * d + i) * nc + col];      /* K += Ke */
          }
      }
}
