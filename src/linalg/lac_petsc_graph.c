/* lac_petsc_graph.c -- the aggregation graph of GAMG with a threshold on
 *                      the couplings of the constrained nodes only
 *                      (see lac_petsc_graph.h)
 */
#include "linalg/lac_petsc_graph.h"

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

#if PETSC_VERSION_MAJOR == 3 && PETSC_VERSION_MINOR == 18
#define GRAPH_HOOK 1
#include <petsc/private/pcgamgimpl.h>
#else
#define GRAPH_HOOK 0
#endif

int
lac_petsc_graph_available (void)
{
  return GRAPH_HOOK;
}

#if GRAPH_HOOK

/* What the wrapper needs, composed on the PC under this name. */
#define CONTEXT "lac_contact_graph"

typedef struct
{
  PetscErrorCode (*graph) (PC, Mat, Mat *);   /* GAMG's own               */
  Mat B;                                      /* the constraints, borrowed */
  PetscReal threshold;
} graph_ctx;

static PetscErrorCode
graph_ctx_free (void *ctx)
{
  return PetscFree (ctx);
}

/* The contact nodes among the own nodes (own[i], i local) and among the
 * graph's off-process columns (ghost[q], the q-th of garray): a node is
 * one if a row of its bs dofs in B has an entry (B keeps its pattern:
 * inactive multipliers too). */
static PetscErrorCode
contact_nodes (Mat B, PetscInt bs, PetscInt nghost, const PetscInt *garray,
               PetscBool **own, PetscBool **ghost)
{
  PetscInt r0, r1, nc, N;
  Vec mask, mg;
  IS from;
  VecScatter sc;
  const PetscScalar *a;
  PetscCall (MatGetOwnershipRange (B, &r0, &r1));
  PetscCall (MatGetSize (B, &N, NULL));
  PetscCall (PetscCalloc1 ((r1 - r0) / bs, own));
  PetscCall (PetscMalloc1 (nghost, ghost));
  PetscCall (VecCreateMPI (PetscObjectComm ((PetscObject) B), (r1 - r0) / bs,
                           N / bs, &mask));
  PetscCall (VecSet (mask, 0.0));
  for (PetscInt i = r0; i < r1; i++)
    {
      PetscCall (MatGetRow (B, i, &nc, NULL, NULL));
      if (nc)
        (*own)[(i - r0) / bs] = PETSC_TRUE;
      PetscCall (MatRestoreRow (B, i, &nc, NULL, NULL));
    }
  PetscScalar *m;
  PetscCall (VecGetArray (mask, &m));
  for (PetscInt i = 0; i < (r1 - r0) / bs; i++)
    m[i] = (*own)[i];
  PetscCall (VecRestoreArray (mask, &m));
  PetscCall (VecCreateSeq (PETSC_COMM_SELF, nghost, &mg));
  PetscCall (ISCreateGeneral (PETSC_COMM_SELF, nghost, garray,
                              PETSC_USE_POINTER, &from));
  PetscCall (VecScatterCreate (mask, from, mg, NULL, &sc));
  PetscCall (VecScatterBegin (sc, mask, mg, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall (VecScatterEnd (sc, mask, mg, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall (VecGetArrayRead (mg, &a));
  for (PetscInt q = 0; q < nghost; q++)
    (*ghost)[q] = a[q] != 0;
  PetscCall (VecRestoreArrayRead (mg, &a));
  PetscCall (VecScatterDestroy (&sc));
  PetscCall (ISDestroy (&from));
  PetscCall (VecDestroy (&mg));
  return VecDestroy (&mask);
}

/* The couplings of local row i of the diagonal block (part 0, columns
 * local) or of the off-process block (part 1, columns ghosts) that the
 * graph keeps: into jj (global columns) and vv, their number in *k. */
static PetscErrorCode
kept_row (Mat part, int off, PetscInt i, PetscInt c0, const PetscInt *garray,
          const PetscBool *own, const PetscBool *ghost, PetscReal t,
          PetscInt *jj, PetscScalar *vv, PetscInt *k)
{
  PetscInt nc;
  const PetscInt *cols;
  const PetscScalar *v;
  *k = 0;
  PetscCall (MatGetRow (part, i, &nc, &cols, &v));
  for (PetscInt q = 0; q < nc; q++)
    {
      PetscBool contact = own[i] || (off ? ghost[cols[q]] : own[cols[q]]);
      PetscBool diagonal = !off && cols[q] == i;
      if (contact && !diagonal && PetscAbsScalar (v[q]) < t)
        continue;
      jj[*k] = off ? garray[cols[q]] : c0 + cols[q];
      vv[(*k)++] = v[q];
    }
  return MatRestoreRow (part, i, &nc, &cols, &v);
}

/* *G without the couplings below the threshold at a contact node: two
 * passes over G's rows, one to count (the preallocation), one to copy. */
static PetscErrorCode
drop_contact_couplings (graph_ctx *c, PetscInt bs, Mat *G)
{
  Mat Gd, Go, F;
  const PetscInt *garray;
  PetscInt c0, c1, n, N, nghost, maxrow = 0, *dn, *on, *jj, k;
  PetscBool *own, *ghost;
  PetscScalar *vv;
  PetscBool mpi;
  PetscCall (PetscObjectTypeCompare ((PetscObject) *G, MATMPIAIJ, &mpi));
  if (mpi)                        /* the own columns, the others' */
    {
      PetscCall (MatMPIAIJGetSeqAIJ (*G, &Gd, &Go, &garray));
      PetscCall (MatGetSize (Go, NULL, &nghost));
    }
  else                            /* one process: all its own */
    Gd = *G, Go = NULL, garray = NULL, nghost = 0;
  PetscCall (MatGetOwnershipRangeColumn (*G, &c0, &c1));
  PetscCall (MatGetSize (*G, &N, NULL));
  n = c1 - c0;
  PetscCall (contact_nodes (c->B, bs, nghost, garray, &own, &ghost));
  for (PetscInt i = 0; i < n; i++)
    {
      PetscInt nd, no;           /* MatRestoreRow sets its count to 0 */
      PetscCall (MatGetRow (Gd, i, &nd, NULL, NULL));
      maxrow = PetscMax (maxrow, nd);
      PetscCall (MatRestoreRow (Gd, i, NULL, NULL, NULL));
      if (!Go)
        continue;
      PetscCall (MatGetRow (Go, i, &no, NULL, NULL));
      maxrow = PetscMax (maxrow, no);
      PetscCall (MatRestoreRow (Go, i, NULL, NULL, NULL));
    }
  PetscCall (PetscMalloc4 (n, &dn, n, &on, maxrow, &jj, maxrow, &vv));
  for (PetscInt i = 0; i < n; i++)
    {
      PetscCall (kept_row (Gd, 0, i, c0, garray, own, ghost, c->threshold,
                           jj, vv, &dn[i]));
      on[i] = 0;
      if (Go)
        PetscCall (kept_row (Go, 1, i, c0, garray, own, ghost, c->threshold,
                             jj, vv, &on[i]));
    }
  PetscCall (MatCreateAIJ (PetscObjectComm ((PetscObject) *G), n, n, N, N,
                           0, dn, 0, on, &F));
  PetscCall (MatSetOption (F, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));
  for (PetscInt i = 0, row = c0; i < n; i++, row++)
    for (int off = 0; off < (Go ? 2 : 1); off++)
      {
        PetscCall (kept_row (off ? Go : Gd, off, i, c0, garray, own, ghost,
                             c->threshold, jj, vv, &k));
        PetscCall (MatSetValues (F, 1, &row, k, jj, vv, INSERT_VALUES));
      }
  PetscCall (MatAssemblyBegin (F, MAT_FINAL_ASSEMBLY));
  PetscCall (MatAssemblyEnd (F, MAT_FINAL_ASSEMBLY));
  PetscCall (MatSetOption (F, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall (PetscFree4 (dn, on, jj, vv));
  PetscCall (PetscFree (own));
  PetscCall (PetscFree (ghost));
  PetscCall (MatDestroy (G));
  *G = F;
  return 0;
}

/* GAMG's creategraph: its own graph, then, on the finest level, without
 * the contact nodes' weak couplings. */
static PetscErrorCode
contact_graph (PC pc, Mat A, Mat *G)
{
  PC_GAMG *gamg = (PC_GAMG *) ((PC_MG *) pc->data)->innerctx;
  PetscContainer box;
  graph_ctx *c;
  PetscInt bs;
  PetscCall (PetscObjectQuery ((PetscObject) pc, CONTEXT,
                               (PetscObject *) &box));
  PetscCheck (box, PetscObjectComm ((PetscObject) pc), PETSC_ERR_PLIB,
              "the contact graph lost its context");
  PetscCall (PetscContainerGetPointer (box, (void **) &c));
  PetscCall (c->graph (pc, A, G));
  if (gamg->current_level != 0)
    return 0;
  PetscCall (MatGetBlockSize (A, &bs));
  return drop_contact_couplings (c, bs, G);
}

int
lac_petsc_graph_contact (lac_graph_pc pc, lac_graph_mat B, double threshold)
{
  PC_GAMG *gamg;
  PetscContainer box;
  graph_ctx *c;
  PetscReal zero = 0;
  PetscBool is_gamg, is_agg;
  TRY (PetscObjectTypeCompare ((PetscObject) pc, PCGAMG, &is_gamg));
  if (!is_gamg)                   /* another multigrid chosen by options */
    return LAC_SUCCESS;
  gamg = (PC_GAMG *) ((PC_MG *) pc->data)->innerctx;
  TRY (PetscStrcmp (gamg->type, PCGAMGAGG, &is_agg));
  if (!is_agg)                    /* the other types have no such graph */
    return LAC_SUCCESS;
  TRY (PetscCalloc1 (1, &c));
  c->graph = gamg->ops->creategraph;
  c->B = B;
  c->threshold = threshold;
  TRY (PetscContainerCreate (PETSC_COMM_SELF, &box));
  TRY (PetscContainerSetPointer (box, c));
  TRY (PetscContainerSetUserDestroy (box, graph_ctx_free));
  TRY (PetscObjectCompose ((PetscObject) pc, CONTEXT, (PetscObject) box));
  TRY (PetscContainerDestroy (&box));
  gamg->ops->creategraph = contact_graph;
  TRY (PCGAMGSetThreshold (pc, &zero, 1));
  return LAC_SUCCESS;
}

#else

int
lac_petsc_graph_contact (lac_graph_pc pc, lac_graph_mat B, double threshold)
{
  (void) pc, (void) B, (void) threshold;
  LAC_ERROR (LAC_EDEP, "this PETSc (%d.%d) has no hook for the contact "
             "graph", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR);
}

#endif
#endif
