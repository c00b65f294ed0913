/* lac_petsc_graph.c -- the aggregation of GAMG near the contact: the
 *                      contact nodes' weak couplings dropped from its
 *                      graph, its single-node aggregates grouped
 *                      (see lac_petsc_graph.h)
 */
#include "linalg/lac_petsc_graph.h"

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"

#define GROUP 4          /* nodes at most in a group of single nodes     */

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

/* What the wrappers need, composed on the PC under this name. */
#define CONTEXT "lac_contact_graph"

typedef struct
{
  PetscErrorCode (*graph) (PC, Mat, Mat *);   /* GAMG's own               */
  PetscErrorCode (*coarsen) (PC, Mat *, PetscCoarsenData **);   /* same  */
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

/* ---- the singleton aggregates ------------------------------------------ */

/* *s: the one node of aggregate r if it holds exactly one node of this
 * process (my0 <= s < end), else -1. */
static PetscErrorCode
singleton (PetscCoarsenData *agg, PetscInt r, PetscInt my0, PetscInt end,
           PetscInt *s)
{
  PetscInt size, gid;
  PetscCDIntNd *pos;
  *s = -1;
  PetscCall (PetscCDSizeAt (agg, r, &size));
  if (size != 1)
    return 0;
  PetscCall (PetscCDGetHeadPos (agg, r, &pos));
  PetscCall (PetscCDIntNdGetID (pos, &gid));
  if (gid >= my0 && gid < end)
    *s = gid;
  return 0;
}

/* Node gid (local) from its aggregate into aggregate r. */
static PetscErrorCode
move (PetscCoarsenData *agg, PetscInt *owner, PetscInt my0, PetscInt gid,
      PetscInt r)
{
  PetscCall (PetscCDRemoveAll (agg, owner[gid - my0]));
  PetscCall (PetscCDAppendID (agg, r, gid));
  owner[gid - my0] = r;
  return 0;
}

/* Aggregate r, the singleton of node s, takes the singletons within two
 * couplings of s (through a node j of this process), up to GROUP nodes;
 * nb: room for a row of G.  *members: the nodes it holds then. */
static PetscErrorCode
gather (Mat G, PetscCoarsenData *agg, PetscInt *owner, PetscInt my0,
        PetscInt end, PetscInt r, PetscInt s, PetscInt *nb, PetscInt *members)
{
  PetscInt nc, nn;
  const PetscInt *cols;
  *members = 1;
  PetscCall (MatGetRow (G, s, &nn, &cols, NULL));  /* one row at a time */
  PetscCall (PetscArraycpy (nb, cols, nn));
  PetscCall (MatRestoreRow (G, s, NULL, &cols, NULL));
  for (PetscInt a = 0; a < nn && *members < GROUP; a++)
    {
      if (nb[a] < my0 || nb[a] >= end || nb[a] == s)
        continue;
      PetscCall (MatGetRow (G, nb[a], &nc, &cols, NULL));
      for (PetscInt q = 0; q < nc && *members < GROUP; q++)
        {
          PetscInt k = cols[q], t, other;
          if (k < my0 || k >= end || k == s || (t = owner[k - my0]) < 0
              || t == r)
            continue;
          PetscCall (singleton (agg, t, my0, end, &other));
          if (other == k)
            {
              PetscCall (move (agg, owner, my0, k, r));
              (*members)++;
            }
        }
      PetscCall (MatRestoreRow (G, nb[a], NULL, &cols, NULL));
    }
  return 0;
}

/* The singleton s (aggregate r) joins the aggregate of its strongest
 * neighbour on this process that holds more than one node; *joined = 1
 * if there was one. */
static PetscErrorCode
join (Mat G, PetscCoarsenData *agg, PetscInt *owner, PetscInt my0,
      PetscInt end, PetscInt r, PetscInt s, int *joined)
{
  PetscInt nc, best = -1;
  PetscReal strongest = 0;
  const PetscInt *cols;
  const PetscScalar *v;
  PetscCall (MatGetRow (G, s, &nc, &cols, &v));
  for (PetscInt q = 0; q < nc; q++)
    {
      PetscInt t, size;
      if (cols[q] < my0 || cols[q] >= end || cols[q] == s
          || (t = owner[cols[q] - my0]) < 0 || t == r)
        continue;
      PetscCall (PetscCDSizeAt (agg, t, &size));
      if (size > 1 && (best < 0 || PetscAbsScalar (v[q]) > strongest))
        best = t, strongest = PetscAbsScalar (v[q]);
    }
  PetscCall (MatRestoreRow (G, s, &nc, &cols, &v));
  *joined = best >= 0;
  return best >= 0 ? move (agg, owner, my0, s, best) : 0;
}

/* owner[i]: the aggregate (local root) of local node i, -1 if none here;
 * *maxrow: the longest row of G. */
static PetscErrorCode
owners (Mat G, PetscCoarsenData *agg, PetscInt my0, PetscInt end,
        PetscInt **owner, PetscInt *maxrow)
{
  PetscInt nloc = end - my0;
  PetscCall (PetscMalloc1 (nloc, owner));
  *maxrow = 0;
  for (PetscInt i = 0; i < nloc; i++)
    {
      PetscInt nc;
      (*owner)[i] = -1;
      PetscCall (MatGetRow (G, my0 + i, &nc, NULL, NULL));
      *maxrow = PetscMax (*maxrow, nc);
      PetscCall (MatRestoreRow (G, my0 + i, NULL, NULL, NULL));
    }
  for (PetscInt r = 0; r < nloc; r++)
    {
      PetscCDIntNd *pos;
      PetscCall (PetscCDGetHeadPos (agg, r, &pos));
      while (pos)
        {
          PetscInt gid;
          PetscCall (PetscCDIntNdGetID (pos, &gid));
          if (gid >= my0 && gid < end)
            (*owner)[gid - my0] = r;
          PetscCall (PetscCDGetNextPos (agg, r, &pos));
        }
    }
  return 0;
}

/* The singletons of agg (lists indexed by local root) grouped (gather),
 * then those still alone joined to a neighbour's aggregate (join). */
static PetscErrorCode
group_singletons (Mat G, PetscCoarsenData *agg, int *grouped, int *joined)
{
  PetscInt my0, end, *owner, maxrow = 0, *nb, s, members;
  int one = 0;
  *grouped = *joined = 0;
  PetscCall (MatGetOwnershipRange (G, &my0, &end));
  PetscCall (owners (G, agg, my0, end, &owner, &maxrow));
  PetscCall (PetscMalloc1 (maxrow, &nb));
  for (PetscInt r = 0; r < end - my0; r++)
    {
      PetscCall (singleton (agg, r, my0, end, &s));
      if (s < 0)
        continue;
      PetscCall (gather (G, agg, owner, my0, end, r, s, nb, &members));
      *grouped += members > 1 ? (int) members : 0;
    }
  for (PetscInt r = 0; r < end - my0; r++)
    {
      PetscCall (singleton (agg, r, my0, end, &s));
      if (s < 0)
        continue;
      PetscCall (join (G, agg, owner, my0, end, r, s, &one));
      *joined += one;
    }
  PetscCall (PetscFree (nb));
  return PetscFree (owner);
}

/* GAMG's coarsen: its own aggregates, then, on the finest level, the
 * singletons grouped (the graph G is the one its aggregates were made
 * from; PETSc's coarsen may replace *G). */
static PetscErrorCode
contact_coarsen (PC pc, Mat *G, PetscCoarsenData **agg)
{
  PC_GAMG *gamg = (PC_GAMG *) ((PC_MG *) pc->data)->innerctx;
  PetscContainer box;
  graph_ctx *c;
  Mat G0 = *G;
  int grouped, joined;
  PetscCall (PetscObjectQuery ((PetscObject) pc, CONTEXT,
                               (PetscObject *) &box));
  PetscCheck (box, PetscObjectComm ((PetscObject) pc), PETSC_ERR_PLIB,
              "the contact graph lost its context");
  PetscCall (PetscContainerGetPointer (box, (void **) &c));
  PetscCall (PetscObjectReference ((PetscObject) G0));
  PetscCall (c->coarsen (pc, G, agg));
  if (gamg->current_level == 0)
    {
      PetscCall (group_singletons (G0, *agg, &grouped, &joined));
      PetscCall (PetscInfo (pc, "%d nodes of singleton aggregates grouped, "
                            "%d joined a neighbour's\n", grouped, joined));
    }
  return MatDestroy (&G0);
}

int
lac_petsc_graph_group (lac_graph_mat G, lac_graph_aggregates agg,
                       int *grouped, int *joined)
{
  TRY (group_singletons (G, agg, grouped, joined));
  return LAC_SUCCESS;
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
  c->coarsen = gamg->ops->coarsen;
  c->B = B;
  c->threshold = threshold;
  TRY (PetscContainerCreate (PETSC_COMM_SELF, &box));
  TRY (PetscContainerSetPointer (box, c));
  TRY (PetscContainerSetUserDestroy (box, graph_ctx_free));
  TRY (PetscObjectCompose ((PetscObject) pc, CONTEXT, (PetscObject) box));
  TRY (PetscContainerDestroy (&box));
  gamg->ops->creategraph = contact_graph;
  gamg->ops->coarsen = contact_coarsen;
  TRY (PCGAMGSetThreshold (pc, &zero, 1));
  return LAC_SUCCESS;
}

#else

int
lac_petsc_graph_group (lac_graph_mat G, lac_graph_aggregates agg,
                       int *grouped, int *joined)
{
  (void) G, (void) agg, *grouped = *joined = 0;
  LAC_ERROR (LAC_EDEP, "this PETSc (%d.%d) has no hook for the contact "
             "graph", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR);
}

int
lac_petsc_graph_contact (lac_graph_pc pc, lac_graph_mat B, double threshold)
{
  (void) pc, (void) B, (void) threshold;
  LAC_ERROR (LAC_EDEP, "this PETSc (%d.%d) has no hook for the contact "
             "graph", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR);
}

#endif
#endif
