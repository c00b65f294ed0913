/* lac_obstacle.c -- rigid analytic obstacle (see lac_obstacle.h)
 *                                                  [LAC (18), §5.3]
 */
#include "contact/lac_obstacle.h"

#include <math.h>
#include <string.h>
#include "contact/lac_contact_facet.h"
#include "base/lac_mem.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

double
lac_obstacle_height (const lac_obstacle *o, const double *x)
{
  double h = o->height;
  for (int k = 0; k < o->dim - 1; k++)
    h += o->curv[k] * (x[k] - o->center[k]) * (x[k] - o->center[k]);
  return h;
}

/* F(g) = v(x + g n) - h(w(x + g n)) = A g^2 + B g + C0 = 0. */
int
lac_obstacle_gap (const lac_obstacle *o, const double *x, const double *n,
                  double *g)
{
  int v = o->dim - 1;
  double A = 0, B = n[v], C0 = x[v] - o->height;
  for (int k = 0; k < v; k++)
    {
      double d = x[k] - o->center[k];
      A -= o->curv[k] * n[k] * n[k];
      B -= 2 * o->curv[k] * n[k] * d;
      C0 -= o->curv[k] * d * d;
    }
  double scale = fabs (B) + sqrt (fabs (A * C0));
  if (fabs (A) <= 1e-14 * (scale > 0 ? scale : 1))        /* linear */
    {
      if (B == 0)
        LAC_ERROR (LAC_EINVAL, "the slave normal (%g, %g) never meets the "
                   "obstacle", n[0], n[1]);
      *g = -C0 / B;
      return LAC_SUCCESS;
    }
  double disc = B * B - 4 * A * C0;
  if (disc < 0)
    LAC_ERROR (LAC_EINVAL, "the slave normal at (%g, %g) misses the "
               "obstacle", x[0], x[1]);
  double q = -0.5 * (B + copysign (sqrt (disc), B));      /* stable roots */
  double g1 = q / A, g2 = q != 0 ? C0 / q : g1;
  *g = fabs (g1) < fabs (g2) ? g1 : g2;
  return LAC_SUCCESS;
}

/* Allocate the arrays of a pairing with np points on ns slave facets. */

/* The graph's point X(w), its tangents t_k = e_k + h_k e_v and the
 * un-normalized outward normal m = (-grad h, 1) at w. */
static void
graph_at (const lac_obstacle *o, const double *w, double *X, double t[2][3],
          double *m)
{
  int v = o->dim - 1;
  X[v] = lac_obstacle_height (o, w);
  m[v] = 1;
  for (int k = 0; k < v; k++)
    {
      double hk = 2 * o->curv[k] * (w[k] - o->center[k]);
      X[k] = w[k];
      m[k] = -hk;
      for (int c = 0; c <= v; c++)
        t[k][c] = c == k ? 1 : c == v ? hk : 0;
    }
}

/* A = T T^T - (x_v - h) 2 diag(curv): minus the derivative of the
 * residual R_k = (x - X).t_k with respect to w (nv = dim - 1 rows). */
static void
newton_matrix (const lac_obstacle *o, const double *x, const double *X,
               double t[2][3], double *A)
{
  int v = o->dim - 1;
  for (int k = 0; k < v; k++)
    for (int l = 0; l < v; l++)
      {
        double s = 0;
        for (int c = 0; c <= v; c++)
          s += t[k][c] * t[l][c];
        A[k * v + l] = s - (k == l ? 2 * o->curv[k] * (x[v] - X[v]) : 0);
      }
}

/* Solve A z = r for 1 or 2 unknowns; 0 unless A is positive definite. */
static int
solve_spd (int nv, const double *A, const double *r, double *z)
{
  if (nv == 1)
    {
      if (!(A[0] > 0))
        return 0;
      z[0] = r[0] / A[0];
      return 1;
    }
  double det = A[0] * A[3] - A[1] * A[2];
  if (!(A[0] > 0 && det > 0))
    return 0;
  z[0] = (A[3] * r[0] - A[1] * r[1]) / det;
  z[1] = (A[0] * r[1] - A[2] * r[0]) / det;
  return 1;
}

int
lac_obstacle_project (const lac_obstacle *o, const double *x, double *g,
                      double *n, double *dndx)
{
  int v = o->dim - 1, it;
  double w[2] = { 0, 0 }, X[3], t[2][3], m[3], A[4], r[2], z[2], step = 1;
  for (int k = 0; k < v; k++)
    w[k] = x[k];                                   /* vertical projection */
  for (it = 0; it < 60 && step > 0; it++)
    {
      graph_at (o, w, X, t, m);
      newton_matrix (o, x, X, t, A);
      double scale = fabs (o->height);       /* the lengths of the scene */
      for (int c = 0; c <= v; c++)
        scale = fmax (scale, fmax (fabs (x[c]), fabs (X[c])));
      for (int k = 0; k < v; k++)
        {
          r[k] = 0;
          for (int c = 0; c <= v; c++)
            r[k] += (x[c] - X[c]) * t[k][c];
          scale = fmax (scale, fabs (o->center[k]));
        }
      if (!solve_spd (v, A, r, z))
        LAC_ERROR (LAC_EINVAL, "the point (%g, %g%s) has no unique closest "
                   "point on the obstacle", x[0], x[1], v == 2 ? ", ..." : "");
      step = 0;
      for (int k = 0; k < v; k++)
        {
          w[k] += z[k];
          step = fmax (step, fabs (z[k]));
        }
      if (step <= 1e-14 * scale)              /* g is stationary in w */
        step = 0;
    }
  if (step > 0)
    LAC_ERROR (LAC_EINVAL, "the closest point of (%g, %g) on the obstacle "
               "did not converge", x[0], x[1]);
  graph_at (o, w, X, t, m);
  newton_matrix (o, x, X, t, A);
  double len = 0;
  for (int c = 0; c <= v; c++)
    len += m[c] * m[c];
  len = sqrt (len);
  *g = 0;
  for (int c = 0; c <= v; c++)
    {
      n[c] = m[c] / len;
      *g += (x[c] - X[c]) * n[c];
    }
  if (!dndx)
    return LAC_SUCCESS;
  /* dw/dx = A^-1 T;  dn/dw_l = (I - n n^T) (-2 curv_l e_l) / |m| */
  for (int c = 0; c <= v; c++)
    {
      double rc[2] = { 0, 0 }, dw[2] = { 0, 0 };
      for (int k = 0; k < v; k++)
        rc[k] = t[k][c];
      solve_spd (v, A, rc, dw);
      for (int r2 = 0; r2 <= v; r2++)
        {
          double s = 0;
          for (int l = 0; l < v; l++)
            s += ((r2 == l) - n[r2] * n[l]) * (-2 * o->curv[l]) / len * dw[l];
          dndx[r2 * o->dim + c] = s;
        }
    }
  return LAC_SUCCESS;
}

/* Allocate the arrays of a pairing with np points on ns slave facets. */
static lac_pairing *
pairing_alloc (int dim, size_t ns, size_t np, int along_n)
{
  lac_pairing *P = lac_calloc (1, sizeof *P);
  if (!P)
    return NULL;
  P->dim = dim;
  P->nslave = ns;
  P->npoints = np;
  P->ptr = lac_calloc (ns + 1, sizeof *P->ptr);
  P->xs = lac_calloc (np * (size_t) (dim - 1) + 1, sizeof *P->xs);
  P->xm = lac_calloc (np * (size_t) (dim - 1) + 1, sizeof *P->xm);
  P->master = lac_calloc (np + 1, sizeof *P->master);
  P->w = lac_calloc (np + 1, sizeof *P->w);
  P->gap = lac_calloc (np + 1, sizeof *P->gap);
  P->normal = along_n ? NULL
                      : lac_calloc (np * (size_t) dim + 1, sizeof *P->normal);
  P->covered = lac_calloc (ns + 1, sizeof *P->covered);
  P->measure = lac_calloc (ns + 1, sizeof *P->measure);
  P->lost = lac_calloc (ns + 1, sizeof *P->lost);
  P->pair_ptr = lac_calloc (ns + 1, sizeof *P->pair_ptr);
  P->pair_pt = lac_calloc (1, sizeof *P->pair_pt);
  if (!P->ptr || !P->xs || !P->xm || !P->master || !P->w || !P->gap
      || (!along_n && !P->normal) || !P->covered || !P->measure || !P->lost
      || !P->pair_ptr
      || !P->pair_pt)
    {
      lac_pairing_free (P);
      return NULL;
    }
  return P;
}

int
lac_obstacle_pairing (const lac_pairing_facets *slave,
                      const lac_obstacle *o, int degree, lac_pairing **out)
{
  const lac_mesh *m = slave->mesh;
  int dim = m->dim, nodes[LAC_MAX_FACE_NODES], st = LAC_SUCCESS;
  double no[3] = { 0, 0, 0 };
  lac_quad *q = NULL;
  lac_map mp;
  *out = NULL;
  if (o->dim != dim)
    LAC_ERROR (LAC_EINVAL, "a %dD obstacle for a %dD mesh", o->dim, dim);
  if (slave->n == 0)
    LAC_ERROR (LAC_EINVAL, "no slave facets");
  if (degree <= 0)
    degree = dim == 2 ? 5 : 4;
  lac_elem_type ft;
  if (lac_mesh_facet_nodes (m, slave->cell[0], slave->face[0], nodes, &ft) <= 0)
    LAC_ERROR (LAC_EINVAL, "slave facet 0 does not exist");
  const lac_refelem *fre = lac_refelem_get (ft);
  /* every facet of a slave group has the same shape in lac's meshes but
   * the type (order) may differ: one rule per shape, checked below */
  if (!(q = lac_quad_alloc (fre->shape, degree + 2 * fre->order)))
    return LAC_ENOMEM;
  lac_pairing *P = pairing_alloc (dim, slave->n, slave->n * (size_t) q->n,
                                  o->slave_normal);
  if (!P)
    {
      lac_quad_free (q);
      LAC_ERROR (LAC_ENOMEM, "obstacle pairing of %zu facets", slave->n);
    }
  size_t np = 0;
  for (size_t s = 0; !st && s < slave->n; s++)
    {
      lac_mesh_facet_nodes (m, slave->cell[s], slave->face[s], nodes, &ft);
      if (lac_refelem_get (ft)->shape != fre->shape)
        st = LAC_ERRMSG (LAC_EINVAL, "slave facets of mixed shapes against "
                         "an obstacle (facet %zu)", s);
      for (int p = 0; !st && p < q->n; p++, np++)
        {
          const double *xi = q->xi + p * (dim - 1);
          int nn = lac_contact_facet_eval (m, slave->cell[s], slave->face[s],
                                           xi, nodes, &mp);
          if (nn < 0)
            st = -nn;
          else if (o->slave_normal)
            st = lac_obstacle_gap (o, mp.x, mp.normal, &P->gap[np]);
          else
            st = lac_obstacle_project (o, mp.x, &P->gap[np], no, NULL);
          for (int c = 0; P->normal && c < dim; c++)      /* nu = -n^O */
            P->normal[np * (size_t) dim + c] = -no[c];
          memcpy (P->xs + np * (dim - 1), xi, (size_t) (dim - 1) * sizeof *xi);
          P->master[np] = LAC_OBSTACLE_MASTER;
          P->w[np] = q->w[p] * mp.detJ;                   /* dGamma */
          P->covered[s] += P->w[np];
        }
      P->measure[s] = P->covered[s];
      P->ptr[s + 1] = np;
    }
  lac_quad_free (q);
  if (st)
    {
      lac_pairing_free (P);
      return st;
    }
  *out = P;
  return LAC_SUCCESS;
}
