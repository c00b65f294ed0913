/* t6-pairing-mesh.h -- contact surfaces built in code for the pairing
 * tests (t6xx) and bench/bench_pairing.c.  Header-only, static functions.
 *
 * A surface is a list of vertices given by parameters (u in 2D, (u, v) in
 * 3D) and facets given by 2, 3 or 4 vertices; a map S(param) -> (x, n)
 * places it in space and gives the outward normal wanted for its facets.
 * pm_add_side turns every facet into one thin cell (tri in 2D, tet or hex
 * in 3D) lying on the -n side of the surface, whose face on the surface is
 * the facet: vertices are shared between the facets of a side, every
 * other node is the cell's own; nodes on the surface (edge and face nodes
 * of quadratic facets) are placed exactly on S, the others on straight
 * lines.  All sides go into one mesh (pm_finish), or each into its own.
 */
#ifndef T6_PAIRING_MESH_H
#define T6_PAIRING_MESH_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem/lac_mesh.h"
#include "contact/lac_pairing.h"
#include "fem/lac_spaces.h"

/* The map of a surface: x = S(p), n = wanted outward normal at p. */
typedef void pm_map (const double *p, double *x, double *n, const void *ctx);

typedef struct pm_surf
{
  int pdim;          /* 1 (2D) or 2 (3D)                                */
  size_t nv;
  double *p;         /* nv*pdim parameters                               */
  size_t nf;
  int *fv;           /* nf*4 vertices (-1 past the facet's)              */
} pm_surf;

typedef struct pm_builder
{
  int dim;
  size_t nn, ncap;   double *x;       /* nodes                             */
  size_t nc, ccap;   lac_elem_type *type; size_t *ptr; int *conn; size_t kcap;
} pm_builder;

/* One side: facets (cell, face) of the builder's mesh. */
typedef struct pm_side
{
  size_t n;
  size_t *cell;
  int *face;
} pm_side;

/* ---- random numbers (xorshift64*, deterministic) ------------------------ */

static unsigned long long pm_seed = 88172645463325252ull;

static inline double
pm_rand (void)                                  /* uniform in [0, 1) */
{
  pm_seed ^= pm_seed >> 12, pm_seed ^= pm_seed << 25, pm_seed ^= pm_seed >> 27;
  return (double) ((pm_seed * 2685821657736338717ull) >> 11) * 0x1.0p-53;
}

/* ---- surfaces ------------------------------------------------------------ */

static inline void
pm_surf_free (pm_surf *s)
{
  free (s->p), free (s->fv);
  memset (s, 0, sizeof *s);
}

static inline void
pm_surf_alloc (pm_surf *s, int pdim, size_t nv, size_t nf)
{
  s->pdim = pdim, s->nv = nv, s->nf = nf;
  s->p = calloc (nv * (size_t) pdim + 1, sizeof *s->p);
  s->fv = malloc ((nf * 4 + 1) * sizeof *s->fv);
  for (size_t i = 0; i < nf * 4; i++)
    s->fv[i] = -1;
}

/* 2D: [a, b] cut at n-1 points (random if jitter > 0: uniform points,
 * sorted; regular if jitter == 0). */
static inline void
pm_line (pm_surf *s, double a, double b, size_t n, int random)
{
  pm_surf_alloc (s, 1, n + 1, n);
  for (size_t i = 0; i <= n; i++)
    s->p[i] = a + (b - a) * (double) i / (double) n;
  if (random)
    {
      for (size_t i = 1; i < n; i++)
        s->p[i] = a + (b - a) * pm_rand ();
      for (size_t i = 1; i < n; i++)       /* insertion sort */
        for (size_t j = i; j > 1 && s->p[j - 1] > s->p[j]; j--)
          {
            double t = s->p[j];
            s->p[j] = s->p[j - 1], s->p[j - 1] = t;
          }
    }
  for (size_t i = 0; i < n; i++)
    s->fv[4 * i] = (int) i, s->fv[4 * i + 1] = (int) i + 1;
}

/* 3D: an nx x ny grid on the rectangle [ax, bx] x [ay, by] of the
 * parameter plane, rotated by theta about its centre, interior vertices
 * moved by up to jitter x cell size; quadrangles (tri == 0), or each
 * quadrangle cut into two triangles along alternating diagonals
 * (tri == 1). */
static inline void
pm_rect (pm_surf *s, double ax, double bx, double ay, double by, size_t nx,
         size_t ny, double theta, double jitter, int tri)
{
  size_t nv = (nx + 1) * (ny + 1), nf = nx * ny * (tri ? 2 : 1), f = 0;
  double cx = 0.5 * (ax + bx), cy = 0.5 * (ay + by);
  double hx = (bx - ax) / (double) nx, hy = (by - ay) / (double) ny;
  pm_surf_alloc (s, 2, nv, nf);
  for (size_t j = 0; j <= ny; j++)
    for (size_t i = 0; i <= nx; i++)
      {
        double u = ax + hx * (double) i, v = ay + hy * (double) j;
        if (i > 0 && i < nx && j > 0 && j < ny)
          u += jitter * hx * (2 * pm_rand () - 1),
            v += jitter * hy * (2 * pm_rand () - 1);
        double *q = s->p + 2 * (j * (nx + 1) + i);
        q[0] = cx + cos (theta) * (u - cx) - sin (theta) * (v - cy);
        q[1] = cy + sin (theta) * (u - cx) + cos (theta) * (v - cy);
      }
  for (size_t j = 0; j < ny; j++)
    for (size_t i = 0; i < nx; i++)
      {
        int v0 = (int) (j * (nx + 1) + i), v1 = v0 + 1;
        int v3 = v0 + (int) nx + 1, v2 = v3 + 1;
        if (!tri)
          {
            int *q = s->fv + 4 * f++;
            q[0] = v0, q[1] = v1, q[2] = v2, q[3] = v3;
          }
        else if ((i + j) % 2 == 0)
          {
            int *q = s->fv + 4 * f++;
            q[0] = v0, q[1] = v1, q[2] = v2;
            q = s->fv + 4 * f++;
            q[0] = v0, q[1] = v2, q[2] = v3;
          }
        else
          {
            int *q = s->fv + 4 * f++;
            q[0] = v0, q[1] = v1, q[2] = v3;
            q = s->fv + 4 * f++;
            q[0] = v1, q[1] = v2, q[2] = v3;
          }
      }
}

/* The square [a, b]^2, n x n cells. */
static inline void
pm_grid (pm_surf *s, double a, double b, size_t nx, size_t ny, double theta,
         double jitter, int tri)
{
  pm_rect (s, a, b, a, b, nx, ny, theta, jitter, tri);
}

/* ---- the mesh builder ---------------------------------------------------- */

static inline size_t
pm_node (pm_builder *B, const double *x)
{
  if (B->nn == B->ncap)
    B->ncap = 2 * B->ncap + 64,
      B->x = realloc (B->x, B->ncap * (size_t) B->dim * sizeof *B->x);
  memcpy (B->x + B->nn * (size_t) B->dim, x, (size_t) B->dim * sizeof *x);
  return B->nn++;
}

static inline void
pm_builder_init (pm_builder *B, int dim)
{
  memset (B, 0, sizeof *B);
  B->dim = dim;
}

static inline void
pm_builder_free (pm_builder *B)
{
  free (B->x), free (B->type), free (B->ptr), free (B->conn);
  memset (B, 0, sizeof *B);
}

/* The volume cell of a facet type, and its linear counterpart. */
static inline lac_elem_type
pm_cell_type (lac_elem_type ft, lac_elem_type *lin)
{
  switch (ft)
    {
    case LAC_SEG2: *lin = LAC_TRI3; return LAC_TRI3;
    case LAC_SEG3: *lin = LAC_TRI3; return LAC_TRI6;
    case LAC_TRI3: *lin = LAC_TET4; return LAC_TET4;
    case LAC_TRI6: *lin = LAC_TET4; return LAC_TET10;
    case LAC_QUAD4: *lin = LAC_HEX8; return LAC_HEX8;
    case LAC_QUAD8: *lin = LAC_HEX8; return LAC_HEX20;
    case LAC_QUAD9: *lin = LAC_HEX8; return LAC_HEX27;
    default: *lin = LAC_ELEM_NONE; return LAC_ELEM_NONE;
    }
}

/* Add the cells of surface s (facets of type ft, mapped by S) to B; the
 * cells are `thick` deep.  Returns the side's (cell, face) list. */
static inline pm_side
pm_add_side (pm_builder *B, const pm_surf *s, lac_elem_type ft, pm_map *S,
             const void *ctx, double thick)
{
  lac_elem_type lt, ct = pm_cell_type (ft, &lt);
  const lac_refelem *ce = lac_refelem_get (ct), *le = lac_refelem_get (lt);
  const lac_refelem *fe = lac_refelem_get (ft);
  int d = B->dim, pd = s->pdim, nfv = fe->nvertices, nlv = le->nnodes;
  pm_side side = { s->nf, malloc ((s->nf + 1) * sizeof (size_t)),
                   malloc ((s->nf + 1) * sizeof (int)) };
  size_t *vnode = malloc ((s->nv + 1) * sizeof *vnode);
  for (size_t v = 0; v < s->nv; v++)
    {
      double x[3], n[3];
      S (s->p + v * (size_t) pd, x, n, ctx);
      vnode[v] = pm_node (B, x);
    }
  if (!B->ptr)
    B->ptr = calloc (1, sizeof *B->ptr);
  for (size_t f = 0; f < s->nf; f++)
    {
      int fv[4], tmp;
      double X[8 * 3], P[8 * 2], x[3], n[3], c[3] = { 0, 0, 0 };
      for (int a = 0; a < nfv; a++)
        fv[a] = s->fv[4 * f + (size_t) a];
      /* Orientation: the facet's own normal must be +n (its vertices are
       * then reordered for the cell as explained in the file block). */
      double pc[2] = { 0, 0 };
      for (int a = 0; a < nfv; a++)
        for (int k = 0; k < pd; k++)
          pc[k] += s->p[(size_t) fv[a] * (size_t) pd + (size_t) k] / nfv;
      S (pc, c, n, ctx);
      const double *y[4];
      for (int a = 0; a < nfv; a++)
        y[a] = B->x + vnode[fv[a]] * (size_t) d;
      double o;
      if (d == 2)
        o = (y[1][0] - y[0][0]) * n[1] - (y[1][1] - y[0][1]) * n[0];
      else
        {
          int i2 = nfv == 3 ? 2 : 3, i1 = nfv == 3 ? 1 : 2, j0 = nfv == 3 ? 0 : 1;
          double e1[3], e2[3];
          for (int k = 0; k < 3; k++)
            e1[k] = y[i1][k] - y[0][k], e2[k] = y[i2][k] - y[j0][k];
          o = (e1[1] * e2[2] - e1[2] * e2[1]) * n[0]
            + (e1[2] * e2[0] - e1[0] * e2[2]) * n[1]
            + (e1[0] * e2[1] - e1[1] * e2[0]) * n[2];
        }
      /* 2D and hex: the facet runs with normal +n (o < 0 in 2D, o > 0 for
       * quads); tet: the cell's base (0,1,2) must have normal -n. */
      int flip = d == 2 ? o > 0 : (nfv == 4 ? o < 0 : o > 0);
      if (flip)                   /* reverse: swap 0,1 / 1,2 / 1,3 */
        {
          int i = nfv == 2 ? 0 : 1;
          tmp = fv[i], fv[i] = fv[nfv - 1], fv[nfv - 1] = tmp;
        }
      /* The cell's vertices: facet vertices + vertices moved by -thick n. */
      int top[4], ntop = 0, ncv = 0;
      size_t cv[8];
      if (ct == LAC_HEX8 || ct == LAC_HEX20 || ct == LAC_HEX27)
        {
          for (int a = 0; a < 4; a++)
            {
              S (s->p + (size_t) fv[a] * 2, x, n, ctx);
              for (int k = 0; k < 3; k++)
                X[3 * a + k] = x[k] - thick * n[k], X[3 * (a + 4) + k] = x[k];
              for (int k = 0; k < 2; k++)
                P[2 * (a + 4) + k] = s->p[(size_t) fv[a] * 2 + (size_t) k];
              cv[a + 4] = vnode[fv[a]], top[ntop++] = a + 4;
            }
          ncv = 8;
        }
      else
        {
          for (int a = 0; a < nfv; a++)
            {
              S (s->p + (size_t) fv[a] * (size_t) pd, x, n, ctx);
              for (int k = 0; k < d; k++)
                X[d * a + k] = x[k];
              for (int k = 0; k < pd; k++)
                P[pd * a + k] = s->p[(size_t) fv[a] * (size_t) pd + (size_t) k];
              cv[a] = vnode[fv[a]], top[ntop++] = a;
            }
          for (int k = 0; k < d; k++)           /* apex: below the centre */
            X[d * nfv + k] = c[k] - thick * n[k];
          ncv = nfv + 1;
        }
      /* Nodes of the cell: from the linear weights L_v(xi_a). */
      if (B->nc == B->ccap)
        B->ccap = 2 * B->ccap + 64,
          B->type = realloc (B->type, B->ccap * sizeof *B->type),
          B->ptr = realloc (B->ptr, (B->ccap + 1) * sizeof *B->ptr);
      size_t k0 = B->ptr[B->nc];
      if (k0 + (size_t) ce->nnodes > B->kcap)
        B->kcap = 2 * (k0 + (size_t) ce->nnodes) + 64,
          B->conn = realloc (B->conn, B->kcap * sizeof *B->conn);
      for (int a = 0; a < ce->nnodes; a++)
        {
          double L[8], on = 0, p[2] = { 0, 0 };
          size_t node;
          lac_refelem_eval (le, ce->xi + a * ce->dim, L, NULL);
          for (int t = 0; t < ntop; t++)
            on += L[top[t]];
          if (a < nlv && fabs (L[a] - 1) < 1e-14)
            {                                        /* a vertex */
              int is_top = 0;
              for (int t = 0; t < ntop; t++)
                is_top |= top[t] == a;
              node = is_top ? cv[a] : pm_node (B, X + d * a);
            }
          else if (fabs (on - 1) < 1e-12)            /* on the facet */
            {
              for (int t = 0; t < ntop; t++)
                for (int k = 0; k < pd; k++)
                  p[k] += L[top[t]] * P[pd * top[t] + k];
              S (p, x, n, ctx);
              node = pm_node (B, x);
            }
          else                                       /* inside: straight */
            {
              for (int k = 0; k < d; k++)
                {
                  x[k] = 0;
                  for (int v = 0; v < ncv; v++)
                    x[k] += L[v] * X[d * v + k];
                }
              node = pm_node (B, x);
            }
          B->conn[k0 + (size_t) a] = (int) node;
        }
      B->type[B->nc] = ct;
      B->ptr[B->nc + 1] = k0 + (size_t) ce->nnodes;
      /* The local face whose vertices are the top vertices. */
      side.cell[f] = B->nc, side.face[f] = -1;
      for (int fc = 0; fc < ce->nfaces; fc++)
        {
          int hit = 0;
          for (int i = 0; i < nfv; i++)
            for (int t = 0; t < ntop; t++)
              hit += ce->face_node[fc][i] == top[t];
          if (hit == nfv)
            side.face[f] = fc;
        }
      B->nc++;
    }
  free (vnode);
  return side;
}

static inline void
pm_side_free (pm_side *s)
{
  free (s->cell), free (s->face);
  memset (s, 0, sizeof *s);
}

/* The mesh of everything added to B. */
static inline lac_mesh *
pm_finish (const pm_builder *B)
{
  lac_mesh *m = lac_mesh_alloc (B->dim, B->nn, B->nc, B->nc ? B->ptr[B->nc] : 0);
  if (!m)
    return NULL;
  memcpy (m->x, B->x, B->nn * (size_t) B->dim * sizeof *m->x);
  for (size_t c = 0; c < B->nc; c++)
    m->type[c] = B->type[c], m->ptr[c + 1] = B->ptr[c + 1], m->body[c] = 0;
  if (B->nc)
    memcpy (m->conn, B->conn, B->ptr[B->nc] * sizeof *m->conn);
  return m;
}

static inline lac_pairing_facets
pm_facets (const lac_mesh *m, const pm_side *s)
{
  lac_pairing_facets f = { m, s->n, s->cell, s->face };
  return f;
}

/* ---- maps ---------------------------------------------------------------- */

/* The plane z = z0 (3D) or the line y = z0 (2D); ctx: double[2] = { z0,
 * normal sign }. */
static inline void
pm_flat3 (const double *p, double *x, double *n, const void *ctx)
{
  const double *c = ctx;
  x[0] = p[0], x[1] = p[1], x[2] = c[0];
  n[0] = 0, n[1] = 0, n[2] = c[1];
}

static inline void
pm_flat2 (const double *p, double *x, double *n, const void *ctx)
{
  const double *c = ctx;
  x[0] = p[0], x[1] = c[0];
  n[0] = 0, n[1] = c[1];
}

/* Circle of radius R (2D, p = angle) and cylinder of radius R around z
 * (3D, p = (angle, z)); ctx: double[2] = { R, sign of the radial normal }. */
static inline void
pm_circle (const double *p, double *x, double *n, const void *ctx)
{
  const double *c = ctx;
  x[0] = c[0] * cos (p[0]), x[1] = c[0] * sin (p[0]);
  n[0] = c[1] * cos (p[0]), n[1] = c[1] * sin (p[0]);
}

static inline void
pm_cylinder (const double *p, double *x, double *n, const void *ctx)
{
  const double *c = ctx;
  x[0] = c[0] * cos (p[0]), x[1] = c[0] * sin (p[0]), x[2] = p[1];
  n[0] = c[1] * cos (p[0]), n[1] = c[1] * sin (p[0]), n[2] = 0;
}

/* Sphere of radius R, p = (longitude, latitude). */
static inline void
pm_sphere (const double *p, double *x, double *n, const void *ctx)
{
  const double *c = ctx;
  double cl = cos (p[1]);
  n[0] = c[1] * cl * cos (p[0]), n[1] = c[1] * cl * sin (p[0]);
  n[2] = c[1] * sin (p[1]);
  for (int k = 0; k < 3; k++)
    x[k] = c[0] * n[k] * c[1];
}

#endif /* T6_PAIRING_MESH_H */
