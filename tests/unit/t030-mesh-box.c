/* t030: box meshes of every type: counts, measure, groups, conformity,
 * straight-sided high-order nodes, distortion  [LAC §2] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_mesh.h"
#include "base/lac_status.h"

/* A face of a cell: sorted vertices, for matching. */
typedef struct
{
  int v[4];
  size_t cell;
  int face;
} fkey;

static int
cmp_fkey (const void *a, const void *b)
{
  const fkey *x = a, *y = b;
  for (int i = 0; i < 4; i++)
    if (x->v[i] != y->v[i])
      return x->v[i] < y->v[i] ? -1 : 1;
  return 0;
}

static int
nvert_of (lac_elem_type t)
{
  return lac_refelem_get (t)->nvertices;
}

static void
make_key (const lac_mesh *m, size_t c, int f, fkey *k)
{
  int nodes[LAC_MAX_FACE_NODES], nv;
  lac_elem_type ft;
  lac_mesh_facet_nodes (m, c, f, nodes, &ft);
  nv = nvert_of (ft);
  for (int i = 0; i < 4; i++)
    k->v[i] = i < nv ? nodes[i] : -1;
  for (int i = 1; i < nv; i++)
    for (int j = i; j > 0 && k->v[j - 1] > k->v[j]; j--)
      {
        int t = k->v[j];
        k->v[j] = k->v[j - 1];
        k->v[j - 1] = t;
      }
  k->cell = c;
  k->face = f;
}

/* Normal of a face from its first vertices (right-hand rule). */
static void
face_normal (const lac_mesh *m, size_t c, int f, double *nrm)
{
  int nodes[LAC_MAX_FACE_NODES], d = m->dim;
  const double *x0, *x1, *x2;
  lac_mesh_facet_nodes (m, c, f, nodes, NULL);
  x0 = m->x + nodes[0] * d;
  x1 = m->x + nodes[1] * d;
  if (d == 2)
    {
      nrm[0] = x1[1] - x0[1];
      nrm[1] = -(x1[0] - x0[0]);
      nrm[2] = 0;
      return;
    }
  x2 = m->x + nodes[2] * d;
  {
    double a[3], b[3];
    for (int i = 0; i < 3; i++)
      {
        a[i] = x1[i] - x0[i];
        b[i] = x2[i] - x0[i];
      }
    nrm[0] = a[1] * b[2] - a[2] * b[1];
    nrm[1] = a[2] * b[0] - a[0] * b[2];
    nrm[2] = a[0] * b[1] - a[1] * b[0];
  }
}

static double
dot3 (const double *a, const double *b, int d)
{
  double s = 0;
  for (int i = 0; i < d; i++)
    s += a[i] * b[i];
  return s;
}

/* Interior faces are shared by two cells with opposite normals and the
 * same nodes; the faces seen once are exactly the facets of the groups,
 * with outward normals. */
static void
check_conformity (const lac_mesh *m, const char *name)
{
  const lac_refelem *re = lac_refelem_get (m->type[0]);
  size_t nf = m->ncells * (size_t) re->nfaces, nbnd = 0, ngrp = 0;
  fkey *k = malloc (nf * sizeof *k);
  int bad_pair = 0, bad_mult = 0;

  for (size_t c = 0, i = 0; c < m->ncells; c++)
    for (int f = 0; f < re->nfaces; f++)
      make_key (m, c, f, &k[i++]);
  qsort (k, nf, sizeof *k, cmp_fkey);
  for (size_t i = 0; i < nf;)
    {
      size_t j = i + 1;
      while (j < nf && cmp_fkey (&k[i], &k[j]) == 0)
        j++;
      if (j - i == 1)
        nbnd++;
      else if (j - i == 2)
        {
          double n1[3], n2[3];
          int a[LAC_MAX_FACE_NODES], b[LAC_MAX_FACE_NODES], na, nb, same = 0;
          face_normal (m, k[i].cell, k[i].face, n1);
          face_normal (m, k[i + 1].cell, k[i + 1].face, n2);
          bad_pair += dot3 (n1, n2, m->dim) >= 0;
          na = lac_mesh_facet_nodes (m, k[i].cell, k[i].face, a, NULL);
          nb = lac_mesh_facet_nodes (m, k[i + 1].cell, k[i + 1].face, b, NULL);
          for (int p = 0; p < na; p++)
            for (int q = 0; q < nb; q++)
              same += a[p] == b[q];
          bad_pair += na != nb || same != na;
        }
      else
        bad_mult++;
      i = j;
    }
  check_int (bad_mult, 0, "%s: faces shared by more than two cells", name);
  check_int (bad_pair, 0, "%s: interior face pairs that do not match", name);
  for (size_t g = 0; g < m->ngroups; g++)
    {
      const lac_group *G = &m->group[g];
      int axis, side, bad = 0;
      if (G->dim != m->dim - 1)
        continue;
      ngrp += G->n;
      axis = (G->name[0] - 'x');
      side = strcmp (G->name + 1, "max") == 0 ? 1 : -1;
      for (size_t e = 0; e < G->n; e++)
        {
          fkey key, *hit;
          double nrm[3];
          make_key (m, G->cell[e], G->face[e], &key);
          hit = bsearch (&key, k, nf, sizeof *k, cmp_fkey);
          bad += !hit || (hit > k && cmp_fkey (hit - 1, &key) == 0)
                 || (hit + 1 < k + nf && cmp_fkey (hit + 1, &key) == 0);
          face_normal (m, G->cell[e], G->face[e], nrm);
          bad += side * nrm[axis] <= 0;
        }
      check_int (bad, 0, "%s: facets of '%s' on the boundary, outward", name,
                 G->name);
    }
  check_int ((long) ngrp, (long) nbnd, "%s: boundary faces = group facets",
             name);
  free (k);
}

/* High-order nodes sit where the linear (multilinear) map of the vertices
 * puts them: straight-sided cells. */
static void
check_straight (const lac_mesh *m, const char *name)
{
  static const lac_elem_type lin[LAC_NELEM_TYPES] = {
    [LAC_TRI6] = LAC_TRI3, [LAC_QUAD8] = LAC_QUAD4, [LAC_QUAD9] = LAC_QUAD4,
    [LAC_TET10] = LAC_TET4, [LAC_HEX20] = LAC_HEX8, [LAC_HEX27] = LAC_HEX8 };
  const lac_refelem *re = lac_refelem_get (m->type[0]), *rl;
  double err = 0;
  int d = m->dim;
  if (re->order == 1)
    return;
  rl = lac_refelem_get (lin[re->type]);
  for (size_t c = 0; c < m->ncells; c++)
    for (int a = re->nvertices; a < re->nnodes; a++)
      {
        double N[LAC_MAX_NODES], x[3] = { 0 };
        const int *cn = m->conn + m->ptr[c];
        lac_refelem_eval (rl, re->xi + a * d, N, NULL);
        for (int v = 0; v < rl->nnodes; v++)
          for (int i = 0; i < d; i++)
            x[i] += N[v] * m->x[cn[v] * d + i];
        for (int i = 0; i < d; i++)
          err = fmax (err, fabs (x[i] - m->x[cn[a] * d + i]));
      }
  check_abs (err, 0, 1e-14, "%s: high-order nodes on the linear map", name);
}

static size_t
expected_nodes (lac_elem_type t, const size_t *n, int d)
{
  size_t v = 1, l = 1, e = 0;
  for (int k = 0; k < d; k++)
    {
      v *= n[k] + 1;
      l *= 2 * n[k] + 1;
    }
  switch (t)
    {
    case LAC_TRI3: case LAC_QUAD4: case LAC_TET4: case LAC_HEX8:
      return v;
    case LAC_QUAD8:
      return l - n[0] * n[1];
    case LAC_HEX20:
      for (int k = 0; k < 3; k++)
        e += n[k] * v / (n[k] + 1);
      return v + e;
    default:
      return l;
    }
}

static void
check_type (lac_elem_type t, double distort)
{
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 3, 2, 2 }, nbox = 1, nsub;
  double L[3] = { 2.0, 1.5, 0.7 }, vol = 1;
  int d = re->dim, status;
  lac_mesh *m = NULL;
  char name[64];
  const lac_group *body;

  snprintf (name, sizeof name, "%s distort %g", re->name, distort);
  status = lac_mesh_box (t, n, L, distort, &m);
  check_status (status, LAC_SUCCESS, "%s: lac_mesh_box", name);
  if (status)
    return;
  for (int k = 0; k < d; k++)
    {
      nbox *= n[k];
      vol *= L[k];
    }
  nsub = re->shape == LAC_SHAPE_TRI ? 2 : re->shape == LAC_SHAPE_TET ? 6 : 1;
  check_int (m->dim, d, "%s: dim", name);
  check_int ((long) m->ncells, (long) (nbox * nsub), "%s: cells", name);
  check_int ((long) m->nnodes, (long) expected_nodes (t, n, d), "%s: nodes",
             name);
  check_int ((long) lac_mesh_nconn_max (m), re->nnodes, "%s: nconn_max",
             name);
  check_rel (lac_mesh_measure (m), vol, 1e-13, "%s: measure", name);

  /* groups: 2d facet groups with the expected numbers of facets, "body" */
  for (int k = 0; k < d; k++)
    for (int end = 0; end < 2; end++)
      {
        char gname[8];
        size_t want = 1;
        const lac_group *G;
        snprintf (gname, sizeof gname, "%c%s", 'x' + k, end ? "max" : "min");
        G = lac_mesh_group (m, gname);
        check_true (G != NULL, "%s: group %s", name, gname);
        if (!G)
          continue;
        for (int j = 0; j < d; j++)
          if (j != k)
            want *= n[j];
        if (re->shape == LAC_SHAPE_TET)
          want *= 2;
        check_int ((long) G->n, (long) want, "%s: facets of %s", name, gname);
        check_int (G->dim, d - 1, "%s: dim of %s", name, gname);
        {
          int off = 0;
          double want_x = end ? L[k] : 0;
          for (size_t i = 0; i < G->nnodes; i++)
            off += fabs (m->x[G->node[i] * d + k] - want_x) > 1e-14;
          check_int (off, 0, "%s: nodes of %s on the plane", name, gname);
        }
      }
  body = lac_mesh_group (m, "body");
  check_true (body && body->n == m->ncells && body->dim == d
              && body->nnodes == m->nnodes, "%s: group body", name);
  if (body)
    {
      int bad = 0;
      for (size_t c = 0; c < m->ncells; c++)
        bad += m->body[c] != (int) (body - m->group) || body->cell[c] != c
               || body->face[c] != -1;
      check_int (bad, 0, "%s: body[c]", name);
    }
  check_true (lac_mesh_group (m, "nope") == NULL, "%s: unknown group", name);
  check_message ("nope", "%s: unknown group message", name);

  check_conformity (m, name);
  check_straight (m, name);

  /* distortion: interior vertices move, by at most distort*h */
  {
    double move = 0;
    size_t moved = 0;
    int too_far = 0;
    for (size_t i = 0; i < m->nnodes; i++)
      for (int k = 0; k < d; k++)
        {
          double h = L[k] / (double) n[k] / re->order;
          double x = m->x[i * d + k], r = x / h - round (x / h);
          move = fmax (move, fabs (r));
          moved += fabs (r) > 1e-12;
          too_far += fabs (r) / re->order > distort + 1e-12;
        }
    if (distort == 0)
      check_abs (move, 0, 1e-12, "%s: nodes on the grid", name);
    else
      check_true (moved > 0, "%s: some nodes moved", name);
    check_int (too_far, 0, "%s: moves within distort*h", name);
  }
  /* orientation is already positive everywhere */
  {
    size_t nflip = 99;
    check_status (lac_mesh_check_orientation (m, 1, &nflip), LAC_SUCCESS,
                  "%s: orientation", name);
    check_int ((long) nflip, 0, "%s: nothing to flip", name);
  }
  lac_mesh_free (m);
}

int
main (void)
{
  static const lac_elem_type types[] = {
    LAC_TRI3, LAC_TRI6, LAC_QUAD4, LAC_QUAD8, LAC_QUAD9,
    LAC_TET4, LAC_TET10, LAC_HEX8, LAC_HEX20, LAC_HEX27 };
  size_t n[3] = { 2, 2, 2 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = (lac_mesh *) 1;
  int nodes[LAC_MAX_FACE_NODES];

  for (size_t i = 0; i < sizeof types / sizeof *types; i++)
    {
      check_type (types[i], 0);
      check_type (types[i], 0.2);
    }

  /* bad requests */
  check_status (lac_mesh_box (LAC_PYR5, n, L, 0, &m), LAC_EINVAL, "pyr5 box");
  check_message ("pyr5", "pyr5 box message");
  check_true (m == NULL, "no mesh on failure");
  check_status (lac_mesh_box (LAC_SEG2, n, L, 0, &m), LAC_EINVAL, "seg2 box");
  check_status (lac_mesh_box (LAC_QUAD4, n, L, 0.5, &m), LAC_EINVAL,
                "distort 0.5");
  n[1] = 0;
  check_status (lac_mesh_box (LAC_QUAD4, n, L, 0, &m), LAC_EINVAL, "n = 0");
  n[1] = 2;
  L[0] = -1;
  check_status (lac_mesh_box (LAC_HEX8, n, L, 0, &m), LAC_EINVAL, "L < 0");
  L[0] = 1;

  /* queries on a small mesh */
  check_status (lac_mesh_box (LAC_QUAD9, n, L, 0, &m), LAC_SUCCESS, "quad9");
  check_int (lac_mesh_facet_nodes (m, 0, 4, nodes, NULL), -LAC_EINVAL,
             "face 4 of a quad9");
  check_int (lac_mesh_facet_nodes (m, 99, 0, nodes, NULL), -LAC_EINVAL,
             "cell 99");
  check_int (lac_mesh_facet_nodes (m, 0, 0, nodes, NULL), 3, "quad9 edge");
  {
    double xe[9 * 2];
    lac_mesh_cell_coords (m, 3, xe);
    check_abs (xe[0], 0.5, 1e-15, "cell 3 node 0 x");
    check_abs (xe[1], 0.5, 1e-15, "cell 3 node 0 y");
    check_abs (xe[16], 0.75, 1e-15, "cell 3 centre x");
  }
  {
    size_t cell[1] = { 0 };
    int face[1] = { 7 };
    size_t ng = m->ngroups;
    check_status (lac_mesh_add_group (m, "bad", 1, 0, 1, cell, face),
                  LAC_EINVAL, "face 7 rejected");
    check_status (lac_mesh_add_group (m, "xmin", 2, 0, 1, cell, NULL),
                  LAC_EINVAL, "duplicate name rejected");
    check_status (lac_mesh_add_group (m, "pt", 0, 0, 1, cell, NULL),
                  LAC_EINVAL, "dim 0 group needs node form");
    check_int ((long) m->ngroups, (long) ng, "failed adds leave no group");
    face[0] = 2;
    check_status (lac_mesh_add_group (m, "top", 1, 7, 1, cell, face),
                  LAC_SUCCESS, "facet group");
    check_int ((long) lac_mesh_group (m, "top")->nnodes, 3, "facet nodes");
    {
      size_t pts[3] = { 5, 1, 5 };
      check_status (lac_mesh_add_node_group (m, "pts", 0, 3, 3, pts),
                    LAC_SUCCESS, "node group");
      check_int ((long) lac_mesh_group (m, "pts")->nnodes, 2, "unique nodes");
      check_int ((long) lac_mesh_group (m, "pts")->node[0], 1, "sorted nodes");
    }
  }
  lac_mesh_free (m);
  lac_mesh_free (NULL);
  return check_summary ();
}
