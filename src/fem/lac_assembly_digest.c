/* lac_assembly_digest.c -- what the Dirichlet elimination leaves of K,
 *                          without K whole (see lac_assembly_digest.h)
 *                                                          [LAC §4.3]
 *
 * For each block of nodes b0 <= b < b1:
 *   1. the block's columns of K, from every cell around its nodes, in the
 *      order of the cells (lac_pattern_build_nodes, lac_pattern_add);
 *   2. each column j in order: its entries counted, its elimination
 *      (lac_dirichlet_column: the lift F -= K(:,j) g_j, fixed rows and
 *      columns zeroed, d_j on a fixed diagonal), its sum of |k_ij| and its
 *      diagonal (lac_csc_diag_norm1 of the eliminated K).
 * Then F(k) = d_k g_k on the fixed dofs (step 3).
 */
#include "fem/lac_assembly_digest.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_pattern.h"

#define DEFAULT_BLOCK ((size_t) 1 << 23)   /* entries of K in a block */

void
lac_k_digest_clear (lac_k_digest *k)
{
  if (!k)
    return;
  lac_free (k->diag);
  memset (k, 0, sizeof *k);
}

/* Nodes in the first block of about `block` entries: entries per node
 * estimated by dim^2 sum_c nen_c^2 / nnodes (at least the true mean;
 * the next blocks follow what the last one held, next_step). */
static size_t
nodes_per_block (const lac_mesh *m, size_t block)
{
  size_t sum = 0, d = (size_t) m->dim;
  for (size_t c = 0; c < m->ncells; c++)
    {
      size_t nen = m->ptr[c + 1] - m->ptr[c];
      sum += nen * nen;
    }
  size_t per_node = m->nnodes ? d * d * (sum / m->nnodes + 1) : 1;
  size_t nodes = (block ? block : DEFAULT_BLOCK) / per_node;
  return nodes ? nodes : 1;
}

/* Step 1: the columns of the block P from the cells kept, in order. */
static int
fill_block (const lac_mesh *m, const lac_elastic *mat, const char *cells,
            lac_pattern *P, lac_quad_cache *qc, double *Ke)
{
  for (size_t c = 0; c < m->ncells; c++)
    if (cells[c] && P->cptr[c + 1] > P->cptr[c])
      {
        int status = lac_assembly_cell_stiffness_q (m, mat, c, qc, Ke);
        if (status)
          return status;
        lac_pattern_add (P, m, c, Ke);                       /* K += Ke */
      }
  return LAC_SUCCESS;
}

/* Step 2 for column jl of the block, dof j: its elimination
 * (lac_dirichlet_column, in place: the block is thrown away), then its
 * diagonal and sum of |k_ij| (lac_csc_diag_norm1's, row numbers being
 * dofs). */
static int
read_column (lac_csc *K, size_t jl, size_t j, const char *fixed, double *g,
             double *F, double *diag, double *norm1)
{
  double sum = 0;
  int status = lac_dirichlet_column (K, jl, j, fixed, g, F);
  if (status)
    return status;
  diag[j] = 0;
  for (int p = K->p[jl]; p < K->p[jl + 1]; p++)
    {
      sum += fabs (K->x[p]);
      if ((size_t) K->i[p] == j)
        diag[j] = K->x[p];
    }
  *norm1 = fmax (*norm1, sum);
  return LAC_SUCCESS;
}

/* Steps 1 and 2 for the nodes b0 <= b < b1; *entries: the block's. */
static int
one_block (const lac_mesh *m, const lac_elastic *mat, const char *cells,
           size_t b0, size_t b1, const char *fixed, double *g, double *F,
           lac_quad_cache *qc, double *Ke, lac_k_digest *out,
           size_t *entries)
{
  lac_pattern *P = lac_pattern_build_nodes (m, cells, b0, b1);
  size_t d = (size_t) m->dim;
  int status = P ? fill_block (m, mat, cells, P, qc, Ke) : LAC_ENOMEM;
  *entries = P ? (size_t) P->K->p[P->K->ncol] : 0;
  for (size_t jl = 0; !status && jl < d * (b1 - b0); jl++)
    {
      out->nnz += (size_t) (P->K->p[jl + 1] - P->K->p[jl]);
      status = read_column (P->K, jl, d * b0 + jl, fixed, g, F, out->diag,
                            &out->norm1);
    }
  lac_pattern_free (P);
  return status;
}

/* The nodes of the next block: the last block's scaled to `block`
 * entries by what it held (between half and twice as many nodes). */
static size_t
next_step (size_t step, size_t entries, size_t block)
{
  double r = entries ? (double) block / (double) entries : 2.0;
  size_t next = (size_t) ((double) step * (r < 0.5 ? 0.5 : r > 2.0 ? 2.0
                                           : r));
  return next ? next : 1;
}

int
lac_assembly_digest (const lac_mesh *m, const lac_elastic *mat,
                     const lac_dirichlet *d, size_t block, double *F,
                     lac_k_digest *out)
{
  size_t n = m ? (size_t) m->dim * m->nnodes : 0;
  char *fixed = NULL, *cells = NULL;
  double *g = NULL, *Ke = NULL;
  lac_quad_cache qc;
  int status;
  memset (out, 0, sizeof *out);
  memset (&qc, 0, sizeof qc);
  if (!m || !mat || !d || !F || !mat->E)
    LAC_ERROR (LAC_EINVAL, "mesh, material, Dirichlet list or loads NULL");
  if ((status = lac_dirichlet_dense (d, n, &fixed, &g)))
    goto done;
  cells = lac_malloc (m->ncells + 1);
  Ke = lac_malloc (LAC_MAX_NODES * 3 * LAC_MAX_NODES * 3 * sizeof *Ke);
  out->diag = lac_calloc (n ? n : 1, sizeof *out->diag);
  if (!cells || !Ke || !out->diag)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "the digest of K of %zu dofs", n);
      goto done;
    }
  for (size_t c = 0; c < m->ncells; c++)
    cells[c] = mat->E[c] > 0.0;            /* the cells of elastic bodies */
  size_t step = nodes_per_block (m, block), entries = 0;
  block = block ? block : DEFAULT_BLOCK;
  for (size_t b0 = 0, b1; b0 < m->nnodes && !status; b0 = b1)
    {
      b1 = b0 + step < m->nnodes ? b0 + step : m->nnodes;
      status = one_block (m, mat, cells, b0, b1, fixed, g, F, &qc, Ke, out,
                          &entries);
      step = next_step (step, entries, block);
    }
  for (size_t k = 0; !status && k < n; k++)
    if (fixed[k])
      F[k] = g[k];                                   /* F(k) = d_k g_k */
done:
  lac_quad_cache_free (&qc);
  lac_free (Ke);
  lac_free (cells);
  lac_free (g);
  lac_free (fixed);
  if (status)
    lac_k_digest_clear (out);
  return status;
}
