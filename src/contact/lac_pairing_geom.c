/* lac_pairing_geom.c -- geometry kernels of the pairing          [LAC §4.6]
 *
 * The pieces of one (slave, master) test, each a pure function of the two
 * facets: the overlap of the linearised facets in a plane chart of the
 * slave (an interval of its reference segment in 2D, a clipped polygon in
 * 3D), and the integration points on that overlap.  The projection of a
 * point onto a face map (Newton with line search in reference coordinates)
 * is in lac_pairing_project.c; the search that decides which pairs to test
 * is in lac_pairing_search.c.
 *
 * Tolerances are relative: reference coordinates are O(1) whatever the
 * facet size, so thresholds on them (1e-14 for an empty overlap, 1e-13 for
 * a full one) are relative to the facet; physical residuals are measured
 * against the facet diameter h plus the rounding level of |x|.
 *
 * References: I. E. Sutherland, G. W. Hodgman, "Reentrant polygon
 * clipping", CACM 17 (1974).
 */
#include "contact/lac_pairing_geom.h"

#include <math.h>
#include <string.h>

#include "contact/lac_pairing_project.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

#define EMPTY_TOL 1e-14      /* overlap measure / reference measure       */
#define FULL_TOL 1e-13       /* 1 - overlap measure / reference measure    */
#define SNAP_TOL 1e-12       /* snap to the reference cell's lines         */

/* ---- polygons ----------------------------------------------------------- */

/* Signed area, shoelace formula: A = 1/2 sum (x_i y_{i+1} - x_{i+1} y_i). */
double
lac_pairing_polygon_area (int n, const double *q)
{
  double a = 0;
  for (int i = 0; i < n; i++)
    {
      int j = (i + 1) % n;
      a += q[2 * i] * q[2 * j + 1] - q[2 * j] * q[2 * i + 1];
    }
  return 0.5 * a;
}

double
lac_pairing_overlap_fraction (const lac_pairing_facet *f, int np,
                              const double *poly)
{
  if (f->sdim == 2)                        /* an interval of [-1, 1] */
    return 0.5 * (poly[1] - poly[0]);
  return lac_pairing_polygon_area (np, poly)
         / lac_pairing_polygon_area (f->nz, f->z);
}

/* lac_pairing_clip: Sutherland-Hodgman clipping of the polygon q against
 * the convex polygon c.
 *
 *   c is the intersection of the half-planes on the left of its edges
 *   (c is counter-clockwise): f(P) = (C_{i+1} - C_i) x (P - C_i) >= 0.  The
 *   polygon is clipped by one half-plane after the other: walking its
 *   edges P -> Q, a vertex P inside is kept and an edge that crosses the
 *   line contributes the crossing P + s (Q - P), s = f(P) / (f(P) - f(Q)).
 *   Since c is convex the result is exact for a convex subject (a projected
 *   master facet); for a non-convex one (a strongly warped master quad) it
 *   may contain zero-width spikes along the boundary of c, which carry no
 *   area.  Consecutive points closer than 1e-14 are merged, so that
 *   matching facets do not produce rounding-size slivers.
 *
 *   [in]  nc, c  the clip polygon (3 or 4 points, counter-clockwise)
 *   [in]  n, q   the subject polygon (3 or 4 points, either orientation)
 *   [out] out    the clipped polygon (same orientation as q), at most
 *                LAC_PAIRING_MAXPOLY points
 *   returns the number of points, 0 if the overlap has no interior
 */
int
lac_pairing_clip (int nc, const double *c, int n, const double *q,
                  double *out)
{
  double bufa[4 * LAC_PAIRING_MAXPOLY], bufb[4 * LAC_PAIRING_MAXPOLY];
  double *a = bufa, *b = bufb;
  int na = n, nb;

  if (n < 3 || n > 4 || nc < 3 || nc > 4)
    return 0;
  memcpy (a, q, 2 * (size_t) n * sizeof *q);
  for (int e = 0; e < nc && na > 0; e++)
    {
      const double *C0 = c + 2 * e, *C1 = c + 2 * ((e + 1) % nc);
      double tx = C1[0] - C0[0], ty = C1[1] - C0[1];
      nb = 0;
      for (int i = 0; i < na; i++)
        {
          const double *P = a + 2 * i, *Q = a + 2 * ((i + 1) % na);
          double fp = tx * (P[1] - C0[1]) - ty * (P[0] - C0[0]);
          double fq = tx * (Q[1] - C0[1]) - ty * (Q[0] - C0[0]);
          if (nb + 2 > 2 * LAC_PAIRING_MAXPOLY)
            return 0;                   /* cannot happen for n, nc <= 4 */
          if (fp >= 0)                  /* P inside: keep it */
            b[2 * nb] = P[0], b[2 * nb + 1] = P[1], nb++;
          if ((fp > 0 && fq < 0) || (fp < 0 && fq > 0))
            {                           /* the edge crosses the line */
              double s = fp / (fp - fq);
              b[2 * nb] = P[0] + s * (Q[0] - P[0]);
              b[2 * nb + 1] = P[1] + s * (Q[1] - P[1]);
              nb++;
            }
        }
      double *tmp = a;
      a = b, b = tmp, na = nb;
    }
  nb = 0;                               /* merge near-duplicates */
  for (int i = 0; i < na; i++)
    {
      const double *P = a + 2 * i;
      if (nb > 0 && fabs (P[0] - out[2 * nb - 2]) <= 1e-14
          && fabs (P[1] - out[2 * nb - 1]) <= 1e-14)
        continue;
      if (nb == LAC_PAIRING_MAXPOLY)
        return 0;
      out[2 * nb] = P[0], out[2 * nb + 1] = P[1], nb++;
    }
  while (nb > 1 && fabs (out[0] - out[2 * nb - 2]) <= 1e-14
         && fabs (out[1] - out[2 * nb - 1]) <= 1e-14)
    nb--;
  return nb >= 3 ? nb : 0;
}

/* ---- facets and their charts -------------------------------------------- */

/* Chart coordinates of the point P: the orthogonal projection of P onto
 * the chart plane x = o + zeta_1 e_1 + zeta_2 e_2, solved from the normal
 * equations G zeta = (r.e_1, r.e_2), r = P - o (G^{-1} is f->g). */
static void
chart_coords (const lac_pairing_facet *f, const double *P, double *z)
{
  double r[3] = { P[0] - f->o[0], P[1] - f->o[1], P[2] - f->o[2] };
  double r1 = lac_vec_dot (3, r, f->e), r2 = lac_vec_dot (3, r, f->e + 3);
  z[0] = f->g[0] * r1 + f->g[1] * r2;
  z[1] = f->g[1] * r1 + f->g[2] * r2;
}

/* The chart of a 3D facet.  Triangle: its own affine map, o = v_0,
 * e_k = v_k - v_0, so that chart and reference coordinates coincide and
 * the chart polygon is the reference triangle.  Quadrangle: the plane
 * tangent to its bilinear map at the centre, o = c, e_1 = (v_1 + v_2 - v_0
 * - v_3)/4, e_2 = (v_2 + v_3 - v_0 - v_1)/4; its chart polygon is the
 * projection of its vertices, snapped to the reference square (-1,1)^2
 * when within 1e-12 (a parallelogram: the chart is then its own map); it
 * must be convex (the clipping polygon, and a bilinear map that can be
 * inverted inside it).  Returns LAC_ESING for a degenerate chart or a
 * non-convex quadrangle. */
static int
chart_set (lac_pairing_facet *f)
{
  const double *v = f->xe;
  int tri = f->lin->type == LAC_TRI3;
  for (int i = 0; i < 3; i++)
    if (tri)
      f->o[i] = v[i], f->e[i] = v[3 + i] - v[i], f->e[3 + i] = v[6 + i] - v[i];
    else
      {
        f->o[i] = f->c[i];
        f->e[i] = (v[3 + i] + v[6 + i] - v[i] - v[9 + i]) / 4;
        f->e[3 + i] = (v[6 + i] + v[9 + i] - v[i] - v[3 + i]) / 4;
      }
  double g11 = lac_vec_dot (3, f->e, f->e);
  double g12 = lac_vec_dot (3, f->e, f->e + 3);
  double g22 = lac_vec_dot (3, f->e + 3, f->e + 3);
  double det = g11 * g22 - g12 * g12;
  if (!(det > 1e-24 * g11 * g22))
    return LAC_ESING;
  f->g[0] = g22 / det, f->g[1] = -g12 / det, f->g[2] = g11 / det;
  f->nz = f->lin->nnodes;
  for (int a = 0; a < f->nz; a++)
    {
      if (tri)
        {
          f->z[2 * a] = f->lin->xi[2 * a];
          f->z[2 * a + 1] = f->lin->xi[2 * a + 1];
          continue;
        }
      chart_coords (f, v + 3 * a, f->z + 2 * a);
      for (int k = 0; k < 2; k++)
        if (fabs (f->z[2 * a + k] - f->lin->xi[2 * a + k]) <= SNAP_TOL)
          f->z[2 * a + k] = f->lin->xi[2 * a + k];
    }
  for (int a = 0; !tri && a < 4; a++)           /* a convex quadrangle */
    {
      const double *A = f->z + 2 * a, *B = f->z + 2 * ((a + 1) % 4);
      const double *C = f->z + 2 * ((a + 2) % 4);
      if (!((B[0] - A[0]) * (C[1] - B[1]) - (B[1] - A[1]) * (C[0] - B[0])
            > 1e-12))
        return LAC_ESING;
    }
  f->affine = tri;
  for (int k = 0; !tri && k < 8; k++)
    f->affine = k ? f->affine && f->z[k] == f->lin->xi[k]
      : f->z[k] == f->lin->xi[k];
  return LAC_SUCCESS;
}

/* lac_pairing_facet_set: gather the facet's nodes, centre, linearised
 * normal, diameter and (3D) chart. */
int
lac_pairing_facet_set (lac_pairing_facet *f, lac_elem_type type, int sdim,
                       const double *xe)
{
  const lac_refelem *re = lac_refelem_get (type);
  lac_elem_type lt;
  if (!re || re->dim != sdim - 1 || (sdim != 2 && sdim != 3))
    LAC_ERROR (LAC_EINVAL, "a %s facet in %d-D: expected seg2/seg3 in 2D, "
               "tri3/tri6/quad4/quad8/quad9 in 3D", re ? re->name : "(bad)",
               sdim);
  lt = re->shape == LAC_SHAPE_LINE ? LAC_SEG2
    : re->shape == LAC_SHAPE_TRI ? LAC_TRI3 : LAC_QUAD4;
  f->re = re, f->lin = lac_refelem_get (lt), f->sdim = sdim;
  memcpy (f->xe, xe, (size_t) (re->nnodes * sdim) * sizeof *xe);
  int nv = re->nvertices;
  const double *v = f->xe;
  double n[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; i++)
    {
      f->c[i] = 0;
      for (int a = 0; i < sdim && a < nv; a++)
        f->c[i] += v[a * sdim + i] / nv;
    }
  f->h = lac_pairing_face_diameter (re, sdim, xe);
  f->affine = 1;                       /* 2D: the reference segment */
  if (sdim == 2)
    n[0] = v[3] - v[1], n[1] = -(v[2] - v[0]);    /* (t_y, -t_x) */
  else
    {
      double e1[3], e2[3];
      int i1 = nv == 3 ? 1 : 2, i2 = nv == 3 ? 2 : 3, j = nv == 3 ? 0 : 1;
      for (int i = 0; i < 3; i++)
        {                     /* tri: (v1-v0)x(v2-v0); quad: (v2-v0)x(v3-v1) */
          e1[i] = v[i1 * 3 + i] - v[i];
          e2[i] = v[i2 * 3 + i] - v[j * 3 + i];
        }
      lac_vec_cross (e1, e2, n);
    }
  double nn = lac_vec_norm (3, n);
  if (!(f->h > 0) || !(nn > 1e-12 * pow (f->h, sdim - 1)))
    LAC_ERROR (LAC_ESING, "degenerate %s facet (diameter %g, normal %g)",
               re->name, f->h, nn);
  if (sdim == 3 && chart_set (f))
    LAC_ERROR (LAC_ESING, "%s facet is not a convex quadrangle (a vertex "
               "angle >= 180 degrees: an inverted cell?)", re->name);
  for (int i = 0; i < 3; i++)
    f->n[i] = n[i] / nn;
  return LAC_SUCCESS;
}

/* Snap the chart point z of a master vertex onto the slave's chart
 * polygon when it is within SNAP_TOL (chart units, i.e. relative to the
 * facet) of one of its vertices, else of one of its edge lines.  On
 * matching or nearly matching meshes this turns rounding-size slivers into
 * exact coincidences; the snap depends on the vertex alone, so the master
 * facets sharing it see the same point and still tile the slave facet. */
static void
snap_vertex (const lac_pairing_facet *s, double *z)
{
  for (int a = 0; a < s->nz; a++)
    if (fabs (z[0] - s->z[2 * a]) <= SNAP_TOL
        && fabs (z[1] - s->z[2 * a + 1]) <= SNAP_TOL)
      {
        z[0] = s->z[2 * a], z[1] = s->z[2 * a + 1];
        return;
      }
  for (int a = 0; a < s->nz; a++)
    {
      const double *A = s->z + 2 * a, *B = s->z + 2 * ((a + 1) % s->nz);
      double t[2] = { B[0] - A[0], B[1] - A[1] };
      double l = sqrt (t[0] * t[0] + t[1] * t[1]);
      double d = (t[0] * (z[1] - A[1]) - t[1] * (z[0] - A[0])) / l;
      if (fabs (d) > SNAP_TOL)
        continue;
      if (t[1] == 0)                       /* horizontal line: exact */
        z[1] = A[1];
      else if (t[0] == 0)                  /* vertical line: exact   */
        z[0] = A[0];
      else
        z[0] -= d * t[1] / l, z[1] += d * t[0] / l;
    }
}

/* lac_pairing_overlap: the overlap of the linearised facets in the chart
 * of the slave.                                          [LAC §4.6, item 3]
 *
 *   Step 1: orientation filter, -n_s.n_m > facing (linearised normals at
 *           the facet centres).
 *   Step 2: 2D: the master end vertices are projected orthogonally onto
 *           the slave segment, xi = -1 + 2 (P - A).(B - A) / |B - A|^2, and
 *           the interval they span is clipped to [-1,1].  3D: the master
 *           vertices are projected orthogonally onto the slave's chart (a
 *           plane, see chart_set) and the projected master polygon is
 *           clipped against the slave's chart polygon (Sutherland-Hodgman),
 *           then oriented counter-clockwise.  Both maps are affine, so a
 *           straight master edge stays straight and on flat facets the
 *           overlap is the exact physical one.  Projected vertices within
 *           1e-12 of the slave's vertices or edges are snapped onto them;
 *           overlaps of measure <= 1e-14 of the slave are empty (rounding
 *           slivers, e.g. along the shared edges of matching meshes).
 *   Step 3: distance filter: the gap g between the linearised facets along
 *           the slave normal at the vertex centroid c of the overlap,
 *           X_s(c) + g n_s in the master plane, must satisfy |g| <= dmax.
 */
int
lac_pairing_overlap (const lac_pairing_facet *s, const lac_pairing_facet *m,
                     double dmax, double facing, double *poly, int *np)
{
  int sdim = s->sdim, nvm = m->lin->nnodes;
  double q[2 * 4], c[2] = { 0, 0 }, X[3];
  double cosn = lac_vec_dot (sdim, s->n, m->n);
  *np = 0;
  if (!(-cosn > facing))                                     /* step 1 */
    return LAC_PAIRING_NOT_FACING;
  if (sdim == 2)                                              /* step 2 */
    {
      const double *A = s->xe;
      double e[2] = { s->xe[2] - A[0], s->xe[3] - A[1] };
      double ee = lac_vec_dot (2, e, e);
      for (int a = 0; a < 2; a++)
        {
          double r[2] = { m->xe[2 * a] - A[0], m->xe[2 * a + 1] - A[1] };
          q[a] = -1 + 2 * lac_vec_dot (2, r, e) / ee;
          for (int v = -1; v <= 1; v += 2)
            if (fabs (q[a] - v) <= SNAP_TOL)
              q[a] = v;
        }
      double lo = fmax (-1, fmin (q[0], q[1]));
      double hi = fmin (1, fmax (q[0], q[1]));
      if (!(hi - lo > 2 * EMPTY_TOL))
        return LAC_PAIRING_DISJOINT;
      poly[0] = lo, poly[1] = hi, *np = 2;
      c[0] = 0.5 * (lo + hi);
      for (int i = 0; i < 2; i++)
        X[i] = A[i] + 0.5 * (c[0] + 1) * e[i];
    }
  else
    {
      for (int a = 0; a < nvm; a++)
        {
          chart_coords (s, m->xe + 3 * a, q + 2 * a);
          snap_vertex (s, q + 2 * a);
        }
      int n = lac_pairing_clip (s->nz, s->z, nvm, q, poly);
      double A = n ? lac_pairing_polygon_area (n, poly) : 0;
      if (!(fabs (A) > EMPTY_TOL * lac_pairing_polygon_area (s->nz, s->z)))
        return LAC_PAIRING_DISJOINT;
      if (A < 0)                                   /* counter-clockwise */
        for (int i = 0, j = n - 1; i < j; i++, j--)
          for (int k = 0; k < 2; k++)
            {
              double tmp = poly[2 * i + k];
              poly[2 * i + k] = poly[2 * j + k], poly[2 * j + k] = tmp;
            }
      for (int i = 0; i < n; i++)
        c[0] += poly[2 * i] / n, c[1] += poly[2 * i + 1] / n;
      for (int i = 0; i < 3; i++)
        X[i] = s->o[i] + c[0] * s->e[i] + c[1] * s->e[3 + i];
      *np = n;
    }
  double num = 0;                                             /* step 3 */
  for (int i = 0; i < sdim; i++)
    num += (m->c[i] - X[i]) * m->n[i];
  if (!(fabs (num) <= dmax * fabs (cosn)))          /* |g| = |num/cosn| */
    {
      *np = 0;
      return LAC_PAIRING_TOO_FAR;
    }
  return LAC_PAIRING_OVERLAP;
}

/* ---- integration points ------------------------------------------------- */

/* Reference coordinates xi of the chart point z of a slave facet, and the
 * Jacobian det dz/dxi.  Identity for a triangle and a parallelogram; for
 * another quadrangle, z(xi) = sum_a z_a N_a(xi) is the bilinear map of its
 * chart polygon, inverted by Newton's method from xi = z (the point is
 * inside the convex chart polygon, where the map is invertible). */
static int
chart_to_ref (const lac_pairing_facet *s, const double *z, double *xi,
              double *detz)
{
  double N[4], dN[8];
  int polish = 0;
  xi[0] = z[0], xi[1] = z[1], *detz = 1;
  if (s->affine)
    return LAC_SUCCESS;
  for (int it = 0; it < 30; it++)
    {
      double r[2] = { -z[0], -z[1] }, J[4] = { 0, 0, 0, 0 };
      lac_refelem_eval (s->lin, xi, N, dN);
      for (int a = 0; a < 4; a++)
        for (int i = 0; i < 2; i++)
          {
            r[i] += s->z[2 * a + i] * N[a];                 /* z(xi) - z */
            for (int k = 0; k < 2; k++)
              J[2 * i + k] += s->z[2 * a + i] * dN[2 * a + k];
          }
      double det = J[0] * J[3] - J[1] * J[2];
      *detz = det;
      if (!(det > 0) || polish)
        break;
      double d0 = (J[3] * r[0] - J[1] * r[1]) / det;
      double d1 = (J[0] * r[1] - J[2] * r[0]) / det;
      xi[0] -= d0, xi[1] -= d1;
      polish = fabs (d0) + fabs (d1) <= 1e-13;  /* one more step, then det */
    }
  if (polish && *detz > 0)
    return LAC_SUCCESS;
  LAC_ERROR (LAC_EMAXITER, "%s slave facet: no reference point for chart "
             "point (%g, %g) (det %g)", s->re->name, z[0], z[1], *detz);
}

/* One integration point at slave chart point z with chart weight wz:
 * xi = its reference point, x_s, n_s and the surface element from the
 * exact slave map, the master point by projection along n_s (warm-started
 * at the previous one), and the weight wz |dx/dxi| / det(dz/dxi).
 * [LAC §4.6, item 2] */
static int
add_point (const lac_pairing_facet *s, const lac_pairing_facet *m,
           const double *z, double wz, double *eta, double *xs, double *xm,
           double *w, double *gap, int *k)
{
  int d = s->sdim - 1, status;
  double xi[2], detz = 1;
  lac_map ms;
  if (d == 1)
    xi[0] = z[0];
  else if ((status = chart_to_ref (s, z, xi, &detz)))
    return status;
  if ((status = lac_map_face (s->re, s->sdim, s->xe, xi, &ms)))
    return status;
  if ((status = lac_pairing_project (m->re, m->sdim, m->xe, ms.x, ms.normal,
                                     eta, gap + *k)))
    return status;
  for (int j = 0; j < d; j++)
    xs[*k * d + j] = xi[j], xm[*k * d + j] = eta[j];
  w[*k] = wz * ms.detJ / detz;            /* w = w_ref |sub| dGamma_s */
  (*k)++;
  return LAC_SUCCESS;
}

/* Triangle t of the fan that cuts the polygon poly (np >= 3 points,
 * counter-clockwise) from its first vertex: (p_0, p_{t+1}, p_{t+2}),
 * t = 0 .. np-3.  Returns its Jacobian det[B-A, C-A] = 2 |ABC|, or 0 if it
 * has no area (a rounding sliver). */
static double
fan_triangle (const double *poly, int t, const double **A, double *e1,
              double *e2)
{
  const double *B = poly + 2 * (t + 1), *C = poly + 2 * (t + 2);
  *A = poly;
  e1[0] = B[0] - poly[0], e1[1] = B[1] - poly[1];
  e2[0] = C[0] - poly[0], e2[1] = C[1] - poly[1];
  double jac = e1[0] * e2[1] - e1[1] * e2[0];
  return fabs (jac) > 2 * EMPTY_TOL ? jac : 0;
}

/* Is the 3D overlap the whole slave facet? */
static int
overlap_is_full (const lac_pairing_facet *s, int np, const double *poly)
{
  double As = lac_pairing_polygon_area (s->nz, s->z);
  return lac_pairing_polygon_area (np, poly) >= (1 - FULL_TOL) * As;
}

/* lac_pairing_npoints: the number of points lac_pairing_points writes. */
int
lac_pairing_npoints (const lac_pairing_facet *s, int np, const double *poly,
                     const lac_quad *sub, const lac_quad *full)
{
  const double *A;
  double e1[2], e2[2];
  int k = 0;
  if (s->sdim == 2)
    return sub->n;
  if (overlap_is_full (s, np, poly))
    return full->n;
  for (int t = 0; t + 2 < np; t++)
    if (fan_triangle (poly, t, &A, e1, e2) != 0)
      k += sub->n;
  return k;
}

/* lac_pairing_points: integration points on the overlap poly.
 *
 *   2D: the Gauss rule `sub` on [lo, hi] = poly:  xi = (lo+hi)/2 + r (hi-lo)/2,
 *       w = w_r (hi-lo)/2 |dx/dxi|.
 *   3D: if the overlap is the whole slave facet, the slave's own rule
 *       `full` in its reference cell, w = w_q |dx/dxi|.  Otherwise the
 *       (convex) polygon is cut into np - 2 triangles by a fan from its
 *       first vertex (a fan from the centroid would need np triangles:
 *       twice the points for a quadrangle), and each triangle (A, B, C) of
 *       the chart carries the triangle rule: z = A + (B-A) r + (C-A) s,
 *       xi = xi(z), w = w_rs det[B-A, C-A] |dx/dxi| / det(dz/dxi).
 *   Each point is projected onto the master along the slave normal.  A
 *   fan triangle of a non-convex polygon (a strongly warped master) may
 *   have a negative Jacobian: its weights are then negative, and the
 *   measures still sum exactly.
 */
int
lac_pairing_points (const lac_pairing_facet *s, const lac_pairing_facet *m,
                    int np, const double *poly, const lac_quad *sub,
                    const lac_quad *full, double *xs, double *xm, double *w,
                    double *gap, int *npts)
{
  double eta[2] = { 0, 0 }, z[2], e1[2], e2[2];
  const double *A;
  int k = 0, status;
  if (m->re->shape == LAC_SHAPE_TRI)
    eta[0] = eta[1] = 1.0 / 3;
  *npts = 0;
  if (s->sdim == 2)
    {
      double mid = 0.5 * (poly[0] + poly[1]), half = 0.5 * (poly[1] - poly[0]);
      for (int p = 0; p < sub->n; p++)
        {
          z[0] = mid + half * sub->xi[p];
          if ((status = add_point (s, m, z, sub->w[p] * half, eta, xs, xm, w,
                                   gap, &k)))
            return status;
        }
    }
  else if (overlap_is_full (s, np, poly))
    {
      lac_pairing_facet sref = *s;  /* the rule is in reference coordinates */
      sref.affine = 1;
      for (int p = 0; p < full->n; p++)
        if ((status = add_point (&sref, m, full->xi + 2 * p, full->w[p], eta,
                                 xs, xm, w, gap, &k)))
          return status;
    }
  else
    for (int t = 0; t + 2 < np; t++)
      {
        double jac = fan_triangle (poly, t, &A, e1, e2);
        if (jac == 0)
          continue;                                 /* no area, no points */
        for (int p = 0; p < sub->n; p++)
          {
            double r = sub->xi[2 * p], u = sub->xi[2 * p + 1];
            z[0] = A[0] + e1[0] * r + e2[0] * u;
            z[1] = A[1] + e1[1] * r + e2[1] * u;
            if ((status = add_point (s, m, z, sub->w[p] * jac, eta, xs, xm, w,
                                     gap, &k)))
              return status;
          }
      }
  *npts = k;
  return LAC_SUCCESS;
}
