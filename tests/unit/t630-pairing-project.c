/* t630: Newton projection of points onto curved seg3/tri6/quad9 facets
 * (along a direction and closest point) converges; points without a
 * projection return a clear status, never loop  [LAC §4.6, item 2] */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "contact/lac_pairing.h"
#include "contact/lac_pairing_project.h"
#include "base/lac_status.h"

/* x(xi), the unit normal and J of a face. */
static void
face_at (const lac_refelem *re, int sdim, const double *xe, const double *xi,
         double *x, double *n)
{
  lac_map m;
  lac_map_face (re, sdim, xe, xi, &m);
  memcpy (x, m.x, sizeof m.x);
  memcpy (n, m.normal, sizeof m.normal);
}

/* Project x* = X(xi*) + t* d' back (along d' = -dir, i.e. solve
 * X(xi) = x* + t dir) from the reference centre, and by closest point from
 * x = X(xi*) + t* n(xi*); check both recover xi* and t*. */
static void
roundtrip (const lac_refelem *re, const double *xe, const double *xs,
           double ts, const double *dir, const char *what)
{
  int sdim = re->dim + 1, d = re->dim;
  double X[3], n[3], x[3], xi[2], t, c = re->shape == LAC_SHAPE_TRI ? 1.0 / 3 : 0;
  face_at (re, sdim, xe, xs, X, n);
  for (int i = 0; i < sdim; i++)
    x[i] = X[i] - ts * dir[i];
  xi[0] = xi[1] = c;
  check_status (lac_pairing_project (re, sdim, xe, x, dir, xi, &t),
                LAC_SUCCESS, "%s along dir: status", what);
  for (int k = 0; k < d; k++)
    check_abs (xi[k], xs[k], 1e-12, "%s along dir: xi_%d", what, k);
  check_abs (t, ts, 1e-12, "%s along dir: t", what);
  for (int i = 0; i < sdim; i++)
    x[i] = X[i] + ts * n[i];
  xi[0] = xi[1] = c;
  check_status (lac_pairing_project (re, sdim, xe, x, NULL, xi, &t),
                LAC_SUCCESS, "%s closest point: status", what);
  for (int k = 0; k < d; k++)
    check_abs (xi[k], xs[k], 1e-10, "%s closest point: xi_%d", what, k);
  check_abs (t, ts, 1e-10, "%s closest point: distance", what);
}

/* Node coordinates of a face element from a height function over its
 * reference nodes: x = (xi, h(xi)) (2D) or (xi, eta, h(xi, eta)) (3D). */
static void
curved (const lac_refelem *re, double (*h) (const double *), double *xe)
{
  int d = re->dim;
  for (int a = 0; a < re->nnodes; a++)
    {
      for (int k = 0; k < d; k++)
        xe[a * (d + 1) + k] = re->xi[a * d + k];
      xe[a * (d + 1) + d] = h (re->xi + a * d);
    }
}

static double h_seg (const double *p) { return 0.5 * (1 - p[0] * p[0]); }
static double h_arch (const double *p) { return 2 * (1 - p[0] * p[0]); }
static double h_tri (const double *p) { return 0.4 * p[0] * p[1] + 0.3 * p[0] * p[0]; }
static double h_quad (const double *p)
{
  return 0.25 * (p[0] * p[0] - p[1] * p[1]) + 0.2 * p[0] * p[1] + 0.1 * p[1];
}

int
main (void)
{
  const lac_refelem *s3 = lac_refelem_get (LAC_SEG3);
  const lac_refelem *t6 = lac_refelem_get (LAC_TRI6);
  const lac_refelem *q9 = lac_refelem_get (LAC_QUAD9);
  double xe[LAC_MAX_FACE_NODES * 3], xi[2], t, x[3];
  lac_init ();

  /* 1. Convergence: points on a grid of each face (and outside it, up to
   *    xi = 1.3), at distances up to 0.3 along tilted directions. */
  curved (s3, h_seg, xe);
  for (double a = -1.3; a <= 1.31; a += 0.26)
    for (double ts = -0.3; ts <= 0.31; ts += 0.15)
      {
        double dir[2] = { 0.3, -1 }, xs[1] = { a };
        roundtrip (s3, xe, xs, ts, dir, "seg3");
      }
  curved (t6, h_tri, xe);
  for (double a = -0.2; a <= 1.01; a += 0.2)
    for (double b = -0.2; a + b <= 1.21; b += 0.2)
      {
        double dir[3] = { 0.2, 0.1, -1 }, xs[2] = { a, b };
        roundtrip (t6, xe, xs, 0.25, dir, "tri6");
      }
  curved (q9, h_quad, xe);
  for (double a = -1.2; a <= 1.21; a += 0.3)
    for (double b = -1.2; b <= 1.21; b += 0.4)
      {
        double dir[3] = { -0.1, 0.25, -1 }, xs[2] = { a, b };
        roundtrip (q9, xe, xs, -0.2, dir, "quad9");
      }

  /* 2. No solution along dir: the arch y = 2 (1 - xi^2) never reaches the
   *    horizontal line y = 5. */
  curved (s3, h_arch, xe);
  x[0] = 0, x[1] = 5, xi[0] = 0.5;
  double horiz[2] = { 1, 0 };
  check_status (lac_pairing_project (s3, 2, xe, x, horiz, xi, &t),
                LAC_EMAXITER, "arch, no intersection");
  check_message ("projection onto seg3", "arch: message names the face");

  /* 3. Closest point beyond the neighbourhood of the facet: diverged. */
  x[0] = 1e3, x[1] = -2e6, xi[0] = 0;
  check_status (lac_pairing_project (s3, 2, xe, x, NULL, xi, &t),
                LAC_EMAXITER, "arch, far point");
  check_message ("diverged", "arch, far point: message");

  /* 4. Direction tangent to a straight facet: singular. */
  double seg[6] = { 0, 0, 1, 0, 0.5, 0 };
  x[0] = 3, x[1] = 1, xi[0] = 0;
  check_status (lac_pairing_project (s3, 2, seg, x, horiz, xi, &t),
                LAC_ESING, "tangent direction");
  check_message ("tangent", "tangent direction: message");

  /* 5. Bad input: not a face element, zero direction. */
  double zero[3] = { 0, 0, 0 };
  check_status (lac_pairing_project (lac_refelem_get (LAC_TET4), 3, xe, x,
                                     NULL, xi, &t), LAC_EINVAL, "tet4");
  curved (t6, h_tri, xe);
  xi[0] = xi[1] = 0.3;
  check_status (lac_pairing_project (t6, 3, xe, x, zero, xi, &t), LAC_EINVAL,
                "zero direction");
  return check_summary ();
}
