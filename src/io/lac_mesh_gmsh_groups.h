/* lac_mesh_gmsh_groups.h -- physical groups of a gmsh model      [LAC §2]
 *
 * For lac_mesh_read (lac_mesh_gmsh.c), once the cells are read
 * (lac_mesh_gmsh_cells.h); see lac_mesh_gmsh_groups.c.
 */
#ifndef LAC_MESH_GMSH_GROUPS_H
#define LAC_MESH_GMSH_GROUPS_H

#include "fem/lac_mesh.h"
#include "io/lac_mesh_gmsh_reader.h"

/* Every physical group of the model, added to m: cell groups, facet
 * groups (cell, local face), node groups. */
int lac_gmsh_read_groups (lac_gmsh_reader *R, lac_mesh *m);

#endif /* LAC_MESH_GMSH_GROUPS_H */
