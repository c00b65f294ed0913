/* lac_mesh_gmsh_cells.h -- nodes and cells of a gmsh model       [LAC §2]
 *
 * For lac_mesh_read (lac_mesh_gmsh.c): gmsh tags become 0-based indices
 * here (see lac_mesh_gmsh_cells.c).
 */
#ifndef LAC_MESH_GMSH_CELLS_H
#define LAC_MESH_GMSH_CELLS_H

#include "fem/lac_mesh.h"
#include "io/lac_mesh_gmsh_reader.h"

/* All nodes of the model, sorted by tag, into R->tag, index, coord. */
int lac_gmsh_read_nodes (lac_gmsh_reader *R);

/* The highest dimension (3, 2 or 1) that has elements, 0 if none. */
int lac_gmsh_top_dimension (const lac_gmsh_reader *R, int *tdim);

/* Cells: the elements of every top-dimension entity, into a new *out. */
int lac_gmsh_read_cells (lac_gmsh_reader *R, lac_mesh **out);

#endif /* LAC_MESH_GMSH_CELLS_H */
