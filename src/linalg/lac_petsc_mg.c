/* lac_petsc_mg.c -- the multigrid of K_W near the contact: smoothed
 *                   aggregation's finest level by lac, GAMG below
 *                   (see lac_petsc_mg.h)                      [chapter 13]
 */
#include "linalg/lac_petsc_mg.h"

#ifdef LAC_HAVE_PETSC

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <petscksp.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"

#define EIG_STEPS 10         /* CG iterations of the estimate of lambda   */
#define SMOOTH_STEPS 2       /* Chebyshev steps on the finest level       */
#define CHEB_LOW 0.1         /* its interval: [0.1, 1.1] lambda (GAMG's)  */
#define CHEB_HIGH 1.1

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

struct lac_petsc_mg
{
  PetscLogEvent event;       /* "lac contact MG" (-log_view): the finest
                                level's set-up                           */
  PC pc;                     /* borrowed: the PCMG it configures         */
  double threshold;          /* contact nodes' couplings below it out    */
  Mat P, A1;                 /* owned: the prolongator, P^T K P          */
  MatNullSpace nsp;          /* owned: A_1's near-null space             */
  lac_petsc_mg_counts counts;
};

/* ---- step 1: the graph -------------------------------------------------- */

void
lac_petsc_mg_graph_free (lac_mg_graph *g)
{
  lac_free (g->ptr);
  lac_free (g->adj);
  lac_free (g->g);
  memset (g, 0, sizeof *g);
}

/* *Ad: K's block of the own rows and columns (local numbers). */
static int
own_block (Mat K, Mat *Ad)
{
  PetscBool mpi, seq;
  Mat Ao;
  const PetscInt *garray;
  TRY (PetscObjectTypeCompare ((PetscObject) K, MATMPIAIJ, &mpi));
  TRY (PetscObjectTypeCompare ((PetscObject) K, MATSEQAIJ, &seq));
  if (mpi)
    TRY (MatMPIAIJGetSeqAIJ (K, Ad, &Ao, &garray));
  else if (seq)
    *Ad = K;
  else
    LAC_ERROR (LAC_EINVAL, "the contact multigrid needs K as an AIJ matrix");
  return LAC_SUCCESS;
}

/* sum[j] += |K_ij|_1 over the blocks of node i (sum: -1 where untouched;
 * the nodes touched into nb, *nn of them). */
static int
node_row (Mat Ad, PetscInt bs, int i, double *sum, int *nb, int *nn)
{
  *nn = 0;
  for (PetscInt c = 0; c < bs; c++)
    {
      PetscInt nc;
      const PetscInt *cols;
      const PetscScalar *v;
      TRY (MatGetRow (Ad, bs * i + c, &nc, &cols, &v));
      for (PetscInt q = 0; q < nc; q++)
        {
          int j = (int) (cols[q] / bs);
          if (sum[j] < 0)
            sum[j] = 0, nb[(*nn)++] = j;
          sum[j] += PetscAbsScalar (v[q]);
        }
      TRY (MatRestoreRow (Ad, bs * i + c, &nc, &cols, &v));
    }
  return LAC_SUCCESS;
}

/* contact[i] = 1 if a row of node i has an entry in B (own rows). */
static int
contact_nodes (Mat B, PetscInt bs, int n, char *contact)
{
  PetscInt b0, b1;
  memset (contact, 0, (size_t) n);
  if (!B)
    return LAC_SUCCESS;
  TRY (MatGetOwnershipRange (B, &b0, &b1));
  if (b1 - b0 != bs * n)
    LAC_ERROR (LAC_EBADLEN, "B has %d own rows, K %d", (int) (b1 - b0),
               (int) (bs * n));
  for (PetscInt r = b0; r < b1; r++)
    {
      PetscInt nc;
      TRY (MatGetRow (B, r, &nc, NULL, NULL));
      if (nc)
        contact[(r - b0) / bs] = 1;
      TRY (MatRestoreRow (B, r, &nc, NULL, NULL));
    }
  return LAC_SUCCESS;
}

/* Room for one more coupling in g (*cap entries, doubled when full). */
static int
room (lac_mg_graph *g, int top, int *cap)
{
  int *adj;
  double *w;
  if (top < *cap)
    return LAC_SUCCESS;
  if (!(adj = lac_realloc (g->adj, 2 * (size_t) *cap * sizeof *adj)))
    LAC_ERROR (LAC_ENOMEM, "the graph of the multigrid (%d couplings)",
               2 * *cap);
  g->adj = adj;
  if (!(w = lac_realloc (g->g, 2 * (size_t) *cap * sizeof *w)))
    LAC_ERROR (LAC_ENOMEM, "the graph of the multigrid (%d couplings)",
               2 * *cap);
  g->g = w;
  *cap *= 2;
  return LAC_SUCCESS;
}

/* Node i's row of the graph, after the rows before it (d: the diagonal
 * blocks' sums; sum, nb: scratch, sum -1 on return): g_ij, the weak
 * couplings of a contact node left out (counted once, j > i). */
static int
graph_row (Mat Ad, PetscInt bs, int i, const double *d, const char *contact,
           double t, double *sum, int *nb, lac_mg_graph *g, int *cap,
           long long *dropped)
{
  int nn, top = g->ptr[i], status = node_row (Ad, bs, i, sum, nb, &nn);
  for (int q = 0; !status && q < nn; q++)
    {
      int j = nb[q];
      double gij = d[i] > 0 && d[j] > 0 ? sum[j] / sqrt (d[i] * d[j]) : 0;
      if (j == i || !(gij > 0))
        continue;
      if ((contact[i] || contact[j]) && gij < t)
        {
          *dropped += j > i;
          continue;
        }
      if (!(status = room (g, top, cap)))
        g->adj[top] = j, g->g[top++] = gij;
    }
  for (int q = 0; q < nn; q++)
    sum[nb[q]] = -1;
  g->ptr[i + 1] = top;
  return status;
}

/* d[i] = |K_ii|_1, the sum of |a| over node i's diagonal block. */
static int
block_diagonal (Mat Ad, PetscInt bs, int n, double *d, double *sum, int *nb)
{
  int nn, status = LAC_SUCCESS;
  for (int i = 0; !status && i < n; i++)
    {
      status = node_row (Ad, bs, i, sum, nb, &nn);
      d[i] = sum[i] > 0 ? sum[i] : 0;
      for (int q = 0; q < nn; q++)
        sum[nb[q]] = -1;
    }
  return status;
}

int
lac_petsc_mg_graph (Mat K, Mat B, double threshold, lac_mg_graph *g,
                    long long *dropped)
{
  PetscInt bs, nl;
  Mat Ad;
  int n, cap, status;
  memset (g, 0, sizeof *g);
  *dropped = 0;
  if ((status = own_block (K, &Ad)))
    return status;
  TRY (MatGetBlockSize (K, &bs));
  TRY (MatGetLocalSize (K, &nl, NULL));
  n = (int) (nl / bs);
  cap = 32 * n + 32;
  double *d = lac_malloc ((size_t) n * sizeof *d + 1);
  double *sum = lac_malloc ((size_t) n * sizeof *sum + 1);
  int *nb = lac_malloc ((size_t) n * sizeof *nb + 1);
  char *contact = lac_malloc ((size_t) n + 1);
  g->n = n;
  g->ptr = lac_calloc ((size_t) n + 1, sizeof *g->ptr);
  g->adj = lac_malloc ((size_t) cap * sizeof *g->adj);
  g->g = lac_malloc ((size_t) cap * sizeof *g->g);
  status = !d || !sum || !nb || !contact || !g->ptr || !g->adj || !g->g
           ? LAC_ERRMSG (LAC_ENOMEM, "the graph of %d nodes", n)
           : contact_nodes (B, bs, n, contact);
  for (int i = 0; i < n && sum; i++)
    sum[i] = -1;
  if (!status)
    status = block_diagonal (Ad, bs, n, d, sum, nb);
  for (int i = 0; !status && i < n; i++)
    status = graph_row (Ad, bs, i, d, contact, threshold, sum, nb, g, &cap,
                        dropped);
  lac_free (d);
  lac_free (sum);
  lac_free (nb);
  lac_free (contact);
  if (status)
    lac_petsc_mg_graph_free (g);
  return status;
}

/* ---- steps 2 and 3: the aggregates -------------------------------------- */

/* first[a] .. first[a + 1] - 1: the nodes of aggregate a in node[]. */
static int
members (const int *agg, int n, int nagg, int *first, int *node)
{
  int maxsize = 0;
  memset (first, 0, ((size_t) nagg + 2) * sizeof *first);
  for (int i = 0; i < n; i++)
    if (agg[i] >= 0)
      first[agg[i] + 2]++;
  for (int a = 0; a < nagg; a++)
    {
      maxsize = first[a + 2] > maxsize ? first[a + 2] : maxsize;
      first[a + 2] += first[a + 1];
    }
  for (int i = 0; i < n; i++)
    if (agg[i] >= 0)
      node[first[agg[i] + 1]++] = i;
  return maxsize;
}

/* perm: 0 .. n-1 shuffled (Fisher-Yates, a fixed linear congruential
 * sequence: the same order on every run). */
static void
shuffle (int n, int *perm)
{
  unsigned long long x = 88172645463325252ULL;
  for (int i = 0; i < n; i++)
    perm[i] = i;
  for (int i = n - 1; i > 0; i--)
    {
      x = x * 6364136223846793005ULL + 1442695040888963407ULL;
      int j = (int) ((x >> 33) % (unsigned long long) (i + 1)), t = perm[i];
      perm[i] = perm[j], perm[j] = t;
    }
}

/* order: the vertices of g with couplings, fewest couplings first, in a
 * shuffled order among equals (the order of the numbering would pack
 * the aggregates of a regular mesh into a tight lattice, smaller ones);
 * *m: their number.  -1: no memory. */
static int
by_degree (const lac_mg_graph *g, int *order, int *m)
{
  int maxdeg = 0;
  for (int i = 0; i < g->n; i++)
    maxdeg = g->ptr[i + 1] - g->ptr[i] > maxdeg
             ? g->ptr[i + 1] - g->ptr[i] : maxdeg;
  int *start = lac_calloc ((size_t) maxdeg + 2, sizeof *start);
  int *perm = lac_malloc (((size_t) g->n + 1) * sizeof *perm);
  *m = 0;
  if (!start || !perm)
    {
      lac_free (start);
      lac_free (perm);
      return -1;
    }
  shuffle (g->n, perm);
  for (int i = 0; i < g->n; i++)
    start[g->ptr[i + 1] - g->ptr[i] + 1]++;
  for (int k = 1; k <= maxdeg + 1; k++)
    start[k] += start[k - 1];
  int zero = start[1];                  /* the vertices without couplings */
  for (int p = 0; p < g->n; p++)
    {
      int i = perm[p], deg = g->ptr[i + 1] - g->ptr[i];
      if (deg > 0)
        order[start[deg]++ - zero] = i, (*m)++;
    }
  lac_free (start);
  lac_free (perm);
  return 0;
}

/* One greedy pass (a maximal independent set, one coupling wide): each
 * vertex of g in `order` (m of them) that is in no group yet starts one
 * and takes its neighbours that are in none.  grp (g->n): the group of
 * each vertex, -1 for those not in order.  The number of groups. */
static int
greedy_pass (const lac_mg_graph *g, const int *order, int m, int *grp)
{
  int count = 0;
  for (int i = 0; i < g->n; i++)
    grp[i] = -1;
  for (int o = 0; o < m; o++)
    {
      int i = order[o];
      if (grp[i] >= 0)
        continue;
      grp[i] = count;
      for (int q = g->ptr[i]; q < g->ptr[i + 1]; q++)
        if (grp[g->adj[q]] < 0)
          grp[g->adj[q]] = count;
      count++;
    }
  return count;
}

/* *c: the graph of the ng groups grp of g's vertices (two groups are
 * coupled when two of their vertices are; c->g all 1). */
static int
group_graph (const lac_mg_graph *g, const int *grp, int ng, lac_mg_graph *c)
{
  int *first = lac_malloc (((size_t) ng + 2) * sizeof *first);
  int *vert = lac_malloc (((size_t) g->n + 1) * sizeof *vert);
  int *mark = lac_malloc (((size_t) ng + 1) * sizeof *mark);
  int cap = 16 * ng + 16, status = LAC_SUCCESS;
  memset (c, 0, sizeof *c);
  c->n = ng;
  c->ptr = lac_calloc ((size_t) ng + 1, sizeof *c->ptr);
  c->adj = lac_malloc ((size_t) cap * sizeof *c->adj);
  c->g = lac_malloc ((size_t) cap * sizeof *c->g);
  if (!first || !vert || !mark || !c->ptr || !c->adj || !c->g)
    status = LAC_ERRMSG (LAC_ENOMEM, "the graph of %d groups", ng);
  else
    members (grp, g->n, ng, first, vert);
  for (int a = 0; !status && a < ng; a++)
    mark[a] = -1;
  for (int a = 0, top = 0; !status && a < ng; a++)
    {
      for (int p = first[a]; !status && p < first[a + 1]; p++)
        for (int q = g->ptr[vert[p]]; !status && q < g->ptr[vert[p] + 1]; q++)
          {
            int b = grp[g->adj[q]];
            if (b < 0 || b == a || mark[b] == a
                || (status = room (c, top, &cap)))
              continue;
            mark[b] = a;
            c->adj[top] = b, c->g[top++] = 1;
          }
      c->ptr[a + 1] = top;
    }
  lac_free (first);
  lac_free (vert);
  lac_free (mark);
  if (status)
    lac_petsc_mg_graph_free (c);
  return status;
}

/* Step 2, as PETSc's GAMG (3.18) makes the aggressive aggregates of its
 * finest level, MIS-2 by two passes of MIS-1: a greedy pass over the
 * nodes, fewest couplings first, groups them; a second pass groups
 * the groups on their own graph, in the order of the numbering (of
 * their first nodes).  agg (n): the aggregate of each node, -1 for one
 * without couplings.  The number of aggregates, -1: no memory. */
static int
two_passes (const lac_mg_graph *g, int *agg)
{
  lac_mg_graph c = { 0, NULL, NULL, NULL };
  size_t n1 = (size_t) g->n + 1;
  int *order = lac_malloc (n1 * sizeof *order);
  int *grp2 = lac_malloc (n1 * sizeof *grp2);
  int m, ng = -1, count = -1;
  if (order && grp2 && !by_degree (g, order, &m))
    ng = greedy_pass (g, order, m, agg);
  if (ng >= 0 && !group_graph (g, agg, ng, &c))
    {
      for (int a = 0; a < ng; a++)
        grp2[a] = 0;                          /* seen */
      m = 0;
      for (int i = 0; i < g->n; i++)          /* groups by first node */
        if (agg[i] >= 0 && !grp2[agg[i]])
          grp2[agg[i]] = 1, order[m++] = agg[i];
      count = greedy_pass (&c, order, m, grp2);
      for (int i = 0; i < g->n; i++)
        agg[i] = agg[i] >= 0 ? grp2[agg[i]] : -1;
    }
  lac_petsc_mg_graph_free (&c);
  lac_free (order);
  lac_free (grp2);
  return count;
}

/* Node k into aggregate a if it is alone in its own; 1 if it moved. */
static int
take_single (int *agg, int *size, int a, int k)
{
  int t = agg[k];
  if (t < 0 || t == a || size[t] != 1)
    return 0;
  agg[k] = a, size[t] = 0, size[a]++;
  return 1;
}

/* Aggregate a, the single node s, takes the single nodes within two
 * couplings of s, up to LAC_PETSC_MG_GROUP nodes. */
static void
gather (const lac_mg_graph *g, int *agg, int *size, int a, int s)
{
  for (int q = g->ptr[s]; q < g->ptr[s + 1]; q++)
    {
      int j = g->adj[q];
      if (size[a] < LAC_PETSC_MG_GROUP)
        take_single (agg, size, a, j);
      for (int p = g->ptr[j]; p < g->ptr[j + 1]; p++)
        if (size[a] < LAC_PETSC_MG_GROUP && g->adj[p] != s)
          take_single (agg, size, a, g->adj[p]);
    }
}

/* The single node s (aggregate a) joins the aggregate of more than one
 * node of its strongest neighbour; 1 if there was one. */
static int
join (const lac_mg_graph *g, int *agg, int *size, int a, int s)
{
  int best = -1;
  double strongest = 0;
  for (int q = g->ptr[s]; q < g->ptr[s + 1]; q++)
    {
      int t = agg[g->adj[q]];
      if (t >= 0 && t != a && size[t] > 1 && g->g[q] > strongest)
        best = t, strongest = g->g[q];
    }
  if (best < 0)
    return 0;
  agg[s] = best, size[a] = 0, size[best]++;
  return 1;
}

/* Step 3 on the nagg aggregates agg (size: their nodes; root: the node
 * of those of one): every single node gathers (gather), then those
 * still alone join a neighbour's aggregate (join). */
static void
no_single (const lac_mg_graph *g, int nagg, const int *root, int *agg,
           int *size, int *grouped, int *joined)
{
  *grouped = *joined = 0;
  for (int a = 0; a < nagg; a++)
    if (size[a] == 1)
      {
        gather (g, agg, size, a, root[a]);
        *grouped += size[a] > 1 ? size[a] : 0;
      }
  for (int a = 0; a < nagg; a++)
    if (size[a] == 1)
      *joined += join (g, agg, size, a, root[a]);
}

/* The aggregates of at least min nodes numbered 0, 1, ... in their
 * order; the nodes of the others in none (-1).  Their number. */
static int
renumber (int n, int nagg, int min, int *agg, int *size)
{
  int count = 0;
  for (int a = 0; a < nagg; a++)
    size[a] = size[a] >= min && size[a] > 0 ? count++ : -1;
  for (int i = 0; i < n; i++)
    agg[i] = agg[i] >= 0 ? size[agg[i]] : -1;
  return count;
}

int
lac_petsc_mg_singles (const lac_mg_graph *g, int min, int *agg, int *nagg,
                      int *grouped, int *joined)
{
  size_t n1 = (size_t) (g->n > *nagg ? g->n : *nagg) + 1;
  int *root = lac_malloc (n1 * sizeof *root);
  int *size = lac_calloc (n1, sizeof *size);
  *grouped = *joined = 0;
  if (!root || !size)
    {
      lac_free (root);
      lac_free (size);
      LAC_ERROR (LAC_ENOMEM, "the aggregates of %d nodes", g->n);
    }
  for (int i = 0; i < g->n; i++)
    if (agg[i] >= 0)
      size[agg[i]]++, root[agg[i]] = i;         /* the node of a single */
  no_single (g, *nagg, root, agg, size, grouped, joined);
  *nagg = renumber (g->n, *nagg, min, agg, size);
  lac_free (root);
  lac_free (size);
  return LAC_SUCCESS;
}

int
lac_petsc_mg_aggregate (const lac_mg_graph *g, int min, int *agg, int *nagg,
                        int *grouped, int *joined)
{
  *nagg = *grouped = *joined = 0;
  if ((*nagg = two_passes (g, agg)) < 0)
    {
      *nagg = 0;
      LAC_ERROR (LAC_ENOMEM, "the aggregates of %d nodes", g->n);
    }
  return lac_petsc_mg_singles (g, min, agg, nagg, grouped, joined);
}

/* ---- step 4: the tentative prolongator ---------------------------------- */

#define MAX_NULL 16          /* near-null vectors at most                 */

/* K's near-null vectors: m of them, the constant first if has_const;
 * a: the local arrays of the others (without a near-null space: the
 * constants of the bs components). */
typedef struct
{
  int m, has_const, given;
  PetscInt bs;
  const Vec *vec;            /* borrowed from K's near-null space        */
  const PetscScalar *a[MAX_NULL];
} near_null;

static int
near_null_open (Mat K, near_null *z)
{
  MatNullSpace nsp;
  PetscBool has_const = PETSC_FALSE;
  PetscInt nv = 0;
  memset (z, 0, sizeof *z);
  TRY (MatGetBlockSize (K, &z->bs));
  TRY (MatGetNearNullSpace (K, &nsp));
  if (nsp)
    TRY (MatNullSpaceGetVecs (nsp, &has_const, &nv, &z->vec));
  z->given = nsp != NULL;
  z->has_const = has_const == PETSC_TRUE;
  z->m = z->given ? (int) nv + z->has_const : (int) z->bs;
  if (z->m < 1 || z->m > MAX_NULL)
    LAC_ERROR (LAC_EINVAL, "%d near-null vectors (1 to %d)", z->m, MAX_NULL);
  for (PetscInt k = 0; k < nv; k++)
    TRY (VecGetArrayRead (z->vec[k], &z->a[k]));
  return LAC_SUCCESS;
}

static int
near_null_close (near_null *z)
{
  for (int k = 0; z->given && k < z->m - z->has_const; k++)
    TRY (VecRestoreArrayRead (z->vec[k], &z->a[k]));
  return LAC_SUCCESS;
}

/* Vector k at the local dof r. */
static double
near_null_at (const near_null *z, int k, PetscInt r)
{
  if (!z->given)
    return r % z->bs == k ? 1.0 : 0.0;
  if (z->has_const && k == 0)
    return 1.0;
  return PetscRealPart (z->a[k - z->has_const][r]);
}

static double
norm2 (const double *v, int n)
{
  double s = 0;
  for (int i = 0; i < n; i++)
    s += v[i] * v[i];
  return sqrt (s);
}

/* v -= Q_j (Q_j . v) for the k columns Q_j before it (twice: modified
 * Gram-Schmidt, repeated), r[j] += the coefficients (r NULL: not kept). */
static void
orthogonalize (double *v, const double *Q, int nr, int k, double *r)
{
  for (int pass = 0; pass < 2; pass++)
    for (int j = 0; j < k; j++)
      {
        double d = 0;
        for (int i = 0; i < nr; i++)
          d += Q[j * nr + i] * v[i];
        for (int i = 0; i < nr; i++)
          v[i] -= d * Q[j * nr + i];
        if (r)
          r[j] += d;
      }
}

/* B (nr x m, by columns) = Q R: Q in B, orthonormal columns; R (m x m,
 * by columns) upper triangular.  A column in the span of those before
 * it gets a unit vector e_p orthogonalized instead, and R_kk = 0 (an
 * aggregate of two nodes does not see the rotation about their line). */
static void
qr (double *B, int nr, int m, double *R)
{
  memset (R, 0, (size_t) m * (size_t) m * sizeof *R);
  for (int k = 0; k < m; k++)
    {
      double *v = B + (size_t) k * (size_t) nr, n0 = norm2 (v, nr), nk;
      orthogonalize (v, B, nr, k, R + (size_t) k * (size_t) m);
      nk = norm2 (v, nr);
      if (nk > 1e-10 * n0 && nk > 0)
        R[(size_t) k * (size_t) m + (size_t) k] = nk;
      else
        for (int p = 0; p < nr; p++)
          {
            memset (v, 0, (size_t) nr * sizeof *v);
            v[p] = 1;
            orthogonalize (v, B, nr, k, NULL);
            if ((nk = norm2 (v, nr)) > 0.5)
              break;
          }
      for (int i = 0; i < nr; i++)
        v[i] /= nk;
    }
}

/* P: K's rows, m columns an aggregate (nagg here, Nagg in all), m
 * entries in each row of a node in one. */
static int
create_tentative (Mat K, int m, const int *agg, int nagg, PetscInt Nagg,
                  Mat *P)
{
  PetscInt bs, nl, N, *dnz;
  TRY (MatGetBlockSize (K, &bs));
  TRY (MatGetLocalSize (K, &nl, NULL));
  TRY (MatGetSize (K, &N, NULL));
  TRY (PetscMalloc1 (nl + 1, &dnz));
  for (PetscInt r = 0; r < nl; r++)
    dnz[r] = agg[r / bs] >= 0 ? m : 0;
  TRY (MatCreate (PetscObjectComm ((PetscObject) K), P));
  TRY (MatSetSizes (*P, nl, m * nagg, N, m * Nagg));
  TRY (MatSetBlockSizes (*P, bs, m));
  TRY (MatSetType (*P, MATAIJ));
  TRY (MatSeqAIJSetPreallocation (*P, 0, dnz));
  TRY (MatMPIAIJSetPreallocation (*P, 0, dnz, 0, NULL));
  TRY (MatSetOption (*P, MAT_ROW_ORIENTED, PETSC_FALSE));
  TRY (MatSetOption (*P, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));
  TRY (PetscFree (dnz));
  return LAC_SUCCESS;
}

/* Aggregate a's block of P: the near-null vectors on its nodes (na of
 * them at node[]), Q of their QR into rows r0 + dofs, columns m (a0 +
 * a) ..; R (m x m, by columns) into R. B: room for bs na m. */
static int
tentative_block (Mat P, const near_null *z, PetscInt r0, const int *node,
                 int na, PetscInt col0, double *B, PetscInt *rows,
                 PetscInt *cols, double *R)
{
  int bs = (int) z->bs, nr = bs * na, m = z->m;
  for (int p = 0; p < na; p++)
    for (int c = 0; c < bs; c++)
      {
        PetscInt r = (PetscInt) bs * node[p] + c;
        rows[p * bs + c] = r0 + r;
        for (int k = 0; k < m; k++)
          B[(size_t) k * (size_t) nr + (size_t) (p * bs + c)]
            = near_null_at (z, k, r);
      }
  for (int k = 0; k < m; k++)
    cols[k] = col0 + k;
  qr (B, nr, m, R);
  TRY (MatSetValues (P, nr, rows, m, cols, B, INSERT_VALUES));
  return LAC_SUCCESS;
}

/* The coarse near-null vectors: vector k is R_a's column k on the m
 * coarse dofs of each aggregate a (R: nagg blocks m x m, by columns),
 * then orthonormalized (their span is what GAMG uses). */
static int
coarse_near_null (Mat P, int m, int nagg, const double *R, MatNullSpace *nsp)
{
  Vec v[MAX_NULL];
  PetscScalar *a;
  TRY (MatCreateVecs (P, &v[0], NULL));
  for (int k = 1; k < m; k++)
    TRY (VecDuplicate (v[0], &v[k]));
  for (int k = 0; k < m; k++)
    {
      TRY (VecGetArray (v[k], &a));
      for (int g = 0; g < nagg; g++)
        for (int j = 0; j < m; j++)
          a[g * m + j] = R[((size_t) g * (size_t) m + (size_t) k)
                           * (size_t) m + (size_t) j];
      TRY (VecRestoreArray (v[k], &a));
      for (int j = 0; j < k; j++)
        {
          PetscScalar d;
          TRY (VecDot (v[k], v[j], &d));
          TRY (VecAXPY (v[k], -d, v[j]));
        }
      TRY (VecNormalize (v[k], NULL));
    }
  TRY (MatNullSpaceCreate (PetscObjectComm ((PetscObject) P), PETSC_FALSE,
                           m, v, nsp));
  for (int k = 0; k < m; k++)
    TRY (VecDestroy (&v[k]));
  return LAC_SUCCESS;
}

/* The blocks of every aggregate into P (assembled), their R into R. */
static int
fill_tentative (Mat K, Mat P, const near_null *z, const int *agg, int nagg,
                PetscInt a0, double *R)
{
  PetscInt r0, nl;
  int status = LAC_SUCCESS, bs = (int) z->bs, m = z->m;
  TRY (MatGetOwnershipRange (K, &r0, NULL));
  TRY (MatGetLocalSize (K, &nl, NULL));
  int n = (int) nl / bs;
  int *first = lac_malloc (((size_t) nagg + 2) * sizeof *first);
  int *node = lac_malloc (((size_t) n + 1) * sizeof *node);
  int maxsize = first && node ? members (agg, n, nagg, first, node) : 0;
  size_t nr = (size_t) bs * (size_t) maxsize + 1;
  double *B = lac_malloc (nr * (size_t) m * sizeof *B);
  PetscInt *rows = lac_malloc (nr * sizeof *rows);
  PetscInt cols[MAX_NULL];
  if (!first || !node || !B || !rows)
    status = LAC_ERRMSG (LAC_ENOMEM, "the tentative prolongator");
  for (int a = 0; !status && a < nagg; a++)
    status = tentative_block (P, z, r0, node + first[a], first[a + 1]
                              - first[a], (PetscInt) m * (a0 + a), B, rows,
                              cols, R + (size_t) a * (size_t) m * (size_t) m);
  lac_free (first);
  lac_free (node);
  lac_free (B);
  lac_free (rows);
  if ((status = lac_petsc_agree (status)))       /* before the assembly */
    return status;
  TRY (MatAssemblyBegin (P, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (P, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* This process's first aggregate among all, and their number. */
static int
aggregate_offset (Mat K, int nagg, PetscInt *a0, PetscInt *Nagg)
{
  long long mine = nagg, before = 0, all = 0;
  MPI_Comm comm = PetscObjectComm ((PetscObject) K);
  if (MPI_Exscan (&mine, &before, 1, MPI_LONG_LONG, MPI_SUM, comm)
      || MPI_Allreduce (&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, comm))
    LAC_ERROR (LAC_EDEP, "MPI: the numbers of aggregates");
  int rank;
  MPI_Comm_rank (comm, &rank);
  *a0 = rank ? (PetscInt) before : 0;     /* MPI_Exscan: undefined on 0 */
  *Nagg = (PetscInt) all;
  if (all == 0)
    LAC_ERROR (LAC_EINVAL, "the contact multigrid found no aggregate (no "
               "coupling between the nodes of K)");
  return LAC_SUCCESS;
}

int
lac_petsc_mg_tentative (Mat K, const int *agg, int nagg, Mat *P,
                        MatNullSpace *nsp)
{
  near_null z;
  PetscInt a0 = 0, Nagg = 0;
  double *R = NULL;
  int status;
  *P = NULL;
  *nsp = NULL;
  if ((status = aggregate_offset (K, nagg, &a0, &Nagg))
      || (status = near_null_open (K, &z)))
    return status;
  if (!(R = lac_malloc (((size_t) nagg + 1) * (size_t) z.m * (size_t) z.m
                        * sizeof *R)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the coarse near-null vectors");
  if (!status)
    status = create_tentative (K, z.m, agg, nagg, Nagg, P);
  if (!status)
    status = fill_tentative (K, *P, &z, agg, nagg, a0, R);
  int closed = near_null_close (&z);
  if (!status && !(status = closed))
    status = coarse_near_null (*P, z.m, nagg, R, nsp);
  lac_free (R);
  return status;
}

/* ---- step 5: one Jacobi step -------------------------------------------- */

/* *lambda: the largest eigenvalue of D^-1 K, from EIG_STEPS iterations of
 * CG with Jacobi on K x = b, b random (PETSc's generator, its default
 * seed: the same on every run of the same layout). */
static int
largest_eigenvalue (Mat K, double *lambda)
{
  KSP ksp;
  PC pc;
  Vec b, x;
  PetscRandom rnd;
  PetscReal emax, emin;
  MPI_Comm comm = PetscObjectComm ((PetscObject) K);
  TRY (MatCreateVecs (K, &x, &b));
  TRY (PetscRandomCreate (comm, &rnd));
  TRY (VecSetRandom (b, rnd));
  TRY (PetscRandomDestroy (&rnd));
  TRY (KSPCreate (comm, &ksp));
  TRY (KSPSetType (ksp, KSPCG));
  TRY (KSPSetOperators (ksp, K, K));
  TRY (KSPGetPC (ksp, &pc));
  TRY (PCSetType (pc, PCJACOBI));
  TRY (KSPSetTolerances (ksp, 1e-30, 1e-50, 1e10, EIG_STEPS));
  TRY (KSPSetConvergenceTest (ksp, KSPConvergedSkip, NULL, NULL));
  TRY (KSPSetNormType (ksp, KSP_NORM_NONE));
  TRY (KSPSetComputeSingularValues (ksp, PETSC_TRUE));
  TRY (KSPSolve (ksp, b, x));
  TRY (KSPComputeExtremeSingularValues (ksp, &emax, &emin));
  TRY (KSPDestroy (&ksp));
  TRY (VecDestroy (&b));
  TRY (VecDestroy (&x));
  if (!(emax > 0))
    LAC_ERROR (LAC_ESING, "the contact multigrid: the largest eigenvalue of "
               "D^-1 K is %g, not positive", (double) emax);
  *lambda = emax;
  return LAC_SUCCESS;
}

/* *P = (I - w D^-1 K) *P, w = 4 / (3 lambda): the tentative prolongator
 * made smooth where K is stiff. */
static int
smooth (Mat K, double lambda, Mat *P)
{
  Mat KP;
  Vec dinv;
  TRY (MatMatMult (K, *P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &KP));
  TRY (MatProductClear (KP));
  TRY (MatCreateVecs (K, NULL, &dinv));
  TRY (MatGetDiagonal (K, dinv));
  TRY (VecReciprocal (dinv));
  TRY (MatDiagonalScale (KP, dinv, NULL));                 /* D^-1 K P  */
  TRY (MatAYPX (KP, -4.0 / (3.0 * lambda), *P, SUBSET_NONZERO_PATTERN));
  TRY (VecDestroy (&dinv));
  TRY (MatDestroy (P));
  *P = KP;
  return LAC_SUCCESS;
}

/* ---- the two levels ----------------------------------------------------- */

/* Steps 1 to 3 on this process: agg (n + 1), *nagg, and the counts. */
static int
aggregates (lac_petsc_mg *mg, Mat K, Mat B, int **agg, int *nagg)
{
  lac_mg_graph g;
  near_null z;
  int grouped, joined, min, status;
  long long dropped;
  *agg = NULL;
  if ((status = near_null_open (K, &z)) || (status = near_null_close (&z))
      || (status = lac_petsc_mg_graph (K, B, mg->threshold, &g, &dropped)))
    return status;
  min = z.bs < z.m ? 2 : 1;             /* an aggregate holds m dofs     */
  if (!(*agg = lac_malloc (((size_t) g.n + 1) * sizeof **agg)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the aggregates of %d nodes", g.n);
  else
    status = lac_petsc_mg_aggregate (&g, min, *agg, nagg, &grouped, &joined);
  mg->counts.nodes = g.n;
  mg->counts.dropped = dropped;
  mg->counts.grouped = grouped;
  mg->counts.joined = joined;
  mg->counts.left = 0;
  for (int i = 0; !status && i < g.n; i++)
    mg->counts.left += (*agg)[i] < 0;
  lac_petsc_mg_graph_free (&g);
  return status;
}

/* The counts summed over the processes (nagg: this process's aggregates),
 * and, in PETSc's -info, nnz(A_1) / nnz(K). */
static int
sum_counts (lac_petsc_mg *mg, Mat K, int nagg)
{
  lac_petsc_mg_counts *c = &mg->counts;
  long long mine[6] = { c->nodes, nagg, c->dropped, c->grouped, c->joined,
                        c->left }, all[6];
  MatInfo ik, i1;
  if (MPI_Allreduce (mine, all, 6, MPI_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI: the counts of the contact multigrid");
  c->nodes = all[0], c->aggregates = all[1], c->dropped = all[2];
  c->grouped = all[3], c->joined = all[4], c->left = all[5];
  TRY (MatGetInfo (K, MAT_GLOBAL_SUM, &ik));
  TRY (MatGetInfo (mg->A1, MAT_GLOBAL_SUM, &i1));
  TRY (PetscInfo (mg->pc, "lac's finest level: %lld nodes, %lld aggregates, "
                  "%lld couplings dropped, %lld single nodes grouped, %lld "
                  "joined, %lld in none, lambda %g, nnz(A_1) / nnz(K) %g\n",
                  all[0], all[1], all[2], all[3], all[4], all[5], c->lambda,
                  ik.nz_used > 0 ? i1.nz_used / ik.nz_used : 0.0));
  return LAC_SUCCESS;
}

/* The finest level from K and B: P and A_1 = P^T K P with its near-null
 * space, the interpolation and the smoother's interval. */
static int
finest_level (lac_petsc_mg *mg, Mat K, Mat B)
{
  int *agg = NULL, nagg = 0;
  int status = lac_petsc_agree (aggregates (mg, K, B, &agg, &nagg));
  KSP ks;
  if (!status)
    status = lac_petsc_mg_tentative (K, agg, nagg, &mg->P, &mg->nsp);
  lac_free (agg);
  if (status || (status = largest_eigenvalue (K, &mg->counts.lambda))
      || (status = smooth (K, mg->counts.lambda, &mg->P)))
    return status;
  TRY (MatPtAP (K, mg->P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &mg->A1));
  if ((status = sum_counts (mg, K, nagg)))
    return status;
  TRY (MatSetNearNullSpace (mg->A1, mg->nsp));
  TRY (PCMGSetInterpolation (mg->pc, 1, mg->P));
  TRY (PCMGGetSmoother (mg->pc, 1, &ks));
  TRY (KSPChebyshevSetEigenvalues (ks, CHEB_HIGH * mg->counts.lambda,
                                   CHEB_LOW * mg->counts.lambda));
  return LAC_SUCCESS;
}

int
lac_petsc_mg_update (lac_petsc_mg *mg, Mat K, Mat B)
{
  KSP ks, kc;
  int status = LAC_SUCCESS;
  TRY (PetscLogEventBegin (mg->event, 0, 0, 0, 0));
  if (!mg->P)
    status = finest_level (mg, K, B);
  else          /* new values: the aggregates and P kept, A_1 made again */
    TRY (MatPtAP (K, mg->P, MAT_REUSE_MATRIX, PETSC_DEFAULT, &mg->A1));
  TRY (PetscLogEventEnd (mg->event, 0, 0, 0, 0));
  if (status)
    return status;
  TRY (PCMGGetSmoother (mg->pc, 1, &ks));
  TRY (KSPSetOperators (ks, K, K));
  TRY (PCMGGetCoarseSolve (mg->pc, &kc));
  TRY (KSPSetOperators (kc, mg->A1, mg->A1));
  TRY (PCSetOperators (mg->pc, K, K));
  return LAC_SUCCESS;
}

void
lac_petsc_mg_get_counts (const lac_petsc_mg *mg, lac_petsc_mg_counts *c)
{
  *c = mg->counts;
}

/* The finest level's smoother: SMOOTH_STEPS of Chebyshev with Jacobi,
 * its interval from lambda (no estimate of its own). */
static int
fine_smoother (PC pc)
{
  KSP ks;
  PC p;
  TRY (PCMGGetSmoother (pc, 1, &ks));
  TRY (KSPSetType (ks, KSPCHEBYSHEV));
  TRY (KSPChebyshevEstEigSet (ks, 0, 0, 0, 0));
  TRY (KSPSetTolerances (ks, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT,
                         SMOOTH_STEPS));
  TRY (KSPSetConvergenceTest (ks, KSPConvergedSkip, NULL, NULL));
  TRY (KSPSetNormType (ks, KSP_NORM_NONE));
  TRY (KSPGetPC (ks, &p));
  TRY (PCSetType (p, PCJACOBI));
  return LAC_SUCCESS;
}

/* The coarse solve: one V-cycle of GAMG on A_1, every nonzero coupling of
 * its graph kept (threshold 0 on every level), no aggressive
 * aggregation (the finest level had it), its interpolation kept when
 * only the values change.  The aggressive levels by the option (PETSc
 * reads it again at its set-up, over PCGAMGSetAggressiveLevels); its
 * name changed with PETSc 3.18. */
static int
coarse_solver (PC pc)
{
  KSP kc;
  PC p;
  PetscReal zero = 0;
  const char *pre;
  char name[200];
  TRY (PCMGGetCoarseSolve (pc, &kc));
  TRY (KSPSetType (kc, KSPPREONLY));
  TRY (KSPGetPC (kc, &p));
  TRY (PCSetType (p, PCGAMG));
  TRY (PCGAMGSetThreshold (p, &zero, 1));
  TRY (PCGAMGSetReuseInterpolation (p, PETSC_TRUE));
  TRY (PCGetOptionsPrefix (p, &pre));
  snprintf (name, sizeof name, "-%s%s", pre ? pre : "",
            PETSC_VERSION_LT (3, 18, 0) ? "pc_gamg_square_graph"
            : "pc_gamg_aggressive_coarsening");
  return lac_petsc_option_default (name, "0");
}

/* pc as the two levels, then its options. */
static int
configure (PC pc)
{
  PetscInt levels;
  int status;
  TRY (PCSetType (pc, PCMG));
  TRY (PCMGSetLevels (pc, 2, NULL));
  TRY (PCMGSetGalerkin (pc, PC_MG_GALERKIN_NONE));
  if ((status = fine_smoother (pc)) || (status = coarse_solver (pc)))
    return status;
  TRY (PCSetFromOptions (pc));
  TRY (PCMGGetLevels (pc, &levels));
  if (levels != 2)
    LAC_ERROR (LAC_EINVAL, "the contact multigrid has two levels (lac's "
               "finest, GAMG below), not %d: leave -pc_mg_levels unset, or "
               "choose another preconditioner with -elast_pc_type",
               (int) levels);
  return LAC_SUCCESS;
}

int
lac_petsc_mg_create (PC pc, double threshold, lac_petsc_mg **out)
{
  lac_petsc_mg *mg = lac_calloc (1, sizeof *mg);
  int status;
  *out = NULL;
  if (!mg)
    LAC_ERROR (LAC_ENOMEM, "the contact multigrid");
  mg->pc = pc;
  mg->threshold = threshold;
  if (PetscLogEventRegister ("lac contact MG", PC_CLASSID, &mg->event))
    status = lac_petsc_fail (1, __func__, "PetscLogEventRegister");
  else
    status = configure (pc);
  if (status)
    {
      lac_free (mg);
      return status;
    }
  *out = mg;
  return LAC_SUCCESS;
}

void
lac_petsc_mg_free (lac_petsc_mg *mg)
{
  if (!mg)
    return;
  MatDestroy (&mg->P);
  MatDestroy (&mg->A1);
  MatNullSpaceDestroy (&mg->nsp);
  lac_free (mg);
}

#else

typedef int lac_petsc_mg_unused;        /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
