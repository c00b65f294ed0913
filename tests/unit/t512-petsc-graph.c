/* t512: the aggregation graph with a threshold at the contact nodes only
 *                                                            [chapter 13]
 *
 * linalg/lac_petsc_graph.h on a chain of six nodes, three dofs each: K's
 * node blocks are I on the diagonal and a_i I between nodes i and i+1
 * (a = 0.05, 0.5, 0.05, 0.05, 0.05), so the scaled coupling of PETSc's
 * graph is g_ij = a_i; B has a row at node 1 and one at node 3.  With the
 * threshold 0.1, GAMG's graph (PCGAMGCreateGraph) keeps the diagonal, the
 * strong coupling 1-2 and the weak 4-5 (no contact node), and drops the
 * weak couplings 0-1, 2-3 and 3-4 (a contact node at one end): the
 * values of the kept ones are a_i, and the graph is symmetric.  Without
 * the hook (another PETSc than 3.18) the install fails with a message.
 * Then the grouping of the singleton aggregates on a graph of eight
 * nodes (one process): aggregates {0 1 2}, {3}, {4}, {5}, {6 7}; 3 and 5
 * are two couplings apart (through 1), 4 has no single node near it and
 * couples most strongly to 7: the result is {0 1 2}, {3 5}, {6 7 4}, two
 * nodes grouped and one joined.  Runs on any number of processes
 * (tests/cases-petsc.sh runs it on 2 and 3).
 */
#include <math.h>
#include "check.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"
#include "linalg/lac_petsc_graph.h"

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>
#include <petscmatcoarsen.h>
#if PETSC_VERSION_MAJOR == 3 && PETSC_VERSION_MINOR == 18
#include <petsc/private/pcgamgimpl.h>     /* the coarsening, below */
#define HOOK 1
#else
#define HOOK 0
#endif

#define NODES 6
#define BS 3
#define THRESHOLD 0.1

static const double a[NODES - 1] = { 0.05, 0.5, 0.05, 0.05, 0.05 };
static const int contact[NODES] = { 0, 1, 0, 1, 0, 0 };

/* The own nodes [*n0, *n1) of this process: a near-even split. */
static void
own_nodes (int *n0, int *n1)
{
  int rank, size;
  lac_petsc_rank (&rank, &size);
  *n0 = NODES * rank / size;
  *n1 = NODES * (rank + 1) / size;
}

static Mat
stiffness (void)
{
  Mat K;
  int n0, n1;
  own_nodes (&n0, &n1);
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
  own_nodes (&n0, &n1);
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

/* The coupling the graph should hold between nodes i and j (i != j
 * neighbours), or 0 if dropped. */
static double
expected (int i, int j)
{
  double g = a[i < j ? i : j];
  return (contact[i] || contact[j]) && g < THRESHOLD ? 0 : g;
}

static void
check_graph (Mat G)
{
  int n0, n1;
  PetscBool sym = PETSC_FALSE;
  own_nodes (&n0, &n1);
  for (PetscInt i = n0; i < n1; i++)
    {
      PetscInt nc;
      const PetscInt *cols;
      const PetscScalar *v;
      double want[NODES] = { 0 };
      want[i] = 1;
      if (i > 0)
        want[i - 1] = expected ((int) i, (int) i - 1);
      if (i < NODES - 1)
        want[i + 1] = expected ((int) i, (int) i + 1);
      MatGetRow (G, i, &nc, &cols, &v);
      int count = 0;
      for (int j = 0; j < NODES; j++)
        count += want[j] != 0;
      check_true (nc == count, "node %d: %d couplings kept, want %d",
                  (int) i, (int) nc, count);
      for (PetscInt q = 0; q < nc; q++)
        check_true (want[cols[q]] != 0
                    && fabs (PetscRealPart (v[q]) - want[cols[q]]) < 1e-14,
                    "node %d: coupling to %d is %g, want %g", (int) i,
                    (int) cols[q], (double) PetscRealPart (v[q]),
                    want[cols[q]]);
      MatRestoreRow (G, i, &nc, &cols, &v);
    }
  MatIsSymmetric (G, 0.0, &sym);
  check_true (sym, "the graph is symmetric");
}

/* The grouping of singletons (lac_petsc_graph_group), on this process
 * alone. */
static void
check_group (void)
{
  static const int edge[][2] = { { 0, 1 }, { 1, 2 }, { 1, 3 }, { 1, 5 },
                                 { 4, 6 }, { 4, 7 }, { 6, 7 } };
  static const double g[] = { 0.9, 0.9, 0.5, 0.3, 0.2, 0.9, 0.8 };
  static const int list[8] = { 0, 0, 0, 3, 4, 5, 6, 6 };   /* the roots */
  static const int want[8] = { 3, 0, 0, 2, 0, 0, 3, 0 };   /* sizes after */
  Mat G;
  PetscCoarsenData *agg;
  int grouped = -1, joined = -1;
  MatCreateSeqAIJ (PETSC_COMM_SELF, 8, 8, 8, NULL, &G);
  for (int i = 0; i < 8; i++)
    MatSetValue (G, i, i, 1.0, INSERT_VALUES);
  for (int e = 0; e < 7; e++)
    {
      MatSetValue (G, edge[e][0], edge[e][1], g[e], INSERT_VALUES);
      MatSetValue (G, edge[e][1], edge[e][0], g[e], INSERT_VALUES);
    }
  MatAssemblyBegin (G, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (G, MAT_FINAL_ASSEMBLY);
  PetscCDCreate (8, &agg);
  for (int i = 0; i < 8; i++)
    PetscCDAppendID (agg, list[i], i);
  check_status (lac_petsc_graph_group (G, agg, &grouped, &joined),
                LAC_SUCCESS, "group the singletons");
  check_true (grouped == 2 && joined == 1, "2 nodes grouped (%d), 1 joined "
              "(%d)", grouped, joined);
  for (int r = 0; r < 8; r++)
    {
      PetscInt size = -1;
      PetscCDSizeAt (agg, r, &size);
      check_true (size == want[r], "aggregate %d holds %d nodes, want %d", r,
                  (int) size, want[r]);
    }
  PetscCDIntNd *pos;
  PetscInt last = -1;
  for (PetscCDGetHeadPos (agg, 6, &pos); pos; PetscCDGetNextPos (agg, 6, &pos))
    PetscCDIntNdGetID (pos, &last);
  check_true (last == 4, "node 4 joined aggregate 6 (its last node is %d)",
              (int) last);
  PetscCDDestroy (agg);
  MatDestroy (&G);
}

int
main (void)
{
  Mat K, B, G = NULL;
  PC pc;
  lac_init ();
  check_status (lac_petsc_initialize (NULL), LAC_SUCCESS, "initialize");
  K = stiffness ();
  B = constraints ();
  PCCreate (PETSC_COMM_WORLD, &pc);
  PCSetOperators (pc, K, K);
  PCSetType (pc, PCGAMG);
  PCSetFromOptions (pc);
  if (lac_petsc_graph_available ())
    {
      check_status (lac_petsc_graph_contact (pc, B, THRESHOLD), LAC_SUCCESS,
                    "install the contact graph");
      check_true (PCGAMGCreateGraph (pc, K, &G) == 0, "the graph");
      check_graph (G);
      check_group ();
#if HOOK
      {                        /* PETSc's coarsening frees the coarsener
                                  its graph step made (and groups) */
        PC_GAMG *gamg = (PC_GAMG *) ((PC_MG *) pc->data)->innerctx;
        PetscCoarsenData *agg = NULL;
        check_true (gamg->ops->coarsen (pc, &G, &agg) == 0, "the coarsening");
        PetscCDDestroy (agg);
      }
#endif
    }
  else
    {
      check_status (lac_petsc_graph_contact (pc, B, THRESHOLD), LAC_EDEP,
                    "no hook: refused");
      check_message ("no hook", "no hook: the message says why");
    }
  MatDestroy (&G);
  PCDestroy (&pc);
  MatDestroy (&B);
  MatDestroy (&K);
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
