/* lac_petsc_mg_aggregate.c -- the contact multigrid's finest level,
 *                             steps 1 to 3: the graph of K without the
 *                             weak couplings of the contact nodes, its
 *                             aggregates, none of a single node
 *                             (see lac_petsc_mg.h)          [chapter 13]
 */
#ifdef LAC_HAVE_PETSC

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_mg_internal.h"

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
int
lac_petsc_mg_members (const int *agg, int n, int nagg, int *first,
                      int *node)
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
    lac_petsc_mg_members (grp, g->n, ng, first, vert);
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

#else

typedef int lac_petsc_mg_aggregate_unused;        /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
