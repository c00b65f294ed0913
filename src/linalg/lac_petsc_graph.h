/* lac_petsc_graph.h -- the aggregation graph of GAMG with a threshold on
 *                      the couplings of the constrained nodes only
 *                                                          [chapter 13]
 *
 * Smoothed aggregation (PCGAMG) groups the nodes of a graph of K: the
 * couplings g_ij = |K_ij|_1 / sqrt(|K_ii|_1 |K_jj|_1) of the node blocks
 * (sums of absolute values).  PETSc's threshold drops the couplings below
 * it in the whole mesh; lac_petsc_graph_contact installs a graph that
 * keeps every coupling except those below `threshold` with a contact
 * node at one end (a node with a row of B, the constraints), on the
 * finest level only: the contact term C_A W C_A^T weakens the couplings
 * of those nodes to the bulk, the bulk keeps the aggregation of plain
 * elasticity.  The graph stays symmetric (the test is on i or j).
 *
 * PETSc has no public way to change the graph: this wraps the creategraph
 * operation of GAMG's private structure (petsc/private/pcgamgimpl.h, which
 * Debian's libpetsc-real-dev installs).  That structure changes between
 * PETSc's versions, so the wrapper is compiled for the versions it was
 * written and tested against (3.18) only; elsewhere
 * lac_petsc_graph_available is 0 and the caller keeps PETSc's threshold.
 */
#ifndef LAC_PETSC_GRAPH_H
#define LAC_PETSC_GRAPH_H

#ifdef LAC_HAVE_PETSC

typedef struct _p_PC *lac_graph_pc;
typedef struct _p_Mat *lac_graph_mat;

/* 1 if this PETSc has the hook lac_petsc_graph_contact needs. */
int lac_petsc_graph_available (void);

/* pc: after PCSetFromOptions (nothing is done unless it is PCGAMG of
 * type agg, the smoothed aggregation); B: n x k with K's rows, borrowed
 * (its pattern is read at every set-up of the graph).  Sets PETSc's
 * threshold to 0 on every level (every nonzero coupling kept, but the
 * contact nodes' below `threshold` on the finest).  Collective. */
int lac_petsc_graph_contact (lac_graph_pc pc, lac_graph_mat B,
                             double threshold);

#endif
#endif
