/* lac_assembly_dist.c -- K_W assembled by the processes that own the cells
 *                        (see lac_assembly_dist.h)          [LAC (8), (17)]
 */
#include "fem/lac_assembly_dist.h"

#ifdef LAC_HAVE_PETSC

#include <petscmat.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

#define NC_MAX (LAC_MAX_NODES * 3)   /* dofs of a cell, at most          */

struct lac_dist
{
  int rank, size, bs, cells;   /* cells: K from the cells               */
  size_t n;
  PetscInt *rstart;            /* size + 1: the processes' first rows   */
  PetscInt *row;               /* n: PETSc row of a dof (NULL: itself)  */
  /* cells: the mesh (the root's, or a copy), its partition */
  const lac_mesh *m;
  lac_mesh *copy;              /* owned on the others                   */
  lac_elastic mat;             /* E, nu: the root's or owned            */
  double *E, *nu;              /* owned on the others                   */
  char *fixed;                 /* owned, n                              */
  int *owner;                  /* owned, ncells                         */
  double *probe;               /* owned, n: s sum_e K_e x of the own
                                  cells, x the probe (probe_at)         */
  /* contact: C on every process */
  lac_csc *C;                  /* owned (k = C->ncol)                   */
  int *col;                    /* owned, k: 1 if this process owns it   */
};

/* ---- the mesh to every process ------------------------------------------ */

typedef struct sizes
{
  int dim, model;
  size_t nnodes, ncells, nconn;
} sizes;

static int
bcast_arrays (lac_dist *d, lac_mesh *m, double *E, double *nu)
{
  int status;
  size_t nc = m->ncells;
  if ((status = lac_petsc_bcast (m->x, m->nnodes * (size_t) m->dim
                                 * sizeof *m->x))
      || (status = lac_petsc_bcast (m->type, nc * sizeof *m->type))
      || (status = lac_petsc_bcast (m->ptr, (nc + 1) * sizeof *m->ptr))
      || (status = lac_petsc_bcast (m->conn, m->ptr[nc] * sizeof *m->conn))
      || (status = lac_petsc_bcast (m->cell_tag, nc * sizeof *m->cell_tag))
      || (status = lac_petsc_bcast (E, nc * sizeof *E))
      || (status = lac_petsc_bcast (nu, nc * sizeof *nu)))
    return status;
  return lac_petsc_bcast (d->fixed, d->n);
}

/* The others: a copy of the root's mesh, material and Dirichlet dofs. */
static int
receive_mesh (lac_dist *d, const sizes *z)
{
  int status = LAC_SUCCESS;
  d->copy = lac_mesh_alloc (z->dim, z->nnodes, z->ncells, z->nconn);
  d->E = lac_malloc ((z->ncells + 1) * sizeof *d->E);
  d->nu = lac_malloc ((z->ncells + 1) * sizeof *d->nu);
  if (!d->copy || !d->E || !d->nu)
    status = LAC_ERRMSG (LAC_ENOMEM, "a copy of the mesh, %zu cells",
                         z->ncells);
  if ((status = lac_petsc_agree (status)))
    return status;
  d->m = d->copy;
  d->mat.model = (lac_model) z->model;
  return bcast_arrays (d, d->copy, d->E, d->nu);
}

/* The root's mesh to every process (d->m, d->mat, d->fixed). */
static int
share_mesh (lac_dist *d, const lac_dist_source *src)
{
  sizes z = { 0, 0, 0, 0, 0 };
  int status = LAC_SUCCESS;
  if (d->rank == 0)
    {
      const lac_mesh *m = src->mesh;
      z = (sizes) { m->dim, (int) src->mat->model, m->nnodes, m->ncells,
                    m->ptr[m->ncells] };
    }
  if ((status = lac_petsc_bcast (&z, sizeof z)))
    return status;
  if (!(d->fixed = lac_calloc (d->n + 1, 1)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the Dirichlet dofs, n = %zu", d->n);
  if (d->rank != 0)
    return status ? lac_petsc_agree (status) : receive_mesh (d, &z);
  if ((status = lac_petsc_agree (status)))
    return status;
  d->m = src->mesh;
  d->mat = *src->mat;
  memcpy (d->fixed, src->fixed, d->n);
  return d->size > 1 ? bcast_arrays (d, (lac_mesh *) src->mesh,
                                     (double *) src->mat->E,
                                     (double *) src->mat->nu) : LAC_SUCCESS;
}

/* ---- the partition of the cells ----------------------------------------- */

/* Cells c0 .. c1-1's neighbours (cells sharing dim nodes) in CSR, made
 * with PETSc's allocator (MatCreateMPIAdj takes them): node -> cells
 * first. */
static int
dual_graph (const lac_mesh *m, size_t c0, size_t c1, PetscInt **ia,
            PetscInt **ja)
{
  size_t nn = m->nnodes, *np = lac_calloc (nn + 1, sizeof *np), cap = 0;
  size_t *nc = lac_malloc ((m->ptr[m->ncells] + 1) * sizeof *nc);
  int *seen = lac_calloc (m->ncells + 1, sizeof *seen), status = 0;
  *ia = NULL, *ja = NULL;
  if (!np || !nc || !seen || PetscMalloc1 (c1 - c0 + 1, ia))
    status = LAC_ENOMEM;
  for (size_t p = 0; !status && p < m->ptr[m->ncells]; p++)
    np[m->conn[p] + 1]++;
  for (size_t a = 0; !status && a < nn; a++)
    np[a + 1] += np[a];
  for (size_t c = 0; !status && c < m->ncells; c++)
    for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
      nc[np[m->conn[p]]++] = c;
  for (size_t a = nn; !status && a > 0; a--)
    np[a] = np[a - 1];
  if (!status)
    np[0] = 0;
  for (size_t c = c0; !status && c < c1; c++)    /* count, then fill */
    for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
      cap += np[m->conn[p] + 1] - np[m->conn[p]];
  if (!status && PetscMalloc1 (cap + 1, ja))
    status = LAC_ENOMEM;
  if (!status)
    (*ia)[0] = 0;
  for (size_t c = c0; !status && c < c1; c++)
    {
      PetscInt *row = *ja + (*ia)[c - c0], len = 0;
      for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
        for (size_t q = np[m->conn[p]]; q < np[m->conn[p] + 1]; q++)
          if (nc[q] != c && ++seen[nc[q]] == m->dim)
            row[len++] = (PetscInt) nc[q];
      for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
        for (size_t q = np[m->conn[p]]; q < np[m->conn[p] + 1]; q++)
          seen[nc[q]] = 0;
      (*ia)[c - c0 + 1] = (*ia)[c - c0] + len;
    }
  lac_free (np);
  lac_free (nc);
  lac_free (seen);
  if (status)
    {
      PetscFree (*ia);
      PetscFree (*ja);
      return LAC_ERRMSG (status, "the dual graph of %zu cells", c1 - c0);
    }
  return LAC_SUCCESS;
}

/* owner[c] for every cell: PETSc's partition of the dual graph, each
 * process giving the rows of its share of the cells. */
static int
partition (lac_dist *d)
{
  size_t nc = d->m->ncells, c0 = nc * (size_t) d->rank / (size_t) d->size;
  size_t c1 = nc * ((size_t) d->rank + 1) / (size_t) d->size;
  PetscInt *ia, *ja;
  const PetscInt *who;
  MatPartitioning part;
  Mat adj;
  IS is, all;
  int status = dual_graph (d->m, c0, c1, &ia, &ja);
  if ((status = lac_petsc_agree (status)))
    return status;
  TRY (MatCreateMPIAdj (PETSC_COMM_WORLD, (PetscInt) (c1 - c0),
                        (PetscInt) nc, ia, ja, NULL, &adj));
  TRY (MatPartitioningCreate (PETSC_COMM_WORLD, &part));
  TRY (MatPartitioningSetAdjacency (part, adj));
#ifdef PETSC_HAVE_PTSCOTCH
  TRY (MatPartitioningSetType (part, MATPARTITIONINGPTSCOTCH));
#endif
  TRY (PetscObjectSetOptionsPrefix ((PetscObject) part, "lac_part_"));
  TRY (MatPartitioningSetFromOptions (part));
  TRY (MatPartitioningApply (part, &is));
  TRY (ISAllGather (is, &all));
  TRY (ISGetIndices (all, &who));
  for (size_t c = 0; c < nc; c++)
    d->owner[c] = (int) who[c];
  TRY (ISRestoreIndices (all, &who));
  TRY (ISDestroy (&all));
  TRY (ISDestroy (&is));
  TRY (MatPartitioningDestroy (&part));
  TRY (MatDestroy (&adj));
  return LAC_SUCCESS;
}

/* The process of every node: its first cell's (0 for none). */
static void
node_owners (const lac_dist *d, int *node)
{
  const lac_mesh *m = d->m;
  for (size_t a = 0; a < m->nnodes; a++)
    node[a] = -1;
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
      if (node[m->conn[p]] < 0)
        node[m->conn[p]] = d->owner[c];
  for (size_t a = 0; a < m->nnodes; a++)
    node[a] = node[a] < 0 ? 0 : node[a];
}

/* row[] and rstart[] from the nodes' processes: the nodes of process 0
 * first, each process's in their order. */
static int
number_rows (lac_dist *d)
{
  size_t nn = d->m->nnodes, bs = (size_t) d->bs;
  int *node = lac_malloc ((nn + 1) * sizeof *node);
  PetscInt *next = lac_calloc ((size_t) d->size + 1, sizeof *next);
  if (!node || !next || !(d->row = lac_malloc (d->n * sizeof *d->row)))
    {
      lac_free (node);
      lac_free (next);
      LAC_ERROR (LAC_ENOMEM, "the rows of %zu dofs", d->n);
    }
  node_owners (d, node);
  for (size_t a = 0; a < nn; a++)
    d->rstart[node[a] + 1] += (PetscInt) bs;
  for (int p = 0; p < d->size; p++)
    {
      d->rstart[p + 1] += d->rstart[p];
      next[p] = d->rstart[p];
    }
  for (size_t a = 0; a < nn; a++)
    {
      for (size_t i = 0; i < bs; i++)
        d->row[bs * a + i] = next[node[a]] + (PetscInt) i;
      next[node[a]] += (PetscInt) bs;
    }
  lac_free (node);
  lac_free (next);
  return LAC_SUCCESS;
}

/* ---- the object ---------------------------------------------------------- */

/* Without cells: whole nodes in N contiguous ranges. */
static void
node_ranges (lac_dist *d)
{
  size_t bs = (size_t) d->bs, nb = d->n / bs;
  for (int p = 0; p <= d->size; p++)
    d->rstart[p] = (PetscInt) (bs * (nb * (size_t) p / (size_t) d->size));
}

static int
with_cells (lac_dist *d, const lac_dist_source *src)
{
  int status;
  if ((status = share_mesh (d, src)))
    return status;
  if ((size_t) d->bs * d->m->nnodes != d->n)
    LAC_ERROR (LAC_EBADLEN, "%zu dofs for %zu nodes of %d components",
               d->n, d->m->nnodes, d->bs);
  d->mat.E = d->rank == 0 ? src->mat->E : d->E;
  d->mat.nu = d->rank == 0 ? src->mat->nu : d->nu;
  if (!(d->owner = lac_calloc (d->m->ncells + 1, sizeof *d->owner)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the owners of %zu cells",
                         d->m->ncells);
  if ((status = lac_petsc_agree (status))
      || (d->size > 1 && (status = partition (d))))
    return status;
  return lac_petsc_agree (number_rows (d));
}

int
lac_dist_alloc (const lac_dist_source *src, size_t n, int bs, lac_dist **out)
{
  lac_dist *d = lac_calloc (1, sizeof *d);
  int status = d ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "the rows");
  *out = NULL;
  if (!status)
    {
      lac_petsc_rank (&d->rank, &d->size);
      d->n = n;
      d->bs = bs;
      d->cells = d->rank == 0 && src && src->mesh;
      if (!(d->rstart = lac_calloc ((size_t) d->size + 2, sizeof
                                    *d->rstart)))
        status = LAC_ERRMSG (LAC_ENOMEM, "the rows");
    }
  if ((status = lac_petsc_agree (status))
      || (status = lac_petsc_bcast (&d->cells, sizeof d->cells)))
    {
      lac_dist_free (d);
      return status;
    }
  if (d->cells)
    status = with_cells (d, src);
  else
    node_ranges (d);
  if (status)
    lac_dist_free (d);
  else
    *out = d;
  return status;
}

void
lac_dist_free (lac_dist *d)
{
  if (!d)
    return;
  lac_mesh_free (d->copy);
  lac_free (d->E);
  lac_free (d->nu);
  lac_free (d->fixed);
  lac_free (d->owner);
  lac_free (d->probe);
  lac_free (d->rstart);
  lac_free (d->row);
  lac_csc_free (d->C);
  lac_free (d->col);
  lac_free (d);
}

_Static_assert (sizeof (PetscInt) == sizeof (int), "rows are int");

void
lac_dist_rows (const lac_dist *d, int *r0, int *r1)
{
  *r0 = d->rstart[d->rank];
  *r1 = d->rstart[d->rank + 1];
}

const lac_csc *
lac_dist_c (const lac_dist *d)
{
  return d->C;
}

const lac_mesh *
lac_dist_mesh (const lac_dist *d)
{
  return d->cells ? d->m : NULL;
}

const lac_elastic *
lac_dist_material (const lac_dist *d)
{
  return d->cells ? &d->mat : NULL;
}

void
lac_dist_own_cells (const lac_dist *d, char *mine)
{
  for (size_t c = 0; d->cells && c < d->m->ncells; c++)
    mine[c] = d->owner[c] == d->rank;
}

const int *
lac_dist_row (const lac_dist *d)
{
  return d->row;
}

static PetscInt
row_of (const lac_dist *d, size_t j)
{
  return d->row ? d->row[j] : (PetscInt) j;
}

/* The process of row r. */
static int
process_of (const lac_dist *d, PetscInt r)
{
  int a = 0, b = d->size;
  while (b - a > 1)
    {
      int c = (a + b) / 2;
      if (d->rstart[c] <= r)
        a = c;
      else
        b = c;
    }
  return a;
}

/* ---- contact: C on every process ---------------------------------------- */

/* The others: an empty C of the root's sizes. */
static int
c_arrays (lac_dist *d, const size_t *z)
{
  int status = LAC_SUCCESS;
  if (d->rank != 0)
    {
      lac_csc_free (d->C);
      if (!(d->C = lac_csc_alloc (z[0], z[1], z[2])))
        status = LAC_ERRMSG (LAC_ENOMEM, "C, %zu x %zu", z[0], z[1]);
    }
  lac_free (d->col);
  if (!(d->col = lac_calloc (z[1] + 1, sizeof *d->col)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the columns of C, k = %zu", z[1]);
  return lac_petsc_agree (status);
}

int
lac_dist_set_c (lac_dist *d, const lac_csc *C, int pattern)
{
  size_t z[3] = { 0, 0, 0 };
  int status;
  lac_csc *M;
  if (d->rank == 0 && d->size == 1 && !pattern)
    return (memcpy (d->C->x, C->x, (size_t) C->p[C->ncol] * sizeof *C->x),
            LAC_SUCCESS);
  if (d->rank == 0)
    {
      lac_csc_free (d->C);
      z[0] = C->nrow, z[1] = C->ncol, z[2] = (size_t) C->p[C->ncol];
      status = (d->C = lac_csc_copy (C)) ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "a copy of C");
      if ((status = lac_petsc_agree (status)))
        return status;
      if (!pattern)
        return lac_petsc_bcast (C->x, z[2] * sizeof *C->x);
    }
  else if ((status = lac_petsc_agree (LAC_SUCCESS)))
    return status;
  if (!pattern)
    return lac_petsc_bcast (d->C->x, (size_t) d->C->p[d->C->ncol]
                            * sizeof *d->C->x);
  if ((status = lac_petsc_bcast (z, sizeof z)) || (status = c_arrays (d, z)))
    return status;
  M = d->C;
  if ((status = lac_petsc_bcast (M->p, (z[1] + 1) * sizeof *M->p))
      || (status = lac_petsc_bcast (M->i, z[2] * sizeof *M->i))
      || (status = lac_petsc_bcast (M->x, z[2] * sizeof *M->x)))
    return status;
  for (size_t i = 0; i < z[1]; i++)      /* the process of its first node */
    d->col[i] = M->p[i + 1] > M->p[i]
                && process_of (d, row_of (d, (size_t) M->i[M->p[i]]))
                   == d->rank;
  return LAC_SUCCESS;
}

/* ---- patterns and values ------------------------------------------------- */

/* The rows of cell c's dofs; their number. */
static int
cell_rows (const lac_dist *d, size_t c, PetscInt *rows)
{
  const lac_mesh *m = d->m;
  int nc = 0;
  for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
    for (int i = 0; i < d->bs; i++)
      rows[nc++] = row_of (d, (size_t) m->conn[p] * (size_t) d->bs
                           + (size_t) i);
  return nc;
}

/* Column i's rows and values (times a) into rows, v; their number. */
static int
column (const lac_dist *d, size_t i, double a, PetscInt *rows, double *v)
{
  const lac_csc *C = d->C;
  int m = 0;
  for (int p = C->p[i]; p < C->p[i + 1]; p++, m++)
    {
      rows[m] = row_of (d, (size_t) C->i[p]);
      if (v)
        v[m] = a * C->x[p];
    }
  return m;
}

/* The outer products of the own columns (pattern: dw NULL). */
static int
add_outer (lac_dist *d, Mat M, const double *dw)
{
  size_t k = d->C ? d->C->ncol : 0, cap = 1;
  PetscInt *rows;
  double *v, *vv;
  int status = LAC_SUCCESS;
  for (size_t i = 0; i < k; i++)
    cap = d->col[i] && (size_t) (d->C->p[i + 1] - d->C->p[i]) > cap
          ? (size_t) (d->C->p[i + 1] - d->C->p[i]) : cap;
  rows = lac_malloc (cap * sizeof *rows);
  v = lac_malloc (cap * sizeof *v);
  vv = lac_calloc (cap * cap, sizeof *vv);
  if (!rows || !v || !vv)
    status = LAC_ERRMSG (LAC_ENOMEM, "a column of C, %zu entries", cap);
  for (size_t i = 0; !status && i < k; i++)
    if (d->col[i] && (!dw || dw[i] != 0))
      {
        int m = column (d, i, 1.0, rows, v);
        for (int a = 0; dw && a < m; a++)
          for (int b = 0; b < m; b++)
            vv[a * m + b] = dw[i] * v[a] * v[b];
        PetscErrorCode e = MatSetValues (M, m, rows, m, rows, vv,
                                         ADD_VALUES);
        if (e)
          status = lac_petsc_fail ((int) e, __func__, "MatSetValues");
      }
  lac_free (rows);
  lac_free (v);
  lac_free (vv);
  return status;
}

/* The root's K (no cells): its columns are rows (symmetric), times s. */
static int
add_root_k (lac_dist *d, const lac_csc *K, Mat M, double s)
{
  double *v = NULL;
  int status = LAC_SUCCESS;
  size_t cap = 1;
  if (d->rank != 0)
    return LAC_SUCCESS;
  for (size_t j = 0; j < K->ncol; j++)
    cap = (size_t) (K->p[j + 1] - K->p[j]) > cap
          ? (size_t) (K->p[j + 1] - K->p[j]) : cap;
  if (!(v = lac_malloc (cap * sizeof *v)))
    LAC_ERROR (LAC_ENOMEM, "a row of K, %zu entries", cap);
  for (PetscInt j = 0; !status && j < (PetscInt) K->ncol; j++)
    {
      PetscInt m = K->p[j + 1] - K->p[j];
      for (PetscInt t = 0; t < m; t++)
        v[t] = s * K->x[K->p[j] + t];
      PetscErrorCode e = MatSetValues (M, 1, &j, m, K->i + K->p[j], v,
                                       ADD_VALUES);
      if (e)
        status = lac_petsc_fail ((int) e, __func__, "MatSetValues");
    }
  lac_free (v);
  return status;
}

#ifdef LAC_TEST_FAULTS
/* A failure on purpose on process LAC_TEST_FAIL_RANK (test builds). */
static int
injected (const lac_dist *d)
{
  const char *v = getenv ("LAC_TEST_FAIL_RANK");
  if (v && *v && atoi (v) == d->rank)
    LAC_ERROR (LAC_EDEP, "failure injected by LAC_TEST_FAIL_RANK in the "
               "assembly of the cells");
  return LAC_SUCCESS;
}

/* The factor of the first own cell's matrix in PETSc's K (test builds:
 * LAC_TEST_SCALE_CELL, a K that is not the cells' sum), else 1. */
static double
perturbed (const lac_dist *d, size_t c)
{
  const char *v = getenv ("LAC_TEST_SCALE_CELL");
  size_t first = 0;
  if (!v || !*v)
    return 1.0;
  while (first < d->m->ncells && d->owner[first] != d->rank)
    first++;
  return c == first ? atof (v) : 1.0;
}
#else
#define injected(d) LAC_SUCCESS
#define perturbed(d, c) 1.0
#endif

/* Cell c's element matrix (nc x nc) times s into ke, its dofs into dof,
 * the Dirichlet dofs' rows and columns zero but the diagonal (as in K:
 * lac_dirichlet_apply). */
static int
cell_matrix (const lac_dist *d, size_t c, lac_quad_cache *qc, double s,
             double *ke, size_t *dof, int *nc)
{
  const lac_mesh *m = d->m;
  size_t bs = (size_t) d->bs;
  int status = lac_assembly_cell_stiffness_q (m, &d->mat, c, qc, ke);
  *nc = (int) ((m->ptr[c + 1] - m->ptr[c]) * bs);
  for (int a = 0; a < *nc; a++)
    dof[a] = (size_t) m->conn[m->ptr[c] + (size_t) a / bs] * bs
             + (size_t) a % bs;
  for (int a = 0; !status && a < *nc; a++)
    for (int b = 0; b < *nc; b++)
      ke[a * *nc + b] = (d->fixed[dof[a]] || d->fixed[dof[b]])
                        && dof[a] != dof[b] ? 0.0 : s * ke[a * *nc + b];
  return status;
}

/* The probe x_j of dof j: a vector without structure (a hash of j, in
 * [-1, 1]), the same on every process. */
static double
probe_at (size_t j)
{
  unsigned long long h = (unsigned long long) j * 0x9E3779B97F4A7C15ULL;
  h ^= h >> 29;
  return (double) (h % 2000001ULL) / 1000000.0 - 1.0;
}

/* d->probe += ke x on the cell's dofs (nc of them). */
static void
add_probe (lac_dist *d, const double *ke, const size_t *dof, int nc)
{
  for (int a = 0; a < nc; a++)
    {
      double t = 0;
      for (int b = 0; b < nc; b++)
        t += ke[a * nc + b] * probe_at (dof[b]);
      d->probe[dof[a]] += t;
    }
}

/* The own cells' Ke times s (s = 0: the pattern, ke zeros), Dirichlet
 * rows and columns zero but the diagonal; with values, their product
 * with the probe into d->probe (lac_dist_check_stiffness). */
static int
add_cells (lac_dist *d, Mat M, double s, double *ke)
{
  PetscInt rows[NC_MAX];
  size_t dof[NC_MAX];
  lac_quad_cache qc;              /* the rules of each cell type, once */
  int status = injected (d), nc;
  memset (&qc, 0, sizeof qc);
  for (size_t c = 0; !status && c < d->m->ncells; c++)
    if (d->owner[c] == d->rank && d->mat.E[c] > 0.0)
      {
        nc = cell_rows (d, c, rows);
        if (s != 0 && (status = cell_matrix (d, c, &qc, s, ke, dof, &nc)))
          break;
        if (s != 0)
          add_probe (d, ke, dof, nc);
        for (int q = 0; s != 0 && q < nc * nc; q++)
          ke[q] *= perturbed (d, c);
        PetscErrorCode e = MatSetValues (M, nc, rows, nc, rows, ke,
                                         ADD_VALUES);
        if (e)
          status = lac_petsc_fail ((int) e, __func__, "MatSetValues");
      }
  lac_quad_cache_free (&qc);
  return status;
}

int
lac_dist_add_stiffness (lac_dist *d, const lac_csc *K, Mat Kw, double kappa)
{
  double *ke = lac_malloc (NC_MAX * NC_MAX * sizeof *ke);
  int status = ke ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "Ke");
  if (!status && d->cells && !d->probe
      && !(d->probe = lac_malloc (d->n * sizeof *d->probe + 1)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the probe of K (%zu)", d->n);
  if (!status && d->cells)
    memset (d->probe, 0, d->n * sizeof *d->probe);
  if (!status)
    status = d->cells ? add_cells (d, Kw, 1 / kappa, ke)
                      : add_root_k (d, K, Kw, 1 / kappa);
  lac_free (ke);
  return lac_petsc_agree (status);
}

/* x (own rows: the probe) and y (the cells' probe products added up in
 * PETSc's rows) in Kw's layout. */
static int
probe_vectors (lac_dist *d, Mat Kw, Vec *x, Vec *y)
{
  PetscInt r0, r1;
  TRY (MatCreateVecs (Kw, x, y));
  TRY (MatGetOwnershipRange (Kw, &r0, &r1));
  for (size_t j = 0; j < d->n; j++)
    {
      PetscInt r = row_of (d, j);
      if (r >= r0 && r < r1)
        TRY (VecSetValue (*x, r, probe_at (j), INSERT_VALUES));
      if (d->probe[j] != 0)
        TRY (VecSetValue (*y, r, d->probe[j], ADD_VALUES));
    }
  TRY (VecAssemblyBegin (*x));
  TRY (VecAssemblyEnd (*x));
  TRY (VecAssemblyBegin (*y));
  TRY (VecAssemblyEnd (*y));
  return LAC_SUCCESS;
}

int
lac_dist_check_stiffness (lac_dist *d, Mat Kw, double *err)
{
  Vec x = NULL, y = NULL;
  PetscReal nr, nk;
  int status;
  *err = 0;
  if (!d->cells || !d->probe)
    LAC_ERROR (LAC_EINVAL, "the check of K needs K added from the cells");
  if ((status = probe_vectors (d, Kw, &x, &y)))
    return status;
  TRY (VecScale (y, -1.0));
  TRY (MatMultAdd (Kw, x, y, y));                    /* K x - sum Ke x */
  TRY (VecNorm (y, NORM_INFINITY, &nr));
  TRY (MatNorm (Kw, NORM_INFINITY, &nk));
  TRY (VecDestroy (&x));
  TRY (VecDestroy (&y));
  *err = nk > 0 ? nr / nk : nr;                       /* |x| <= 1 */
  return LAC_SUCCESS;
}

int
lac_dist_add_contact (lac_dist *d, Mat Kw, const double *dw)
{
  return lac_petsc_agree (add_outer (d, Kw, dw));
}

int
lac_dist_set_b (lac_dist *d, Mat B, const char *on)
{
  size_t k = d->C ? d->C->ncol : 0, cap = 1;
  PetscInt *rows;
  double *v;
  int status = LAC_SUCCESS;
  for (size_t i = 0; i < k; i++)
    cap = (size_t) (d->C->p[i + 1] - d->C->p[i]) > cap
          ? (size_t) (d->C->p[i + 1] - d->C->p[i]) : cap;
  rows = lac_malloc (cap * sizeof *rows);
  v = lac_malloc (cap * sizeof *v);
  if (!rows || !v)
    status = LAC_ERRMSG (LAC_ENOMEM, "a column of C, %zu entries", cap);
  for (size_t i = 0; !status && i < k; i++)
    if (d->col[i])
      {
        PetscInt j = (PetscInt) i;
        int m = column (d, i, on && on[i] ? -1.0 : 0.0, rows, v);
        PetscErrorCode e = MatSetValues (B, m, rows, 1, &j, v,
                                         INSERT_VALUES);
        if (e)
          status = lac_petsc_fail ((int) e, __func__, "MatSetValues");
      }
  lac_free (rows);
  lac_free (v);
  return lac_petsc_agree (status);
}

int
lac_dist_pattern (lac_dist *d, const lac_csc *K, Mat Pk, Mat Pb)
{
  double *zero = lac_calloc (NC_MAX * NC_MAX, sizeof *zero);
  int status = zero ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "Ke");
  if (!status)
    status = d->cells ? add_cells (d, Pk, 0.0, zero)
                      : add_root_k (d, K, Pk, 0.0);
  lac_free (zero);
  if ((status = lac_petsc_agree (status))
      || (status = lac_dist_add_contact (d, Pk, NULL))
      || (Pb && (status = lac_dist_set_b (d, Pb, NULL))))
    return status;
  TRY (MatAssemblyBegin (Pk, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (Pk, MAT_FINAL_ASSEMBLY));
  if (Pb)
    {
      TRY (MatAssemblyBegin (Pb, MAT_FINAL_ASSEMBLY));
      TRY (MatAssemblyEnd (Pb, MAT_FINAL_ASSEMBLY));
    }
  return LAC_SUCCESS;
}

#else /* LAC_HAVE_PETSC */

typedef int lac_assembly_dist_unused;   /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
