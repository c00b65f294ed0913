/* lac_mesh.h -- meshes: nodes, cells, physical groups           [LAC §2, §3.1]
 *
 * A mesh is the discretization T_l^h of the bodies: nodes (x[n*dim]),
 * cells of the top dimension (mixed types allowed, connectivity in gmsh node
 * order, compressed-row like CSparse's p/i) and named physical groups.
 * Cells carry the index of the body (volume physical group) they belong to.
 *
 * A group of dimension dim-1 is a set of boundary facets, each stored as
 * (owning cell, local face) so that its nodes and outward orientation come
 * from the cell's reference element (lac_spaces.h).  A group of the top
 * dimension is a set of cells.  Groups of lower dimension keep only nodes.
 *
 * Meshes are read through the gmsh C API (lac_mesh_gmsh.c): .msh files
 * (formats 2.2 and 4.1) or .geo files meshed on the fly; tests may also build
 * meshes in code (lac_mesh_box).  gmsh tags are mapped to contiguous 0-based
 * indices in lac_mesh_gmsh_cells.c and only there; node_tag/cell_tag keep the
 * original tags for messages.
 *
 * Ownership: every pointer field is owned by the mesh; lac_mesh_free frees
 * them all.
 */
#ifndef LAC_MESH_H
#define LAC_MESH_H

#include <stddef.h>
#include "fem/lac_spaces.h"

/* The corner rule: a boundary curve or surface that turns by more than
 * this angle (degrees) at a node has a corner (an edge) there; below it,
 * it is the polygon of a smooth face, whose normal turns by 360 / N
 * degrees per node of a circle cut into N facets: smooth from N = 13 on.
 * The macro-mesh breaks its chains of slave segments at corners
 * (contact/lac_macromesh_gather.h); a roller gets one condition per
 * smooth piece of its face at a node (fem/lac_frames.h). */
#define LAC_MESH_CORNER_DEG 30.0

typedef struct lac_group
{
  char *name;      /* owned                                              */
  int dim;         /* 0, 1, 2 or 3                                       */
  int tag;         /* gmsh physical tag (or 0 for built meshes)          */
  size_t n;        /* number of cells (dim == mesh dim) or facets (dim-1) */
  size_t *cell;    /* owned, n: the cell, or the cell owning the facet   */
  int *face;       /* owned, n: local face index of the facet, -1 for cells */
  size_t nnodes;   /* nodes of the group, sorted, unique                 */
  size_t *node;    /* owned, nnodes                                      */
} lac_group;

typedef struct lac_mesh
{
  int dim;                 /* space dimension, 2 or 3                     */
  size_t nnodes;
  double *x;               /* owned, nnodes*dim                           */
  size_t *node_tag;        /* owned, nnodes: original tags (messages)     */
  size_t ncells;
  lac_elem_type *type;     /* owned, ncells                               */
  size_t *ptr;             /* owned, ncells+1: nodes of cell c are        */
  int *conn;               /*   conn[ptr[c] .. ptr[c+1]-1], gmsh order     */
  size_t *cell_tag;        /* owned, ncells: original tags (messages)     */
  int *body;               /* owned, ncells: index of the volume group the
                              cell belongs to, -1 if none                 */
  size_t ngroups;
  lac_group *group;        /* owned, ngroups                              */
  size_t ndropped;         /* nodes of the file that no cell uses, left
                              out when read (a warning, not an error)     */
} lac_mesh;

/* construct / destroy */
lac_mesh *lac_mesh_alloc (int dim, size_t nnodes, size_t ncells,
                          size_t nconn);   /* ptr[0] = 0, groups empty */
void lac_mesh_free (lac_mesh *m);          /* NULL allowed */

/* A structured box mesh built in code (no gmsh): [0,L0]x[0,L1](x[0,L2]) cut
 * into n0 x n1 (x n2) cells of the given type (any 2D/3D type except pyr5;
 * simplices split each box).  Boundary facet groups "xmin", "xmax", "ymin",
 * "ymax" (, "zmin", "zmax") and a cell group "body".  `distort` moves the
 * interior vertices by up to distort*h in a fixed pseudo-random pattern
 * (high-order nodes stay at edge/face midpoints: straight-sided cells). */
int lac_mesh_box (lac_elem_type type, const size_t *n, const double *L,
                  double distort, lac_mesh **out);

/* The disjoint union of two meshes (two bodies meshed separately; nothing
 * glued): b's nodes, cells and groups follow a's, group names get the
 * prefixes pa and pb. */
int lac_mesh_merge (const lac_mesh *a, const char *pa, const lac_mesh *b,
                    const char *pb, lac_mesh **out);

/* query */
const lac_group *lac_mesh_group (const lac_mesh *m, const char *name);
int lac_mesh_facet_nodes (const lac_mesh *m, size_t cell, int face,
                          int *nodes, lac_elem_type *ftype);
                          /* returns count, -LAC_EINVAL for a bad cell/face */
void lac_mesh_cell_coords (const lac_mesh *m, size_t c, double *xe);
/* The global dofs of cell c, dofs[a*dim + i] = dim*conn[a] + i (room for
 * LAC_MAX_NODES*3); returns their number. */
int lac_mesh_cell_dofs (const lac_mesh *m, size_t c, size_t *dofs);
size_t lac_mesh_nconn_max (const lac_mesh *m);

/* compute */
/* Check det J at the nodes and quadrature points of every cell; flip
 * (flip != 0) or reject cells with det J < 0.  nflipped may be NULL. */
int lac_mesh_check_orientation (lac_mesh *m, int flip, size_t *nflipped);
/* Add a group (copies name, cell, face; computes node list). */
int lac_mesh_add_group (lac_mesh *m, const char *name, int dim, int tag,
                        size_t n, const size_t *cell, const int *face);
/* Add a group that keeps only nodes (dim < mesh dim - 1: points, or curves
 * of a 3D mesh); copies, sorts and uniques the node list. */
int lac_mesh_add_node_group (lac_mesh *m, const char *name, int dim, int tag,
                             size_t nnodes, const size_t *node);
/* Rebuild the node list of group g from its entities. */
int lac_mesh_group_nodes (lac_mesh *m, size_t g);
/* Sum of the cell measures (area or volume; 2D measures are areas). */
double lac_mesh_measure (const lac_mesh *m);

#endif /* LAC_MESH_H */
