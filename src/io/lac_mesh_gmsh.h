/* lac_mesh_gmsh.h -- meshes from gmsh: .msh files and .geo scripts [LAC §2]
 *
 * The only door to gmsh in lac: lac_mesh_read opens a .msh file (formats
 * 2.2 and 4.1) or meshes a .geo script with the gmsh C API and returns a
 * lac_mesh (fem/lac_mesh.h) that owes nothing to gmsh afterwards.  gmsh
 * runs in a child process with memory and time limits (lac_mesh_child.h):
 * a malformed file that crashes it is an error message, not a crash of
 * lac.  An ASCII .msh file is first checked line by line
 * (lac_mesh_msh_check.h), and the mesh that comes back must pass the
 * checks of fem/lac_mesh_check.h.
 *
 * Ownership: *out is allocated here and freed with lac_mesh_free.
 */
#ifndef LAC_MESH_GMSH_H
#define LAC_MESH_GMSH_H

#include "fem/lac_mesh.h"
#include "io/lac_mesh_opts.h"


/* Read a .msh (2.2 or 4.1) or a .geo file through gmsh.  Errors name the
 * file and what was expected (missing file, unsupported element type,
 * inverted cell when flip_inverted == 0, boundary element that is not a face
 * of any cell, a cell listed twice, a face of three cells, overlapping
 * cells, a .geo mesh estimated too large for max_memory) or how gmsh
 * failed in its child process (killed by a signal, out of memory, time
 * limit).
 *   returns LAC_SUCCESS, LAC_EIO (missing, unreadable or malformed file),
 *   LAC_EINVAL (elements, cells or groups that do not fit), LAC_EDEP (gmsh
 *   failed), LAC_ENOMEM, LAC_EMAXITER (time limit) */
int lac_mesh_read (const char *path, const lac_mesh_opts *opts,
                   lac_mesh **out);

#endif /* LAC_MESH_GMSH_H */
