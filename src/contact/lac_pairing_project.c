/* lac_pairing_project.c -- projection onto a face map         [LAC §4.6]
 *
 * lac_pairing_project: the point X(xi) of a (possibly curved) face where the
 * ray x + t dir meets it, or the closest point of the face to x, by Newton's
 * method (Gauss-Newton for the closest point) in reference coordinates,
 * damped by a backtracking line search.  A pure function of the face and
 * the point; used by the pairing (lac_pairing_geom.c, item 2 of §4.6) and
 * by the node-to-segment method (lac_nts.c).
 *
 * Tolerances are relative: reference coordinates are O(1) whatever the
 * facet size; physical residuals are measured against the facet diameter h
 * plus the rounding level of |x|.
 *
 * References: J. Nocedal, S. J. Wright, Numerical Optimization, 2nd ed.,
 * §3.1 (backtracking line search), §10.3 (Gauss-Newton).
 */
#include "contact/lac_pairing_project.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "base/lac_status.h"
#include "base/lac_vec.h"

#define PROJ_MAXITER 50      /* Newton iterations, then LAC_EMAXITER      */
#define PROJ_MAXHALF 30      /* step halvings of the line search          */
#define PROJ_XIMAX 100.0     /* |xi| beyond this: the iteration diverged   */

/* X(xi) and J[i*d + k] = dX_i/dxi_k of the face map with nodes xe. */
static void
face_eval (const lac_refelem *re, int sdim, const double *xe,
           const double *xi, double *X, double *J)
{
  double N[LAC_MAX_FACE_NODES], dN[LAC_MAX_FACE_NODES * 2];
  int d = re->dim;
  lac_refelem_eval (re, xi, N, dN);
  for (int i = 0; i < sdim; i++)
    {
      X[i] = 0;
      for (int k = 0; k < d; k++)
        J[i * d + k] = 0;
    }
  for (int a = 0; a < re->nnodes; a++)
    for (int i = 0; i < sdim; i++)
      {
        X[i] += xe[a * sdim + i] * N[a];                /* X = sum x_a N_a */
        for (int k = 0; k < d; k++)
          J[i * d + k] += xe[a * sdim + i] * dN[a * d + k];
      }
}

/* Solve A y = b for n = 2, 3 (A row-major) by Cramer's rule.  Returns 0 if
 * |det A| <= 1e-12 x (product of the column norms): the columns are then
 * nearly dependent whatever their scales. */
static int
solve_small (int n, const double *A, const double *b, double *y)
{
  double cn = 1;
  for (int k = 0; k < n; k++)
    {
      double s = 0;
      for (int i = 0; i < n; i++)
        s += A[i * n + k] * A[i * n + k];
      cn *= sqrt (s);
    }
  if (n == 2)
    {
      double det = A[0] * A[3] - A[1] * A[2];
      if (!(fabs (det) > 1e-12 * cn))
        return 0;
      y[0] = (b[0] * A[3] - A[1] * b[1]) / det;
      y[1] = (A[0] * b[1] - b[0] * A[2]) / det;
      return 1;
    }
  double c0[3] = { A[0], A[3], A[6] }, c1[3] = { A[1], A[4], A[7] };
  double c2[3] = { A[2], A[5], A[8] }, t[3];
  lac_vec_cross (c1, c2, t);
  double det = lac_vec_dot (3, c0, t);
  if (!(fabs (det) > 1e-12 * cn))
    return 0;
  y[0] = lac_vec_dot (3, b, t) / det;           /* Cramer: det[b c1 c2] */
  lac_vec_cross (b, c2, t);
  y[1] = lac_vec_dot (3, c0, t) / det;          /* det[c0 b c2]         */
  lac_vec_cross (c1, b, t);
  y[2] = lac_vec_dot (3, c0, t) / det;          /* det[c0 c1 b]         */
  return 1;
}

/* lac_pairing_face_diameter: the length scale of residuals. */
double
lac_pairing_face_diameter (const lac_refelem *re, int sdim, const double *xe)
{
  double h = 0;
  for (int a = 0; a < re->nvertices; a++)
    for (int b = a + 1; b < re->nvertices; b++)
      h = fmax (h, lac_vec_dist (sdim, xe + a * sdim, xe + b * sdim));
  return h;
}

/* ---- projection --------------------------------------------------------- */

/* Residual of the projection problem at (xi, t), and its norm:
 *   along dir:    F = X(xi) - x - t dir                    (sdim values)
 *   closest pt:   F_k = (X(xi) - x).dX/dxi_k / |dX/dxi_k|   (d values),
 * and the merit function of the line search: |F|^2/2 along dir, the
 * objective |X - x|^2/2 for the closest point. */
static double
proj_residual (const lac_refelem *re, int sdim, const double *xe,
               const double *x, const double *dir, const double *xi,
               double t, double *F, double *X, double *J, double *merit)
{
  int d = re->dim;
  face_eval (re, sdim, xe, xi, X, J);
  if (dir)
    {
      for (int i = 0; i < sdim; i++)
        F[i] = X[i] - x[i] - t * dir[i];
      *merit = 0.5 * lac_vec_dot (sdim, F, F);
      return sqrt (2 * *merit);
    }
  double s = 0, r2 = 0;
  for (int i = 0; i < sdim; i++)
    r2 += (X[i] - x[i]) * (X[i] - x[i]);
  for (int k = 0; k < d; k++)
    {
      double g = 0, jn = 0;
      for (int i = 0; i < sdim; i++)
        {
          g += (X[i] - x[i]) * J[i * d + k];
          jn += J[i * d + k] * J[i * d + k];
        }
      F[k] = jn > 0 ? g / sqrt (jn) : 0;
      s += F[k] * F[k];
    }
  *merit = 0.5 * r2;
  return sqrt (s);
}

/* Slope of the merit function along dy: -|F|^2 along dir (Newton), and
 * (J^T (X - x)).dy for the closest point. */
static double
proj_slope (int sdim, int d, const double *x, const double *dir,
            const double *X, const double *J, const double *F,
            const double *dy)
{
  double sl = 0;
  if (dir)
    return -lac_vec_dot (sdim, F, F);
  for (int k = 0; k < d; k++)
    for (int i = 0; i < sdim; i++)
      sl += (X[i] - x[i]) * J[i * d + k] * dy[k];
  return sl;
}

/* The Newton (along dir) or Gauss-Newton (closest point) step dy on
 * y = (xi, t): [J | -dir] dy = -F, or (J^T J) dxi = -J^T (X - x). */
static int
proj_step (int sdim, int d, const double *x, const double *dir,
           const double *X, const double *J, const double *F, double *dy)
{
  double A[9], b[3];
  if (dir)
    {
      for (int i = 0; i < sdim; i++)
        {
          for (int k = 0; k < d; k++)
            A[i * sdim + k] = J[i * d + k];
          A[i * sdim + d] = -dir[i];
          b[i] = -F[i];
        }
      return solve_small (sdim, A, b, dy);
    }
  if (d == 1)
    {
      double jj = 0, g = 0;
      for (int i = 0; i < sdim; i++)
        jj += J[i] * J[i], g += J[i] * (X[i] - x[i]);
      if (!(jj > 0))
        return 0;
      dy[0] = -g / jj;
      return 1;
    }
  for (int k = 0; k < d; k++)
    {
      b[k] = 0;
      for (int i = 0; i < sdim; i++)
        b[k] -= J[i * d + k] * (X[i] - x[i]);          /* -J^T (X - x) */
      for (int l = 0; l < d; l++)
        {
          A[k * d + l] = 0;
          for (int i = 0; i < sdim; i++)
            A[k * d + l] += J[i * d + k] * J[i * d + l];   /* J^T J */
        }
    }
  return solve_small (2, A, b, dy);
}

/* A trial point of the line search: y = (xi, t) and what it gives. */
typedef struct proj_point
{
  double xi[2], t;             /* the point y                              */
  double F[3], X[3], J[6];     /* residual, face point, tangents at xi     */
  double fn, merit;            /* |F| and the merit function               */
} proj_point;

/* Step 3 of lac_pairing_project: backtracking from y = (xi, tt) along dy,
 * alpha = 1, 1/2, 1/4, ... until the Armijo condition on the merit function
 * (slope its derivative along dy) holds or |F| drops by 1 - 1e-4 alpha.
 * Returns alpha and the accepted point in *n; 0 if PROJ_MAXHALF halvings
 * gave no descent. */
static double
proj_line_search (const lac_refelem *re, int sdim, const double *xe,
                  const double *x, const double *dir, const double *xi,
                  double tt, const double *dy, double fn, double mer,
                  double slope, proj_point *n)
{
  int d = re->dim;
  double a = 1;
  for (int h2 = 0; h2 < PROJ_MAXHALF; h2++, a *= 0.5)
    {                                       /* backtracking, Armijo 1e-4 */
      for (int k = 0; k < d; k++)
        n->xi[k] = xi[k] + a * dy[k];
      n->t = dir ? tt + a * dy[d] : 0;
      n->fn = proj_residual (re, sdim, xe, x, dir, n->xi, n->t, n->F, n->X,
                             n->J, &n->merit);
      if (n->merit <= mer + 1e-4 * a * slope     /* Armijo, or the */
          || n->fn <= (1 - 1e-4 * a) * fn)       /* residual drops */
        return a;
    }
  return 0;
}

/* Step 5 of lac_pairing_project: the signed distance (x - X).n, with n the
 * normal of the face at X built from its tangents J (0 if they vanish). */
static double
proj_distance (int sdim, const double *x, const double *X, const double *J)
{
  double n[3] = { 0, 0, 0 };
  if (sdim == 2)
    n[0] = J[1], n[1] = -J[0];
  else
    {
      double t1[3] = { J[0], J[2], J[4] }, t2[3] = { J[1], J[3], J[5] };
      lac_vec_cross (t1, t2, n);
    }
  double nn = lac_vec_norm (sdim, n), s = 0;
  for (int i = 0; i < sdim; i++)
    s += (x[i] - X[i]) * n[i];
  return nn > 0 ? s / nn : 0;
}

/* lac_pairing_project: X(xi) = x + t dir (dir != NULL) or the closest
 * point of the face map to x (dir == NULL).              [LAC §4.6, item 2]
 *
 *   Newton's method on y = (xi, t) (Gauss-Newton on xi for the closest
 *   point), each step damped by backtracking: alpha = 1, 1/2, 1/4, ...
 *   until phi(y + alpha dy) <= phi(y) + 1e-4 alpha phi'(y).dy (Armijo), with
 *   phi = |F|^2/2 along dir and phi = |X - x|^2/2 for the closest point
 *   (dy is a descent direction of both), or until |F| drops by the factor
 *   1 - 1e-4 alpha (near a closest point at distance t the decrease of
 *   |X - x|^2 is below the rounding of t^2, the drop of |F| is not).
 *   The line search is what makes the iteration safe on strongly curved
 *   quadratic faces, where a full step can jump to the far branch of the
 *   quadratic map.  Convergence: |F| <= 1e-13 h + 8 eps |x| (h the facet
 *   diameter; the second term is the rounding level of X - x), or a step
 *   below rounding.  Failure is reported, never looped on: at most
 *   PROJ_MAXITER steps, and |xi| > PROJ_XIMAX means that the point has no
 *   projection near the facet.
 *
 *   [in]     re, sdim, xe   the face element and its nodes
 *   [in]     x              the point;  dir  the direction or NULL
 *   [in,out] xi             starting point / solution (re->dim values)
 *   [out]    t              the parameter along dir, or the signed
 *                           distance (x - X).n (may be NULL)
 *   returns  LAC_SUCCESS, LAC_EINVAL, LAC_ESING, LAC_EMAXITER
 */
int
lac_pairing_project (const lac_refelem *re, int sdim, const double *xe,
                     const double *x, const double *dir, double *xi,
                     double *t)
{
  int d = re ? re->dim : 0;
  double X[3], J[6], F[3], dy[3], tt = 0, xmax = 0;
  if (!re || d < 1 || d > 2 || sdim != d + 1)
    LAC_ERROR (LAC_EINVAL, "%s is not a face of a %d-D cell",
               re ? re->name : "(null)", sdim);
  double h = lac_pairing_face_diameter (re, sdim, xe);
  for (int i = 0; i < sdim; i++)
    xmax = fmax (xmax, fabs (x[i]));
  if (!(h > 0) || !isfinite (xmax))
    LAC_ERROR (LAC_ESING, "%s face of diameter %g, point |x| = %g", re->name,
               h, xmax);
  double tol = 1e-13 * h + 8 * DBL_EPSILON * (xmax + h);
  /* Step 1: start at xi, with t such that F is orthogonal to dir. */
  if (dir)
    {
      face_eval (re, sdim, xe, xi, X, J);
      double dd = lac_vec_dot (sdim, dir, dir);
      if (!(dd > 0))
        LAC_ERROR (LAC_EINVAL, "projection direction is zero");
      for (int i = 0; i < sdim; i++)
        tt += (X[i] - x[i]) * dir[i] / dd;
    }
  double mer, fn = proj_residual (re, sdim, xe, x, dir, xi, tt, F, X, J, &mer);
  for (int it = 0; it < PROJ_MAXITER; it++)
    {
      if (fn <= tol)
        break;
      /* Step 2: the Newton (Gauss-Newton) step. */
      if (!proj_step (sdim, d, x, dir, X, J, F, dy))
        LAC_ERROR (LAC_ESING, "projection onto %s: singular Newton matrix at "
                   "xi = (%g, %g)%s", re->name, xi[0], d > 1 ? xi[1] : 0.0,
                   dir ? "; is the direction tangent to the face?" : "");
      /* Step 3: backtracking line search. */
      proj_point n;
      double smax = 0;
      double a = proj_line_search (re, sdim, xe, x, dir, xi, tt, dy, fn, mer,
                                   proj_slope (sdim, d, x, dir, X, J, F, dy),
                                   &n);
      if (a == 0)
        {
          if (fn <= 1e-8 * h)          /* stalled at rounding: accept */
            break;
          LAC_ERROR (LAC_EMAXITER, "projection onto %s: no descent at "
                     "iteration %d (|F| = %g, facet size %g): the point has "
                     "no projection near the face", re->name, it, fn, h);
        }
      /* Step 4: accept; divergence and rounding tests. */
      for (int k = 0; k < d; k++)
        {
          smax = fmax (smax, fabs (a * dy[k]));
          xi[k] = n.xi[k];
          if (!(fabs (xi[k]) <= PROJ_XIMAX))
            LAC_ERROR (LAC_EMAXITER, "projection onto %s diverged: |xi| = %g "
                       "after %d iterations (the point is far outside the "
                       "face)", re->name, fabs (xi[k]), it + 1);
        }
      if (dir)
        tt += a * dy[d], smax = fmax (smax, fabs (a * dy[d]) / h);
      fn = n.fn, mer = n.merit;
      memcpy (F, n.F, sizeof F), memcpy (X, n.X, sizeof X);
      memcpy (J, n.J, sizeof J);
      if (smax <= 4 * DBL_EPSILON && fn <= 1e-8 * h)
        break;                       /* the step is below rounding */
      if (it == PROJ_MAXITER - 1 && fn > tol)
        LAC_ERROR (LAC_EMAXITER, "projection onto %s: no convergence in %d "
                   "iterations (|F| = %g, facet size %g)", re->name,
                   PROJ_MAXITER, fn, h);
    }
  /* Step 5: t along dir, or the signed distance. */
  if (t && dir)
    *t = tt;
  else if (t)                               /* t = (x - X).n */
    *t = proj_distance (sdim, x, X, J);
  return LAC_SUCCESS;
}
