/* lac_mesh_gmsh.c -- reading meshes through gmsh, at arm's length [LAC §2]
 *
 * lac_mesh_read is the driver of one read:
 *
 *   1. the file: its kind from the extension, that it exists (gmshOpen is
 *      silent about a missing file), and for a .msh file the line-by-line
 *      check of lac_mesh_msh_check.h, which refuses the files that gmsh
 *      would read wrong without a word or choke on;
 *   2. gmsh in a child process (lac_mesh_child.h) that runs one session
 *      (lac_mesh_gmsh_session.h: open, mesh, copy) and sends the mesh back
 *      through a pipe (lac_mesh_wire.h);
 *   3. the checks of fem/lac_mesh_check.h: the arrays fit together (types,
 *      node counts, indices, finite coordinates), then the cells form a
 *      mesh (no flat cell, no cell twice, no face of three cells, no
 *      overlapping cells).
 *
 * Messages name lac_mesh_read and the file.
 */
#include "io/lac_mesh_gmsh.h"

#include <stdio.h>
#include <string.h>

#include "base/lac_input.h"
#include "base/lac_status.h"
#include "fem/lac_mesh_check.h"
#include "io/lac_mesh_child.h"
#include "io/lac_mesh_geo_check.h"
#include "io/lac_mesh_gmsh_session.h"
#include "io/lac_mesh_msh_check.h"

#define READ_FAIL(status, ...) lac_error_set ((status), "lac_mesh_read", \
                                              __VA_ARGS__)

/* What the child process is given. */
typedef struct session_arg
{
  const char *path;
  int kind;
  const lac_mesh_opts *opts;
} session_arg;

static int
session (void *arg, lac_mesh **out)
{
  const session_arg *a = arg;
  return lac_gmsh_session (a->path, a->kind, a->opts, out);
}

/* The kind of file from its extension, and that it is a regular file
 * that opens, no larger than the memory the read may take (gmsh would
 * block on a named pipe and read /dev/zero until the limit killed it:
 * base/lac_input.h). */
static int
file_kind (const char *path, double max_memory, int *kind)
{
  const char *ext = strrchr (path, '.');
  if (ext && strcmp (ext, ".geo") == 0)
    *kind = LAC_GMSH_GEO;
  else if (ext && strcmp (ext, ".msh") == 0)
    *kind = LAC_GMSH_MSH;
  else
    return READ_FAIL (LAC_EINVAL, "'%s': expected a .msh or .geo file", path);
  return lac_input_check (path, max_memory, "--max-memory", NULL);
}

/* Every element of the top dimension of the file came back as a cell:
 * gmsh 4.8 drops an element of a second order from an entity of first-
 * order ones (a tri6 among tri3) without a word, and the mesh then has
 * a hole that the solve does not see. */
static int
all_cells (const char *path, const lac_msh_counts *c, const lac_mesh *m)
{
  char types[256] = "";
  size_t n = 0, want = c->by_dim[m->dim];
  if (want == 0 || want == m->ncells)
    return LAC_SUCCESS;
  for (int t = 1; t < LAC_MSH_NTYPES && n < sizeof types; t++)
    if (c->by_type[t] && lac_msh_type_dim (t) == m->dim)
      n += (size_t) snprintf (types + n, sizeof types - n, "%s%zu %s",
                              n ? ", " : "", c->by_type[t],
                              lac_msh_type_name (t));
  return READ_FAIL (LAC_EINVAL, "'%s': the file has %zu %dD elements (%s), "
                    "gmsh read %zu of them: it drops elements of a second "
                    "order from an entity of another order, which would "
                    "leave a hole in the mesh; give each entity elements of "
                    "one order", path, want, m->dim, types, m->ncells);
}

/* A lac_mesh_* message, with the file in front. */
static int
with_path (const char *path, int status)
{
  return READ_FAIL (status, "'%s': %s", path, lac_error_message ());
}

/* lac_mesh_read: see lac_mesh_gmsh.h. */
int
lac_mesh_read (const char *path, const lac_mesh_opts *opts, lac_mesh **out)
{
  lac_mesh_opts o = { 0 };
  lac_msh_counts counts = { { 0 }, { 0 } };
  session_arg arg;
  int kind = LAC_GMSH_MSH, status;

  if (!out)
    return READ_FAIL (LAC_EINVAL, "no output pointer");
  *out = NULL;
  if (!path)
    return READ_FAIL (LAC_EINVAL, "no file name");
  if (opts)
    o = *opts;
  if (o.max_memory <= 0)
    o.max_memory = lac_mesh_default_memory ();
  if ((status = file_kind (path, o.max_memory, &kind)))
    return status;
  if (kind == LAC_GMSH_MSH
      && (status = lac_msh_check (path, o.max_memory, &counts)))
    return status;
  if (kind == LAC_GMSH_GEO && (status = lac_geo_check (path, &o)))
    return status;
  arg = (session_arg) { path, kind, &o };
  status = lac_mesh_child_run (kind == LAC_GMSH_GEO ? "mesh" : "read", path,
                               session, &arg, o.max_memory, o.max_seconds,
                               out);
  if (!status && (status = all_cells (path, &counts, *out)))
    {
      lac_mesh_free (*out);
      *out = NULL;
    }
  if (!status && ((status = lac_mesh_validate (*out))
                  || (status = lac_mesh_check_topology (*out))))
    {
      status = with_path (path, status);
      lac_mesh_free (*out);
      *out = NULL;
    }
  return status;
}
