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
 * node-to-cell list.
 *
 * Ownership: lac_pattern_build / lac_pattern_free; the pattern owns its
 * CSC (values zeroed by lac_pattern_build and lac_pattern_zero).
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
  size_t b0, b1;         /* the columns are those of nodes b0 <= b < b1
                            (all: 0, nnodes)                               */
  lac_csc *K;            /* owned, ndof x dim (b1 - b0): the pattern, its
                            values; column dim (b - b0) + k is dof dim b + k */
  size_t *cptr;          /* owned, ncells+1: the map of cell c is
                            pos[cptr[c] .. cptr[c+1]), nen^2 values, or
                            nothing for a cell left out                    */
  int *pos;              /* owned: pos[cptr[c] + a nen + b] = the position
                            of node a among the neighbours of node b       */
} lac_pattern;

/* The pattern of the cells c with cells[c] != 0 (cells NULL: all).
 * NULL on error (LAC_ENOMEM, LAC_EINVAL: more than INT_MAX entries). */
lac_pattern *lac_pattern_build (const lac_mesh *m, const char *cells);
/* The same for the columns of nodes b0 <= b < b1 only (a block of K's
 * columns, whole: every cell kept around those nodes adds to them; the
 * map holds the cells with a node among them, -1 for the others' nodes).
 * NULL on error (also LAC_EINVAL: not 0 <= b0 <= b1 <= nnodes). */
lac_pattern *lac_pattern_build_nodes (const lac_mesh *m, const char *cells,
                                      size_t b0, size_t b1);
void lac_pattern_free (lac_pattern *p);               /* NULL allowed */

/* K->x = 0. */
void lac_pattern_zero (lac_pattern *p);
/* K += Ke for cell c (Ke: (nen dim)^2 values, row-major, in the order of
 * lac_mesh_cell_dofs), into the pattern's columns; the cell must be one
 * of the pattern's. */
void lac_pattern_add (lac_pattern *p, const lac_mesh *m, size_t c,
                      const double *Ke);

#endif /* LAC_PATTERN_H */
