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
 * node-to-cell list.  The two halves (below) only where they are asked
 * for: 8 bytes per cell, and while they are made 17 more per cell and 1
 * per node.
 *
 * Ownership: lac_pattern_build / lac_pattern_free; the pattern owns its
 * CSC (values zeroed by lac_pattern_build and lac_pattern_zero) and the
 * order of its halves once lac_pattern_halves made it.
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
  size_t *order;         /* owned, NULL until lac_pattern_halves: the
                            cells of the pattern in three runs of nrun[0],
                            nrun[1], nrun[2] cells: two halves of the mesh
                            that share no node, then the cells that touch
                            both (see below)                               */
  size_t nrun[3];        /* 0, 0, 0 while order is NULL                    */
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

/* The two halves.  A cell block adds to the columns and rows of its own
 * nodes only, so two cells that share no node can be added at the same
 * time (two threads, linalg/lac_tasks.h); lac_pattern_halves cuts the
 * cells of the pattern at the median of their centres along the longest
 * side of the mesh's box, and the cells of either half that have a node
 * of the other go to the third run, added after the two.  The layer is
 * one or two cells thick: about 1 / (cells along that side) of the mesh
 * on each side of the cut.  Assemblies that add the runs in that order,
 * one thread or two, add every entry in the same order: the same sums to
 * the last bit.
 *
 * p->order and p->nrun of the pattern p of mesh m (the mesh it was built
 * from), made by the first call; a later call does nothing.  LAC_SUCCESS,
 * LAC_EINVAL (another mesh's pattern) or LAC_ENOMEM (p as it was). */
int lac_pattern_halves (lac_pattern *p, const lac_mesh *m);

/* K->x = 0. */
void lac_pattern_zero (lac_pattern *p);
/* K += Ke for cell c (Ke: (nen dim)^2 values, row-major, in the order of
 * lac_mesh_cell_dofs); the cell must be one of the pattern's. */
void lac_pattern_add (lac_pattern *p, const lac_mesh *m, size_t c,
                      const double *Ke);

#endif /* LAC_PATTERN_H */
