/* lac_mesh_gmsh_internal.h -- internal: shared by the lac_mesh_gmsh*.c files
 *                                                                   [LAC §2]
 * Not part of the public interface.  lac_mesh_read (lac_mesh_gmsh.c) opens
 * or meshes the file through gmsh and holds a lac_gmsh_reader for the whole
 * read; the conversion of the gmsh model into a lac_mesh is split by what
 * it converts:
 *
 *   lac_mesh_gmsh.c         opening a .msh, meshing a .geo, the driver and
 *                           the error helpers;
 *   lac_mesh_gmsh_cells.c   nodes and cells: gmsh tags -> 0-based indices;
 *   lac_mesh_gmsh_groups.c  physical groups: cell, facet (matched to cell
 *                           faces through a hash) and node groups.
 */
#ifndef LAC_MESH_GMSH_INTERNAL_H
#define LAC_MESH_GMSH_INTERNAL_H

#include <stddef.h>

#include "io/lac_mesh_gmsh.h"
#include "base/lac_status.h"

/* Messages name the public function, whatever helper sets them. */
#define READ_ERR(status, ...) lac_error_set ((status), "lac_mesh_read", \
                                             __VA_ARGS__)

typedef struct lac_gmsh_face_slot
{
  int v[4];                    /* sorted vertices, -1 padded               */
  size_t cell;                 /* SIZE_MAX: empty slot                     */
  int face;
} lac_gmsh_face_slot;

/* Everything a read holds between gmsh calls; freed in one place. */
typedef struct lac_gmsh_reader
{
  const char *path;            /* borrowed                                 */
  const lac_mesh_opts *opts;   /* borrowed                                 */
  int tdim;                    /* dimension of the cells                   */
  /* all gmsh nodes, sorted by tag: tag[k] is node index[k] of the mesh   */
  size_t nall;
  size_t *tag;                 /* owned, nall                              */
  size_t *index;               /* owned, nall; SIZE_MAX: in no cell        */
  double *coord;               /* owned, 3*nall, in tag order              */
  /* top-dimension entities: cells ent_first[e] .. ent_first[e+1]-1       */
  size_t nent;
  int *ent_tag;                /* owned, nent                              */
  size_t *ent_first;           /* owned, nent+1                            */
  /* faces of all cells, hashed by their sorted vertices                  */
  size_t hcap;                 /* power of 2; 0 until built                */
  lac_gmsh_face_slot *slot;    /* owned, hcap                              */
} lac_gmsh_reader;

/* Elements of one gmsh call (getElements), released together. */
typedef struct lac_gmsh_elements
{
  int *types;
  size_t ntypes;
  size_t **etags, *etags_n, netags;
  size_t **ntags, *ntags_n, nntags;
} lac_gmsh_elements;

/* Error helpers (lac_mesh_gmsh.c). */

/* Put the file name in front of the message a lac_mesh_* call stored. */
int lac_gmsh_with_path (const lac_gmsh_reader *R, int status);

/* Set the message for a failed gmsh call, with gmsh's last error. */
int lac_gmsh_fail (const lac_gmsh_reader *R, int status, const char *what);

/* Nodes and cells (lac_mesh_gmsh_cells.c). */

/* All nodes of the model, sorted by tag, into R->tag, index, coord. */
int lac_gmsh_read_nodes (lac_gmsh_reader *R);

/* The highest dimension (3, 2 or 1) that has elements, 0 if none. */
int lac_gmsh_top_dimension (const lac_gmsh_reader *R, int *tdim);

/* Cells: the elements of every top-dimension entity, into a new *out. */
int lac_gmsh_read_cells (lac_gmsh_reader *R, lac_mesh **out);

/* Mesh index of node tag t, or SIZE_MAX if it is in no cell. */
size_t lac_gmsh_node_index (const lac_gmsh_reader *R, size_t t);

/* gmsh elements of dimension dim on entity tag (-1: all); freed below. */
int lac_gmsh_get_elements (const lac_gmsh_reader *R, lac_gmsh_elements *E,
                           int dim, int tag);
void lac_gmsh_elements_free (lac_gmsh_elements *E);

/* The reference element of gmsh type t, or NULL and an error. */
const lac_refelem *lac_gmsh_refelem (const lac_gmsh_reader *R, int t);

/* Physical groups (lac_mesh_gmsh_groups.c). */

/* Every physical group of the model, added to m. */
int lac_gmsh_read_groups (lac_gmsh_reader *R, lac_mesh *m);

#endif /* LAC_MESH_GMSH_INTERNAL_H */
