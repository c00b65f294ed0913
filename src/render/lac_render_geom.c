/* lac_render_geom.c -- what to draw: triangles and lines in space
 *
 * A 2D cell or a boundary face of a 3D cell is a tri or quad reference
 * element; it is cut into sub-triangles on a regular grid of its reference
 * element and each grid point is mapped with the element's own shape
 * functions (lac_refelem_eval), so that a quadratic face is drawn curved
 * and a nodal field is interpolated as the finite element interpolates it.
 * Grid: 1 x 1 for tri3, 2 x 2 for quad4 (bilinear), subdiv x subdiv for
 * quadratic elements.  Edges are the images of the reference edges, cut
 * likewise.
 *
 * The boundary of a 3D mesh is the set of faces that belong to exactly one
 * cell; faces are matched by their sorted vertex numbers in an open
 * addressing hash table (two bodies meshed separately have distinct nodes,
 * so their faces in contact are both boundary faces).
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "base/lac_mem.h"
#include "render/lac_render_internal.h"
#include "base/lac_status.h"

/* ---- growing lists ----------------------------------------------------- */

/* The capacity, doubled from cap (1024 at first), that holds need items. */
static size_t
grown (size_t cap, size_t need)
{
  cap = cap ? cap : 1024;
  while (cap < need)
    cap *= 2;
  return cap;
}

/* *a resized to cap * per doubles; 0 if out of memory (*a kept). */
static int
resize (double **a, size_t cap, size_t per)
{
  double *p = lac_realloc (*a, cap * per * sizeof *p);
  if (p)
    *a = p;
  return p != NULL;
}

static int
tris_reserve (lac_render_tris *T, size_t more)
{
  size_t cap = grown (T->cap, T->n + more);
  if (T->n + more <= T->cap)
    return LAC_SUCCESS;
  if (!resize (&T->x, cap, 9) || !resize (&T->nrm, cap, 9)
      || !resize (&T->v, cap, 3))
    LAC_ERROR (LAC_ENOMEM, "cannot allocate %zu triangles to draw", cap);
  T->cap = cap;
  return LAC_SUCCESS;
}

static int
lines_reserve (lac_render_lines *L, size_t more)
{
  size_t cap = grown (L->cap, L->n + more);
  if (L->n + more <= L->cap)
    return LAC_SUCCESS;
  if (!resize (&L->x, cap, 6) || !resize (&L->v, cap, 2))
    LAC_ERROR (LAC_ENOMEM, "cannot allocate %zu lines to draw", cap);
  L->cap = cap;
  return LAC_SUCCESS;
}

/* Append the segment from a to b with the value v at both ends (room
 * reserved). */
static void
line_add (lac_render_lines *L, const double *a, const double *b, double v)
{
  memcpy (L->x + 6 * L->n, a, 3 * sizeof *a);
  memcpy (L->x + 6 * L->n + 3, b, 3 * sizeof *b);
  L->v[2 * L->n] = L->v[2 * L->n + 1] = v;
  L->n++;
}

void
lac_render_geom_free (lac_render_geom *g)
{
  lac_render_tris *t[2] = { &g->body, &g->overlay };
  lac_render_lines *l[2] = { &g->edges, &g->thick };
  for (int k = 0; k < 2; k++)
    {
      lac_free (t[k]->x);
      lac_free (t[k]->nrm);
      lac_free (t[k]->v);
      lac_free (l[k]->x);
      lac_free (l[k]->v);
      memset (t[k], 0, sizeof *t[k]);
      memset (l[k], 0, sizeof *l[k]);
    }
}

/* ---- boundary faces ---------------------------------------------------- */

typedef struct face_entry
{
  int v[4];        /* sorted vertices, -1 padded */
  size_t cell;
  int face, count;
} face_entry;

static uint64_t
face_hash (const int *v)
{
  uint64_t h = 1469598103934665603ull;
  for (int k = 0; k < 4; k++)
    h = (h ^ (uint64_t) (uint32_t) v[k]) * 1099511628211ull;
  return h ^ (h >> 29);
}

static void
face_key (const lac_mesh *m, size_t c, const lac_refelem *re, int f, int *v)
{
  const lac_refelem *fe = lac_refelem_get (re->face_type[f]);
  int n = fe->nvertices;
  for (int k = 0; k < 4; k++)
    v[k] = k < n ? m->conn[m->ptr[c] + (size_t) re->face_node[f][k]] : -1;
  for (int i = 1; i < n; i++)            /* insertion sort, n <= 4 */
    for (int j = i; j > 0 && v[j - 1] > v[j]; j--)
      {
        int t = v[j];
        v[j] = v[j - 1];
        v[j - 1] = t;
      }
}

/* lac_render_boundary_faces: the faces of exactly one cell, in cell order. */
int
lac_render_boundary_faces (const lac_mesh *m, size_t *nf, size_t **cell,
                           int **face)
{
  size_t total = 0, cap = 16, ne = 0, nb = 0;
  face_entry *e;
  size_t *table;
  *nf = 0;
  *cell = NULL;
  *face = NULL;
  for (size_t c = 0; c < m->ncells; c++)
    total += (size_t) lac_refelem_get (m->type[c])->nfaces;
  while (cap < 2 * total)
    cap *= 2;
  e = lac_malloc ((total + 1) * sizeof *e);
  table = lac_malloc (cap * sizeof *table);
  if (!e || !table)
    {
      lac_free (e);
      lac_free (table);
      LAC_ERROR (LAC_ENOMEM, "cannot allocate the face table (%zu faces)",
                 total);
    }
  for (size_t k = 0; k < cap; k++)
    table[k] = SIZE_MAX;
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      for (int f = 0; f < re->nfaces; f++)
        {
          int v[4];
          size_t h;
          face_key (m, c, re, f, v);
          h = (size_t) face_hash (v) & (cap - 1);
          while (table[h] != SIZE_MAX && memcmp (e[table[h]].v, v, sizeof v))
            h = (h + 1) & (cap - 1);           /* linear probing */
          if (table[h] != SIZE_MAX)
            {
              e[table[h]].count++;
              continue;
            }
          table[h] = ne;
          memcpy (e[ne].v, v, sizeof v);
          e[ne].cell = c;
          e[ne].face = f;
          e[ne++].count = 1;
        }
    }
  lac_free (table);
  for (size_t k = 0; k < ne; k++)
    nb += e[k].count == 1;
  *cell = lac_malloc ((nb + 1) * sizeof **cell);
  *face = lac_malloc ((nb + 1) * sizeof **face);
  if (!*cell || !*face)
    {
      lac_free (e);
      lac_free (*cell);
      lac_free (*face);
      *cell = NULL;
      *face = NULL;
      LAC_ERROR (LAC_ENOMEM, "cannot allocate %zu boundary faces", nb);
    }
  for (size_t k = 0; k < ne; k++)
    if (e[k].count == 1)
      {
        (*cell)[*nf] = e[k].cell;
        (*face)[(*nf)++] = e[k].face;
      }
  lac_free (e);
  return LAC_SUCCESS;
}

/* ---- tessellation of one tri or quad ----------------------------------- */

/* Grid points of a tri (i/n, j/n; i + j <= n) or quad (-1 + 2i/n, ...). */
static size_t
grid_index (lac_shape s, int n, int i, int j)
{
  if (s == LAC_SHAPE_TRI)
    return (size_t) (j * (n + 1) - j * (j - 1) / 2 + i);
  return (size_t) (j * (n + 1) + i);
}

static void
grid_point (lac_shape s, int n, int i, int j, double *xi)
{
  if (s == LAC_SHAPE_TRI)
    {
      xi[0] = (double) i / n;
      xi[1] = (double) j / n;
    }
  else
    {
      xi[0] = -1.0 + 2.0 * i / n;
      xi[1] = -1.0 + 2.0 * j / n;
    }
}

static int
nsub_of (const lac_refelem *fe, int subdiv)
{
  if (fe->order >= 2)
    return subdiv;
  return fe->shape == LAC_SHAPE_QUAD ? 2 : 1;
}

/* Position, normal (t_1 x t_2, 3D) and value at xi of an element with node
 * positions P (3 per node) and values V (NULL: cval). */
static void
map_point (const lac_refelem *fe, const double *P, const double *V,
           double cval, const double *xi, double *x, double *nrm, double *v)
{
  double N[LAC_MAX_NODES], dN[LAC_MAX_NODES * 3], t1[3] = { 0 },
    t2[3] = { 0 };
  lac_refelem_eval (fe, xi, N, dN);
  x[0] = x[1] = x[2] = 0;
  *v = V ? 0 : cval;
  for (int a = 0; a < fe->nnodes; a++)
    for (int i = 0; i < 3; i++)
      {
        x[i] += N[a] * P[3 * a + i];
        t1[i] += dN[a * fe->dim] * P[3 * a + i];
        t2[i] += dN[a * fe->dim + 1] * P[3 * a + i];
      }
  for (int a = 0; V && a < fe->nnodes; a++)
    *v += N[a] * V[a];
  nrm[0] = t1[1] * t2[2] - t1[2] * t2[1];
  nrm[1] = t1[2] * t2[0] - t1[0] * t2[2];
  nrm[2] = t1[0] * t2[1] - t1[1] * t2[0];
}

/* Append the sub-triangles of one tri/quad element. */
static int
add_patch (lac_render_tris *T, const lac_refelem *fe, const double *P,
           const double *V, double cval, int subdiv)
{
  enum { NMAX = 16 };
  double gx[(NMAX + 1) * (NMAX + 1)][3], gn[(NMAX + 1) * (NMAX + 1)][3],
    gv[(NMAX + 1) * (NMAX + 1)];
  int n = nsub_of (fe, subdiv), tri = fe->shape == LAC_SHAPE_TRI, status;
  n = n < 1 ? 1 : n > NMAX ? NMAX : n;
  if ((status = tris_reserve (T, 2 * (size_t) (n * n))))
    return status;
  for (int j = 0; j <= n; j++)
    for (int i = 0; i <= (tri ? n - j : n); i++)
      {
        double xi[2];
        size_t p = grid_index (fe->shape, n, i, j);
        grid_point (fe->shape, n, i, j, xi);
        map_point (fe, P, V, cval, xi, gx[p], gn[p], &gv[p]);
      }
  for (int j = 0; j < n; j++)
    for (int i = 0; i < (tri ? n - j : n); i++)
      {
        size_t q[2][3];
        int nt = 2;
        size_t a = grid_index (fe->shape, n, i, j),
          b = grid_index (fe->shape, n, i + 1, j),
          c = grid_index (fe->shape, n, i, j + 1);
        if (tri)
          {
            size_t d = i + j < n - 1 ? grid_index (fe->shape, n, i + 1, j + 1)
                                     : 0;
            q[0][0] = a, q[0][1] = b, q[0][2] = c;
            q[1][0] = b, q[1][1] = d, q[1][2] = c;
            nt = i + j < n - 1 ? 2 : 1;
          }
        else
          {
            size_t d = grid_index (fe->shape, n, i + 1, j + 1);
            q[0][0] = a, q[0][1] = b, q[0][2] = d;
            q[1][0] = a, q[1][1] = d, q[1][2] = c;
          }
        for (int t = 0; t < nt; t++, T->n++)
          for (int k = 0; k < 3; k++)
            {
              memcpy (T->x + 9 * T->n + 3 * k, gx[q[t][k]], 3 * sizeof (double));
              memcpy (T->nrm + 9 * T->n + 3 * k, gn[q[t][k]],
                      3 * sizeof (double));
              T->v[3 * T->n + k] = gv[q[t][k]];
            }
      }
  return LAC_SUCCESS;
}

/* Append the edges of one tri/quad element (value NaN: ink). */
static int
add_edges (lac_render_lines *L, const lac_refelem *fe, const double *P,
           int subdiv)
{
  int n = fe->order >= 2 ? subdiv : 1, status;
  n = n < 1 ? 1 : n;
  if ((status = lines_reserve (L, (size_t) (fe->nfaces * n))))
    return status;
  for (int f = 0; f < fe->nfaces; f++)
    {
      const double *xa = fe->xi + 2 * fe->face_node[f][0],
        *xb = fe->xi + 2 * fe->face_node[f][1];
      double prev[3], nrm[3], v;
      for (int s = 0; s <= n; s++)
        {
          double t = (double) s / n, xi[2], x[3];
          xi[0] = (1 - t) * xa[0] + t * xb[0];
          xi[1] = (1 - t) * xa[1] + t * xb[1];
          map_point (fe, P, NULL, 0, xi, x, nrm, &v);
          if (s > 0)
            line_add (L, prev, x, NAN);
          memcpy (prev, x, sizeof x);
        }
    }
  return LAC_SUCCESS;
}

/* Node positions (3 per node, z = 0 in 2D) and values of nodes[0..nn-1]. */
static void
gather (const lac_mesh *m, const double *u, double scale, const double *field,
        const int *nodes, int nn, double *P, double *V)
{
  size_t d = (size_t) m->dim;
  for (int a = 0; a < nn; a++)
    {
      size_t p = (size_t) nodes[a];
      for (size_t i = 0; i < 3; i++)
        P[3 * a + (int) i] = i < d ? m->x[p * d + i]
                                     + (u ? scale * u[p * d + i] : 0) : 0;
      if (V)
        V[a] = field[p];
    }
}

static int
add_element (lac_render_geom *g, const lac_mesh *m, const double *u,
             double scale, const double *field, const int *nodes,
             const lac_refelem *fe, double cval, int subdiv, int edges)
{
  double P[3 * LAC_MAX_NODES], V[LAC_MAX_NODES];
  int status;
  gather (m, u, scale, field, nodes, fe->nnodes, P, field ? V : NULL);
  if ((status = add_patch (&g->body, fe, P, field ? V : NULL, cval, subdiv)))
    return status;
  return edges ? add_edges (&g->edges, fe, P, subdiv) : LAC_SUCCESS;
}

/* lac_render_geom_mesh: the 2D cells or the 3D boundary faces. */
int
lac_render_geom_mesh (lac_render_geom *g, const lac_mesh *m, const double *u,
                      double scale, const double *field, int subdiv, int edges)
{
  size_t nf = 0, *cell = NULL;
  int *face = NULL, status = LAC_SUCCESS, nodes[LAC_MAX_NODES];
  if (m->dim == 2)
    {
      for (size_t c = 0; c < m->ncells && !status; c++)
        {
          const lac_refelem *re = lac_refelem_get (m->type[c]);
          if (re->dim != 2)
            LAC_ERROR (LAC_EINVAL, "cell %zu is a %s in a 2D mesh", c,
                       re->name);
          for (int a = 0; a < re->nnodes; a++)
            nodes[a] = m->conn[m->ptr[c] + (size_t) a];
          status = add_element (g, m, u, scale, field, nodes, re, NAN,
                                subdiv, edges);
        }
      return status;
    }
  if ((status = lac_render_boundary_faces (m, &nf, &cell, &face)))
    return status;
  for (size_t k = 0; k < nf && !status; k++)
    {
      lac_elem_type ft;
      int nn = lac_mesh_facet_nodes (m, cell[k], face[k], nodes, &ft);
      if (nn < 0)
        status = -nn;
      else
        status = add_element (g, m, u, scale, field, nodes,
                              lac_refelem_get (ft), NAN, subdiv, edges);
    }
  lac_free (cell);
  lac_free (face);
  return status;
}

/* A facet of a 2D mesh (seg2/seg3) as thick line pieces of value v. */
static int
add_thick (lac_render_lines *L, const lac_refelem *fe, const double *P,
           double v, int subdiv)
{
  int n = fe->order >= 2 ? subdiv : 1, status;
  double prev[3];
  n = n < 1 ? 1 : n;
  if ((status = lines_reserve (L, (size_t) n)))
    return status;
  for (int s = 0; s <= n; s++)
    {
      double xi = -1.0 + 2.0 * s / n, N[LAC_MAX_NODES], x[3] = { 0 };
      lac_refelem_eval (fe, &xi, N, NULL);
      for (int a = 0; a < fe->nnodes; a++)
        for (int i = 0; i < 3; i++)
          x[i] += N[a] * P[3 * a + i];
      if (s > 0)
        line_add (L, prev, x, v);
      memcpy (prev, x, sizeof x);
    }
  return LAC_SUCCESS;
}

/* lac_render_geom_facets: facets with one value each. */
int
lac_render_geom_facets (lac_render_geom *g, const lac_mesh *m,
                        const double *u, double scale, size_t n,
                        const size_t *cell, const int *face,
                        const double *value, int subdiv, int edges)
{
  int nodes[LAC_MAX_NODES], status = LAC_SUCCESS;
  for (size_t k = 0; k < n && !status; k++)
    {
      lac_elem_type ft;
      const lac_refelem *fe;
      double P[3 * LAC_MAX_NODES];
      int nn = lac_mesh_facet_nodes (m, cell[k], face[k], nodes, &ft);
      if (nn < 0)
        return -nn;
      fe = lac_refelem_get (ft);
      if (m->dim == 2)
        {
          gather (m, u, scale, NULL, nodes, nn, P, NULL);
          status = add_thick (&g->thick, fe, P, value[k], subdiv);
        }
      else
        status = add_element (g, m, u, scale, NULL, nodes, fe, value[k],
                              subdiv, edges);
    }
  return status;
}

/* ---- discs ------------------------------------------------------------- */

static const double PI = 3.14159265358979323846;

/* Eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix A
 * (row-major, destroyed), by cyclic Jacobi rotations. */
static void
smallest_eigvec (double *A, double *vec)
{
  double V[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  int kmin = 0;
  for (int sweep = 0; sweep < 30; sweep++)
    {
      double off = fabs (A[1]) + fabs (A[2]) + fabs (A[5]);
      if (off < 1e-14 * (fabs (A[0]) + fabs (A[4]) + fabs (A[8])) + 1e-300)
        break;
      for (int p = 0; p < 2; p++)
        for (int q = p + 1; q < 3; q++)
          {
            double apq = A[3 * p + q], th, c, s;
            if (apq == 0)
              continue;
            th = 0.5 * atan2 (2 * apq, A[3 * q + q] - A[3 * p + p]);
            c = cos (th);
            s = sin (th);
            for (int k = 0; k < 3; k++)     /* A <- A G, V <- V G */
              {
                double akp = A[3 * k + p], akq = A[3 * k + q];
                A[3 * k + p] = c * akp - s * akq;
                A[3 * k + q] = s * akp + c * akq;
                akp = V[3 * k + p];
                akq = V[3 * k + q];
                V[3 * k + p] = c * akp - s * akq;
                V[3 * k + q] = s * akp + c * akq;
              }
            for (int k = 0; k < 3; k++)     /* A <- G^T A */
              {
                double apk = A[3 * p + k], aqk = A[3 * q + k];
                A[3 * p + k] = c * apk - s * aqk;
                A[3 * q + k] = s * apk + c * aqk;
              }
          }
    }
  for (int k = 1; k < 3; k++)
    if (A[4 * k] < A[4 * kmin])
      kmin = k;
  for (int i = 0; i < 3; i++)
    vec[i] = V[3 * i + kmin];
}

/* Normal of the plane fitted to the points within distance r of point i
 * (all points when r <= 0); 0 if fewer than 3 points. */
static int
fit_normal (size_t n, const double *xyz, size_t i, double r, double *nrm)
{
  double c[3] = { 0 }, A[9] = { 0 };
  size_t cnt = 0;
  for (size_t j = 0; j < n; j++)
    {
      double d2 = 0;
      for (int k = 0; k < 3; k++)
        d2 += (xyz[3 * j + k] - xyz[3 * i + k])
              * (xyz[3 * j + k] - xyz[3 * i + k]);
      if (r > 0 && d2 > r * r)
        continue;
      for (int k = 0; k < 3; k++)
        c[k] += xyz[3 * j + k];
      cnt++;
    }
  if (cnt < 3)
    return 0;
  for (int k = 0; k < 3; k++)
    c[k] /= (double) cnt;
  for (size_t j = 0; j < n; j++)
    {
      double d[3], d2 = 0;
      for (int k = 0; k < 3; k++)
        {
          d[k] = xyz[3 * j + k] - c[k];
          d2 += (xyz[3 * j + k] - xyz[3 * i + k])
                * (xyz[3 * j + k] - xyz[3 * i + k]);
        }
      if (r > 0 && d2 > r * r)
        continue;
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
          A[3 * a + b] += d[a] * d[b];
    }
  smallest_eigvec (A, nrm);
  return 1;
}

/* Distance from point i to its nearest other point (0 if alone). */
static double
nearest (size_t n, const double *xyz, size_t i)
{
  double best = INFINITY;
  for (size_t j = 0; j < n; j++)
    {
      double d2 = 0;
      if (j == i)
        continue;
      for (int k = 0; k < 3; k++)
        d2 += (xyz[3 * j + k] - xyz[3 * i + k])
              * (xyz[3 * j + k] - xyz[3 * i + k]);
      best = d2 < best ? d2 : best;
    }
  return isfinite (best) ? sqrt (best) : 0;
}

static int
add_disc (lac_render_tris *T, const double *c, const double *nrm, double r,
          double v)
{
  enum { NSEG = 24 };
  double e1[3], e2[3], a[3] = { 1, 0, 0 }, len;
  int status;
  if (fabs (nrm[0]) > 0.8)
    a[0] = 0, a[1] = 1;
  e1[0] = nrm[1] * a[2] - nrm[2] * a[1];          /* e1 = n x a */
  e1[1] = nrm[2] * a[0] - nrm[0] * a[2];
  e1[2] = nrm[0] * a[1] - nrm[1] * a[0];
  len = sqrt (e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int k = 0; k < 3; k++)
    e1[k] /= len;
  e2[0] = nrm[1] * e1[2] - nrm[2] * e1[1];        /* e2 = n x e1 */
  e2[1] = nrm[2] * e1[0] - nrm[0] * e1[2];
  e2[2] = nrm[0] * e1[1] - nrm[1] * e1[0];
  if ((status = tris_reserve (T, NSEG)))
    return status;
  for (int s = 0; s < NSEG; s++, T->n++)
    {
      double t0 = 2 * PI * s / NSEG, t1 = 2 * PI * (s + 1) / NSEG;
      double *x = T->x + 9 * T->n;
      for (int k = 0; k < 3; k++)
        {
          x[k] = c[k];
          x[3 + k] = c[k] + r * (cos (t0) * e1[k] + sin (t0) * e2[k]);
          x[6 + k] = c[k] + r * (cos (t1) * e1[k] + sin (t1) * e2[k]);
        }
      for (int k = 0; k < 9; k++)
        T->nrm[9 * T->n + k] = nrm[k % 3];
      T->v[3 * T->n] = T->v[3 * T->n + 1] = T->v[3 * T->n + 2] = v;
    }
  return LAC_SUCCESS;
}

/* lac_render_geom_discs: discs in the plane fitted to their neighbours
 * (3D; z = 0 in 2D), radius 0.45 x the distance to the nearest point when
 * not given, at most half that distance when given.  Neighbour searches are all-pairs: above 20000 points the
 * normal is the global one and the automatic radius comes from the bounding
 * box. */
int
lac_render_geom_discs (lac_render_geom *g, size_t n, const double *xyz,
                       const double *radius, const double *value)
{
  int big = n > 20000, status = LAC_SUCCESS;
  double gn[3] = { 0, 0, 1 }, lo[3], hi[3], rbig;
  for (int k = 0; k < 3; k++)
    lo[k] = INFINITY, hi[k] = -INFINITY;
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < 3; k++)
      {
        lo[k] = fmin (lo[k], xyz[3 * i + k]);
        hi[k] = fmax (hi[k], xyz[3 * i + k]);
      }
  rbig = n ? 0.45 * sqrt (fmax ((hi[0] - lo[0]) * (hi[1] - lo[1]),
                              fmax ((hi[1] - lo[1]) * (hi[2] - lo[2]),
                                    (hi[0] - lo[0]) * (hi[2] - lo[2])))
                         / (double) n) : 0;
  if (g->dim == 3 && !fit_normal (n, xyz, 0, 0, gn))
    gn[0] = 0, gn[1] = 0, gn[2] = 1;
  for (size_t i = 0; i < n && !status; i++)
    {
      double dn = big ? 0 : nearest (n, xyz, i), nrm[3] = { gn[0], gn[1],
                                                               gn[2] },
        r = radius ? radius[i] : big ? rbig : 0.45 * dn;
      if (radius && dn > 0 && r > 0.5 * dn)
        r = 0.5 * dn;                    /* discs do not overlap */
      if (!(r > 0))
        r = rbig > 0 ? rbig : 1;
      if (g->dim == 3 && !big)
        fit_normal (n, xyz, i, 3.0 * r, nrm);
      status = add_disc (&g->overlay, xyz + 3 * i, nrm, r, value[i]);
    }
  return status;
}
