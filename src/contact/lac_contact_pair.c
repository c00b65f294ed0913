/* lac_contact_pair.c -- one slave/master pair at given coordinates
 *                       (see lac_contact_pair.h)
 *                                        [LAC §4.6, Def. 1, (16)-(18)]
 */
#include "contact/lac_contact_pair.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "contact/lac_contact_facet.h"
#include "contact/lac_tangential.h"

/* The mesh with its nodes at x: a shallow copy (x borrowed). */
static lac_mesh
moved (const lac_mesh *m, const double *x)
{
  lac_mesh cur = *m;
  if (x)
    cur.x = (double *) x;
  return cur;
}

/* Pairing of the slave facets S with the master (on the mesh `cur`),
 * with the options po and `more` reach. */
static int
pair_facets (const lac_contact_pair *p, const lac_mesh *cur,
             const lac_pairing_facets *S, const lac_pairing_opts *po,
             double more, lac_pairing **P)
{
  lac_pairing_opts o = *po;
  if (!p->master)
    return lac_obstacle_pairing (S, p->obstacle, po->degree, P);
  lac_pairing_facets Mf = *p->master;
  Mf.mesh = cur;
  o.dist_abs += more;
  return lac_pairing_build (S, &Mf, &o, P);
}

int
lac_contact_pair_pairing (const lac_contact_pair *p, const double *x,
                          lac_pairing **P)
{
  lac_mesh cur = moved (p->mesh, x);
  const lac_macro *M = p->M;
  lac_pairing_facets S = { &cur, M->ptr[M->n], M->cell, M->face };
  *P = NULL;
  return pair_facets (p, &cur, &S, &p->popts, p->widened, P);
}

/* The diagonal of the bounding box of the nodes of m at x. */
static double
diagonal (const lac_mesh *m)
{
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 }, d = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; i < m->dim; i++)
      {
        double v = m->x[a * (size_t) m->dim + (size_t) i];
        lo[i] = a ? fmin (lo[i], v) : v;
        hi[i] = a ? fmax (hi[i], v) : v;
      }
  for (int i = 0; i < m->dim; i++)
    d += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return sqrt (d);
}

int
lac_contact_pair_facing (const lac_contact_pair *p, const double *x,
                         int *facing)
{
  enum { NPROBE = 64 };
  lac_mesh cur = moved (p->mesh, x);
  const lac_macro *M = p->M;
  size_t nf = M->ptr[M->n], n = nf < NPROBE ? nf : NPROBE, cell[NPROBE];
  int face[NPROBE];
  lac_pairing_opts po = p->popts;
  lac_pairing *P = NULL;
  *facing = !p->master;                   /* an obstacle faces everything */
  if (!p->master || nf == 0)
    return LAC_SUCCESS;
  for (size_t j = 0; j < n; j++)          /* spread over the surface */
    {
      cell[j] = M->cell[j * nf / n];
      face[j] = M->face[j * nf / n];
    }
  lac_pairing_facets S = { &cur, n, cell, face };
  po.allow_empty = 1;
  int status = pair_facets (p, &cur, &S, &po, diagonal (&cur), &P);
  *facing = !status && P->npairs > 0;
  lac_pairing_free (P);
  return status;
}

int
lac_contact_pair_contact (const lac_contact_pair *p, const double *x,
                          const lac_pairing *P, lac_contact **c)
{
  lac_mesh cur = moved (p->mesh, x);
  const lac_macro *M = p->M;
  lac_pairing_facets Mf;
  double eps = p->epsilon > 0 ? p->epsilon : LAC_EPSILON_DEFAULT;
  int status;
  *c = NULL;
  if (p->master && P->npairs == 0)
    return LAC_SUCCESS;      /* nothing in reach (popts.allow_*): no column */
  if (p->master)
    {
      Mf = *p->master;
      Mf.mesh = &cur;
    }
  status = p->nts ? lac_contact_build_nts (&cur, p->model, M, P,
                                           p->master ? &Mf : NULL, c)
                  : lac_contact_build (&cur, p->model, M, P,
                                       p->master ? &Mf : NULL, eps, c);
  if (status == LAC_EADMISS && p->popts.allow_empty)
    {
      lac_error_clear ();                 /* nothing in reach: k = 0 */
      return LAC_SUCCESS;
    }
  if (!status && p->offset != 0)
    status = lac_contact_set_offset (*c, p->offset);   /* g0 - delta */
  if (!status && p->tangential && *c)                  /* friction */
    status = lac_tangential_build (*c, &cur, p->model, M, P,
                                   p->master ? &Mf : NULL, p->friction);
  return status;
}

int
lac_contact_pair_build (const lac_contact_pair *p, const double *x,
                        lac_pairing **P, lac_contact **c)
{
  int status;
  *c = NULL;
  if ((status = lac_contact_pair_pairing (p, x, P)))
    return status;
  return lac_contact_pair_contact (p, x, *P, c);
}

double
lac_contact_pair_h (const lac_contact_pair *p, size_t m)
{
  double a = p->M->meas[m];
  return p->mesh->dim == 3 ? sqrt (a) : a;
}

/* The sub-facets of the macro-elements without a column: S (cell, face
 * arrays allocated here) and their macro-element (of). */
static int
uncovered_facets (const lac_macro *M, const lac_contact *c,
                  lac_pairing_facets *S, size_t **of)
{
  size_t nf = M->ptr[M->n], n = 0;
  size_t *cell = lac_malloc ((nf + 1) * sizeof *cell);
  int *face = lac_malloc ((nf + 1) * sizeof *face);
  *of = lac_malloc ((nf + 1) * sizeof **of);
  if (!cell || !face || !*of)
    {
      lac_free (cell);
      lac_free (face);
      lac_free (*of);
      LAC_ERROR (LAC_ENOMEM, "%zu facets", nf);
    }
  for (size_t m = 0; m < M->n; m++)
    if (!c || c->mult[m] < 0)
      for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)
        {
          cell[n] = M->cell[j];
          face[n] = M->face[j];
          (*of)[n++] = m;
        }
  S->n = n;
  S->cell = cell;
  S->face = face;
  return LAC_SUCCESS;
}

/* The mean gap of macro-element m over its points in P (facets j0 .. j1
 * of S) and the centroid of those points; 0 if it has none. */
static double
mean_gap (const lac_mesh *cur, const lac_pairing_facets *S,
          const lac_pairing *P, size_t j0, size_t j1, double *xc)
{
  double wg = 0, w = 0;
  int nodes[LAC_MAX_FACE_NODES], dim = cur->dim;
  lac_map mp;
  memset (xc, 0, 3 * sizeof *xc);
  for (size_t j = j0; j < j1; j++)
    for (size_t q = P->ptr[j]; q < P->ptr[j + 1]; q++)
      {
        if (lac_contact_facet_eval (cur, S->cell[j], S->face[j],
                                    P->xs + q * (size_t) (dim - 1), nodes,
                                    &mp) < 0)
          continue;
        wg += P->w[q] * P->gap[q];
        w += P->w[q];
        for (int k = 0; k < dim; k++)
          xc[k] += P->w[q] * mp.x[k];
      }
  for (int k = 0; k < dim && w > 0; k++)
    xc[k] /= w;
  return w > 0 ? wg / w : 0.0;
}

/* The deepest of u and a slot of depth `depth`, size h, at xc. */
static void
deeper (lac_contact_uncovered *u, double depth, double h, size_t slot,
        int paired, const double *xc)
{
  if (depth > 0 && (u->depth <= 0 || depth / h > u->depth / u->h))
    {
      u->depth = depth;
      u->h = h;
      u->macro = slot;
      u->paired = paired;
      memcpy (u->x, xc, sizeof u->x);
    }
}

/* Node-to-segment: its slots are the slave nodes, in an order that does
 * not depend on x (lac_nts.c).  The nodes without a multiplier in c,
 * projected onto the master at x with `reach` more: their gaps. */
static int
nts_uncovered (const lac_contact_pair *p, const double *x,
               const lac_contact *c, double reach, double tol,
               lac_contact_uncovered *u)
{
  lac_contact_pair q = *p;
  lac_pairing *P = NULL;
  lac_contact *cx = NULL;
  q.widened += reach;
  q.popts.allow_empty = 1;
  int status = lac_contact_pair_build (&q, x, &P, &cx);
  for (size_t i = 0; !status && cx && i < cx->k; i++)
    {
      size_t m = cx->macro[i];
      if (c && m < c->nmacro && c->mult[m] >= 0)
        continue;                                /* it has a multiplier */
      double depth = -cx->G[i] / cx->area[i];    /* G: w (g - delta) */
      if (depth > tol * cx->size[i])
        u->count++;
      deeper (u, depth, cx->size[i], m, 0, cx->xpt + 3 * i);
    }
  lac_contact_free (cx);
  lac_pairing_free (P);
  return status;
}

int
lac_contact_pair_uncovered (const lac_contact_pair *p, const double *x,
                            const lac_contact *c, double reach, double tol,
                            lac_contact_uncovered *u)
{
  lac_mesh cur = moved (p->mesh, x);
  lac_pairing_facets S = { &cur, 0, NULL, NULL };
  lac_pairing_opts po = p->popts;
  lac_pairing *P = NULL;
  size_t *of = NULL;
  int status;
  memset (u, 0, sizeof *u);
  if (p->nts)
    return nts_uncovered (p, x, c, reach, tol, u);
  if ((status = uncovered_facets (p->M, c, &S, &of)))
    return status;
  po.allow_empty = 1;
  if (S.n > 0)
    status = pair_facets (p, &cur, &S, &po, p->widened + reach, &P);
  for (size_t j = 0; !status && P && j < S.n;)
    {
      size_t m = of[j], j1 = j;
      double xc[3], h = lac_contact_pair_h (p, m);
      while (j1 < S.n && of[j1] == m)
        j1++;
      double depth = p->offset - mean_gap (&cur, &S, P, j, j1, xc);
      if (depth > tol * h)
        u->count++;
      deeper (u, depth, h, m, c && c->covered[m] > 0, xc);
      j = j1;
    }
  lac_pairing_free (P);
  lac_free ((void *) S.cell);
  lac_free ((void *) S.face);
  lac_free (of);
  return status;
}
