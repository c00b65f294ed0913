/* lac_assembly_digest.c -- what the Dirichlet elimination leaves of K on
 *                          the program that reads the mesh, without K
 *                          (see lac_assembly_digest.h)     [LAC §4.3]
 *
 1. the cells of bodies around each node (lac_pattern_node_cells) and
 *    from them the entries (lac_pattern_count);
 * 2. every fixed dof has a cell of a body around its node (else the error
 *    of lac_dirichlet_column);
 * 3. for each node a with a nonzero Dirichlet value, in node order: its
 *    dim columns K(:, dim a + k), summed over the cells around a in
 *    their order, then lac_dirichlet_column on each of them in order
 *    (the lift F -= K(:,j) g_j, g_j *= d_j on a fixed dof j);
 * 4. F(k) = d_k g_k on the fixed dofs (lac_dirichlet_apply's step 3).
 */
#include "fem/lac_assembly_digest.h"

#include <stdint.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_pattern.h"

/* The columns of one node: its neighbours nbr[0 .. nn) (slot[b]: the
 * place of node b among them, SIZE_MAX if none) and col, the entries
 * K(dim nbr[s] + i, dim a + k) at col[(dim s + i) dim + k]; Kc, the same
 * as dim compressed columns whose rows are dofs. */
typedef struct node_columns
{
  size_t *cptr, *cidx;     /* the cells of bodies around each node       */
  size_t *slot, *nbr, nn;
  double *col, *Ke;
  lac_csc *Kc;
  lac_quad_cache qc;
} node_columns;

/* 1 if node a has a fixed dof with a nonzero value. */
static int
lifted (size_t a, size_t d, const char *fixed, const double *g)
{
  for (size_t k = 0; k < d; k++)
    if (fixed[d * a + k] && g[d * a + k] != 0.0)
      return 1;
  return 0;
}

/* Step 3's columns of node a: the sum of its cells' blocks, in order. */
static int
columns (const lac_mesh *m, const lac_elastic *mat, size_t a,
         node_columns *nc)
{
  size_t d = (size_t) m->dim;
  nc->nn = 0;
  for (size_t q = nc->cptr[a]; q < nc->cptr[a + 1]; q++)
    {
      size_t c = nc->cidx[q], nen = m->ptr[c + 1] - m->ptr[c], ia = 0;
      const int *conn = m->conn + m->ptr[c];
      int status = lac_assembly_cell_stiffness_q (m, mat, c, &nc->qc, nc->Ke);
      if (status)
        return status;
      while ((size_t) conn[ia] != a)
        ia++;
      for (size_t b = 0; b < nen; b++)
        {
          size_t *s = nc->slot + conn[b];
          if (*s == SIZE_MAX)
            {
              *s = nc->nn++;
              nc->nbr[*s] = (size_t) conn[b];
              memset (nc->col + *s * d * d, 0, d * d * sizeof *nc->col);
            }
          for (size_t i = 0; i < d; i++)
            for (size_t k = 0; k < d; k++)                    /* K += Ke */
              nc->col[(*s * d + i) * d + k]
                += nc->Ke[(b * d + i) * nen * d + ia * d + k];
        }
    }
  return LAC_SUCCESS;
}

/* Step 3 for node a: its columns, then lac_dirichlet_column on each. */
static int
lift_node (const lac_mesh *m, const lac_elastic *mat, size_t a,
           const char *fixed, double *g, double *F, node_columns *nc)
{
  size_t d = (size_t) m->dim;
  int status = columns (m, mat, a, nc);
  size_t nr = nc->nn * d;                     /* entries in each column */
  for (size_t k = 0; k <= d; k++)
    nc->Kc->p[k] = (int) (k * nr);
  for (size_t k = 0; k < d; k++)
    for (size_t s = 0; s < nc->nn; s++)
      for (size_t i = 0; i < d; i++)
        {
          size_t q = k * nr + s * d + i;
          nc->Kc->i[q] = (int) (d * nc->nbr[s] + i);
          nc->Kc->x[q] = nc->col[(s * d + i) * d + k];
        }
  for (size_t k = 0; !status && k < d; k++)
    status = lac_dirichlet_column (nc->Kc, k, d * a + k, fixed, g, F);
  for (size_t s = 0; s < nc->nn; s++)
    nc->slot[nc->nbr[s]] = SIZE_MAX;
  return status;
}

/* Step 2: the first fixed dof of a node in no cell of a body. */
static int
check_fixed (const lac_mesh *m, const char *fixed, const size_t *cptr)
{
  size_t d = (size_t) m->dim;
  for (size_t j = 0; j < d * m->nnodes; j++)
    if (fixed[j] && cptr[j / d + 1] == cptr[j / d])
      LAC_ERROR (LAC_EINVAL, "fixed dof %zu has no diagonal entry in K: "
                 "its node belongs to no assembled cell", j);
  return LAC_SUCCESS;
}

/* The arrays of nc for the lifted nodes: neighbours at most the sum of
 * the cells' nodes around one of them. */
static int
alloc_columns (const lac_mesh *m, const char *fixed, const double *g,
               node_columns *nc)
{
  size_t d = (size_t) m->dim, cap = 1;
  for (size_t a = 0; a < m->nnodes; a++)
    if (lifted (a, d, fixed, g))
      {
        size_t sum = 0;
        for (size_t q = nc->cptr[a]; q < nc->cptr[a + 1]; q++)
          sum += m->ptr[nc->cidx[q] + 1] - m->ptr[nc->cidx[q]];
        cap = sum > cap ? sum : cap;
      }
  nc->slot = lac_malloc ((m->nnodes + 1) * sizeof *nc->slot);
  nc->nbr = lac_malloc (cap * sizeof *nc->nbr);
  nc->col = lac_malloc (cap * d * d * sizeof *nc->col);
  nc->Ke = lac_malloc (LAC_MAX_NODES * 3 * LAC_MAX_NODES * 3
                       * sizeof *nc->Ke);
  nc->Kc = lac_csc_alloc (d * m->nnodes, d, cap * d * d);
  if (!nc->slot || !nc->nbr || !nc->col || !nc->Ke || !nc->Kc)
    LAC_ERROR (LAC_ENOMEM, "the lift of %zu nodes", m->nnodes);
  for (size_t a = 0; a <= m->nnodes; a++)
    nc->slot[a] = SIZE_MAX;
  return LAC_SUCCESS;
}

int
lac_assembly_digest (const lac_mesh *m, const lac_elastic *mat,
                     const lac_dirichlet *d, double *F, size_t *nnz)
{
  size_t n = m ? (size_t) m->dim * m->nnodes : 0;
  char *fixed = NULL, *cells = NULL;
  double *g = NULL;
  node_columns nc;
  int status;
  memset (&nc, 0, sizeof nc);
  *nnz = 0;
  if (!m || !mat || !d || !F || !mat->E)
    LAC_ERROR (LAC_EINVAL, "mesh, material, Dirichlet list or loads NULL");
  if ((status = lac_dirichlet_dense (d, n, &fixed, &g)))
    goto done;
  if (!(cells = lac_malloc (m->ncells + 1)))
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "the cells of %zu", m->ncells);
      goto done;
    }
  for (size_t c = 0; c < m->ncells; c++)
    cells[c] = mat->E[c] > 0.0;            /* the cells of elastic bodies */
  if ((status = lac_pattern_node_cells (m, cells, &nc.cptr, &nc.cidx))
      || (status = lac_pattern_count (m, nc.cptr, nc.cidx, nnz))    /* 1 */
      || (status = check_fixed (m, fixed, nc.cptr))                  /* 2 */
      || (status = alloc_columns (m, fixed, g, &nc)))
    goto done;
  for (size_t a = 0; !status && a < m->nnodes; a++)                  /* 3 */
    if (lifted (a, (size_t) m->dim, fixed, g))
      status = lift_node (m, mat, a, fixed, g, F, &nc);
  for (size_t k = 0; !status && k < n; k++)                          /* 4 */
    if (fixed[k])
      F[k] = g[k];                                     /* F(k) = d_k g_k */
done:
  lac_quad_cache_free (&nc.qc);
  lac_csc_free (nc.Kc);
  lac_free (nc.Ke);
  lac_free (nc.col);
  lac_free (nc.nbr);
  lac_free (nc.slot);
  lac_free (nc.cidx);
  lac_free (nc.cptr);
  lac_free (cells);
  lac_free (g);
  lac_free (fixed);
  if (status)
    *nnz = 0;
  return status;
}
