/* lac_mesh.c -- meshes: storage, queries, groups, two bodies in one mesh
 *                                                          [LAC §2, §3.1]
 *
 * The mesh is plain data (lac_mesh.h).  This file builds and queries it:
 * allocation, physical groups (their node lists come from the faces of the
 * reference elements in lac_spaces.h), the merge of two meshes into one.
 * The measure of the domain and the sign of det J in every cell are in
 * lac_mesh_jacobian.c, structured box meshes in lac_mesh_box.c, reading
 * through gmsh in lac_mesh_gmsh.c.
 */
#include "fem/lac_mesh.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

/* ---------------------------------------------------------------------- */
/* construct / destroy                                                     */
/* ---------------------------------------------------------------------- */

/* lac_mesh_alloc: a mesh of nnodes nodes and ncells cells with room for
 * nconn connectivity entries.  Coordinates and conn are zero, ptr[0] = 0,
 * tags are 1-based positions, body[c] = -1, types LAC_ELEM_NONE, no groups.
 * Returns NULL with a message on failure. */
lac_mesh *
lac_mesh_alloc (int dim, size_t nnodes, size_t ncells, size_t nconn)
{
  lac_mesh *m;

  if (dim != 2 && dim != 3)
    LAC_ERROR_NULL (LAC_EINVAL, "space dimension %d, expected 2 or 3", dim);
  if (nnodes > (size_t) INT_MAX)
    LAC_ERROR_NULL (LAC_EINVAL, "%zu nodes: more than INT_MAX", nnodes);
  m = lac_calloc (1, sizeof *m);
  if (!m)
    LAC_ERROR_NULL (LAC_ENOMEM, "cannot allocate a mesh");
  m->dim = dim;
  m->nnodes = nnodes;
  m->ncells = ncells;
  m->x = lac_calloc (nnodes * (size_t) dim, sizeof *m->x);
  m->node_tag = lac_malloc (nnodes * sizeof *m->node_tag);
  m->type = lac_malloc (ncells * sizeof *m->type);
  m->ptr = lac_calloc (ncells + 1, sizeof *m->ptr);
  m->conn = lac_calloc (nconn, sizeof *m->conn);
  m->cell_tag = lac_malloc (ncells * sizeof *m->cell_tag);
  m->body = lac_malloc (ncells * sizeof *m->body);
  if (!m->x || !m->node_tag || !m->type || !m->ptr || !m->conn
      || !m->cell_tag || !m->body)
    {
      lac_mesh_free (m);
      LAC_ERROR_NULL (LAC_ENOMEM, "cannot allocate a mesh of %zu nodes and "
                      "%zu cells", nnodes, ncells);
    }
  for (size_t i = 0; i < nnodes; i++)
    m->node_tag[i] = i + 1;
  for (size_t c = 0; c < ncells; c++)
    {
      m->type[c] = LAC_ELEM_NONE;
      m->cell_tag[c] = c + 1;
      m->body[c] = -1;
    }
  return m;
}

static void
group_clear (lac_group *g)
{
  lac_free (g->name);
  lac_free (g->cell);
  lac_free (g->face);
  lac_free (g->node);
  memset (g, 0, sizeof *g);
}

void
lac_mesh_free (lac_mesh *m)
{
  if (!m)
    return;
  for (size_t g = 0; g < m->ngroups; g++)
    group_clear (&m->group[g]);
  lac_free (m->group);
  lac_free (m->x);
  lac_free (m->node_tag);
  lac_free (m->type);
  lac_free (m->ptr);
  lac_free (m->conn);
  lac_free (m->cell_tag);
  lac_free (m->body);
  lac_free (m);
}

/* ---------------------------------------------------------------------- */
/* query                                                                   */
/* ---------------------------------------------------------------------- */

/* lac_mesh_group: the group called `name', or NULL (with a message listing
 * the groups of the mesh). */
const lac_group *
lac_mesh_group (const lac_mesh *m, const char *name)
{
  char list[256] = "";
  size_t len = 0;

  if (!m || !name)
    LAC_ERROR_NULL (LAC_EINVAL, "no mesh or no group name");
  for (size_t g = 0; g < m->ngroups; g++)
    if (strcmp (m->group[g].name, name) == 0)
      return &m->group[g];
  for (size_t g = 0; g < m->ngroups && len + 8 < sizeof list; g++)
    {
      int k = snprintf (list + len, sizeof list - len, "%s'%s'",
                        g ? ", " : "", m->group[g].name);
      if (k < 0)
        break;
      len += (size_t) k;
    }
  if (len >= sizeof list)
    strcpy (list + sizeof list - 5, "...");
  LAC_ERROR_NULL (LAC_EINVAL, "no group named '%s' in the mesh (groups: %s)",
                  name, m->ngroups ? list : "none");
}

/* lac_mesh_facet_nodes: the global nodes of local face `face' of cell
 * `cell', in the face element's node order, oriented outward.
 *   [out] nodes  at least LAC_MAX_FACE_NODES entries
 *   [out] ftype  face element type (may be NULL)
 *   returns the number of nodes, or -LAC_EINVAL (message set) */
int
lac_mesh_facet_nodes (const lac_mesh *m, size_t cell, int face, int *nodes,
                      lac_elem_type *ftype)
{
  const lac_refelem *re, *fe;

  if (!m || cell >= m->ncells)
    return -LAC_ERRMSG (LAC_EINVAL, "cell %zu out of range", cell);
  re = lac_refelem_get (m->type[cell]);
  if (!re || face < 0 || face >= re->nfaces)
    return -LAC_ERRMSG (LAC_EINVAL, "cell %zu (tag %zu) has no face %d", cell,
                        m->cell_tag[cell], face);
  fe = lac_refelem_get (re->face_type[face]);
  if (!fe)
    return -LAC_ERRMSG (LAC_ESANITY, "face %d of a %s has no type", face,
                        re->name);
  for (int i = 0; i < fe->nnodes; i++)
    nodes[i] = m->conn[m->ptr[cell] + (size_t) re->face_node[face][i]];
  if (ftype)
    *ftype = fe->type;
  return fe->nnodes;
}

/* xe = coordinates of the nodes of cell c, node by node (nnodes*dim). */
void
lac_mesh_cell_coords (const lac_mesh *m, size_t c, double *xe)
{
  size_t d = (size_t) m->dim;
  for (size_t k = m->ptr[c]; k < m->ptr[c + 1]; k++)
    for (size_t i = 0; i < d; i++)
      *xe++ = m->x[(size_t) m->conn[k] * d + i];
}

/* dofs[a*dim + i] = dim*conn[a] + i: the global dofs of cell c, node by
 * node; returns their number. */
int
lac_mesh_cell_dofs (const lac_mesh *m, size_t c, size_t *dofs)
{
  int nen = (int) (m->ptr[c + 1] - m->ptr[c]);
  for (int a = 0; a < nen; a++)
    for (int i = 0; i < m->dim; i++)
      dofs[a * m->dim + i] = (size_t) m->dim * (size_t) m->conn[m->ptr[c] + a]
                             + (size_t) i;
  return nen * m->dim;
}

/* The largest number of nodes of one cell. */
size_t
lac_mesh_nconn_max (const lac_mesh *m)
{
  size_t nmax = 0;
  for (size_t c = 0; c < m->ncells; c++)
    if (m->ptr[c + 1] - m->ptr[c] > nmax)
      nmax = m->ptr[c + 1] - m->ptr[c];
  return nmax;
}

/* ---------------------------------------------------------------------- */
/* groups                                                                  */
/* ---------------------------------------------------------------------- */

static int
cmp_size (const void *a, const void *b)
{
  size_t x = *(const size_t *) a, y = *(const size_t *) b;
  return (x > y) - (x < y);
}

/* Sort and remove duplicates in place; returns the new length. */
static size_t
sort_unique (size_t *v, size_t n)
{
  size_t k = 0;
  if (n == 0)
    return 0;
  qsort (v, n, sizeof *v, cmp_size);
  for (size_t i = 1; i < n; i++)
    if (v[i] != v[k])
      v[++k] = v[i];
  return k + 1;
}

/* lac_mesh_group_nodes: node list of group g = the sorted, unique nodes of
 * its cells (cell group) or of its facets (facet group); a node-only group
 * (dim < mesh dim - 1) just has its list sorted. */
int
lac_mesh_group_nodes (lac_mesh *m, size_t g)
{
  lac_group *G;
  unsigned char *mark;
  size_t count = 0, *node;
  int fn[LAC_MAX_FACE_NODES];

  if (!m || g >= m->ngroups)
    LAC_ERROR (LAC_EINVAL, "group %zu out of range", g);
  G = &m->group[g];
  if (G->dim < m->dim - 1)
    {
      G->nnodes = sort_unique (G->node, G->nnodes);
      return LAC_SUCCESS;
    }
  mark = lac_calloc (m->nnodes, 1);
  if (!mark)
    LAC_ERROR (LAC_ENOMEM, "node marks for group '%s'", G->name);
  for (size_t e = 0; e < G->n; e++)
    {
      size_t c = G->cell[e];
      if (G->dim == m->dim)
        for (size_t k = m->ptr[c]; k < m->ptr[c + 1]; k++)
          mark[m->conn[k]] = 1;
      else
        {
          int nf = lac_mesh_facet_nodes (m, c, G->face[e], fn, NULL);
          if (nf < 0)
            {
              lac_free (mark);
              return -nf;
            }
          for (int i = 0; i < nf; i++)
            mark[fn[i]] = 1;
        }
    }
  for (size_t i = 0; i < m->nnodes; i++)
    count += mark[i];
  node = lac_malloc (count * sizeof *node);
  if (!node)
    {
      lac_free (mark);
      LAC_ERROR (LAC_ENOMEM, "%zu nodes of group '%s'", count, G->name);
    }
  count = 0;
  for (size_t i = 0; i < m->nnodes; i++)
    if (mark[i])
      node[count++] = i;
  lac_free (mark);
  lac_free (G->node);
  G->node = node;
  G->nnodes = count;
  return LAC_SUCCESS;
}

static void
group_pop (lac_mesh *m)
{
  group_clear (&m->group[--m->ngroups]);
}

/* Append a group named `name' (copied; checks the name is new) with room
 * for n nodes (nodes_only) or n cells and faces, still empty: *out. */
static int
group_push (lac_mesh *m, const char *name, int dim, int tag, size_t n,
            int nodes_only, lac_group **out)
{
  lac_group *grp, *G;

  if (!m || !name || !*name)
    LAC_ERROR (LAC_EINVAL, "no mesh or empty group name");
  if (dim < 0 || dim > m->dim)
    LAC_ERROR (LAC_EINVAL, "group '%s': dimension %d in a %dD mesh", name, dim,
               m->dim);
  for (size_t g = 0; g < m->ngroups; g++)
    if (strcmp (m->group[g].name, name) == 0)
      LAC_ERROR (LAC_EINVAL, "two groups named '%s'", name);
  grp = lac_realloc (m->group, (m->ngroups + 1) * sizeof *grp);
  if (!grp)
    LAC_ERROR (LAC_ENOMEM, "group '%s'", name);
  m->group = grp;
  G = &grp[m->ngroups];
  memset (G, 0, sizeof *G);
  G->name = lac_strdup (name);
  if (!G->name)
    LAC_ERROR (LAC_ENOMEM, "group name '%s'", name);
  G->dim = dim;
  G->tag = tag;
  m->ngroups++;
  if (nodes_only)
    G->node = lac_malloc (n * sizeof *G->node);
  else
    {
      G->cell = lac_malloc (n * sizeof *G->cell);
      G->face = lac_malloc (n * sizeof *G->face);
    }
  if (nodes_only ? !G->node : !G->cell || !G->face)
    {
      group_pop (m);
      LAC_ERROR (LAC_ENOMEM, "%sgroup '%s' of %zu %s", nodes_only ? "node "
                 : "", name, n, nodes_only ? "nodes" : "entities");
    }
  *out = G;
  return LAC_SUCCESS;
}

/* lac_mesh_add_group: add a cell group (dim == mesh dim; face may be NULL)
 * or a facet group (dim == mesh dim - 1; face[e] is the local face of
 * cell[e]).  Copies name, cell and face, and computes the node list. */
int
lac_mesh_add_group (lac_mesh *m, const char *name, int dim, int tag,
                    size_t n, const size_t *cell, const int *face)
{
  lac_group *G;
  int status;

  if (m && (dim < m->dim - 1 || dim > m->dim))
    LAC_ERROR (LAC_EINVAL, "group '%s' of dimension %d: a %dD mesh keeps "
               "cells (dim %d) or facets (dim %d); use "
               "lac_mesh_add_node_group", name ? name : "?", dim, m->dim,
               m->dim, m->dim - 1);
  if (m && n > 0 && (!cell || (dim == m->dim - 1 && !face)))
    LAC_ERROR (LAC_EINVAL, "group '%s': no cells or faces given",
               name ? name : "?");
  if ((status = group_push (m, name, dim, tag, n, 0, &G)))
    return status;
  for (size_t e = 0; e < n; e++)
    {
      const lac_refelem *re = cell[e] < m->ncells
                              ? lac_refelem_get (m->type[cell[e]]) : NULL;
      int f = dim == m->dim ? -1 : face[e];
      if (!re || (f >= 0 ? f >= re->nfaces : dim != m->dim))
        {
          group_pop (m);
          LAC_ERROR (LAC_EINVAL, "group '%s': entity %zu is cell %zu, "
                     "face %d, which does not exist", name, e, cell[e], f);
        }
      G->cell[e] = cell[e];
      G->face[e] = f;
    }
  G->n = n;
  status = lac_mesh_group_nodes (m, m->ngroups - 1);
  if (status)
    group_pop (m);
  return status;
}

/* lac_mesh_add_node_group: add a group that keeps only nodes (points, or
 * edges of a 3D mesh: dim < mesh dim - 1).  The node list is copied, sorted
 * and made unique. */
int
lac_mesh_add_node_group (lac_mesh *m, const char *name, int dim, int tag,
                         size_t nnodes, const size_t *node)
{
  lac_group *G;
  int status;

  if (m && (dim < 0 || dim >= m->dim - 1))
    LAC_ERROR (LAC_EINVAL, "node group '%s' of dimension %d in a %dD mesh: "
               "expected dimension < %d", name ? name : "?", dim, m->dim,
               m->dim - 1);
  if (nnodes > 0 && !node)
    LAC_ERROR (LAC_EINVAL, "node group '%s': no nodes given",
               name ? name : "?");
  if ((status = group_push (m, name, dim, tag, nnodes, 1, &G)))
    return status;
  for (size_t i = 0; i < nnodes; i++)
    {
      if (node[i] >= m->nnodes)
        {
          group_pop (m);
          LAC_ERROR (LAC_EINVAL, "node group '%s': node %zu out of range",
                     name, node[i]);
        }
      G->node[i] = node[i];
    }
  G->nnodes = sort_unique (G->node, nnodes);
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* two bodies in one mesh                                                  */
/* ---------------------------------------------------------------------- */

/* Copy the groups of src into out with cell indices shifted by c0, node
 * indices by n0, names prefixed; body indices of the copied cells follow. */
static int
merge_groups (lac_mesh *out, const lac_mesh *src, size_t c0, size_t n0,
              const char *prefix)
{
  int status = LAC_SUCCESS;
  size_t g0 = out->ngroups;
  for (size_t g = 0; !status && g < src->ngroups; g++)
    {
      const lac_group *G = &src->group[g];
      size_t len = strlen (prefix) + strlen (G->name) + 1;
      char *name = lac_malloc (len);
      size_t *cell = lac_malloc ((G->n + 1) * sizeof *cell);
      size_t *node = lac_malloc ((G->nnodes + 1) * sizeof *node);
      if (!name || !cell || !node)
        status = LAC_ERRMSG (LAC_ENOMEM, "merging group '%s'", G->name);
      if (!status)
        {
          snprintf (name, len, "%s%s", prefix, G->name);
          for (size_t e = 0; e < G->n; e++)
            cell[e] = G->cell[e] + c0;
          for (size_t e = 0; e < G->nnodes; e++)
            node[e] = G->node[e] + n0;
          status = G->dim >= out->dim - 1
            ? lac_mesh_add_group (out, name, G->dim, G->tag, G->n, cell, G->face)
            : lac_mesh_add_node_group (out, name, G->dim, G->tag, G->nnodes, node);
        }
      lac_free (name);
      lac_free (cell);
      lac_free (node);
    }
  for (size_t c = 0; !status && c < src->ncells; c++)
    out->body[c0 + c] = src->body[c] < 0 ? -1 : (int) g0 + src->body[c];
  return status;
}

/* lac_mesh_merge: the disjoint union of two meshes of the same dimension
 * (e.g. two bodies meshed separately: nothing is glued, nodes are not
 * merged).  Nodes, cells and groups of b follow those of a; group names
 * get the prefixes pa and pb (which must make them distinct). */
int
lac_mesh_merge (const lac_mesh *a, const char *pa, const lac_mesh *b,
                const char *pb, lac_mesh **out)
{
  *out = NULL;
  if (a->dim != b->dim)
    LAC_ERROR (LAC_EINVAL, "cannot merge a %dD and a %dD mesh", a->dim, b->dim);
  size_t na = a->nnodes, ca = a->ncells, ka = a->ptr[ca];
  lac_mesh *m = lac_mesh_alloc (a->dim, na + b->nnodes, ca + b->ncells,
                                ka + b->ptr[b->ncells]);
  if (!m)
    return LAC_ENOMEM;
  memcpy (m->x, a->x, na * a->dim * sizeof *m->x);
  memcpy (m->x + na * a->dim, b->x, b->nnodes * b->dim * sizeof *m->x);
  for (size_t i = 0; i < na; i++)
    m->node_tag[i] = a->node_tag[i];
  for (size_t i = 0; i < b->nnodes; i++)
    m->node_tag[na + i] = b->node_tag[i] + na;
  for (size_t c = 0; c < ca + b->ncells; c++)
    {
      const lac_mesh *s = c < ca ? a : b;
      size_t cs = c < ca ? c : c - ca;
      size_t off = c < ca ? 0 : na;
      m->type[c] = s->type[cs];
      m->cell_tag[c] = s->cell_tag[cs] + (c < ca ? 0 : ca);
      m->ptr[c + 1] = m->ptr[c] + (s->ptr[cs + 1] - s->ptr[cs]);
      for (size_t p = s->ptr[cs]; p < s->ptr[cs + 1]; p++)
        m->conn[m->ptr[c] + (p - s->ptr[cs])] = s->conn[p] + (int) off;
    }
  int status = merge_groups (m, a, 0, 0, pa);
  if (!status)
    status = merge_groups (m, b, ca, na, pb);
  if (status)
    {
      lac_mesh_free (m);
      return status;
    }
  *out = m;
  return LAC_SUCCESS;
}
