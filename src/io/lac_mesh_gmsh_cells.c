/* lac_mesh_gmsh_cells.c -- nodes and cells of a gmsh model      [LAC §2]
 *
 * The conversion of gmsh nodes and cells into a lac_mesh, for lac_mesh_read
 * (lac_mesh_gmsh.c).  This is where gmsh tags (1-based, not necessarily
 * contiguous) become 0-based indices: all nodes are sorted by tag, those
 * that belong to no cell are dropped (counted, except the nodes of
 * construction points of a .geo), the others are numbered in tag order;
 * node_tag and cell_tag keep the tags for messages.
 *
 *   - cells are the elements of the top dimension, entity by entity (the
 *     entities are kept for the cell groups, lac_mesh_gmsh_groups.c);
 *   - the space dimension is 2 when the cells are 2D and every z is 0, and 3
 *     for 3D cells (2D cells out of the plane z = 0 are rejected).
 */
#include "io/lac_mesh_gmsh_cells.h"

#include <gmshc.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_mem.h"
#include "io/lac_mesh_gmsh_reader.h"
#include "base/lac_status.h"

/* ---------------------------------------------------------------------- */
/* nodes                                                                   */
/* ---------------------------------------------------------------------- */

typedef struct tag_pos
{
  size_t tag, pos;
} tag_pos;

static int
cmp_tag_pos (const void *a, const void *b)
{
  size_t x = ((const tag_pos *) a)->tag, y = ((const tag_pos *) b)->tag;
  return (x > y) - (x < y);
}

/* All nodes of the model, sorted by tag (tags need not be contiguous). */
int
lac_gmsh_read_nodes (lac_gmsh_reader *R)
{
  size_t *tags = NULL, ntags = 0, ncoord = 0, npar = 0;
  double *coord = NULL, *par = NULL;
  tag_pos *tp = NULL;
  int ierr = 0, status = LAC_SUCCESS;

  gmshModelMeshGetNodes (&tags, &ntags, &coord, &ncoord, &par, &npar, -1, -1,
                         0, 0, &ierr);
  if (ierr)
    {
      status = lac_gmsh_fail (R, LAC_EDEP, "cannot get the nodes");
      goto done;
    }
  if (ncoord != 3 * ntags)
    {
      status = READ_ERR (LAC_EDEP, "'%s': gmsh gives %zu coordinates for "
                         "%zu nodes", R->path, ncoord, ntags);
      goto done;
    }
  R->nall = ntags;
  tp = lac_malloc (ntags * sizeof *tp);
  R->tag = lac_malloc (ntags * sizeof *R->tag);
  R->index = lac_malloc (ntags * sizeof *R->index);
  R->coord = lac_malloc (3 * ntags * sizeof *R->coord);
  if (!tp || !R->tag || !R->index || !R->coord)
    {
      status = READ_ERR (LAC_ENOMEM, "'%s': %zu nodes", R->path, ntags);
      goto done;
    }
  for (size_t k = 0; k < ntags; k++)
    {
      tp[k].tag = tags[k];
      tp[k].pos = k;
    }
  qsort (tp, ntags, sizeof *tp, cmp_tag_pos);
  for (size_t k = 0; k < ntags; k++)
    {
      if (k > 0 && tp[k].tag == tp[k - 1].tag)
        {
          status = READ_ERR (LAC_EINVAL, "'%s': node tag %zu appears twice",
                             R->path, tp[k].tag);
          goto done;
        }
      R->tag[k] = tp[k].tag;
      R->index[k] = SIZE_MAX;
      memcpy (R->coord + 3 * k, coord + 3 * tp[k].pos, 3 * sizeof *coord);
    }
done:
  lac_free (tp);
  gmshFree (tags);
  gmshFree (coord);
  gmshFree (par);
  return status;
}

/* ---------------------------------------------------------------------- */
/* cells                                                                   */
/* ---------------------------------------------------------------------- */

/* The highest dimension (3, 2 or 1) that has elements, 0 if none. */
int
lac_gmsh_top_dimension (const lac_gmsh_reader *R, int *tdim)
{
  *tdim = 0;
  for (int d = 3; d >= 1 && !*tdim; d--)
    {
      lac_gmsh_elements E;
      int status = lac_gmsh_get_elements (R, &E, d, -1);
      if (status)
        return status;
      for (size_t i = 0; i < E.netags; i++)
        if (E.etags_n[i] > 0)
          *tdim = d;
      lac_gmsh_elements_free (&E);
    }
  return LAC_SUCCESS;
}

/* Space dimension: 3 for 3D cells; 2 for 2D cells whose nodes all have
 * z = 0 (to 1e-12 of the extent); 2D cells elsewhere are an error. */
static int
space_dim (const lac_gmsh_reader *R, int *dim)
{
  double ext = 0;
  *dim = R->tdim;
  if (R->tdim == 3)
    return LAC_SUCCESS;
  for (size_t k = 0; k < R->nall; k++)
    if (R->index[k] != SIZE_MAX)
      ext = fmax (ext, fmax (fabs (R->coord[3 * k]),
                             fabs (R->coord[3 * k + 1])));
  for (size_t k = 0; k < R->nall; k++)
    if (R->index[k] != SIZE_MAX && fabs (R->coord[3 * k + 2]) > 1e-12 * ext)
      return READ_ERR (LAC_EINVAL, "'%s': 2D cells off the plane z = 0 (node "
                       "%zu has z = %g); lac reads plane meshes in the xy "
                       "plane or 3D meshes", R->path, R->tag[k],
                       R->coord[3 * k + 2]);
  return LAC_SUCCESS;
}

/* Count the cells of the entities, check their types, mark used nodes. */
static int
count_cells (lac_gmsh_reader *R, const lac_gmsh_elements *E, size_t *ncells,
             size_t *nconn)
{
  *ncells = *nconn = 0;
  for (size_t e = 0; e < R->nent; e++)
    {
      R->ent_first[e] = *ncells;
      for (size_t i = 0; i < E[e].ntypes; i++)
        {
          const lac_refelem *re = lac_gmsh_refelem (R, E[e].types[i]);
          size_t ne = E[e].etags_n[i];
          if (!re)
            return LAC_EINVAL;
          if (re->dim != R->tdim || E[e].ntags_n[i] != ne * re->nnodes)
            return READ_ERR (LAC_EDEP, "'%s': gmsh gives %zu node tags for "
                             "%zu %s cells of a %dD mesh", R->path,
                             E[e].ntags_n[i], ne, re->name, R->tdim);
          for (size_t k = 0; k < E[e].ntags_n[i]; k++)
            {
              size_t pos = lac_gmsh_tag_position (R, E[e].ntags[i][k]);
              if (pos == SIZE_MAX)
                return READ_ERR (LAC_EINVAL, "'%s': element %zu has node "
                                 "%zu, which is not in the mesh", R->path,
                                 E[e].etags[i][k / re->nnodes],
                                 E[e].ntags[i][k]);
              R->index[pos] = 0;                   /* used */
            }
          *ncells += ne;
          *nconn += E[e].ntags_n[i];
        }
    }
  R->ent_first[R->nent] = *ncells;
  if (*ncells == 0)
    return READ_ERR (LAC_EINVAL, "'%s': no %dD elements", R->path, R->tdim);
  return LAC_SUCCESS;
}

/* The nodes of construction points: points of the geometry that no curve
 * starts or ends at and no physical group names (the centre of a
 * Circle), in a .geo (a node of a .msh file in no cell is suspect).
 * gmsh meshes them as nodes of their own, in no cell; they are
 * left out with the other nodes in no cell, but not counted as dropped
 * (ndropped warns of nodes that a cell was meant to use). */
static size_t
construction_nodes (void)
{
  int *dt = NULL, ierr = 0;
  size_t ndt = 0, count = 0;
  gmshModelGetEntities (&dt, &ndt, 0, &ierr);
  for (size_t k = 0; !ierr && k + 1 < ndt; k += 2)
    {
      int *up = NULL, *down = NULL, *phys = NULL, e1 = 0, e2 = 0, e3 = 0;
      size_t nup = 0, ndown = 0, nphys = 0, *tags = NULL, ntags = 0;
      double *coord = NULL, *par = NULL;
      size_t ncoord = 0, npar = 0;
      gmshModelGetAdjacencies (0, dt[k + 1], &up, &nup, &down, &ndown, &e1);
      gmshModelGetPhysicalGroupsForEntity (0, dt[k + 1], &phys, &nphys, &e2);
      if (!e1 && !e2 && nup == 0 && nphys == 0)
        {
          gmshModelMeshGetNodes (&tags, &ntags, &coord, &ncoord, &par, &npar,
                                 0, dt[k + 1], 0, 0, &e3);
          count += e3 ? 0 : ntags;
        }
      gmshFree (up);
      gmshFree (down);
      gmshFree (phys);
      gmshFree (tags);
      gmshFree (coord);
      gmshFree (par);
    }
  gmshFree (dt);
  return count;
}

/* Copy nodes (those in cells, numbered in tag order) and cells. */
static int
fill_mesh (lac_gmsh_reader *R, const lac_gmsh_elements *E, size_t ncells,
           size_t nconn, lac_mesh **out)
{
  size_t nnodes = 0, c = 0, k = 0;
  int dim, status;
  lac_mesh *m;

  for (size_t i = 0; i < R->nall; i++)
    if (R->index[i] != SIZE_MAX)
      R->index[i] = nnodes++;                 /* 0-based mesh index */
  status = space_dim (R, &dim);
  if (status)
    return status;
  m = lac_mesh_alloc (dim, nnodes, ncells, nconn);
  if (!m)
    return lac_gmsh_with_path (R, LAC_ENOMEM);
  m->ndropped = R->nall - nnodes;
  {
    size_t built = R->geometry ? construction_nodes () : 0;
    m->ndropped -= built < m->ndropped ? built : m->ndropped;
  }
  for (size_t i = 0; i < R->nall; i++)
    if (R->index[i] != SIZE_MAX)
      {
        memcpy (m->x + R->index[i] * (size_t) dim, R->coord + 3 * i,
                (size_t) dim * sizeof *m->x);
        m->node_tag[R->index[i]] = R->tag[i];
      }
  for (size_t e = 0; e < R->nent; e++)
    for (size_t i = 0; i < E[e].ntypes; i++)
      {
        const lac_refelem *re = lac_refelem_by_gmsh (E[e].types[i]);
        for (size_t j = 0; j < E[e].etags_n[i]; j++, c++)
          {
            m->type[c] = re->type;
            m->cell_tag[c] = E[e].etags[i][j];
            const size_t *nt = E[e].ntags[i] + j * (size_t) re->nnodes;
            for (size_t a = 0; a < (size_t) re->nnodes; a++, k++)
              m->conn[k] = (int) lac_gmsh_node_index (R, nt[a]);
            m->ptr[c + 1] = k;
          }
      }
  *out = m;
  return LAC_SUCCESS;
}

/* Cells: the elements of every top-dimension entity, entity by entity. */
int
lac_gmsh_read_cells (lac_gmsh_reader *R, lac_mesh **out)
{
  int *dimtags = NULL, ierr = 0, status = LAC_SUCCESS;
  size_t ndt = 0, ncells = 0, nconn = 0;
  lac_gmsh_elements *E = NULL;

  gmshModelGetEntities (&dimtags, &ndt, R->tdim, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot get the entities");
  R->nent = ndt / 2;
  E = lac_calloc (R->nent, sizeof *E);
  R->ent_tag = lac_malloc (R->nent * sizeof *R->ent_tag);
  R->ent_first = lac_malloc ((R->nent + 1) * sizeof *R->ent_first);
  if (!E || !R->ent_tag || !R->ent_first)
    {
      status = READ_ERR (LAC_ENOMEM, "'%s': %zu entities", R->path, R->nent);
      goto done;
    }
  for (size_t e = 0; e < R->nent && !status; e++)
    {
      R->ent_tag[e] = dimtags[2 * e + 1];
      status = lac_gmsh_get_elements (R, &E[e], R->tdim, R->ent_tag[e]);
    }
  if (!status)
    status = count_cells (R, E, &ncells, &nconn);
  if (!status)
    status = fill_mesh (R, E, ncells, nconn, out);
done:
  for (size_t e = 0; E && e < R->nent; e++)
    lac_gmsh_elements_free (&E[e]);
  lac_free (E);
  gmshFree (dimtags);
  return status;
}
