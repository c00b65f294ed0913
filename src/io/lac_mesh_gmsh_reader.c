/* lac_mesh_gmsh_reader.c -- one read of a gmsh model              [LAC §2]
 *
 * What the converters of nodes and cells (lac_mesh_gmsh_cells.c) and of
 * physical groups (lac_mesh_gmsh_groups.c) share: the reader's arrays and
 * their release, the messages (the file name in front, gmsh's last error
 * behind), node tags -> mesh indices, and the gmsh element queries.
 */
#include "io/lac_mesh_gmsh_reader.h"

#include <gmshc.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

void
lac_gmsh_reader_free (lac_gmsh_reader *R)
{
  lac_free (R->tag);
  lac_free (R->index);
  lac_free (R->coord);
  lac_free (R->ent_tag);
  lac_free (R->ent_first);
  lac_free (R->slot);
}

/* Put the file name in front of the message a lac_mesh_* call stored. */
int
lac_gmsh_with_path (const lac_gmsh_reader *R, int status)
{
  if (!status)
    return status;
  return READ_ERR (status, "'%s': %s", R->path, lac_error_message ());
}

/* Set the message for a failed gmsh call, with gmsh's last error. */
int
lac_gmsh_fail (const lac_gmsh_reader *R, int status, const char *what)
{
  char *e = NULL;
  int ierr = 0;
  gmshLoggerGetLastError (&e, &ierr);
  status = READ_ERR (status, "'%s': %s: %s", R->path, what,
                     !ierr && e && *e ? e : "gmsh gives no details");
  gmshFree (e);
  return status;
}

/* ---------------------------------------------------------------------- */
/* node tags                                                               */
/* ---------------------------------------------------------------------- */

size_t
lac_gmsh_tag_position (const lac_gmsh_reader *R, size_t t)
{
  size_t lo = 0, hi = R->nall;
  while (lo < hi)
    {
      size_t mid = lo + (hi - lo) / 2;
      if (R->tag[mid] < t)
        lo = mid + 1;
      else
        hi = mid;
    }
  return lo < R->nall && R->tag[lo] == t ? lo : SIZE_MAX;
}

/* Mesh index of node tag t, or SIZE_MAX if it is in no cell. */
size_t
lac_gmsh_node_index (const lac_gmsh_reader *R, size_t t)
{
  size_t k = lac_gmsh_tag_position (R, t);
  return k == SIZE_MAX ? SIZE_MAX : R->index[k];
}

/* ---------------------------------------------------------------------- */
/* elements                                                                */
/* ---------------------------------------------------------------------- */

int
lac_gmsh_get_elements (const lac_gmsh_reader *R, lac_gmsh_elements *E,
                       int dim, int tag)
{
  int ierr = 0;
  memset (E, 0, sizeof *E);
  gmshModelMeshGetElements (&E->types, &E->ntypes, &E->etags, &E->etags_n,
                            &E->netags, &E->ntags, &E->ntags_n, &E->nntags,
                            dim, tag, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot get the elements");
  return LAC_SUCCESS;
}

void
lac_gmsh_elements_free (lac_gmsh_elements *E)
{
  for (size_t i = 0; i < E->netags; i++)
    gmshFree (E->etags[i]);
  for (size_t i = 0; i < E->nntags; i++)
    gmshFree (E->ntags[i]);
  gmshFree (E->types);
  gmshFree (E->etags);
  gmshFree (E->etags_n);
  gmshFree (E->ntags);
  gmshFree (E->ntags_n);
  memset (E, 0, sizeof *E);
}

/* The reference element of gmsh type t, or an error naming the file. */
const lac_refelem *
lac_gmsh_refelem (const lac_gmsh_reader *R, int t)
{
  const lac_refelem *re = lac_refelem_by_gmsh (t);
  if (!re)
    {
      char *name = NULL;
      int dim, order, nn, nv, ierr = 0;
      double *xi = NULL;
      size_t nxi = 0;
      gmshModelMeshGetElementProperties (t, &name, &dim, &order, &nn, &xi,
                                         &nxi, &nv, &ierr);
      READ_ERR (LAC_EINVAL, "'%s': gmsh element type %d (%s) is not "
                "supported", R->path, t, !ierr && name ? name : "unknown");
      gmshFree (name);
      gmshFree (xi);
    }
  return re;
}

