/* t103-spaces-map.c -- isoparametric cell and face maps, inverse map.
 *
 * Each element type is mapped by x = phi(xi) = b + A xi + eps q(xi), with
 * q in the element's own space (0 for P1 and pyr5, xi_0 xi_1 for Q1,
 * xi_0^2 and xi_0 xi_1 for the quadratic elements), so the cell is distorted
 * or curved and the isoparametric map must reproduce phi exactly.  Checks:
 *   - x(xi) = phi(xi), J = D phi, det J = det D phi > 0 (1e-13);
 *   - sum_a x_a dN_a/dx^T = I and dN/dx equals central finite differences
 *     in x, through lac_map_inverse (1e-6);
 *   - lac_map_inverse round trip xi -> x -> xi (1e-12);
 *   - lac_map_cell_at with N and dN/dxi from lac_refelem_eval gives
 *     lac_map_cell's x, N, dN/dx, J and det J bit for bit;
 *   - divergence theorem on the curved cell: sum_f int_f x.n dS computed
 *     with lac_map_face equals dim int_K dx computed with lac_map_cell
 *     (1e-12), and n . (x_f - x_K) > 0 at each face centroid;
 *   - a mirrored (inverted) cell gives LAC_ESING with a message, a collapsed
 *     face LAC_ESING, a NaN target LAC_EMAXITER, a wrong sdim LAC_EINVAL.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"

static const double A[9] = { 1.1, 0.2, -0.1, -0.15, 0.9, 0.1, 0.05, -0.2, 1.2 };
static const double b[3] = { 0.3, -0.7, 2.0 };
static const double cq[3] = { 0.08, -0.06, 0.05 };   /* xi_0^2 term    */
static const double cm[3] = { -0.05, 0.07, 0.04 };   /* xi_0 xi_1 term */

/* Which nonlinear terms the element's space holds. */
static void
terms (const lac_refelem *re, int *quad, int *mixed)
{
  *quad = re->order == 2;
  *mixed = re->dim > 1 && (re->order == 2 || re->shape == LAC_SHAPE_QUAD
                           || re->shape == LAC_SHAPE_HEX);
}

/* phi(xi) and D phi(xi) (G[i*d+k] = dphi_i/dxi_k). */
static void
phi (const lac_refelem *re, const double *xi, double *x, double *G)
{
  int d = re->dim, tq, tm;
  terms (re, &tq, &tm);
  for (int i = 0; i < d; i++)
    {
      x[i] = b[i];
      for (int k = 0; k < d; k++)
        {
          x[i] += A[i * 3 + k] * xi[k];
          if (G)
            G[i * d + k] = A[i * 3 + k];
        }
      if (tq)
        {
          x[i] += cq[i] * xi[0] * xi[0];
          if (G)
            G[i * d] += 2 * cq[i] * xi[0];
        }
      if (tm)
        {
          x[i] += cm[i] * xi[0] * xi[1];
          if (G)
            G[i * d] += cm[i] * xi[1], G[i * d + 1] += cm[i] * xi[0];
        }
    }
}

static void
random_point (const lac_refelem *re, double *xi)
{
  int unit = re->shape == LAC_SHAPE_TRI || re->shape == LAC_SHAPE_TET;
  do
    for (int k = 0; k < re->dim; k++)
      {
        double u = rand () / (RAND_MAX + 1.0);
        xi[k] = (unit || (re->shape == LAC_SHAPE_PYR && k == 2)) ? u
          : 2 * u - 1;
      }
  while (!lac_refelem_contains (re, xi, -1e-2));
}

static double
det (int d, const double *G)
{
  if (d == 1)
    return G[0];
  if (d == 2)
    return G[0] * G[3] - G[1] * G[2];
  return G[0] * (G[4] * G[8] - G[5] * G[7]) - G[1] * (G[3] * G[8] - G[5] * G[6])
    + G[2] * (G[3] * G[7] - G[4] * G[6]);
}

/* dN_a/dx_i by central differences in x, through the inverse map. */
static void
check_fd (const lac_refelem *re, const double *xe, const lac_map *m)
{
  int d = re->dim;
  const double h = 1e-5;
  for (int i = 0; i < d; i++)
    {
      double xp[3], xm[3], xip[3], xim[3], Np[LAC_MAX_NODES], Nm[LAC_MAX_NODES];
      memcpy (xp, m->x, sizeof xp);
      memcpy (xm, m->x, sizeof xm);
      xp[i] += h, xm[i] -= h;
      check_status (lac_map_inverse (re, d, xe, xp, xip), LAC_SUCCESS,
                    "%s: inverse +", re->name);
      check_status (lac_map_inverse (re, d, xe, xm, xim), LAC_SUCCESS,
                    "%s: inverse -", re->name);
      lac_refelem_eval (re, xip, Np, NULL);
      lac_refelem_eval (re, xim, Nm, NULL);
      for (int a = 0; a < re->nnodes; a++)
        check_abs (m->dNdx[a * d + i], (Np[a] - Nm[a]) / (2 * h), 1e-6,
                   "%s: dN_%d/dx_%d by FD", re->name, a, i);
    }
}

static void
check_point (const lac_refelem *re, const double *xe, const double *xi)
{
  int d = re->dim;
  double x[3], G[9], xi2[3];
  lac_map m;
  phi (re, xi, x, G);
  check_status (lac_map_cell (re, d, xe, xi, &m), LAC_SUCCESS, "%s: map",
                re->name);
  for (int i = 0; i < d; i++)
    {
      check_abs (m.x[i], x[i], 1e-13, "%s: x = phi", re->name);
      for (int k = 0; k < d; k++)
        {
          check_abs (m.J[i * d + k], G[i * d + k], 1e-13, "%s: J", re->name);
          double s = 0;                 /* sum_a x_ai dN_a/dx_k = delta_ik */
          for (int a = 0; a < re->nnodes; a++)
            s += xe[a * d + i] * m.dNdx[a * d + k];
          check_abs (s, i == k, 1e-13, "%s: grad x = I", re->name);
        }
    }
  check_rel (m.detJ, det (d, G), 1e-13, "%s: det J", re->name);
  double N[LAC_MAX_NODES], dN[LAC_MAX_NODES * 3];   /* from tables */
  lac_map mt;
  lac_refelem_eval (re, xi, N, dN);
  check_status (lac_map_cell_at (re, d, xe, xi, N, dN, &mt), LAC_SUCCESS,
                "%s: map from tables", re->name);
  check_true (!memcmp (mt.x, m.x, sizeof m.x)
              && !memcmp (mt.J, m.J, sizeof m.J) && mt.detJ == m.detJ
              && !memcmp (mt.N, m.N, (size_t) re->nnodes * sizeof *m.N)
              && !memcmp (mt.dNdx, m.dNdx, (size_t) (re->nnodes * d)
                          * sizeof *m.dNdx),
              "%s: lac_map_cell_at = lac_map_cell bit for bit", re->name);
  check_true (m.detJ > 0, "%s: det J > 0", re->name);
  check_status (lac_map_inverse (re, d, xe, m.x, xi2), LAC_SUCCESS,
                "%s: inverse", re->name);
  for (int k = 0; k < d; k++)
    check_abs (xi2[k], xi[k], 1e-12, "%s: inverse round trip", re->name);
  check_fd (re, xe, &m);
}

/* sum_f int_f x.n dS = d |K| on the mapped cell; outward face normals. */
static void
check_divergence (const lac_refelem *re, const double *xe)
{
  int d = re->dim;
  double vol = 0, flux = 0, xc[3] = { 0, 0, 0 };
  lac_quad *q = lac_quad_alloc (re->shape, 8);
  lac_map m;
  for (int p = 0; p < q->n; p++)
    {
      lac_map_cell (re, d, xe, q->xi + p * d, &m);
      vol += q->w[p] * m.detJ;
      for (int i = 0; i < d; i++)
        xc[i] += q->w[p] * m.detJ * m.x[i];
    }
  lac_quad_free (q);
  for (int i = 0; i < d; i++)
    xc[i] /= vol;
  for (int f = 0; f < re->nfaces; f++)
    {
      const lac_refelem *fe = lac_refelem_get (re->face_type[f]);
      double xf[LAC_MAX_FACE_NODES * 3], c[2] = { 0, 0 }, s = 0;
      for (int k = 0; k < fe->nnodes; k++)
        memcpy (xf + k * d, xe + re->face_node[f][k] * d, d * sizeof (double));
      q = lac_quad_alloc (fe->shape, 8);
      for (int p = 0; p < q->n; p++)
        {
          lac_map_face (fe, d, xf, q->xi + p * fe->dim, &m);
          for (int i = 0; i < d; i++)
            flux += q->w[p] * m.detJ * m.x[i] * m.normal[i];
        }
      lac_quad_free (q);
      if (fe->shape == LAC_SHAPE_TRI)
        c[0] = c[1] = 1.0 / 3;
      lac_map_face (fe, d, xf, c, &m);
      for (int i = 0; i < d; i++)
        s += m.normal[i] * (m.x[i] - xc[i]);
      check_true (s > 0, "%s face %d: outward on the curved cell", re->name,
                  f);
    }
  if (re->nfaces > 0)
    check_rel (flux, d * vol, 1e-12, "%s: divergence theorem", re->name);
}

static void
check_errors (const lac_refelem *re, const double *xe)
{
  int d = re->dim;
  double xm[LAC_MAX_NODES * 3], xi[3] = { 0.2, 0.2, 0.2 }, nan3[3] =
    { NAN, NAN, NAN };
  lac_map m;
  memcpy (xm, xe, sizeof xm);
  for (int a = 0; a < re->nnodes; a++)      /* mirror x_0 -> -x_0 */
    xm[a * d] = -xm[a * d];
  lac_error_clear ();
  check_status (lac_map_cell (re, d, xm, xi, &m), LAC_ESING,
                "%s: inverted cell", re->name);
  check_message ("det J", "%s: inverted cell message", re->name);
  check_status (lac_map_inverse (re, d, xe, nan3, xi), LAC_EMAXITER,
                "%s: NaN target", re->name);
  if (d < 3)
    check_status (lac_map_cell (re, d + 1, xe, xi, &m), LAC_EINVAL,
                  "%s: sdim != dim", re->name);
}

int
main (void)
{
  lac_init ();
  srand (103);
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    {
      const lac_refelem *re = lac_refelem_get ((lac_elem_type) t);
      double xe[LAC_MAX_NODES * 3], xi[3];
      for (int a = 0; a < re->nnodes; a++)
        phi (re, re->xi + a * re->dim, xe + a * re->dim, NULL);
      for (int r = 0; r < 10; r++)
        {
          random_point (re, xi);
          check_point (re, xe, xi);
        }
      check_divergence (re, xe);
      check_errors (re, xe);
    }
  /* A face collapsed to a point is singular. */
  double xz[9] = { 1, 1, 1, 1, 1, 1, 1, 1, 1 }, c[2] = { 0.3, 0.3 };
  lac_map m;
  check_status (lac_map_face (lac_refelem_get (LAC_TRI3), 3, xz, c, &m),
                LAC_ESING, "collapsed tri3 face");
  check_status (lac_map_face (lac_refelem_get (LAC_TRI3), 2, xz, c, &m),
                LAC_EINVAL, "tri3 face in 2D");
  lac_finalize ();
  return check_summary ();
}
