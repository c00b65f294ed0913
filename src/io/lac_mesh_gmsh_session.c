/* lac_mesh_gmsh_session.c -- one gmsh session: open, mesh, copy  [LAC §2]
 *
 * lac_gmsh_session opens a .msh file (formats 2.2 and 4.1) or a .geo file
 * (meshed here, options from lac_mesh_opts) with gmsh, copies nodes, cells
 * and physical groups into a lac_mesh: the mesh owes nothing to gmsh.
 * It runs in the child process of
 * lac_mesh_read (lac_mesh_gmsh.c, lac_mesh_child.c), so that whatever gmsh
 * does with a malformed file stays there.  This file holds the gmsh
 * session (options, opening, meshing); the copy is done by
 * lac_mesh_gmsh_cells.c (nodes and cells: tags -> 0-based indices) and
 * lac_mesh_gmsh_groups.c (physical groups), both on the reader state and
 * messages of lac_mesh_gmsh_reader.c; a .geo is first meshed in 1D so that
 * lac_mesh_gmsh_estimate.c can refuse a mesh too large for the memory
 * limit before gmsh builds it.
 *
 *   - inverted cells are flipped or rejected (opts->flip_inverted);
 *   - size, order, serendipity and recombine apply to .geo files only; a
 *     .msh file is read as it is.
 *
 * gmsh 4.8 notes: gmshOpen on a missing
 * file reports no error, so existence is checked first (lac_mesh_read); the
 * number `level' reaches the .geo as a command-line "-setnumber level N"
 * passed to gmshInitialize (works with DefineConstant[] and with Exists());
 * gmsh keeps such numbers for the whole process, which was a trap when
 * gmsh ran inside lac (a later read saw the numbers of an earlier one): in
 * the child process of each read they die with it; Mesh.Algorithm 8
 * crashes gmsh 4.8 and is replaced by 6; a parse error thrown as an
 * exception poisons later parses (see open_file).
 *
 * The session runs sandboxed (lac_mesh_sandbox.h): a .geo cannot start
 * programs or write files.  So lac_gmsh_session must run in a child
 * process only: the sandbox cannot be left.
 */
#include "io/lac_mesh_gmsh_session.h"

#include <gmshc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/lac_mesh_gmsh_cells.h"
#include "io/lac_mesh_gmsh_estimate.h"
#include "io/lac_mesh_gmsh_groups.h"
#include "io/lac_mesh_gmsh_reader.h"
#include "io/lac_mesh_sandbox.h"
#include "base/lac_status.h"

static int
set_option (const lac_gmsh_reader *R, const char *name, double value)
{
  int ierr = 0;
  gmshOptionSetNumber (name, value, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, name);
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* meshing a .geo                                                          */
/* ---------------------------------------------------------------------- */

/* Generate the mesh of the highest dimension with the options of opts. */
static int
mesh_geo (lac_gmsh_reader *R)
{
  const lac_mesh_opts *o = R->opts;
  double alg = 6;
  int ierr = 0, dim, status = LAC_SUCCESS;

  dim = gmshModelGetDimension (&ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot get the model dimension");
  if (dim < 2)
    return READ_ERR (LAC_EINVAL, "'%s': the geometry has no surface or volume "
                     "(dimension %d)", R->path, dim);
  if (o->size < 0 || o->order < 0 || o->order > 2)
    return READ_ERR (LAC_EINVAL, "'%s': size %g or order %d out of range "
                     "(size >= 0, order 0, 1 or 2)", R->path, o->size,
                     o->order);
  if (o->size > 0)
    status = set_option (R, "Mesh.MeshSizeFactor", o->size);
  if (!status && o->recombine)
    status = set_option (R, "Mesh.RecombineAll", 1);
  if (!status && o->recombine)
    status = set_option (R, "Mesh.RecombinationAlgorithm", 1);   /* blossom */
  if (!status && o->serendipity)
    status = set_option (R, "Mesh.SecondOrderIncomplete", 1);
  gmshOptionGetNumber ("Mesh.Algorithm", &alg, &ierr);
  if (!status && !ierr && alg == 8)   /* crashes gmsh 4.8.4: use the default */
    status = set_option (R, "Mesh.Algorithm", 6);
  if (!status)
    status = lac_gmsh_estimate_check (R, dim);
  if (status)
    return status;
  gmshModelMeshGenerate (dim, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "meshing failed");
  if (o->order > 0)
    {
      gmshModelMeshSetOrder (o->order, &ierr);
      if (ierr)
        return lac_gmsh_fail (R, LAC_EDEP, "cannot set the element order");
    }
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* the reader                                                              */
/* ---------------------------------------------------------------------- */

/* gmshOpen, with its errors taken from the logger.  A parse error thrown
 * as an exception (General.AbortOnError = 2, the API default) leaves the
 * .geo parser of gmsh 4.8 in a state that breaks every later parse in the
 * process, even after gmshFinalize/gmshInitialize; with AbortOnError = 0
 * the parser ends normally and the errors are logged. */
static int
open_file (const lac_gmsh_reader *R, int kind)
{
  char **log = NULL;
  const char *first = NULL;
  size_t nlog = 0;
  int ierr = 0, ierr_log = 0, status;

  status = set_option (R, "General.AbortOnError", 0);
  if (status)
    return status;
  gmshLoggerStart (&ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot start the gmsh logger");
  gmshOpen (R->path, &ierr);
  gmshLoggerGet (&log, &nlog, &ierr_log);
  for (size_t i = 0; i < nlog && !first; i++)
    if (strncmp (log[i], "Error: ", 7) == 0)
      first = log[i] + 7;
  if (first)
    status = READ_ERR (LAC_EIO, "'%s': not a valid %s file: %s", R->path,
                       kind == LAC_GMSH_GEO ? ".geo" : "mesh", first);
  else if (ierr || ierr_log)
    status = lac_gmsh_fail (R, LAC_EIO, kind == LAC_GMSH_GEO
                                    ? "not a valid .geo file"
                                    : "not a valid mesh file");
  for (size_t i = 0; i < nlog; i++)
    gmshFree (log[i]);
  gmshFree (log);
  gmshLoggerStop (&ierr);
  if (!status)
    status = set_option (R, "General.AbortOnError", 2);
  return status;
}

/* Open (and mesh) the file, copy nodes, cells and groups into *out. */
static int
read_model (lac_gmsh_reader *R, int kind, lac_mesh **out)
{
  int status;
  lac_mesh *m = NULL;

  status = set_option (R, "General.Terminal", 0);
  if (!status)
    status = set_option (R, "General.Verbosity", 1);   /* errors, logged */
  if (!status)
    status = open_file (R, kind);
  R->geometry = kind == LAC_GMSH_GEO;
  if (!status && R->geometry)
    status = mesh_geo (R);
  if (!status)
    status = lac_gmsh_read_nodes (R);
  if (!status)
    status = lac_gmsh_top_dimension (R, &R->tdim);
  if (!status && R->tdim < 2)
    status = READ_ERR (LAC_EINVAL, "'%s': no 2D or 3D elements (expected a "
                       "mesh of surfaces or volumes)", R->path);
  if (!status)
    status = lac_gmsh_read_cells (R, &m);
  if (!status)
    status = lac_gmsh_with_path (R, lac_mesh_check_orientation (m,
                                                       R->opts->flip_inverted,
                                                       NULL));
  if (!status)
    status = lac_gmsh_read_groups (R, m);
  if (status)
    lac_mesh_free (m);
  else
    *out = m;
  return status;
}

/* argv for gmshInitialize: "-setnumber level N" and one "-setnumber NAME
 * VALUE" per pair of `numbers` ("n=28, m=3"), checked by
 * lac_mesh_numbers_split (lac_mesh_opts.h); the strings in buf, the
 * values written back exactly (%.17g).  Returns argc, or -1 with a
 * message. */
static int
number_args (const char *path, int level, const char *numbers, char *buf,
             size_t size, char **argv)
{
  static char prog[] = "lac", set[] = "-setnumber", lev[] = "level";
  lac_mesh_number num[LAC_MESH_MAX_NUMBERS];
  char why[400];
  int argc = 0, n = lac_mesh_numbers_split (numbers, num, why, sizeof why);
  size_t used;
  if (n < 0)
    return READ_ERR (LAC_EINVAL, "'%s': numbers = '%s': %s", path, numbers,
                     why), -1;
  argv[argc++] = prog;
  argv[argc++] = set;
  argv[argc++] = lev;
  argv[argc++] = buf;
  used = (size_t) snprintf (buf, size, "%d", level) + 1;
  for (int k = 0; k < n; k++)
    {
      argv[argc++] = set;
      argv[argc++] = buf + used;
      used += (size_t) snprintf (buf + used, size - used, "%s",
                                 num[k].name) + 1;
      argv[argc++] = buf + used;
      used += (size_t) snprintf (buf + used, size - used, "%.17g",
                                 num[k].value) + 1;
    }
  argv[argc] = NULL;
  return argc;
}

/* lac_gmsh_session: see lac_mesh_gmsh_session.h. */
int
lac_gmsh_session (const char *path, int kind, const lac_mesh_opts *opts,
                  lac_mesh **out)
{
  lac_gmsh_reader R = { 0 };
  char buf[(LAC_MESH_NUMBER_NAME + 32) * (LAC_MESH_MAX_NUMBERS + 1)];
  char *argv[4 + 3 * LAC_MESH_MAX_NUMBERS + 4];
  int ierr = 0, status, argc;

  *out = NULL;
  R.path = path;
  R.opts = opts;
  /* "-setnumber level N" defines `level' for the .geo parser (and the
   * other numbers likewise); they live as long as this process. */
  argc = number_args (path, opts->level, opts->numbers, buf, sizeof buf,
                      argv);
  if (argc < 0)
    return LAC_EINVAL;
  /* The sandbox (lac_mesh_sandbox.h): while gmsh starts, writes fail
   * quietly (FLTK's preferences); from the file on, they end the child. */
  if ((status = lac_mesh_sandbox_enter (LAC_SANDBOX_INIT)))
    return status;
  gmshInitialize (argc, argv, 0, &ierr);
  if (ierr)                          /* its first allocations failed */
    status = READ_ERR (LAC_EDEP, "'%s': gmsh failed to initialize within "
                       "the memory limit of %.3g GB (--max-memory)", path,
                       opts->max_memory / 1e9);
  else if (!(status = lac_mesh_sandbox_enter (LAC_SANDBOX_SCRIPT)))
    status = read_model (&R, kind, out);
  /* No gmshFinalize: the child process ends right after this, and gmsh
   * 4.8 has been seen to crash in it after a malformed file, which would
   * lose a mesh already copied. */
  lac_gmsh_reader_free (&R);
  return status;
}
