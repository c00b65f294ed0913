/* lac_mesh_gmsh_reader.h -- one read of a gmsh model: its state, its
 * errors, the gmsh calls the converters share                    [LAC §2]
 *
 * lac_mesh_read (lac_mesh_gmsh.c) opens or meshes the file through gmsh
 * and holds a lac_gmsh_reader for the whole read; the conversion of the
 * gmsh model into a lac_mesh is split by what it converts, each part on
 * top of this module:
 *
 *   lac_mesh_gmsh_cells.c   nodes and cells: gmsh tags -> 0-based indices;
 *   lac_mesh_gmsh_groups.c  physical groups: cell, facet (matched to cell
 *                           faces through a hash) and node groups.
 *
 * Messages name the public function (lac_mesh_read) and the file,
 * whatever helper sets them.
 */
#ifndef LAC_MESH_GMSH_READER_H
#define LAC_MESH_GMSH_READER_H

#include <stddef.h>

#include "fem/lac_mesh.h"
#include "io/lac_mesh_opts.h"
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
  int geometry;                /* 1: meshed from a .geo (it may have
                                  construction points)                    */
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

/* Free the arrays the reader owns (not R itself). */
void lac_gmsh_reader_free (lac_gmsh_reader *R);

/* Put the file name in front of the message a lac_mesh_* call stored. */
int lac_gmsh_with_path (const lac_gmsh_reader *R, int status);

/* Set the message for a failed gmsh call, with gmsh's last error. */
int lac_gmsh_fail (const lac_gmsh_reader *R, int status, const char *what);

/* Position of node tag t in the sorted R->tag, or SIZE_MAX. */
size_t lac_gmsh_tag_position (const lac_gmsh_reader *R, size_t t);

/* Mesh index of node tag t, or SIZE_MAX if it is in no cell. */
size_t lac_gmsh_node_index (const lac_gmsh_reader *R, size_t t);

/* Elements of one gmsh call (getElements), released together. */
typedef struct lac_gmsh_elements
{
  int *types;
  size_t ntypes;
  size_t **etags, *etags_n, netags;
  size_t **ntags, *ntags_n, nntags;
} lac_gmsh_elements;

/* gmsh elements of dimension dim on entity tag (-1: all); freed below. */
int lac_gmsh_get_elements (const lac_gmsh_reader *R, lac_gmsh_elements *E,
                           int dim, int tag);
void lac_gmsh_elements_free (lac_gmsh_elements *E);

/* The reference element of gmsh type t, or NULL and an error. */
const lac_refelem *lac_gmsh_refelem (const lac_gmsh_reader *R, int t);

#endif /* LAC_MESH_GMSH_READER_H */
