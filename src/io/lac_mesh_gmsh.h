/* lac_mesh_gmsh.h -- meshes from gmsh: .msh files and .geo scripts [LAC §2]
 *
 * The only door to gmsh in lac: lac_mesh_read opens a .msh file (formats
 * 2.2 and 4.1) or meshes a .geo script with the gmsh C API and returns a
 * lac_mesh (fem/lac_mesh.h) that owes nothing to gmsh afterwards.
 *
 * Ownership: *out is allocated here and freed with lac_mesh_free.
 */
#ifndef LAC_MESH_GMSH_H
#define LAC_MESH_GMSH_H

#include "fem/lac_mesh.h"

#define LAC_MESH_MAX_NUMBERS 16

/* Options for reading or meshing (.geo) through gmsh. */
typedef struct lac_mesh_opts
{
  double size;         /* characteristic length factor (.geo); 0: as is  */
  int order;           /* 1 or 2 (.geo); 0: as in the file               */
  int serendipity;     /* quad8/hex20 instead of quad9/hex27             */
  int recombine;       /* quadrangles / hexahedra from .geo              */
  int level;           /* exported to the .geo as the number `level`     */
  const char *numbers; /* borrowed, NULL: more numbers for the .geo,
                          "NAME=VALUE" pairs separated by blanks or
                          commas (at most LAC_MESH_MAX_NUMBERS)          */
  int flip_inverted;   /* 1: flip cells with det J < 0; 0: reject them   */
} lac_mesh_opts;

/* Read a .msh (2.2 or 4.1) or a .geo file through gmsh.  Errors name the
 * file and what was expected (missing file, unsupported element type,
 * inverted cell when flip_inverted == 0, boundary element that is not a face
 * of any cell). */
int lac_mesh_read (const char *path, const lac_mesh_opts *opts,
                   lac_mesh **out);

#endif /* LAC_MESH_GMSH_H */
