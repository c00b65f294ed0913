/* lac_pattern.h -- the compressed-column pattern of a stiffness matrix and
 *                  the scatter map of its cell blocks           [LAC (17)]
 *
 * A Newton loop assembles a tangent of the same pattern at every
 * iteration.  Assembling through a triplet list costs a list of every
 * entry of every cell block (16 bytes each: 5 GB for a 1M-dof hex8 cube)
 * and a sort.  Here the pattern is built once from the mesh: the nodes
 * coupled to node b are those of the cells around b (a node-to-cell list,
 * then each node's neighbours sorted: no global list, no global sort);
 * every column of node b has the rows of those neighbours, dim per node
 * (dofs interleaved: dof = dim node + component, lac_spaces.h).  The map
 * gives, for cell c and its local nodes (a, b), the position of node a
 * among the neighbours of node b, so that entry (dim a + i, dim b + k) of
 * the cell block goes to x[p[dim b + k] + dim pos + i] without a search.
 *
 * Memory: the CSC (12 bytes per entry), the map (4 bytes per node pair of
 * each cell: 64 for a hex8, 400 for a hex20) and, while it is built, the
 * node-to-cell list.  The slabs (below) only where they are asked for:
 * 8 bytes per cell, and while they are made 24 more per cell and 17 per
 * node.
 *
 * Ownership: lac_pattern_build / lac_pattern_free; the pattern owns its
 * CSC (values zeroed by lac_pattern_build and lac_pattern_zero) and its
 * runs of cells once lac_pattern_slabs made them.
 */
#ifndef LAC_PATTERN_H
#define LAC_PATTERN_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "linalg/lac_linalg.h"

typedef struct lac_pattern
{
  int dim;
  size_t ndof, ncells;
  lac_csc *K;            /* owned, ndof x ndof: the pattern, its values    */
  size_t *cptr;          /* owned, ncells+1: the map of cell c is
                            pos[cptr[c] .. cptr[c+1]), nen^2 values, or
                            nothing for a cell left out                    */
  int *pos;              /* owned: pos[cptr[c] + a nen + b] = the position
                            of node a among the neighbours of node b       */
  size_t *order;         /* owned, NULL until lac_pattern_slabs: the cells
                            of the pattern, run after run (see below)      */
  size_t *run;           /* owned, nrun + 1: run r is the cells
                            order[run[r] .. run[r + 1])                    */
  size_t nrun;           /* 0 while order is NULL                          */
  size_t phase[4];       /* the runs of phase k (k = 0, 1, 2) are
                            phase[k] <= r < phase[k + 1]                   */
} lac_pattern;

/* The pattern of the cells c with cells[c] != 0 (cells NULL: all).
 * NULL on error (LAC_ENOMEM, LAC_EINVAL: more than INT_MAX entries). */
lac_pattern *lac_pattern_build (const lac_mesh *m, const char *cells);
void lac_pattern_free (lac_pattern *p);               /* NULL allowed */

/* Step 1 alone: the cells c with cells[c] != 0 (cells NULL: all) around
 * each node, in increasing order: those of node a are
 * idx[ptr[a] .. ptr[a + 1]) (*ptr: nnodes + 1 entries; both new, freed by
 * the caller).  LAC_SUCCESS or LAC_ENOMEM (nothing left). */
int lac_pattern_node_cells (const lac_mesh *m, const char *cells,
                            size_t **ptr, size_t **idx);
/* The number of entries of the pattern of the cells in those lists
 * (dim^2 for every pair of nodes that share one of them), without
 * building it: step 2's first pass, one marker per node.  LAC_SUCCESS
 * or LAC_ENOMEM. */
int lac_pattern_count (const lac_mesh *m, const size_t *ptr,
                       const size_t *idx, size_t *nnz);

/* The slabs.  A cell block adds to the columns and rows of its own nodes
 * only, so cells that share no node can be added at the same time (two
 * threads: linalg/lac_queue.h).  lac_pattern_slabs sorts the cells of
 * the pattern by their centres along the longest side of the mesh's box
 * and cuts that order into nslab slabs of equal counts.  Two slabs that
 * are not neighbours share no node as long as the slab between them is
 * thicker than a cell; where it is not (a small mesh, bodies of very
 * different cell sizes side by side) the cells that have a node of
 * another slab of the same parity are found, node by node, and set apart.
 * The runs, in three phases:
 *
 *   phase 0: the even slabs 0, 2, 4 ..., one run each;
 *   phase 1: the odd slabs 1, 3, 5 ..., one run each;
 *   phase 2: one run, the cells set apart.
 *
 * The runs of a phase share no node; a phase starts when the one before
 * it is finished.  Every entry of K, every node of F_int, then receives
 * its terms in one order whoever adds which run: phase after phase, and
 * in each phase from the one run that touches it, cell after cell (the
 * cells of a run are in the cells' order): the same sums to the last
 * bit, on one thread or two, in any timing.  A regular mesh with slabs
 * of two cells and more sets none apart.
 *
 * p->order, p->run, p->nrun and p->phase of the pattern p of mesh m (the
 * mesh it was built from); a later call with the same nslab does nothing,
 * one with another makes them again.  LAC_SUCCESS, LAC_EINVAL (another
 * mesh's pattern, nslab = 0: p as it was) or LAC_ENOMEM (p without
 * slabs). */
int lac_pattern_slabs (lac_pattern *p, const lac_mesh *m, size_t nslab);

/* K->x = 0. */
void lac_pattern_zero (lac_pattern *p);
/* K += Ke for cell c (Ke: (nen dim)^2 values, row-major, in the order of
 * lac_mesh_cell_dofs); the cell must be one of the pattern's. */
void lac_pattern_add (lac_pattern *p, const lac_mesh *m, size_t c,
                      const double *Ke);

#endif /* LAC_PATTERN_H */
