/* t040: reading meshes through gmsh: .msh 2.2 and 4.1, .geo with options
 * (order, serendipity, recombine, level), groups, orientation, errors [LAC §2] */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "io/lac_mesh_gmsh.h"
#include "base/lac_status.h"

#define DIR "tests/meshes/"

static lac_mesh *
read (const char *path, const lac_mesh_opts *o, const char *what)
{
  lac_mesh *m = NULL;
  check_status (lac_mesh_read (path, o, &m), LAC_SUCCESS, "%s: read", what);
  return m;
}

/* Outward normal of a facet from its first vertices (right-hand rule). */
static void
facet_normal (const lac_mesh *m, size_t c, int f, double *nrm)
{
  int v[LAC_MAX_FACE_NODES], d = m->dim;
  double a[3], b[3];
  lac_mesh_facet_nodes (m, c, f, v, NULL);
  for (int i = 0; i < d; i++)
    {
      a[i] = m->x[v[1] * d + i] - m->x[v[0] * d + i];
      b[i] = d == 3 ? m->x[v[2] * d + i] - m->x[v[0] * d + i] : 0;
    }
  if (d == 2)
    {
      nrm[0] = a[1];
      nrm[1] = -a[0];
      return;
    }
  nrm[0] = a[1] * b[2] - a[2] * b[1];
  nrm[1] = a[2] * b[0] - a[0] * b[2];
  nrm[2] = a[0] * b[1] - a[1] * b[0];
}

/* Facet group `name': n facets, nodes on x[axis] = at, normals outward
 * (sign * e_axis). */
static void
check_side (const lac_mesh *m, const char *name, size_t n, int axis,
            double at, int sign, const char *what)
{
  const lac_group *G = lac_mesh_group (m, name);
  int off = 0, in = 0;
  check_true (G != NULL, "%s: group %s", what, name);
  if (!G)
    return;
  check_int (G->dim, m->dim - 1, "%s: %s is a facet group", what, name);
  check_int ((long) G->n, (long) n, "%s: facets of %s", what, name);
  for (size_t i = 0; i < G->nnodes; i++)
    off += fabs (m->x[G->node[i] * m->dim + axis] - at) > 1e-9;
  for (size_t e = 0; e < G->n; e++)
    {
      double nrm[3];
      facet_normal (m, G->cell[e], G->face[e], nrm);
      in += sign * nrm[axis] <= 0;
    }
  check_int (off, 0, "%s: nodes of %s on the side", what, name);
  check_int (in, 0, "%s: facets of %s point outward", what, name);
}

/* The unit square of square.geo/.msh: groups, measure, cells. */
static void
check_square (const lac_mesh *m, lac_elem_type type, size_t nside,
              const char *what)
{
  const lac_group *body, *o, *p7;
  int bad = 0;
  if (!m)
    return;
  check_int (m->dim, 2, "%s: dim", what);
  for (size_t c = 0; c < m->ncells; c++)
    bad += m->type[c] != type;
  check_int (bad, 0, "%s: all cells are %s", what,
             lac_refelem_get (type)->name);
  check_rel (lac_mesh_measure (m), 1, 1e-12, "%s: area", what);
  check_side (m, "bottom", nside, 1, 0, -1, what);
  check_side (m, "right", nside, 0, 1, 1, what);
  check_side (m, "top", nside, 1, 1, 1, what);
  check_side (m, "left", nside, 0, 0, -1, what);
  body = lac_mesh_group (m, "body");
  check_true (body && body->n == m->ncells && body->dim == 2
              && body->nnodes == m->nnodes, "%s: body", what);
  bad = 0;
  for (size_t c = 0; body && c < m->ncells; c++)
    bad += m->body[c] != (int) (body - m->group);
  check_int (bad, 0, "%s: body[c]", what);
  o = lac_mesh_group (m, "origin");
  check_true (o && o->dim == 0 && o->n == 0 && o->nnodes == 1
              && m->x[2 * o->node[0]] == 0 && m->x[2 * o->node[0] + 1] == 0,
              "%s: point group 'origin'", what);
  p7 = lac_mesh_group (m, "0:7");
  check_true (p7 && p7->tag == 7 && p7->nnodes == 1
              && m->x[2 * p7->node[0]] == 1, "%s: unnamed group '0:7'", what);
  check_true (lac_mesh_group (m, "nowhere") == NULL, "%s: unknown group",
              what);
  check_message ("nowhere", "%s: message names the unknown group", what);
}

/* The unit cube of box.geo/.msh. */
static void
check_box (const lac_mesh *m, lac_elem_type type, size_t nside,
           const char *what)
{
  static const char *side[6] = { "xmin", "xmax", "ymin", "ymax", "zmin",
                                 "zmax" };
  const lac_group *edge;
  int bad = 0;
  if (!m)
    return;
  check_int (m->dim, 3, "%s: dim", what);
  for (size_t c = 0; c < m->ncells; c++)
    bad += m->type[c] != type;
  check_int (bad, 0, "%s: all cells are %s", what,
             lac_refelem_get (type)->name);
  check_rel (lac_mesh_measure (m), 1, 1e-12, "%s: volume", what);
  for (int s = 0; s < 6; s++)
    check_side (m, side[s], nside, s / 2, s % 2, s % 2 ? 1 : -1, what);
  edge = lac_mesh_group (m, "edge");
  check_true (edge && edge->dim == 1 && edge->nnodes >= 3, "%s: edge group",
              what);
  check_true (lac_mesh_group (m, "body") && m->body[0] >= 0, "%s: body",
              what);
}

/* Two meshes with the same nodes, cells and tags. */
static void
check_same (const lac_mesh *a, const lac_mesh *b, const char *what)
{
  int diff;
  if (!a || !b)
    return;
  diff = a->nnodes != b->nnodes || a->ncells != b->ncells
         || a->ngroups != b->ngroups;
  for (size_t i = 0; !diff && i < a->nnodes * (size_t) a->dim; i++)
    diff += fabs (a->x[i] - b->x[i]) > 1e-15;
  for (size_t c = 0; !diff && c < a->ncells; c++)
    diff += a->cell_tag[c] != b->cell_tag[c];
  for (size_t k = 0; !diff && k < a->ptr[a->ncells]; k++)
    diff += a->conn[k] != b->conn[k];
  check_int (diff, 0, "%s: same mesh", what);
}

static void
test_square (void)
{
  lac_mesh_opts o = { 0 };
  lac_mesh *m22 = read (DIR "square-v22.msh", NULL, "msh 2.2");
  lac_mesh *m41 = read (DIR "square-v41.msh", NULL, "msh 4.1");
  lac_mesh *g = read (DIR "square.geo", &o, "geo");
  lac_mesh *m;

  check_square (m22, LAC_TRI3, 2, "msh 2.2");
  check_square (m41, LAC_TRI3, 2, "msh 4.1");
  check_square (g, LAC_TRI3, 2, "geo");
  check_same (m22, m41, "msh 2.2 vs 4.1");
  if (m22)
    check_true (m22->cell_tag[0] > 1 && m22->node_tag[0] == 1,
                "msh 2.2: gmsh tags kept");
  lac_mesh_free (m22);
  lac_mesh_free (m41);
  lac_mesh_free (g);

  o.level = 2;                      /* 2^(level+1) segments a side */
  m = read (DIR "square.geo", &o, "level 2");
  check_square (m, LAC_TRI3, 8, "level 2");
  lac_mesh_free (m);
  o.level = 0;                      /* not left over from the last read */
  m = read (DIR "square.geo", &o, "level 0 again");
  check_square (m, LAC_TRI3, 2, "level 0 again");
  lac_mesh_free (m);

  o.order = 2;
  m = read (DIR "square.geo", &o, "tri6");
  check_square (m, LAC_TRI6, 2, "tri6");
  lac_mesh_free (m);
  o.order = 0;
  o.recombine = 1;
  m = read (DIR "square.geo", &o, "quad4");
  check_square (m, LAC_QUAD4, 2, "quad4");
  lac_mesh_free (m);
  o.order = 2;
  m = read (DIR "square.geo", &o, "quad9");
  check_square (m, LAC_QUAD9, 2, "quad9");
  lac_mesh_free (m);
  o.serendipity = 1;
  o.level = 1;
  m = read (DIR "square.geo", &o, "quad8");
  check_square (m, LAC_QUAD8, 4, "quad8");
  lac_mesh_free (m);
  o.level = 0;
  o.serendipity = 0;
  o.recombine = 0;
  o.order = 1;
  o.size = 0.5;                     /* finer inside, sides are transfinite */
  m = read (DIR "square.geo", &o, "size 0.5");
  check_square (m, LAC_TRI3, 2, "size 0.5");
  lac_mesh_free (m);
}

static void
test_box (void)
{
  lac_mesh_opts o = { 0 };
  lac_mesh *m = read (DIR "box.geo", &o, "tet4");
  lac_mesh *m41 = read (DIR "box-v41.msh", NULL, "box msh 4.1");

  check_box (m, LAC_TET4, 8, "tet4");
  check_box (m41, LAC_TET4, 8, "box msh 4.1");
  check_same (m, m41, "box geo vs msh 4.1");
  lac_mesh_free (m);
  lac_mesh_free (m41);
  o.order = 2;
  m = read (DIR "box.geo", &o, "tet10");
  check_box (m, LAC_TET10, 8, "tet10");
  lac_mesh_free (m);
  o.order = 0;
  o.recombine = 1;
  m = read (DIR "box.geo", &o, "hex8");
  check_box (m, LAC_HEX8, 4, "hex8");
  if (m)
    check_int ((long) m->ncells, 8, "hex8: 2x2x2 cells");
  lac_mesh_free (m);
  o.order = 2;
  m = read (DIR "box.geo", &o, "hex27");
  check_box (m, LAC_HEX27, 4, "hex27");
  lac_mesh_free (m);
  o.serendipity = 1;
  o.level = 1;
  m = read (DIR "box.geo", &o, "hex20");
  check_box (m, LAC_HEX20, 16, "hex20");
  lac_mesh_free (m);
}

static void
test_orientation (void)
{
  lac_mesh_opts o = { 0 };
  lac_mesh *m = NULL;
  size_t nflip = 99;

  o.flip_inverted = 1;
  m = read (DIR "clockwise.geo", &o, "clockwise, flipped");
  if (m)
    {
      check_rel (lac_mesh_measure (m), 1, 1e-12, "clockwise: area > 0");
      check_status (lac_mesh_check_orientation (m, 0, &nflip), LAC_SUCCESS,
                    "clockwise: all cells positive after reading");
      check_int ((long) nflip, 0, "clockwise: nothing left to flip");
      check_side (m, "bottom", 2, 1, 0, -1, "clockwise");
      check_side (m, "left", 2, 0, 0, -1, "clockwise");
    }
  lac_mesh_free (m);
  m = (lac_mesh *) 1;
  o.flip_inverted = 0;
  check_status (lac_mesh_read (DIR "clockwise.geo", &o, &m), LAC_EINVAL,
                "clockwise, rejected");
  check_message ("clockwise.geo", "rejection names the file");
  check_message ("tag", "rejection names the cell tag");
  check_message ("inverted", "rejection says why");
  check_true (m == NULL, "no mesh on failure");
}

static void
test_errors (void)
{
  lac_mesh *m = (lac_mesh *) 1;
  lac_mesh_opts o = { 0 };

  check_status (lac_mesh_read (DIR "missing.msh", NULL, &m), LAC_EIO,
                "missing file");
  check_message (DIR "missing.msh: cannot open (", "missing file message");
  check_true (m == NULL, "missing file: no mesh");
  check_status (lac_mesh_read (DIR "garbage.msh", NULL, &m), LAC_EIO,
                "garbage file");
  check_message ("garbage.msh", "garbage message names the file");
  check_status (lac_mesh_read (DIR "square.txt", NULL, &m), LAC_EINVAL,
                "unknown extension");
  check_message (".msh or .geo", "extension message");
  check_status (lac_mesh_read (DIR "stray.geo", NULL, &m), LAC_EINVAL,
                "boundary element off the mesh");
  check_message ("'stray'", "stray message names the group");
  check_message ("not a face of any cell", "stray message says why");
  check_status (lac_mesh_read (DIR "prism.geo", NULL, &m), LAC_EINVAL,
                "prisms");
  check_message ("gmsh element type 6", "prism message names the type");
  check_message ("prism.geo", "prism message names the file");
  check_status (lac_mesh_read (DIR "tilted.geo", NULL, &m), LAC_EINVAL,
                "2D mesh off z = 0");
  check_message ("z = 0", "tilted message");
  o.order = 3;
  check_status (lac_mesh_read (DIR "square.geo", &o, &m), LAC_EINVAL,
                "order 3");
  check_status (lac_mesh_read (NULL, NULL, &m), LAC_EINVAL, "no path");
  check_status (lac_mesh_read (DIR "square.geo", NULL, NULL), LAC_EINVAL,
                "no output");
  check_true (m == NULL, "errors: no mesh");
  /* gmsh still works after all these errors */
  m = read (DIR "square-v41.msh", NULL, "after errors");
  check_square (m, LAC_TRI3, 2, "after errors");
  lac_mesh_free (m);
}

int
main (void)
{
  test_square ();
  test_box ();
  test_orientation ();
  test_errors ();
  return check_summary ();
}
