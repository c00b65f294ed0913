/* t512: the contact multigrid: the finest level lac makes   [chapter 13]
 *
 * linalg/lac_petsc_mg.h, on any number of processes (tests/cases-petsc.sh
 * runs it on 2 and 3):
 *
 * 1. the graph of a chain of six nodes, three dofs each: K's node blocks
 *    are I on the diagonal and a_i I between nodes i and i+1 (a = 0.05,
 *    0.5, 0.05, 0.05, 0.05), so that g_ij = a_i; B has a row at nodes 1
 *    and 3.  With the threshold 0.1 each process's graph of its own nodes
 *    keeps the strong coupling 1-2 and the weak 4-5 (no contact node),
 *    leaves out 0-1, 2-3 and 3-4 (a contact node at one end), with the
 *    values a_i, symmetric;
 * 2. step 3 alone on eight nodes: aggregates {0 1 2}, {3}, {4}, {5},
 *    {6 7}; 3 and 5 are two couplings apart (through 1), 4 has no single
 *    node near it and couples most strongly to 7: {0 1 2}, {3 5},
 *    {4 6 7}, two nodes grouped and one joined;
 * 3. steps 2 and 3 on a grid of 12^3 nodes coupled to their 26
 *    neighbours, but for a node without couplings and a corner coupled to
 *    one neighbour only: every other node in exactly one aggregate, each
 *    aggregate connected, none of one node, the node without couplings in
 *    none; 20 to 150 nodes an aggregate (two couplings wide);
 * 4. the tentative prolongator of the hex8 elastic box (4 x 3 x 3 cells,
 *    the rigid motions as near-null space, its rows cut among the
 *    processes): orthonormal columns, and P_t P_t^T b = b for each rigid
 *    motion b to 1e-12 (the coarse space holds them exactly); the coarse
 *    near-null vectors orthonormal;
 * 5. the whole multigrid (lac_petsc_mg_create, _update) on that box
 *    clamped at x = 0 as the preconditioner of CG: 1e-10 in fewer than
 *    25 iterations, and again after new values of K (the aggregates
 *    kept: the counts do not change).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "fem/lac_assembly.h"
#include "fem/lac_mesh.h"
#include "linalg/lac_petsc_env.h"
#include "linalg/lac_petsc_mg.h"

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>

#define NODES 6
#define BS 3
#define THRESHOLD 0.1

static const double a[NODES - 1] = { 0.05, 0.5, 0.05, 0.05, 0.05 };
static const int contact[NODES] = { 0, 1, 0, 1, 0, 0 };

/* The own nodes [*n0, *n1) of this process among n: a near-even split. */
static void
own_nodes (int n, int *n0, int *n1)
{
  int rank, size;
  lac_petsc_rank (&rank, &size);
  *n0 = n * rank / size;
  *n1 = n * (rank + 1) / size;
}

static Mat
chain (void)
{
  Mat K;
  int n0, n1;
  own_nodes (NODES, &n0, &n1);
  MatCreateAIJ (PETSC_COMM_WORLD, BS * (n1 - n0), BS * (n1 - n0),
                BS * NODES, BS * NODES, 3 * BS, NULL, 2 * BS, NULL, &K);
  MatSetBlockSize (K, BS);
  for (int i = n0; i < n1; i++)
    for (int c = 0; c < BS; c++)
      {
        PetscInt r = BS * i + c;
        MatSetValue (K, r, r, 1.0, INSERT_VALUES);
        if (i > 0)
          MatSetValue (K, r, r - BS, -a[i - 1], INSERT_VALUES);
        if (i < NODES - 1)
          MatSetValue (K, r, r + BS, -a[i], INSERT_VALUES);
      }
  MatAssemblyBegin (K, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (K, MAT_FINAL_ASSEMBLY);
  return K;
}

/* Two columns: node 1's z and node 3's x. */
static Mat
constraints (void)
{
  Mat B;
  int n0, n1, col = 0;
  own_nodes (NODES, &n0, &n1);
  MatCreateAIJ (PETSC_COMM_WORLD, BS * (n1 - n0), PETSC_DECIDE, BS * NODES,
                2, 1, NULL, 1, NULL, &B);
  for (int i = 0; i < NODES; i++)
    if (contact[i])
      {
        if (i >= n0 && i < n1)
          MatSetValue (B, BS * i + (col ? 0 : 2), col, -1.0, INSERT_VALUES);
        col++;
      }
  MatAssemblyBegin (B, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (B, MAT_FINAL_ASSEMBLY);
  return B;
}

/* The coupling of own nodes i and j (neighbours) the graph should hold,
 * 0 if left out. */
static double
expected (int i, int j)
{
  double g = a[i < j ? i : j];
  return (contact[i] || contact[j]) && g < THRESHOLD ? 0 : g;
}

/* 1. */
static void
check_graph (void)
{
  Mat K = chain (), B = constraints ();
  lac_mg_graph g;
  long long dropped = -1, want = 0;
  int n0, n1;
  own_nodes (NODES, &n0, &n1);
  check_status (lac_petsc_mg_graph (K, B, THRESHOLD, &g, &dropped),
                LAC_SUCCESS, "the graph");
  check_true (g.n == n1 - n0, "%d own nodes, want %d", g.n, n1 - n0);
  for (int i = 0; i < g.n; i++)
    {
      int gi = n0 + i, count = 0;
      for (int j = n0; j < n1; j++)
        if (j == gi - 1 || j == gi + 1)
          {
            count += expected (gi, j) != 0;
            want += j > gi && expected (gi, j) == 0;
          }
      check_true (g.ptr[i + 1] - g.ptr[i] == count, "node %d: %d couplings "
                  "kept, want %d", gi, g.ptr[i + 1] - g.ptr[i], count);
      for (int q = g.ptr[i]; q < g.ptr[i + 1]; q++)
        check_true (fabs (g.g[q] - expected (gi, n0 + g.adj[q])) < 1e-14
                    && expected (gi, n0 + g.adj[q]) != 0, "node %d: "
                    "coupling to %d is %g, want %g", gi, n0 + g.adj[q],
                    g.g[q], expected (gi, n0 + g.adj[q]));
    }
  check_true (dropped == want, "%lld couplings left out, want %lld",
              dropped, want);
  lac_petsc_mg_graph_free (&g);
  MatDestroy (&K);
  MatDestroy (&B);
}

/* A graph of n nodes from the pairs e (m of them) and their values w. */
static void
graph_of (int n, int m, const int (*e)[2], const double *w, lac_mg_graph *g)
{
  g->n = n;
  g->ptr = calloc ((size_t) n + 1, sizeof *g->ptr);
  g->adj = malloc (2 * (size_t) m * sizeof *g->adj);
  g->g = malloc (2 * (size_t) m * sizeof *g->g);
  for (int k = 0; k < m; k++)
    g->ptr[e[k][0] + 1]++, g->ptr[e[k][1] + 1]++;
  for (int i = 0; i < n; i++)
    g->ptr[i + 1] += g->ptr[i];
  int *top = malloc ((size_t) n * sizeof *top);
  memcpy (top, g->ptr, (size_t) n * sizeof *top);
  for (int k = 0; k < m; k++)
    for (int s = 0; s < 2; s++)
      {
        int i = e[k][s], j = e[k][1 - s];
        g->adj[top[i]] = j;
        g->g[top[i]++] = w ? w[k] : 1.0;
      }
  free (top);
}

static void
free_graph (lac_mg_graph *g)
{
  free (g->ptr);
  free (g->adj);
  free (g->g);
}

/* 2. */
static void
check_singles (void)
{
  static const int edge[][2] = { { 0, 1 }, { 1, 2 }, { 1, 3 }, { 1, 5 },
                                 { 4, 6 }, { 4, 7 }, { 6, 7 } };
  static const double w[] = { 0.9, 0.9, 0.5, 0.3, 0.2, 0.9, 0.8 };
  static const int want[8] = { 0, 0, 0, 1, 2, 1, 2, 2 };
  int agg[8] = { 0, 0, 0, 1, 2, 3, 4, 4 }, nagg = 5, grouped, joined;
  lac_mg_graph g;
  graph_of (8, 7, edge, w, &g);
  check_status (lac_petsc_mg_singles (&g, 1, agg, &nagg, &grouped, &joined),
                LAC_SUCCESS, "the single nodes");
  check_true (nagg == 3 && grouped == 2 && joined == 1, "%d aggregates "
              "(want 3), %d grouped (2), %d joined (1)", nagg, grouped,
              joined);
  for (int i = 0; i < 8; i++)
    check_true (agg[i] == want[i], "node %d in aggregate %d, want %d", i,
                agg[i], want[i]);
  free_graph (&g);
}

/* Aggregate a of agg connected (its nodes reached from its first one
 * through its own nodes); seen, stack: scratch (n). */
static int
connected (const lac_mg_graph *g, const int *agg, int a, int *seen,
           int *stack)
{
  int first = -1, top = 0, reached = 0, size = 0;
  for (int i = 0; i < g->n; i++)
    {
      seen[i] = 0;
      if (agg[i] == a)
        size++, first = first < 0 ? i : first;
    }
  stack[top++] = first, seen[first] = 1;
  while (top)
    {
      int i = stack[--top];
      reached++;
      for (int q = g->ptr[i]; q < g->ptr[i + 1]; q++)
        if (agg[g->adj[q]] == a && !seen[g->adj[q]])
          seen[g->adj[q]] = 1, stack[top++] = g->adj[q];
    }
  return reached == size;
}

/* 3. */
static void
check_aggregates (void)
{
  enum { N = 12 };
  int (*e)[2] = malloc (13 * N * N * N * sizeof *e), m = 0;
  int lone = N * N * (N / 2) + N * (N / 2) + N / 2;        /* the middle */
  for (int z = 0; z < N; z++)
    for (int y = 0; y < N; y++)
      for (int x = 0; x < N; x++)
        for (int d = 0; d < 27; d++)
          {
            int dx = d % 3 - 1, dy = d / 3 % 3 - 1, dz = d / 9 - 1;
            int X = x + dx, Y = y + dy, Z = z + dz, i = (z * N + y) * N + x;
            int j = (Z * N + Y) * N + X;
            if (X < 0 || Y < 0 || Z < 0 || X >= N || Y >= N || Z >= N
                || j <= i || i == lone || j == lone
                || (i == 0 && j != 1))               /* a corner: one */
              continue;
            e[m][0] = i, e[m][1] = j, m++;
          }
  lac_mg_graph g;
  graph_of (N * N * N, m, e, NULL, &g);
  int *agg = malloc (N * N * N * sizeof *agg), nagg = 0, grouped, joined;
  int *size, *seen = malloc (N * N * N * sizeof *seen);
  int *stack = malloc (N * N * N * sizeof *stack), single = 0, broken = 0;
  check_status (lac_petsc_mg_aggregate (&g, 2, agg, &nagg, &grouped,
                                        &joined), LAC_SUCCESS, "aggregates");
  size = calloc ((size_t) nagg + 1, sizeof *size);
  int bad = 0;
  for (int i = 0; i < g.n; i++)
    bad += i != lone && (agg[i] < 0 || agg[i] >= nagg);
  check_true (!bad && agg[lone] == -1, "%d nodes in no aggregate, the one "
              "without couplings in %d (want -1)", bad, agg[lone]);
  for (int i = 0; !bad && i < g.n; i++)
    if (agg[i] >= 0)
      size[agg[i]]++;
  for (int b = 0; !bad && b < nagg; b++)
    single += size[b] == 1, broken += !connected (&g, agg, b, seen, stack);
  check_true (!single && !broken, "%d aggregates of one node, %d not "
              "connected (want none)", single, broken);
  double mean = nagg ? (N * N * N - 1.0) / nagg : 0;
  check_true (mean >= 20 && mean <= 150, "%.1f nodes an aggregate (%d "
              "aggregates; want 20 to 150)", mean, nagg);
  free (size);
  free (seen);
  free (stack);
  free (agg);
  free (e);
  free_graph (&g);
}

/* ---- the elastic box ---------------------------------------------------- */

typedef struct
{
  Mat K;                 /* rows cut among the processes by whole nodes */
  Vec coords;
  int n;                 /* dofs */
} box;

/* The hex8 box 4 x 3 x 3 cells, E = 1000, nu = 0.3, clamped at x = 0
 * (rows and columns of its dofs zero but the diagonal), times s; the
 * rigid motions as near-null space. */
static void
elastic_box (double s, box *b)
{
  const size_t nc[3] = { 4, 3, 3 };
  const double L[3] = { 4.0, 3.0, 3.0 };
  lac_mesh *m = NULL;
  lac_csc *K = NULL;
  lac_mesh_box (LAC_HEX8, nc, L, 0.0, &m);
  size_t n = 3 * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E);
  double *nu = malloc (m->ncells * sizeof *nu);
  double *F = calloc (n, sizeof *F);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = 1000.0 * s, nu[c] = 0.3;
  lac_elastic mat = { LAC_SOLID3D, E, nu };
  lac_dirichlet *D = lac_dirichlet_alloc ();
  for (int c = 0; c < 3; c++)
    lac_dirichlet_add_group (D, m, lac_mesh_group (m, "xmin"), c, 0.0);
  check_status (lac_assembly_stiffness_csc (m, &mat, &K), LAC_SUCCESS,
                "the box's K");
  lac_dirichlet_apply (D, K, F);
  int n0, n1;
  own_nodes ((int) m->nnodes, &n0, &n1);
  MatCreateAIJ (PETSC_COMM_WORLD, 3 * (n1 - n0), 3 * (n1 - n0), (int) n,
                (int) n, 81, NULL, 81, NULL, &b->K);
  MatSetBlockSize (b->K, 3);
  for (int j = 3 * n0; j < 3 * n1; j++)   /* K symmetric: column = row */
    for (int p = K->p[j]; p < K->p[j + 1]; p++)
      MatSetValue (b->K, j, K->i[p], K->x[p], INSERT_VALUES);
  MatAssemblyBegin (b->K, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (b->K, MAT_FINAL_ASSEMBLY);
  MatCreateVecs (b->K, &b->coords, NULL);
  VecSetBlockSize (b->coords, 3);
  for (int j = 3 * n0; j < 3 * n1; j++)
    VecSetValue (b->coords, j, m->x[j], INSERT_VALUES);
  VecAssemblyBegin (b->coords);
  VecAssemblyEnd (b->coords);
  MatNullSpace nsp;
  MatNullSpaceCreateRigidBody (b->coords, &nsp);
  MatSetNearNullSpace (b->K, nsp);
  MatNullSpaceDestroy (&nsp);
  b->n = (int) n;
  lac_dirichlet_free (D);
  lac_csc_free (K);
  lac_mesh_free (m);
  free (E);
  free (nu);
  free (F);
}

static void
free_box (box *b)
{
  MatDestroy (&b->K);
  VecDestroy (&b->coords);
}

/* 4. */
static void
check_tentative (void)
{
  box b;
  lac_mg_graph g;
  long long dropped;
  int *agg, nagg = 0, grouped, joined;
  Mat P = NULL, PtP;
  MatNullSpace nsp = NULL, fine;
  PetscBool has_const;
  PetscInt nv, nc;
  const Vec *v, *vc;
  elastic_box (1.0, &b);
  check_status (lac_petsc_mg_graph (b.K, NULL, -1.0, &g, &dropped),
                LAC_SUCCESS, "the box's graph");
  agg = malloc (((size_t) g.n + 1) * sizeof *agg);
  check_status (lac_petsc_mg_aggregate (&g, 2, agg, &nagg, &grouped,
                                        &joined), LAC_SUCCESS,
                "the box's aggregates");
  check_status (lac_petsc_mg_tentative (b.K, agg, nagg, &P, &nsp),
                LAC_SUCCESS, "the tentative prolongator");
  MatTransposeMatMult (P, P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &PtP);
  MatShift (PtP, -1.0);
  PetscReal e;
  MatNorm (PtP, NORM_MAX, &e);
  check_abs (e, 0.0, 1e-13, "P_t^T P_t = I");
  MatGetNearNullSpace (b.K, &fine);
  MatNullSpaceGetVecs (fine, &has_const, &nv, &v);
  Vec c, r;
  MatCreateVecs (P, &c, &r);
  for (PetscInt k = 0; k < nv; k++)   /* P P^T b = b on the aggregated rows */
    {
      PetscReal d, nb;
      PetscInt r0, r1;
      const PetscScalar *x, *y;
      MatMultTranspose (P, v[k], c);
      MatMult (P, c, r);
      VecGetOwnershipRange (r, &r0, &r1);
      VecGetArrayRead (r, &y);
      VecGetArrayRead (v[k], &x);
      d = 0;
      for (PetscInt i = r0; i < r1; i++)
        if (agg[(i - r0) / 3] >= 0)
          d = fmax (d, fabs (y[i - r0] - x[i - r0]));
      VecRestoreArrayRead (r, &y);
      VecRestoreArrayRead (v[k], &x);
      MPI_Allreduce (MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MAX,
                     PETSC_COMM_WORLD);
      VecNorm (v[k], NORM_INFINITY, &nb);
      check_abs (d / nb, 0.0, 1e-12, "rigid motion %d held by P_t", (int) k);
    }
  MatNullSpaceGetVecs (nsp, &has_const, &nc, &vc);
  check_true (nc == 6 && !has_const, "%d coarse near-null vectors", (int) nc);
  for (PetscInt k = 0; k < nc; k++)
    for (PetscInt j = 0; j <= k; j++)
      {
        PetscScalar d;
        VecDot (vc[k], vc[j], &d);
        check_abs (d, j == k ? 1.0 : 0.0, 1e-13, "coarse vectors %d . %d",
                   (int) k, (int) j);
      }
  VecDestroy (&c);
  VecDestroy (&r);
  MatDestroy (&PtP);
  MatDestroy (&P);
  MatNullSpaceDestroy (&nsp);
  lac_petsc_mg_graph_free (&g);
  free (agg);
  free_box (&b);
}

/* CG with pc on K x = K 1: iterations to 1e-10, -1 if it failed. */
static int
cg_iterations (Mat K, PC pc)
{
  KSP ksp;
  Vec x, f;
  PetscInt its;
  KSPConvergedReason why;
  MatCreateVecs (K, &x, &f);
  VecSet (x, 1.0);
  MatMult (K, x, f);
  VecSet (x, 0.0);
  KSPCreate (PETSC_COMM_WORLD, &ksp);
  KSPSetType (ksp, KSPCG);
  KSPSetOperators (ksp, K, K);
  KSPSetPC (ksp, pc);
  KSPSetTolerances (ksp, 1e-10, 0, PETSC_DEFAULT, 200);
  KSPSolve (ksp, f, x);
  KSPGetIterationNumber (ksp, &its);
  KSPGetConvergedReason (ksp, &why);
  KSPDestroy (&ksp);
  VecDestroy (&x);
  VecDestroy (&f);
  return why > 0 ? (int) its : -1;
}

/* 5. */
static void
check_multigrid (void)
{
  box b, b2;
  PC pc;
  lac_petsc_mg *mg = NULL;
  lac_petsc_mg_counts c1, c2;
  elastic_box (1.0, &b);
  PCCreate (PETSC_COMM_WORLD, &pc);
  PCSetOptionsPrefix (pc, "t512_");
  check_status (lac_petsc_mg_create (pc, THRESHOLD, &mg), LAC_SUCCESS,
                "the multigrid");
  check_status (lac_petsc_mg_update (mg, b.K, NULL), LAC_SUCCESS,
                "its finest level");
  int its = cg_iterations (b.K, pc);
  lac_petsc_mg_get_counts (mg, &c1);
  check_true (its > 0 && its < 25, "CG with the multigrid: %d iterations "
              "(want 1 to 24)", its);
  check_true (c1.nodes == 80 && c1.aggregates > 0 && c1.aggregates < 20
              && c1.left == 16 && c1.lambda > 1, "%lld nodes, %lld "
              "aggregates, %lld in none (the clamped), lambda %g", c1.nodes,
              c1.aggregates, c1.left, c1.lambda);
  elastic_box (3.0, &b2);                  /* new values, the same pattern */
  MatCopy (b2.K, b.K, SAME_NONZERO_PATTERN);
  check_status (lac_petsc_mg_update (mg, b.K, NULL), LAC_SUCCESS,
                "new values");
  its = cg_iterations (b.K, pc);
  lac_petsc_mg_get_counts (mg, &c2);
  check_true (its > 0 && its < 25 && c2.aggregates == c1.aggregates,
              "again: %d iterations, %lld aggregates (were %lld)", its,
              c2.aggregates, c1.aggregates);
  PCDestroy (&pc);
  lac_petsc_mg_free (mg);
  free_box (&b);
  free_box (&b2);
}

int
main (void)
{
  lac_init ();
  check_status (lac_petsc_initialize (NULL), LAC_SUCCESS, "initialize");
  check_graph ();
  check_singles ();
  check_aggregates ();
  check_tentative ();
  check_multigrid ();
  lac_petsc_finalize ();
  lac_finalize ();
  return check_summary ();
}

#else

int
main (void)
{
  check_true (!lac_petsc_available (), "built without PETSc");
  return check_summary ();
}

#endif
