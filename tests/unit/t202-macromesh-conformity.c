/* t202: the refined mesh is conforming                 [LAC §4.4, Remark 3]
 *
 * After lac_macromesh_build on distorted box meshes (slave = zmax; zmax +
 * xmax, so that edge cells own two slave faces; the whole boundary, so
 * that corner cells own three, and a single cell six):
 *   - det J > 0 at the nodes and quadrature points of every cell;
 *   - every face of every cell is either on the boundary or shared by
 *     exactly two cells, which then have the same nodes on it (vertices and
 *     mid-nodes: the traces coincide);
 *   - the faces seen once tile the box's surface (a hanging node would
 *     leave a face seen once inside the box: too much area);
 *   - u(x) = A x + b set at the nodes is reproduced exactly, from both
 *     sides, at the quadrature points of every interior face.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_refine.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

typedef struct fkey
{
  int v[4];
  size_t c;
  int f;
} fkey;

static int
cmp_key (const void *a, const void *b)
{
  const fkey *p = a, *q = b;
  for (int i = 0; i < 4; i++)
    if (p->v[i] != q->v[i])
      return p->v[i] < q->v[i] ? -1 : 1;
  return 0;
}

static int
cmp_int (const void *a, const void *b)
{
  return *(const int *) a - *(const int *) b;
}

static void
u_exact (const double *x, int d, double *u)
{
  static const double A[3][3] = { { 0.3, -1.2, 0.7 }, { 2.0, 0.1, -0.4 },
                                  { -0.6, 0.9, 1.3 } };
  static const double b[3] = { 0.25, -0.5, 1.0 };
  for (int i = 0; i < d; i++)
    {
      u[i] = b[i];
      for (int k = 0; k < d; k++)
        u[i] += A[i][k] * x[k];
    }
}

/* u_h of cell c at the physical point x (through the inverse map); returns
 * 0 if x is not in the cell. */
static int
u_cell (const lac_mesh *m, size_t c, const double *x, double *u)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  double xe[LAC_MAX_NODES * 3], xi[3] = { 0, 0, 0 }, N[LAC_MAX_NODES];
  int d = m->dim;
  lac_mesh_cell_coords (m, c, xe);
  if (lac_map_inverse (re, d, xe, x, xi) != LAC_SUCCESS
      || !lac_refelem_contains (re, xi, 1e-9))
    return 0;
  lac_refelem_eval (re, xi, N, NULL);
  for (int i = 0; i < d; i++)
    u[i] = 0;
  for (int a = 0; a < re->nnodes; a++)
    {
      double ua[3];
      u_exact (xe + a * d, d, ua);              /* nodal values u(x_a) */
      for (int i = 0; i < d; i++)
        u[i] += N[a] * ua[i];
    }
  return 1;
}

typedef struct conf
{
  size_t nbad_pair, nbad_nodes, nbad_u, nint;
  double area, uerr;
} conf;

static conf
conformity (const lac_mesh *m)
{
  size_t nf = 0, nbad_pair = 0, nbad_nodes = 0, nbad_u = 0, nint = 0;
  fkey *key;
  double area = 0, uerr = 0;
  lac_quad *rule[3] = { lac_quad_alloc (LAC_SHAPE_LINE, 4),
                        lac_quad_alloc (LAC_SHAPE_TRI, 4),
                        lac_quad_alloc (LAC_SHAPE_QUAD, 4) };

  for (size_t c = 0; c < m->ncells; c++)
    nf += (size_t) lac_refelem_get (m->type[c])->nfaces;
  key = malloc (nf * sizeof *key);
  nf = 0;
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      for (int f = 0; f < re->nfaces; f++, nf++)
        {
          int nv = lac_refelem_get (re->face_type[f])->nvertices;
          for (int i = 0; i < 4; i++)
            key[nf].v[i] = i < nv ? m->conn[m->ptr[c] + re->face_node[f][i]]
                                  : -1;
          qsort (key[nf].v, (size_t) nv, sizeof (int), cmp_int);
          key[nf].c = c;
          key[nf].f = f;
        }
    }
  qsort (key, nf, sizeof *key, cmp_key);
  for (size_t i = 0; i < nf;)
    {
      size_t j = i + 1;
      int n1[LAC_MAX_FACE_NODES], n2[LAC_MAX_FACE_NODES], k1, k2;
      lac_elem_type ft;
      const lac_refelem *rf;
      const lac_quad *q;
      double xe[LAC_MAX_FACE_NODES * 3];
      while (j < nf && cmp_key (&key[i], &key[j]) == 0)
        j++;
      k1 = lac_mesh_facet_nodes (m, key[i].c, key[i].f, n1, &ft);
      rf = lac_refelem_get (ft);
      q = rule[rf->shape == LAC_SHAPE_LINE ? 0
               : rf->shape == LAC_SHAPE_TRI ? 1 : 2];
      for (int a = 0; a < k1; a++)
        for (int d = 0; d < m->dim; d++)
          xe[a * m->dim + d] = m->x[(size_t) n1[a] * m->dim + d];
      if (j - i > 2)
        nbad_pair++;
      if (j - i == 1)                            /* boundary: its area */
        for (int p = 0; p < q->n; p++)
          {
            lac_map mp;
            lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
            area += q->w[p] * mp.detJ;
          }
      if (j - i == 2)
        {
          nint++;
          k2 = lac_mesh_facet_nodes (m, key[i + 1].c, key[i + 1].f, n2, NULL);
          qsort (n1, (size_t) k1, sizeof (int), cmp_int);
          qsort (n2, (size_t) k2, sizeof (int), cmp_int);
          if (k1 != k2 || memcmp (n1, n2, (size_t) k1 * sizeof (int)))
            nbad_nodes++;
          lac_mesh_facet_nodes (m, key[i].c, key[i].f, n1, NULL);
          for (int p = 0; p < q->n; p++)
            {
              lac_map mp;
              double ue[3], u1[3], u2[3];
              lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
              u_exact (mp.x, m->dim, ue);
              if (!u_cell (m, key[i].c, mp.x, u1)
                  || !u_cell (m, key[i + 1].c, mp.x, u2))
                {
                  nbad_u++;
                  continue;
                }
              for (int d = 0; d < m->dim; d++)
                {
                  uerr = fmax (uerr, fabs (u1[d] - ue[d]));
                  uerr = fmax (uerr, fabs (u2[d] - ue[d]));
                }
            }
        }
      i = j;
    }
  free (key);
  for (int s = 0; s < 3; s++)
    lac_quad_free (rule[s]);
  return (conf) { nbad_pair, nbad_nodes, nbad_u, nint, area, uerr };
}

static void
check_conforming (const lac_mesh *m, double surface, const char *what)
{
  conf r = conformity (m);
  check_int ((long) r.nbad_pair, 0, "%s: faces in more than 2 cells", what);
  check_int ((long) r.nbad_nodes, 0, "%s: shared faces with different nodes",
             what);
  check_int ((long) r.nbad_u, 0, "%s: face points outside a neighbour",
             what);
  check_true (r.nint > 0 || m->ncells == 1, "%s: has interior faces", what);
  check_abs (r.uerr, 0, 1e-13, "%s: linear field across faces", what);
  check_rel (r.area, surface, 1e-13, "%s: boundary faces tile the surface",
             what);
}

/* Control: cutting a cell on an INTERIOR face leaves a hanging node; the
 * checks above must see it (area of faces seen once grows). */
static void
control (lac_elem_type t)
{
  size_t n[3] = { 1, 1, 1 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL, *r = NULL;
  lac_refine_map *map = NULL;
  conf c;
  int cut[6] = { -1, -1, -1, -1, -1, -1 }, found = 0;
  lac_mesh_box (t, n, L, 0, &m);
  /* an interior face of cell 0: one not in any box side group */
  for (int f = 0; f < lac_refelem_get (t)->nfaces && !found; f++)
    {
      int side = 0;
      for (size_t g = 0; g < m->ngroups; g++)
        for (size_t e = 0; e < m->group[g].n; e++)
          side |= m->group[g].dim == m->dim - 1 && m->group[g].cell[e] == 0
                  && m->group[g].face[e] == f;
      if (!side)
        cut[0] = f, found = 1;
    }
  check_true (found, "control %s: interior face", lac_refelem_get (t)->name);
  check_status (lac_refine_cut (m, cut, NULL, &r, &map), LAC_SUCCESS,
                "control %s: cut", lac_refelem_get (t)->name);
  c = conformity (r);
  check_true (c.area > 6 + 0.01, "control %s: non-conforming "
              "cut detected (area %g)", lac_refelem_get (t)->name, c.area);
  lac_refine_map_free (map);
  lac_mesh_free (r);
  lac_mesh_free (m);
}

static void
union_group (lac_mesh *m, const char *a, const char *b)
{
  const lac_group *A = lac_mesh_group (m, a), *B = lac_mesh_group (m, b);
  size_t n = A->n + B->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      cell[e] = e < A->n ? A->cell[e] : B->cell[e - A->n];
      face[e] = e < A->n ? A->face[e] : B->face[e - A->n];
    }
  lac_mesh_add_group (m, "u", A->dim, 0, n, cell, face);
  free (cell);
  free (face);
}

static void
run (lac_elem_type t, size_t nb, int two, const lac_macro_opts *opts,
     const char *label)
{
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { nb, nb, nb };
  double L[3] = { 1, 1.5, 2 };
  double surface = re->dim == 3 ? 2 * (1 * 1.5 + 1.5 * 2 + 1 * 2)
                                : 2 * (1 + 1.5);
  const char *slave = re->dim == 3 ? "zmax" : "ymax";
  lac_mesh *m = NULL;
  lac_macro *M = NULL;
  char what[96];
  int status;

  snprintf (what, sizeof what, "%s %s %zu^%d%s", re->name, label, nb,
            re->dim, two == 2 ? " all sides" : two ? " 2 sides" : "");
  status = lac_mesh_box (t, n, L, nb > 1 ? 0.2 : 0, &m);
  check_status (status, LAC_SUCCESS, "%s: box", what);
  if (status)
    return;
  if (two == 1)
    {
      union_group (m, slave, "xmax");
      slave = "u";
    }
  if (two == 2)                       /* the whole boundary: corner cells */
    {                                 /* own up to 3 (1 cell: 6) faces    */
      size_t *cell = malloc (6 * m->ncells * sizeof *cell), k = 0;
      int *face = malloc (6 * m->ncells * sizeof *face);
      for (size_t g = 0; g < m->ngroups; g++)
        if (m->group[g].dim == m->dim - 1)
          for (size_t e = 0; e < m->group[g].n; e++, k++)
            cell[k] = m->group[g].cell[e], face[k] = m->group[g].face[e];
      lac_mesh_add_group (m, "all", m->dim - 1, 0, k, cell, face);
      free (cell);
      free (face);
      slave = "all";
    }
  status = lac_macromesh_build (&m, slave, opts, &M);
  check_status (status, LAC_SUCCESS, "%s: build", what);
  if (!status)
    {
      check_status (lac_mesh_check_orientation (m, 0, NULL), LAC_SUCCESS,
                    "%s: det J > 0 in every cell", what);
      check_conforming (m, surface, what);
    }
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 }, cut2d = { 0, 1 };
  lac_init ();
  for (int two = 0; two < 3; two++)
    for (size_t nb = 1; nb <= 3; nb += 2)
      {
        run (LAC_TET4, nb, two, NULL, "");
        run (LAC_TET10, nb, two, NULL, "");
        run (LAC_HEX8, nb, two, NULL, "pyramids");
        run (LAC_HEX8, nb, two, &six, "six");
        run (LAC_HEX20, nb, two, NULL, "six");
        run (LAC_HEX27, nb, two, NULL, "");
        run (LAC_TRI3, nb, two, &cut2d, "cut");
        run (LAC_QUAD4, nb, two, &cut2d, "cut");
        run (LAC_TRI3, nb, two, NULL, "gather");
        run (LAC_QUAD4, nb, two, NULL, "gather");
        run (LAC_TRI6, nb, two, NULL, "");
        run (LAC_QUAD8, nb, two, NULL, "");
        run (LAC_QUAD9, nb, two, NULL, "");
      }
  control (LAC_TET4);
  control (LAC_TET10);
  lac_finalize ();
  return check_summary ();
}
