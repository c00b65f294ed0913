/* lac_mesh_gmsh_session.h -- one gmsh session: open, mesh, copy  [LAC §2]
 *
 * What lac_mesh_read (lac_mesh_gmsh.c) runs in its child process
 * (lac_mesh_child.h): gmshInitialize, open the .msh or mesh the .geo, copy
 * the model into a lac_mesh.  gmsh is not finalized: the child process
 * that called it ends, and nothing of gmsh outlives it.  The session
 * shuts the process in a sandbox first (lac_mesh_sandbox.h: no programs,
 * no writes), for good: call it in a child process only.
 */
#ifndef LAC_MESH_GMSH_SESSION_H
#define LAC_MESH_GMSH_SESSION_H

#include "fem/lac_mesh.h"
#include "io/lac_mesh_gmsh_reader.h"

enum { LAC_GMSH_MSH, LAC_GMSH_GEO };

/* Read path (kind LAC_GMSH_MSH or LAC_GMSH_GEO) with the options opts
 * (max_memory already resolved: the .geo size estimate compares with it);
 * *out is the mesh (caller frees) or NULL with a message naming the file. */
int lac_gmsh_session (const char *path, int kind, const lac_mesh_opts *opts,
                      lac_mesh **out);

#endif /* LAC_MESH_GMSH_SESSION_H */
