/* lac_petsc_mg.h -- the multigrid of K_W near the contact: the finest
 *                   level of smoothed aggregation made by lac, PETSc's
 *                   GAMG on the coarse operator              [chapter 13]
 *
 * One V-cycle of this multigrid preconditions the projected CG of the
 * contact solve (lac_petsc_saddle.h).  Its finest level is built from K
 * (n x n, whole nodes of bs dofs, its near-null space set: the rigid
 * motions, or the constants of each component) and the pattern of B
 * (n x k, the constraints), with PETSc's public interface only:
 *
 *  1. the graph of the own nodes: between nodes i and j the coupling
 *       g_ij = |K_ij|_1 / sqrt(|K_ii|_1 |K_jj|_1)
 *     (sums of absolute values of the bs x bs blocks); a coupling below
 *     `threshold` with a contact node (a node with a row of B) at one
 *     end is left out, every other one kept;
 *  2. aggregates, the nodes visited in order of fewest couplings first:
 *     a node in no aggregate starts one and takes the free nodes within
 *     two couplings of it (the aggressive aggregation of PETSc's GAMG
 *     on its finest level: a maximal independent set two couplings
 *     wide);
 *  3. no aggregate of a single node: each takes the single nodes within
 *     two couplings of it, up to LAC_PETSC_MG_GROUP nodes; a node still
 *     alone joins the aggregate of its strongest neighbour;
 *  4. the tentative prolongator: on aggregate a, the m near-null vectors
 *     restricted to its dofs, orthonormalized, B_a = Q_a R_a; Q_a are
 *     its columns, R_a the coarse near-null vectors of its m coarse dofs;
 *  5. one Jacobi step, P = (I - w D^-1 K) P_t, w = 4 / (3 lambda), D the
 *     diagonal of K, lambda the largest eigenvalue of D^-1 K estimated by
 *     10 CG iterations;
 *  6. the coarse operator A_1 = P^T K P (its near-null vectors from the
 *     R_a), preconditioned by one V-cycle of PETSc's GAMG (prefix:
 *     the PC's and mg_coarse_; its threshold 0: every coupling kept),
 *     the finest level smoothed by two Chebyshev steps with Jacobi on
 *     [0.1, 1.1] lambda (GAMG's smoother).
 *
 * Aggregates never span two processes.  When the statuses change, only
 * the values of K do: the aggregates and P are kept, A_1 is made again.
 * Ownership: lac_petsc_mg_create/_free; K and B are borrowed.
 */
#ifndef LAC_PETSC_MG_H
#define LAC_PETSC_MG_H

#ifdef LAC_HAVE_PETSC

#define LAC_PETSC_MG_GROUP 4  /* nodes at most in a group of single nodes */
#define LAC_PETSC_MG_NAME "lac-sa + gamg"

typedef struct _p_PC *lac_mg_pc;
typedef struct _p_Mat *lac_mg_mat;
typedef struct _p_MatNullSpace *lac_mg_nullspace;
typedef struct lac_petsc_mg lac_petsc_mg;

/* The graph of step 1 on one process: the couplings of node i (no
 * diagonal) are adj[ptr[i] .. ptr[i+1]-1], their values g. */
typedef struct
{
  int n;                      /* own nodes                              */
  int *ptr, *adj;             /* owned: n + 1, ptr[n]                   */
  double *g;                  /* owned: ptr[n]                          */
} lac_mg_graph;

/* What the finest level holds, summed over the processes. */
typedef struct
{
  long long nodes, aggregates;   /* fine nodes, aggregates (coarse nodes) */
  long long dropped;             /* couplings left out (each pair once)  */
  long long grouped, joined;     /* single nodes grouped; joined         */
  long long left;                /* nodes in no aggregate (no coupling)  */
  double lambda;                 /* largest eigenvalue of D^-1 K (est.)  */
} lac_petsc_mg_counts;

/* pc becomes this multigrid (PCMG, two levels; GAMG on the coarse one),
 * then reads its options (the prefix pc has).  threshold < 0: no
 * coupling left out.  Nothing is built before the first _update.
 * Collective. */
int lac_petsc_mg_create (lac_mg_pc pc, double threshold, lac_petsc_mg **out);
void lac_petsc_mg_free (lac_petsc_mg *mg);
/* New values of K (and the first time: the finest level from K and B's
 * pattern; B may be NULL: no contact node); then pc's operators.
 * Collective. */
int lac_petsc_mg_update (lac_petsc_mg *mg, lac_mg_mat K, lac_mg_mat B);
void lac_petsc_mg_get_counts (const lac_petsc_mg *mg,
                              lac_petsc_mg_counts *c);

/* ---- the steps, exposed for the unit test ------------------------------ */

/* Step 1: the own nodes' graph of K (AIJ, block size bs), contact nodes
 * from B's own rows (NULL: none); *dropped: couplings left out (pairs of
 * this process).  This process's rows only. */
int lac_petsc_mg_graph (lac_mg_mat K, lac_mg_mat B, double threshold,
                        lac_mg_graph *g, long long *dropped);
void lac_petsc_mg_graph_free (lac_mg_graph *g);
/* Steps 2 and 3: agg[i] (n) the aggregate of node i, 0 .. *nagg - 1, or
 * -1 (a node without couplings, or alone in an aggregate of fewer than
 * `min` nodes: in none); *grouped, *joined: the single nodes put in
 * groups, and those that joined a neighbour's aggregate.  min: the nodes
 * an aggregate needs (1; 2 when bs < m: a node of bs dofs cannot hold m
 * coarse unknowns). */
int lac_petsc_mg_aggregate (const lac_mg_graph *g, int min, int *agg,
                            int *nagg, int *grouped, int *joined);
/* Step 3 alone, on the *nagg aggregates agg (in and out: renumbered
 * 0, 1, ... without those emptied). */
int lac_petsc_mg_singles (const lac_mg_graph *g, int min, int *agg,
                          int *nagg, int *grouped, int *joined);
/* Step 4: the tentative prolongator of K's near-null space on the
 * aggregates agg (nagg on this process) into *P (n x m Nagg, block sizes
 * bs, m), the coarse near-null vectors into *nsp (P's columns,
 * orthonormal).  Collective. */
int lac_petsc_mg_tentative (lac_mg_mat K, const int *agg, int nagg,
                            lac_mg_mat *P, lac_mg_nullspace *nsp);

#endif /* LAC_HAVE_PETSC */

#endif /* LAC_PETSC_MG_H */
