/* lac_admissibility.c -- which macro-elements carry a multiplier  [LAC Def. 1]
 *
 * For a macro-element T^m with interior basis function phi_{m*+1}:
 *
 *   delta  = |T^m cap Gamma_C| / |T^m|
 *   phibar = (1/|T^m cap Gamma_C|) int_{T^m cap Gamma_C} phi_{m*+1}
 *   T^m admissible  iff  int_{T^m cap Gamma_C} phi_{m*+1}
 *                         / sqrt(|T^m cap Gamma_C| |T^m|)
 *                       = phibar sqrt(delta)  >=  epsilon.
 *
 * T^m cap Gamma_C is the part of T^m paired with the master surface: the
 * integration points of the pairing on the sub-facets of T^m.  When T^m
 * has several interior nodes, phi_{m*+1} is the one of largest integral
 * over T^m cap Gamma_C [LAC Remark 1].  A
 * macro-element with no paired point (delta = 0) is never admissible.
 */
#include "contact/lac_admissibility.h"

#include <math.h>
#include "contact/lac_contact_facet.h"
#include "base/lac_mem.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

#define MAX_INTERIOR 32   /* interior nodes of one macro-element (hex20: 12) */

/* |T^s| of slave sub-facet j by its own quadrature rule. */
static int
facet_measure (const lac_mesh *mesh, lac_model model, lac_quad_cache *qc,
               size_t cell, int face, double *meas)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  lac_map mp;
  int nn = lac_mesh_facet_nodes (mesh, cell, face, nodes, &ft);
  const lac_refelem *re = lac_refelem_get (ft);
  if (nn <= 0 || !re)
    LAC_ERROR (LAC_ESANITY, "cell %zu has no face %d", cell, face);
  const lac_quad *q = lac_quad_cache_get (qc, re->shape, 2 * re->order + 2);
  if (!q)
    return LAC_ENOMEM;
  *meas = 0;
  for (int p = 0; p < q->n; p++)
    {
      int st = lac_contact_facet_eval (mesh, cell, face, q->xi + p * re->dim,
                                       nodes, &mp);
      if (st < 0)
        return -st;
      *meas += q->w[p] * mp.detJ * lac_model_weight (model, mp.x);   /* |T^s| */
    }
  return LAC_SUCCESS;
}

/* Over the paired points of sub-facet j of T^m: add to |T^m cap Gamma_C|
 * and to int_{T^m cap Gamma_C} phi_t for each interior node t of T^m. */
static int
facet_paired (const lac_mesh *mesh, lac_model model, const lac_macro *M,
              size_t j, const lac_pairing *P, size_t nint,
              const size_t *inodes, double *covered, double *phis)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_map mp;
  int dimf = P->dim - 1;
  for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
    {
      int nn = lac_contact_facet_eval (mesh, M->cell[j], M->face[j],
                                       P->xs + p * dimf, nodes, &mp);
      if (nn < 0)
        return -nn;
      double w = P->w[p] * lac_model_weight (model, mp.x);
      *covered += w;                                  /* |T^m cap Gamma_C| */
      for (int a = 0; a < nn; a++)
        for (size_t t = 0; t < nint; t++)
          if ((size_t) nodes[a] == inodes[t])
            phis[t] += w * mp.N[a];                   /* int phi_t */
    }
  return LAC_SUCCESS;
}

/* Measures of T^m and the designated interior node [LAC Remark 1]: among
 * the interior nodes of T^m, the one whose basis function has the largest
 * integral over T^m cap Gamma_C (ties: the macro-mesh's own choice, then
 * the lowest index), so that a partly covered T^m uses a node whose
 * support meets Gamma_C. */
static int
macro_measures (lac_contact *c, const lac_mesh *mesh, lac_model model,
                const lac_macro *M, size_t m, const lac_pairing *P,
                lac_quad_cache *qc)
{
  size_t inodes[MAX_INTERIOR];
  double phis[MAX_INTERIOR] = { 0 };
  size_t nint = lac_macromesh_interior (mesh, M, m, inodes, MAX_INTERIOR);
  if (nint > MAX_INTERIOR)
    LAC_ERROR (LAC_ESANITY, "macro-element %zu has %zu interior nodes",
               m, nint);
  c->meas[m] = c->covered[m] = 0;
  for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)
    {
      double mj = 0;
      int st = facet_measure (mesh, model, qc, M->cell[j], M->face[j], &mj);
      if (!st)
        st = facet_paired (mesh, model, M, j, P, nint, inodes,
                           &c->covered[m], phis);
      if (st)
        return st;
      c->meas[m] += mj;                                         /* |T^m| */
    }
  if (nint == 0)
    {
      /* No interior node (P0 on a linear trace, lac_macromesh_trace):
       * Hypothesis 1 fails; the criterion degenerates to that of the
       * constant function 1, sqrt(delta). */
      c->inode[m] = (size_t) -1;
      c->phiint[m] = c->covered[m];
      return LAC_SUCCESS;
    }
  size_t best = nint;
  for (size_t t = 0; t < nint; t++)
    if (inodes[t] == M->inode[m])
      best = t;
  for (size_t t = 0; t < nint; t++)
    if (best == nint || phis[t] > phis[best] * (1 + 1e-12))
      best = t;
  c->inode[m] = inodes[best];
  c->phiint[m] = phis[best];
  return LAC_SUCCESS;
}

int
lac_admissibility_compute (lac_contact *c, const lac_mesh *mesh,
                           lac_model model, const lac_macro *M,
                           const lac_pairing *P, double epsilon)
{
  if (!(epsilon > 0 && epsilon <= 1))
    LAC_ERROR (LAC_EINVAL, "epsilon = %g is outside (0, 1] [LAC Def. 1]",
               epsilon);
  if (P->nslave != M->ptr[M->n])
    LAC_ERROR (LAC_EINVAL, "the pairing has %zu slave facets, the macro-mesh "
               "%zu sub-facets", P->nslave, M->ptr[M->n]);
  lac_quad_cache qc = { 0 };            /* the facets' rules, made once */
  int st = LAC_SUCCESS;
  c->k = 0;
  for (size_t m = 0; m < M->n && !st; m++)
    {
      st = macro_measures (c, mesh, model, M, m, P, &qc);
      if (st)
        break;
      c->crit[m] = c->covered[m] > 0
        ? c->phiint[m] / sqrt (c->covered[m] * c->meas[m]) : 0.0;
      c->admissible[m] = c->crit[m] >= epsilon;                /* Def. 1 */
      c->mult[m] = c->admissible[m] ? (long) c->k : -1;
      if (c->admissible[m])
        c->macro[c->k++] = m;
    }
  lac_quad_cache_free (&qc);
  return st;
}
