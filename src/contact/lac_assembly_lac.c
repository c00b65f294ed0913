/* lac_assembly_lac.c -- the LAC matrices and mean gaps  [LAC (16)-(18), §4.3]
 *
 * For multiplier i (admissible macro-element T^m) and every integration
 * point of the pairing on the sub-facets of T^m (slave point x_s with
 * shape functions phi^S and unit outward normal n^S, master point x_m =
 * x_s + g0 n^S with shape functions phi^M, weight w):
 *
 *   C(dof(a, c), i) += w phi^S_a(x_s) n^S_c        (C^S  [LAC (16)])
 *   C(dof(b, c), i) -= w phi^M_b(x_m) n^S_c        (C^M, n^M = -n^S)
 *   G_i             += w g0                         ([LAC (18)])
 *   area_i          += w                            (M^LAC_ii [LAC (16)])
 *   size_i          += w without the weight 2 pi r   (h_i, solve/)
 *
 * and lost_i, the part of the sub-facets of T^m whose pairs were dropped
 * (a projection that failed, lac_pairing.h).
 *
 * so that (C^T U)_i = int [u_N] with [u_N] = (u^S - u^M).n^S (lac_newton.h).
 * Against a rigid obstacle (lac_obstacle.h) the points have no master
 * facet, C^M = 0, and the direction is the obstacle's, nu = -n^O (from
 * P->normal) in place of n^S, with g0 the signed distance.  Axisymmetric: w carries 2 pi r.  The variation of
 * C and G with the coordinates (large deformations) is in
 * lac_contact_tangent.h.
 */
#include "contact/lac_assembly_lac.h"

#include <math.h>
#include "contact/lac_contact_facet.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* Add the slave and master terms of one integration point to column i. */
static int
add_point (lac_csc_columns *T, const lac_mesh *mesh, lac_model model,
           size_t scell, int sface, const double *xs, size_t mcell,
           int mface, const double *xm, const double *nu, double w,
           double g, lac_contact *c, size_t i)
{
  int sn[LAC_MAX_FACE_NODES], mn[LAC_MAX_FACE_NODES];
  lac_map ms, mm;
  int dim = mesh->dim, st = LAC_SUCCESS;
  int ns = lac_contact_facet_eval (mesh, scell, sface, xs, sn, &ms), nm = 0;
  if (mcell != (size_t) -1 && ns >= 0)          /* (size_t) -1: rigid obstacle */
    nm = lac_contact_facet_eval (mesh, mcell, mface, xm, mn, &mm);
  if (ns < 0 || nm < 0)
    return ns < 0 ? -ns : -nm;
  c->size[i] += w;                                        /* no weight */
  w *= lac_model_weight (model, ms.x);                    /* 2 pi r dGamma */
  if (!nu)
    nu = ms.normal;                                       /* n^S */
  for (int a = 0; !st && a < ns; a++)
    for (int c = 0; !st && c < dim; c++)                  /* C^S */
      st = lac_csc_columns_add (T, (size_t) sn[a] * dim + c,
                                w * ms.N[a] * nu[c]);
  for (int b = 0; !st && mcell != (size_t) -1 && b < nm; b++)
    for (int c = 0; !st && c < dim; c++)                  /* -C^M */
      st = lac_csc_columns_add (T, (size_t) mn[b] * dim + c,
                                -w * mm.N[b] * ms.normal[c]);
  c->G[i] += w * g;                                       /* int g0 */
  c->area[i] += w;                                        /* |T^m cap Gamma_C| */
  return st;
}

int
lac_assembly_lac (lac_contact *c, const lac_mesh *mesh, lac_model model,
                  const lac_macro *M, const lac_pairing *P,
                  const lac_pairing_facets *master)
{
  size_t ndof = (size_t) mesh->dim * mesh->nnodes;
  int dimf = P->dim - 1, st = LAC_SUCCESS;
  if (master && master->n > 0 && master->mesh != mesh)
    LAC_ERROR (LAC_EINVAL, "slave and master facets must belong to one mesh");
  lac_csc_columns *T = lac_csc_columns_alloc (ndof, c->k);  /* C by columns */
  if (!T)
    return LAC_ENOMEM;
  for (size_t i = 0; !st && i < c->k; i++)
    {
      size_t m = c->macro[i];
      c->G[i] = c->area[i] = c->size[i] = c->lost[i] = 0;
      for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)
        c->lost[i] += P->lost ? P->lost[j] : 0.0;
      for (size_t j = M->ptr[m]; !st && j < M->ptr[m + 1]; j++)
        for (size_t p = P->ptr[j]; !st && p < P->ptr[j + 1]; p++)
          {
            size_t f = P->master[p];
            int rigid = !master || f >= master->n;     /* rigid obstacle */
            st = add_point (T, mesh, model, M->cell[j], M->face[j],
                            P->xs + p * dimf,
                            rigid ? (size_t) -1 : master->cell[f],
                            rigid ? -1 : master->face[f], P->xm + p * dimf,
                            P->normal ? P->normal + p * (size_t) P->dim
                                      : NULL,
                            P->w[p], P->gap[p], c, i);
          }
      if (!st)
        st = lac_csc_columns_end (T);
    }
  /* A mean gap that is zero up to the roundoff of the projections (a
   * few ulps of the facet size) is set to exactly 0 (lac_snap), so that
   * the initial status of [LAC Alg. 1, lines 2-8] does not depend on
   * roundoff. */
  for (size_t i = 0; !st && i < c->k; i++)
    {
      size_t m = c->macro[i];
      double diam = P->dim == 2 ? M->meas[m] : sqrt (M->meas[m]);
      c->G[i] = lac_snap (c->G[i], diam * c->area[i]);
    }
  if (!st)
    {
      lac_csc_free (c->C);
      c->C = lac_csc_columns_take (T);
      if (!c->C)
        st = LAC_ENOMEM;
    }
  lac_csc_columns_free (T);
  return st;
}
