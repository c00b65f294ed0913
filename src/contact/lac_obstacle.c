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
static lac_pairing *
pairing_alloc (int dim, size_t ns, size_t np)
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
  P->covered = lac_calloc (ns + 1, sizeof *P->covered);
  P->measure = lac_calloc (ns + 1, sizeof *P->measure);
  P->pair_ptr = lac_calloc (ns + 1, sizeof *P->pair_ptr);
  P->pair_pt = lac_calloc (1, sizeof *P->pair_pt);
  if (!P->ptr || !P->xs || !P->xm || !P->master || !P->w || !P->gap
      || !P->covered || !P->measure || !P->pair_ptr || !P->pair_pt)
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
  lac_pairing *P = pairing_alloc (dim, slave->n, slave->n * (size_t) q->n);
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
          else
            st = lac_obstacle_gap (o, mp.x, mp.normal, &P->gap[np]);
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
