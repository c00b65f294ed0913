/* lac_mesh_gmsh_groups.c -- physical groups of a gmsh model     [LAC §2]
 *
 * The physical groups of the model, added to the lac_mesh built by
 * lac_mesh_gmsh_cells.c, for lac_mesh_read (lac_mesh_gmsh.c):
 *
 *   - groups of the top dimension become cell groups (and set body[c]);
 *   - groups of dimension top-1 become facet groups, stored as (cell, local
 *     face): their elements are matched to cell faces through a hash of
 *     their sorted vertices;
 *   - lower dimensions become node groups;
 *   - an unnamed group is "<dim>:<tag>".
 */
#include "io/lac_mesh_gmsh_groups.h"

#include <gmshc.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_mem.h"
#include "io/lac_mesh_gmsh_reader.h"
#include "base/lac_status.h"

/* Grow an array to hold at least `need' items. */
static int
grow (void **p, size_t *cap, size_t need, size_t size)
{
  size_t c = *cap ? *cap : 64;
  void *q;
  if (need <= *cap)
    return LAC_SUCCESS;
  while (c < need)
    c *= 2;
  q = lac_realloc (*p, c * size);
  if (!q)
    return READ_ERR (LAC_ENOMEM, "%zu items", need);
  *p = q;
  *cap = c;
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* faces                                                                   */
/* ---------------------------------------------------------------------- */

/* key = the nv vertices sorted, padded with -1. */
static void
face_key (const int *v, int nv, int *key)
{
  for (int i = 0; i < 4; i++)
    key[i] = i < nv ? v[i] : -1;
  for (int i = 1; i < nv; i++)
    for (int j = i; j > 0 && key[j - 1] > key[j]; j--)
      {
        int t = key[j];
        key[j] = key[j - 1];
        key[j - 1] = t;
      }
}

static lac_gmsh_face_slot *
face_lookup (const lac_gmsh_reader *R, const int *key)
{
  uint64_t h = 1469598103934665603ull;              /* FNV-1a */
  size_t i;
  for (int k = 0; k < 4; k++)
    {
      h ^= (uint64_t) (uint32_t) key[k];
      h *= 1099511628211ull;
    }
  h ^= h >> 29;
  for (i = (size_t) h & (R->hcap - 1);; i = (i + 1) & (R->hcap - 1))
    if (R->slot[i].cell == SIZE_MAX
        || memcmp (R->slot[i].v, key, sizeof R->slot[i].v) == 0)
      return &R->slot[i];
}

/* Hash every face of every cell by its sorted vertices (first cell wins
 * for interior faces). */
static int
build_faces (lac_gmsh_reader *R, const lac_mesh *m)
{
  size_t total = 0;
  for (size_t c = 0; c < m->ncells; c++)
    total += (size_t) lac_refelem_get (m->type[c])->nfaces;
  R->hcap = 16;
  while (R->hcap < 2 * total)
    R->hcap *= 2;
  R->slot = lac_malloc (R->hcap * sizeof *R->slot);
  if (!R->slot)
    return READ_ERR (LAC_ENOMEM, "'%s': table of %zu faces", R->path, total);
  for (size_t i = 0; i < R->hcap; i++)
    R->slot[i].cell = SIZE_MAX;
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      for (int f = 0; f < re->nfaces; f++)
        {
          int v[4], key[4];
          int nv = lac_refelem_get (re->face_type[f])->nvertices;
          lac_gmsh_face_slot *s;
          for (int i = 0; i < nv; i++)
            v[i] = m->conn[m->ptr[c] + (size_t) re->face_node[f][i]];
          face_key (v, nv, key);
          s = face_lookup (R, key);
          if (s->cell == SIZE_MAX)
            {
              memcpy (s->v, key, sizeof s->v);
              s->cell = c;
              s->face = f;
            }
        }
    }
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* physical groups                                                         */
/* ---------------------------------------------------------------------- */

static size_t
entity_position (const lac_gmsh_reader *R, int tag)
{
  for (size_t e = 0; e < R->nent; e++)
    if (R->ent_tag[e] == tag)
      return e;
  return SIZE_MAX;
}

/* A group of cells; its cells get body[c] = the group if they have none. */
static int
add_cell_group (lac_gmsh_reader *R, lac_mesh *m, const char *name, int tag,
                const int *ent, size_t nent)
{
  size_t n = 0, *cell = lac_malloc (m->ncells * sizeof *cell);
  int status;
  if (!cell)
    return READ_ERR (LAC_ENOMEM, "'%s': group '%s'", R->path, name);
  for (size_t i = 0; i < nent; i++)
    {
      size_t e = entity_position (R, ent[i]);
      if (e == SIZE_MAX)
        continue;                      /* an entity without elements */
      for (size_t c = R->ent_first[e];
           c < R->ent_first[e + 1] && n < m->ncells; c++)
        cell[n++] = c;
    }
  status = lac_gmsh_with_path (R, lac_mesh_add_group (m, name, R->tdim, tag,
                                                      n, cell, NULL));
  for (size_t i = 0; i < n && !status; i++)
    if (m->body[cell[i]] < 0)
      m->body[cell[i]] = (int) m->ngroups - 1;
  lac_free (cell);
  return status;
}

/* Match the boundary elements of one entity to cell faces. */
static int
match_facets (lac_gmsh_reader *R, const char *name, int ent, size_t **cell,
              int **face, size_t *n, size_t *cap)
{
  lac_gmsh_elements E;
  int status = lac_gmsh_get_elements (R, &E, R->tdim - 1, ent);
  for (size_t i = 0; i < E.ntypes && !status; i++)
    {
      const lac_refelem *fe = lac_gmsh_refelem (R, E.types[i]);
      size_t ne = E.etags_n[i], cap2 = *cap;
      if (!fe || fe->dim != R->tdim - 1)
        {
          status = fe ? READ_ERR (LAC_EINVAL, "'%s': group '%s' holds %s "
                                  "elements, not faces of %dD cells",
                                  R->path, name, fe->name, R->tdim)
                      : LAC_EINVAL;
          break;
        }
      status = grow ((void **) cell, cap, *n + ne, sizeof **cell);
      if (!status)
        status = grow ((void **) face, &cap2, *n + ne, sizeof **face);
      for (size_t j = 0; j < ne && !status; j++)
        {
          int v[4], key[4];
          lac_gmsh_face_slot *s = NULL;
          for (int a = 0; a < fe->nvertices; a++)
            v[a] = (int) lac_gmsh_node_index (R, E.ntags[i][j * fe->nnodes
                                                            + a]);
          face_key (v, fe->nvertices, key);
          if (key[0] >= 0)             /* SIZE_MAX -> -1: node in no cell */
            s = face_lookup (R, key);
          if (!s || s->cell == SIZE_MAX)
            status = READ_ERR (LAC_EINVAL, "'%s': element %zu (%s) of group "
                               "'%s' is not a face of any cell", R->path,
                               E.etags[i][j], fe->name, name);
          else
            {
              (*cell)[*n] = s->cell;
              (*face)[(*n)++] = s->face;
            }
        }
    }
  lac_gmsh_elements_free (&E);
  return status;
}

/* A group of boundary facets, each stored as (cell, local face). */
static int
add_facet_group (lac_gmsh_reader *R, lac_mesh *m, const char *name, int tag,
                 const int *ent, size_t nent)
{
  size_t *cell = NULL, n = 0, cap = 0;
  int *face = NULL, status = LAC_SUCCESS;

  if (!R->slot)
    status = build_faces (R, m);
  for (size_t i = 0; i < nent && !status; i++)
    status = match_facets (R, name, ent[i], &cell, &face, &n, &cap);
  if (!status)
    status = lac_gmsh_with_path (R, lac_mesh_add_group (m, name, R->tdim - 1,
                                                        tag, n, cell, face));
  lac_free (cell);
  lac_free (face);
  return status;
}

/* A group that keeps nodes only (points; curves of a 3D mesh). */
static int
add_node_group (lac_gmsh_reader *R, lac_mesh *m, const char *name, int dim,
                int tag)
{
  size_t *tags = NULL, ntags = 0, nc = 0, *node = NULL;
  double *coord = NULL;
  int ierr = 0, status = LAC_SUCCESS;

  gmshModelMeshGetNodesForPhysicalGroup (dim, tag, &tags, &ntags, &coord, &nc,
                                         &ierr);
  if (ierr)
    status = lac_gmsh_fail (R, LAC_EDEP, "cannot get the nodes of a group");
  else if (!(node = lac_malloc (ntags * sizeof *node)))
    status = READ_ERR (LAC_ENOMEM, "'%s': group '%s'", R->path, name);
  for (size_t i = 0; i < ntags && !status; i++)
    {
      node[i] = lac_gmsh_node_index (R, tags[i]);
      if (node[i] == SIZE_MAX)
        status = READ_ERR (LAC_EINVAL, "'%s': node %zu of group '%s' belongs "
                           "to no cell", R->path, tags[i], name);
    }
  if (!status)
    status = lac_gmsh_with_path (R, lac_mesh_add_node_group (m, name, dim,
                                                             tag, ntags,
                                                             node));
  lac_free (node);
  gmshFree (tags);
  gmshFree (coord);
  return status;
}

/* One physical group: its name ("<dim>:<tag>" if unnamed) and entities. */
static int
read_group (lac_gmsh_reader *R, lac_mesh *m, int dim, int tag)
{
  char *gname = NULL, name[64];
  int *ent = NULL, ierr = 0, status;
  size_t nent = 0;

  gmshModelGetPhysicalName (dim, tag, &gname, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot get a physical name");
  gmshModelGetEntitiesForPhysicalGroup (dim, tag, &ent, &nent, &ierr);
  if (ierr)
    status = lac_gmsh_fail (R, LAC_EDEP, "cannot get a physical group");
  else
    {
      const char *nm = gname && *gname ? gname : name;
      snprintf (name, sizeof name, "%d:%d", dim, tag);
      if (dim == R->tdim)
        status = add_cell_group (R, m, nm, tag, ent, nent);
      else if (dim == R->tdim - 1)
        status = add_facet_group (R, m, nm, tag, ent, nent);
      else if (dim < R->tdim - 1)
        status = add_node_group (R, m, nm, dim, tag);
      else
        status = READ_ERR (LAC_EINVAL, "'%s': physical group '%s' has "
                           "dimension %d but the elements only %d", R->path,
                           nm, dim, R->tdim);
    }
  gmshFree (gname);
  gmshFree (ent);
  return status;
}

int
lac_gmsh_read_groups (lac_gmsh_reader *R, lac_mesh *m)
{
  int *dimtags = NULL, ierr = 0, status = LAC_SUCCESS;
  size_t n = 0;

  gmshModelGetPhysicalGroups (&dimtags, &n, -1, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot get the physical groups");
  for (size_t i = 0; i + 1 < n && !status; i += 2)
    status = read_group (R, m, dimtags[i], dimtags[i + 1]);
  gmshFree (dimtags);
  return status;
}
