/* lac_tangential.c -- the tangential averages of friction
 *                     (see lac_tangential.h)  [LAC (16)-(18), with t for n]
 */
#include "contact/lac_tangential.h"

#include <math.h>
#include "contact/lac_contact_facet.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

void
lac_tangential_reference (const double *nbar, double *ref)
{
  double len = fabs (nbar[0]) + fabs (nbar[1]) + fabs (nbar[2]);
  int best = 0;
  for (int c = 1; c < 3; c++)               /* ties (to rounding): x, y, z */
    if (fabs (nbar[c]) < fabs (nbar[best]) - 1e-8 * len)
      best = c;
  ref[0] = ref[1] = ref[2] = 0;
  ref[best] = 1;
}

void
lac_tangential_frame (int dim, const double *nu, const double *ref,
                      double *t)
{
  if (dim == 2)
    {
      t[0] = -nu[1];                               /* nu turned by +90 deg */
      t[1] = nu[0];
      t[2] = 0;
      return;
    }
  double en = ref[0] * nu[0] + ref[1] * nu[1] + ref[2] * nu[2], len = 0;
  for (int c = 0; c < 3; c++)
    {
      t[c] = ref[c] - en * nu[c];                  /* on the tangent plane */
      len += t[c] * t[c];
    }
  len = sqrt (len);
  for (int c = 0; c < 3; c++)
    t[c] /= len;
  t[3] = nu[1] * t[2] - nu[2] * t[1];              /* t_2 = nu x t_1 */
  t[4] = nu[2] * t[0] - nu[0] * t[2];
  t[5] = nu[0] * t[1] - nu[1] * t[0];
}

/* One point of the pairing: its facets and the normal nu of the normal
 * column (lac_assembly_lac.c). */
typedef struct point
{
  size_t scell, mcell;           /* mcell (size_t) -1: a rigid obstacle */
  int sface, mface;
  const double *xs, *xm, *nu;    /* nu NULL: the slave's normal n^S     */
  double w;
} point;

static point
point_of (const lac_pairing *P, const lac_macro *M,
          const lac_pairing_facets *master, size_t j, size_t p)
{
  int dimf = P->dim - 1;
  size_t f = P->master[p];
  int rigid = !master || f >= master->n;
  return (point) { M->cell[j], rigid ? (size_t) -1 : master->cell[f],
                   M->face[j], rigid ? -1 : master->face[f],
                   P->xs + p * dimf, P->xm + p * dimf,
                   P->normal ? P->normal + p * (size_t) P->dim : NULL,
                   P->w[p] };
}

/* The normals of multiplier i's points summed (3D: its reference axis). */
static int
normal_sum (const lac_mesh *mesh, const lac_macro *M, const lac_pairing *P,
            const lac_pairing_facets *master, size_t m, double *nbar)
{
  int sn[LAC_MAX_FACE_NODES];
  lac_map ms;
  nbar[0] = nbar[1] = nbar[2] = 0;
  for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)
    for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
      {
        point q = point_of (P, M, master, j, p);
        int ns = lac_contact_facet_eval (mesh, q.scell, q.sface, q.xs, sn,
                                         &ms);
        if (ns < 0)
          return -ns;
        for (int c = 0; c < mesh->dim; c++)
          nbar[c] += q.w * (q.nu ? q.nu[c] : ms.normal[c]);
      }
  return LAC_SUCCESS;
}

/* The slave and master terms of one point in the columns of multiplier i. */
static int
add_point (lac_triplet *T, const lac_mesh *mesh, lac_model model,
           const point *q, const double *ref, int ntan, size_t i)
{
  int sn[LAC_MAX_FACE_NODES], mn[LAC_MAX_FACE_NODES], dim = mesh->dim;
  int st = LAC_SUCCESS, nm = 0;
  lac_map ms, mm;
  double t[6];
  int ns = lac_contact_facet_eval (mesh, q->scell, q->sface, q->xs, sn, &ms);
  if (q->mcell != (size_t) -1 && ns >= 0)
    nm = lac_contact_facet_eval (mesh, q->mcell, q->mface, q->xm, mn, &mm);
  if (ns < 0 || nm < 0)
    return ns < 0 ? -ns : -nm;
  double w = q->w * lac_model_weight (model, ms.x);      /* 2 pi r dGamma */
  lac_tangential_frame (dim, q->nu ? q->nu : ms.normal, ref, t);
  for (int b = 0; b < ntan; b++)
    {
      size_t col = i * (size_t) ntan + (size_t) b;
      for (int a = 0; !st && a < ns; a++)
        for (int c = 0; !st && c < dim; c++)             /* slave */
          st = lac_triplet_add (T, (size_t) sn[a] * dim + c, col,
                                w * ms.N[a] * t[3 * b + c]);
      for (int a = 0; !st && a < nm; a++)
        for (int c = 0; !st && c < dim; c++)             /* master */
          st = lac_triplet_add (T, (size_t) mn[a] * dim + c, col,
                                -w * mm.N[a] * t[3 * b + c]);
    }
  return st;
}

int
lac_tangential_build (lac_contact *c, const lac_mesh *mesh, lac_model model,
                      const lac_macro *M, const lac_pairing *P,
                      const lac_pairing_facets *master, double mu)
{
  size_t ndof = (size_t) mesh->dim * mesh->nnodes;
  int ntan = mesh->dim - 1, st = LAC_SUCCESS;
  if (!isfinite (mu) || mu < 0)
    LAC_ERROR (LAC_EINVAL, "friction coefficient %g: expected a number >= 0",
               mu);
  lac_triplet *T = lac_triplet_alloc (ndof, c->k * (size_t) ntan,
                                      64 * (c->k + 1) * (size_t) ntan);
  lac_free (c->sfix);
  lac_free (c->mu);
  c->sfix = lac_calloc (c->k * (size_t) ntan + 1, sizeof *c->sfix);
  c->mu = lac_calloc (c->k + 1, sizeof *c->mu);
  if (!T || !c->sfix || !c->mu)
    {
      lac_triplet_free (T);
      LAC_ERROR (LAC_ENOMEM, "tangential columns of %zu multipliers", c->k);
    }
  for (size_t i = 0; !st && i < c->k; i++)
    {
      size_t m = c->macro[i];
      double nbar[3], ref[3] = { 0, 0, 0 };
      c->mu[i] = mu;
      if (mesh->dim == 3 && !(st = normal_sum (mesh, M, P, master, m, nbar)))
        lac_tangential_reference (nbar, ref);
      for (size_t j = M->ptr[m]; !st && j < M->ptr[m + 1]; j++)
        for (size_t p = P->ptr[j]; !st && p < P->ptr[j + 1]; p++)
          {
            point q = point_of (P, M, master, j, p);
            st = add_point (T, mesh, model, &q, ref, ntan, i);
          }
    }
  if (!st)
    {
      lac_csc_free (c->Ct);
      if (!(c->Ct = lac_csc_from_triplet (T)))
        st = LAC_ENOMEM;
      c->ntan = ntan;
    }
  lac_triplet_free (T);
  return st;
}
