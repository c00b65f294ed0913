/* lac_petsc_graph.h -- the aggregation of GAMG near the contact: a
 *                      threshold on the couplings of the contact nodes
 *                      only, and no aggregates of a single node
 *                                                          [chapter 13]
 *
 * Smoothed aggregation (PCGAMG) groups the nodes of a graph of K: the
 * couplings g_ij = |K_ij|_1 / sqrt(|K_ii|_1 |K_jj|_1) of the node blocks
 * (sums of absolute values).  PETSc's threshold drops the couplings below
 * it in the whole mesh; lac_petsc_graph_contact installs two steps of
 * lac's on the finest level instead:
 *
 * 1. the graph keeps every coupling except those below `threshold` with a
 *    contact node at one end (a node with a row of B, the constraints):
 *    the contact term C_A W C_A^T weakens the couplings of those nodes,
 *    the bulk keeps the aggregation of plain elasticity.  The graph stays
 *    symmetric (the test is on i or j);
 * 2. after PETSc's aggregation, the aggregates of a single node are
 *    grouped by fours (lac_petsc_graph_group).  PETSc's greedy
 *    aggregation visits the nodes of fewest couplings first; the centre
 *    nodes of the slave facets that the macro-mesh adds (chapter 03) are
 *    such nodes, and never neighbours of each other, so many ended alone,
 *    each a coarse node of 6 unknowns for 3 fine ones.
 *
 * PETSc has no public way to change either: this wraps the creategraph
 * and coarsen operations of GAMG's private structure
 * (petsc/private/pcgamgimpl.h, which Debian's libpetsc-real-dev
 * installs).  That structure changes between PETSc's versions, so the
 * wrappers are compiled for the version they were written and tested
 * against (3.18) only; elsewhere lac_petsc_graph_available is 0 and the
 * caller keeps PETSc's threshold.
 */
#ifndef LAC_PETSC_GRAPH_H
#define LAC_PETSC_GRAPH_H

#ifdef LAC_HAVE_PETSC

typedef struct _p_PC *lac_graph_pc;
typedef struct _p_Mat *lac_graph_mat;
typedef struct _PetscCoarsenData *lac_graph_aggregates;

/* 1 if this PETSc has the hook lac_petsc_graph_contact needs. */
int lac_petsc_graph_available (void);

/* pc: after PCSetFromOptions (nothing is done unless it is PCGAMG of
 * type agg, the smoothed aggregation); B: n x k with K's rows, borrowed
 * (its pattern is read at every set-up of the graph).  Sets PETSc's
 * threshold to 0 on every level (every nonzero coupling kept, but the
 * contact nodes' below `threshold` on the finest).  Collective. */
int lac_petsc_graph_contact (lac_graph_pc pc, lac_graph_mat B,
                             double threshold);

/* The second step lac_petsc_graph_contact installs, on the aggregates of
 * the finest level (agg: PETSc's lists, one per local root, of global
 * node numbers; G: the graph they were made from).  Each aggregate of a
 * single node of this process takes the single-node aggregates within two
 * couplings of it (through a node of this process), up to 4 nodes; a node
 * still alone then joins the aggregate of its strongest neighbour that
 * holds more than one node.  *grouped: the nodes put in groups, *joined:
 * those that joined.  Exposed for the unit test. */
int lac_petsc_graph_group (lac_graph_mat G, lac_graph_aggregates agg,
                           int *grouped, int *joined);

#endif
#endif
