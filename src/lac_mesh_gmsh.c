/* lac_mesh_gmsh.c -- reading meshes through the gmsh C API          [LAC §2]
 *
 * lac_mesh_read opens a .msh file (formats 2.2 and 4.1) or a .geo file
 * (meshed here, options from lac_mesh_opts) with gmsh, copies nodes, cells
 * and physical groups into a lac_mesh, and finalizes gmsh: the mesh owes
 * nothing to gmsh afterwards.  This is the only place where gmsh tags
 * (1-based, not necessarily contiguous) become 0-based indices; node_tag
 * and cell_tag keep the tags for messages.
 *
 *   - cells are the elements of the top dimension; nodes that belong to no
 *     cell are dropped;
 *   - physical groups of the top dimension become cell groups (and set
 *     body[c]), groups of dimension top-1 become facet groups whose elements
 *     are matched to cell faces through a hash of their sorted vertices,
 *     lower dimensions become node groups; an unnamed group is "<dim>:<tag>";
 *   - the space dimension is 2 when the cells are 2D and every z is 0, and 3
 *     for 3D cells (2D cells out of the plane z = 0 are rejected);
 *   - inverted cells are flipped or rejected (opts->flip_inverted);
 *   - size, order, serendipity and recombine apply to .geo files only; a
 *     .msh file is read as it is.
 *
 * gmsh 4.8 notes (see the project's dependency notes): gmshOpen on a missing
 * file reports no error, so existence is checked first; the number `level'
 * reaches the .geo as a command-line "-setnumber level N" passed to
 * gmshInitialize (works with DefineConstant[] and with Exists()); such
 * numbers persist in the gmsh process, so level is always set, never left
 * over; Mesh.Algorithm 8 crashes gmsh 4.8 and is replaced by 6; a parse
 * error thrown as an exception poisons later parses (see open_file).
 */
#include "lac_mesh.h"

#include <gmshc.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lac_mem.h"
#include "lac_status.h"

enum { KIND_MSH, KIND_GEO };

/* Messages name the public function, whatever helper sets them. */
#define READ_ERR(status, ...) lac_error_set ((status), "lac_mesh_read", \
                                             __VA_ARGS__)

typedef struct face_slot
{
  int v[4];                    /* sorted vertices, -1 padded               */
  size_t cell;                 /* SIZE_MAX: empty slot                     */
  int face;
} face_slot;

/* Everything a read holds between gmsh calls; freed in one place. */
typedef struct reader
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
  face_slot *slot;             /* owned, hcap                              */
} reader;

static void
reader_free (reader *R)
{
  lac_free (R->tag);
  lac_free (R->index);
  lac_free (R->coord);
  lac_free (R->ent_tag);
  lac_free (R->ent_first);
  lac_free (R->slot);
}

/* Put the file name in front of the message a lac_mesh_* call stored. */
static int
with_path (const reader *R, int status)
{
  char msg[768];
  if (!status)
    return status;
  snprintf (msg, sizeof msg, "%s", lac_error_message ());
  return READ_ERR (status, "'%s': %s", R->path, msg);
}

/* Set the message for a failed gmsh call, with gmsh's last error. */
static int
gmsh_fail (const reader *R, int status, const char *what)
{
  char *e = NULL;
  int ierr = 0;
  gmshLoggerGetLastError (&e, &ierr);
  status = READ_ERR (status, "'%s': %s: %s", R->path, what,
                     !ierr && e && *e ? e : "gmsh gives no details");
  gmshFree (e);
  return status;
}

static int
set_option (const reader *R, const char *name, double value)
{
  int ierr = 0;
  gmshOptionSetNumber (name, value, &ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, name);
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* meshing a .geo                                                          */
/* ---------------------------------------------------------------------- */

/* Generate the mesh of the highest dimension with the options of opts. */
static int
mesh_geo (reader *R)
{
  const lac_mesh_opts *o = R->opts;
  double alg = 6;
  int ierr = 0, dim, status = LAC_SUCCESS;

  dim = gmshModelGetDimension (&ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, "cannot get the model dimension");
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
  if (status)
    return status;
  gmshModelMeshGenerate (dim, &ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, "meshing failed");
  if (o->order > 0)
    {
      gmshModelMeshSetOrder (o->order, &ierr);
      if (ierr)
        return gmsh_fail (R, LAC_EDEP, "cannot set the element order");
    }
  return LAC_SUCCESS;
}

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
static int
read_nodes (reader *R)
{
  size_t *tags = NULL, ntags = 0, ncoord = 0, npar = 0;
  double *coord = NULL, *par = NULL;
  tag_pos *tp = NULL;
  int ierr = 0, status = LAC_SUCCESS;

  gmshModelMeshGetNodes (&tags, &ntags, &coord, &ncoord, &par, &npar, -1, -1,
                         0, 0, &ierr);
  if (ierr)
    {
      status = gmsh_fail (R, LAC_EDEP, "cannot get the nodes");
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

/* Position of node tag t in the sorted list, or SIZE_MAX. */
static size_t
find_tag (const reader *R, size_t t)
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
static size_t
node_index (const reader *R, size_t t)
{
  size_t k = find_tag (R, t);
  return k == SIZE_MAX ? SIZE_MAX : R->index[k];
}

/* ---------------------------------------------------------------------- */
/* cells                                                                   */
/* ---------------------------------------------------------------------- */

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

/* Elements of one gmsh call (getElements), released together. */
typedef struct elements
{
  int *types;
  size_t ntypes;
  size_t **etags, *etags_n, netags;
  size_t **ntags, *ntags_n, nntags;
} elements;

static int
get_elements (const reader *R, elements *E, int dim, int tag)
{
  int ierr = 0;
  memset (E, 0, sizeof *E);
  gmshModelMeshGetElements (&E->types, &E->ntypes, &E->etags, &E->etags_n,
                            &E->netags, &E->ntags, &E->ntags_n, &E->nntags,
                            dim, tag, &ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, "cannot get the elements");
  return LAC_SUCCESS;
}

static void
elements_free (elements *E)
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
static const lac_refelem *
refelem_of (const reader *R, int t)
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


/* The highest dimension (3, 2 or 1) that has elements, 0 if none. */
static int
top_dimension (const reader *R, int *tdim)
{
  *tdim = 0;
  for (int d = 3; d >= 1 && !*tdim; d--)
    {
      elements E;
      int status = get_elements (R, &E, d, -1);
      if (status)
        return status;
      for (size_t i = 0; i < E.netags; i++)
        if (E.etags_n[i] > 0)
          *tdim = d;
      elements_free (&E);
    }
  return LAC_SUCCESS;
}

/* Space dimension: 3 for 3D cells; 2 for 2D cells whose nodes all have
 * z = 0 (to 1e-12 of the extent); 2D cells elsewhere are an error. */
static int
space_dim (const reader *R, int *dim)
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
count_cells (reader *R, const elements *E, size_t *ncells, size_t *nconn)
{
  *ncells = *nconn = 0;
  for (size_t e = 0; e < R->nent; e++)
    {
      R->ent_first[e] = *ncells;
      for (size_t i = 0; i < E[e].ntypes; i++)
        {
          const lac_refelem *re = refelem_of (R, E[e].types[i]);
          size_t ne = E[e].etags_n[i];
          if (!re)
            return LAC_EINVAL;
          if (re->dim != R->tdim || E[e].ntags_n[i] != ne * re->nnodes)
            return READ_ERR (LAC_EDEP, "'%s': gmsh gives %zu node tags for "
                             "%zu %s cells of a %dD mesh", R->path,
                             E[e].ntags_n[i], ne, re->name, R->tdim);
          for (size_t k = 0; k < E[e].ntags_n[i]; k++)
            {
              size_t pos = find_tag (R, E[e].ntags[i][k]);
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

/* Copy nodes (those in cells, numbered in tag order) and cells. */
static int
fill_mesh (reader *R, const elements *E, size_t ncells, size_t nconn,
           lac_mesh **out)
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
    return with_path (R, LAC_ENOMEM);
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
            for (size_t a = 0; a < (size_t) re->nnodes; a++, k++)
              m->conn[k] = (int) node_index (R, E[e].ntags[i][j * (size_t)
                                                              re->nnodes + a]);
            m->ptr[c + 1] = k;
          }
      }
  *out = m;
  return LAC_SUCCESS;
}

/* Cells: the elements of every top-dimension entity, entity by entity. */
static int
read_cells (reader *R, lac_mesh **out)
{
  int *dimtags = NULL, ierr = 0, status = LAC_SUCCESS;
  size_t ndt = 0, ncells = 0, nconn = 0;
  elements *E = NULL;

  gmshModelGetEntities (&dimtags, &ndt, R->tdim, &ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, "cannot get the entities");
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
      status = get_elements (R, &E[e], R->tdim, R->ent_tag[e]);
    }
  if (!status)
    status = count_cells (R, E, &ncells, &nconn);
  if (!status)
    status = fill_mesh (R, E, ncells, nconn, out);
done:
  for (size_t e = 0; E && e < R->nent; e++)
    elements_free (&E[e]);
  lac_free (E);
  gmshFree (dimtags);
  return status;
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

static face_slot *
face_lookup (const reader *R, const int *key)
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
build_faces (reader *R, const lac_mesh *m)
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
          face_slot *s;
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
entity_position (const reader *R, int tag)
{
  for (size_t e = 0; e < R->nent; e++)
    if (R->ent_tag[e] == tag)
      return e;
  return SIZE_MAX;
}

/* A group of cells; its cells get body[c] = the group if they have none. */
static int
add_cell_group (reader *R, lac_mesh *m, const char *name, int tag,
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
  status = with_path (R, lac_mesh_add_group (m, name, R->tdim, tag, n, cell,
                                             NULL));
  for (size_t i = 0; i < n && !status; i++)
    if (m->body[cell[i]] < 0)
      m->body[cell[i]] = (int) m->ngroups - 1;
  lac_free (cell);
  return status;
}

/* Match the boundary elements of one entity to cell faces. */
static int
match_facets (reader *R, const char *name, int ent, size_t **cell,
              int **face, size_t *n, size_t *cap)
{
  elements E;
  int status = get_elements (R, &E, R->tdim - 1, ent);
  for (size_t i = 0; i < E.ntypes && !status; i++)
    {
      const lac_refelem *fe = refelem_of (R, E.types[i]);
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
          face_slot *s = NULL;
          for (int a = 0; a < fe->nvertices; a++)
            v[a] = (int) node_index (R, E.ntags[i][j * fe->nnodes + a]);
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
  elements_free (&E);
  return status;
}

/* A group of boundary facets, each stored as (cell, local face). */
static int
add_facet_group (reader *R, lac_mesh *m, const char *name, int tag,
                 const int *ent, size_t nent)
{
  size_t *cell = NULL, n = 0, cap = 0;
  int *face = NULL, status = LAC_SUCCESS;

  if (!R->slot)
    status = build_faces (R, m);
  for (size_t i = 0; i < nent && !status; i++)
    status = match_facets (R, name, ent[i], &cell, &face, &n, &cap);
  if (!status)
    status = with_path (R, lac_mesh_add_group (m, name, R->tdim - 1, tag, n,
                                               cell, face));
  lac_free (cell);
  lac_free (face);
  return status;
}

/* A group that keeps nodes only (points; curves of a 3D mesh). */
static int
add_node_group (reader *R, lac_mesh *m, const char *name, int dim, int tag)
{
  size_t *tags = NULL, ntags = 0, nc = 0, *node = NULL;
  double *coord = NULL;
  int ierr = 0, status = LAC_SUCCESS;

  gmshModelMeshGetNodesForPhysicalGroup (dim, tag, &tags, &ntags, &coord, &nc,
                                         &ierr);
  if (ierr)
    status = gmsh_fail (R, LAC_EDEP, "cannot get the nodes of a group");
  else if (!(node = lac_malloc (ntags * sizeof *node)))
    status = READ_ERR (LAC_ENOMEM, "'%s': group '%s'", R->path, name);
  for (size_t i = 0; i < ntags && !status; i++)
    {
      node[i] = node_index (R, tags[i]);
      if (node[i] == SIZE_MAX)
        status = READ_ERR (LAC_EINVAL, "'%s': node %zu of group '%s' belongs "
                           "to no cell", R->path, tags[i], name);
    }
  if (!status)
    status = with_path (R, lac_mesh_add_node_group (m, name, dim, tag, ntags,
                                                    node));
  lac_free (node);
  gmshFree (tags);
  gmshFree (coord);
  return status;
}

/* One physical group: its name ("<dim>:<tag>" if unnamed) and entities. */
static int
read_group (reader *R, lac_mesh *m, int dim, int tag)
{
  char *gname = NULL, name[64];
  int *ent = NULL, ierr = 0, status;
  size_t nent = 0;

  gmshModelGetPhysicalName (dim, tag, &gname, &ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, "cannot get a physical name");
  gmshModelGetEntitiesForPhysicalGroup (dim, tag, &ent, &nent, &ierr);
  if (ierr)
    status = gmsh_fail (R, LAC_EDEP, "cannot get a physical group");
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

static int
read_groups (reader *R, lac_mesh *m)
{
  int *dimtags = NULL, ierr = 0, status = LAC_SUCCESS;
  size_t n = 0;

  gmshModelGetPhysicalGroups (&dimtags, &n, -1, &ierr);
  if (ierr)
    return gmsh_fail (R, LAC_EDEP, "cannot get the physical groups");
  for (size_t i = 0; i + 1 < n && !status; i += 2)
    status = read_group (R, m, dimtags[i], dimtags[i + 1]);
  gmshFree (dimtags);
  return status;
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
open_file (const reader *R, int kind)
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
    return gmsh_fail (R, LAC_EDEP, "cannot start the gmsh logger");
  gmshOpen (R->path, &ierr);
  gmshLoggerGet (&log, &nlog, &ierr_log);
  for (size_t i = 0; i < nlog && !first; i++)
    if (strncmp (log[i], "Error: ", 7) == 0)
      first = log[i] + 7;
  if (first)
    status = READ_ERR (LAC_EIO, "'%s': not a valid %s file: %s", R->path,
                       kind == KIND_GEO ? ".geo" : "mesh", first);
  else if (ierr || ierr_log)
    status = gmsh_fail (R, LAC_EIO, kind == KIND_GEO
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
read_model (reader *R, int kind, lac_mesh **out)
{
  int status;
  lac_mesh *m = NULL;

  status = set_option (R, "General.Terminal", 0);
  if (!status)
    status = set_option (R, "General.Verbosity", 1);   /* errors, logged */
  if (!status)
    status = open_file (R, kind);
  if (!status && kind == KIND_GEO)
    status = mesh_geo (R);
  if (!status)
    status = read_nodes (R);
  if (!status)
    status = top_dimension (R, &R->tdim);
  if (!status && R->tdim < 2)
    status = READ_ERR (LAC_EINVAL, "'%s': no 2D or 3D elements (expected a "
                       "mesh of surfaces or volumes)", R->path);
  if (!status)
    status = read_cells (R, &m);
  if (!status)
    status = with_path (R, lac_mesh_check_orientation (m,
                                                       R->opts->flip_inverted,
                                                       NULL));
  if (!status)
    status = read_groups (R, m);
  if (status)
    lac_mesh_free (m);
  else
    *out = m;
  return status;
}

/* lac_mesh_read: read a .msh (2.2, 4.1) or mesh a .geo through gmsh.
 *   [in]  path  the file; its extension says which
 *   [in]  opts  meshing options (NULL: all zero)
 *   [out] out   the mesh (caller frees), NULL on failure
 *   returns LAC_SUCCESS, LAC_EIO (missing or unreadable file), LAC_EINVAL
 *   (unsupported elements, inverted cells, groups that do not fit),
 *   LAC_EDEP (gmsh failed), LAC_ENOMEM */
int
lac_mesh_read (const char *path, const lac_mesh_opts *opts, lac_mesh **out)
{
  static const lac_mesh_opts none;
  reader R = { 0 };
  const char *ext;
  char a0[] = "lac", a1[] = "-setnumber", a2[] = "level", a3[32];
  char *argv[] = { a0, a1, a2, a3, NULL };
  FILE *f;
  int kind, ierr = 0, status;

  if (!out)
    return READ_ERR (LAC_EINVAL, "no output pointer");
  *out = NULL;
  if (!path)
    return READ_ERR (LAC_EINVAL, "no file name");
  ext = strrchr (path, '.');
  if (ext && strcmp (ext, ".geo") == 0)
    kind = KIND_GEO;
  else if (ext && strcmp (ext, ".msh") == 0)
    kind = KIND_MSH;
  else
    return READ_ERR (LAC_EINVAL, "'%s': expected a .msh or .geo file", path);
  f = fopen (path, "r");                 /* gmshOpen is silent if missing */
  if (!f)
    return READ_ERR (LAC_EIO, "cannot open '%s'", path);
  fclose (f);
  R.path = path;
  R.opts = opts ? opts : &none;
  /* "-setnumber level N" defines `level' for the .geo parser; gmsh keeps
   * such numbers for the whole process, so it is always given. */
  snprintf (a3, sizeof a3, "%d", R.opts->level);
  gmshInitialize (4, argv, 0, &ierr);
  if (ierr)
    status = READ_ERR (LAC_EDEP, "'%s': gmsh failed to initialize", path);
  else
    status = read_model (&R, kind, out);
  gmshFinalize (&ierr);
  if (ierr && !status)
    {
      lac_mesh_free (*out);
      *out = NULL;
      status = READ_ERR (LAC_EDEP, "'%s': gmsh failed to finalize", path);
    }
  reader_free (&R);
  return status;
}
