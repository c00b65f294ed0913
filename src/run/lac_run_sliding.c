/* lac_run_sliding.c -- the small sliding of a linear run, checked
 *                      (see lac_run_sliding.h)
 *                                          [LAC §4.6, (16)-(18), Alg. 1]
 */
#include "run/lac_run_sliding.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "contact/lac_contact_facet.h"

/* A macro-element: its mean gaps in the deformed shape and of the small
 * strain model, their difference e, its sliding s (the mean tangential
 * displacement of its points relative to the master), its mean normal n,
 * where it is, its slot in the pair; for the worst of a pair, v: the
 * largest displacement along n of a node of the two bodies, and
 * r = e / v. */
typedef struct slide
{
  double gx, glin, e, s, n[3], x[3], v, r;
  double off;         /* the part of its contact that faces no master in
                         the deformed shape (1: all of it); for the pair,
                         that of the contact of all its active ones      */
  double lost;        /* that part as an area (2 pi r weighted)          */
  size_t macro;
} slide;

/* u at the point of facet (cell, face) at reference point xi; its map in
 * mp.  LAC_SUCCESS or the facet's error. */
static int
u_at (const lac_mesh *m, size_t cell, int face, const double *xi,
      const double *u, lac_map *mp, double *v)
{
  int nodes[LAC_MAX_FACE_NODES];
  int k = lac_contact_facet_eval (m, cell, face, xi, nodes, mp);
  if (k < 0)
    return -k;
  memset (v, 0, 3 * sizeof *v);
  for (int a = 0; a < k; a++)
    for (int d = 0; d < m->dim; d++)
      v[d] += mp->N[a] * u[(size_t) nodes[a] * (size_t) m->dim + (size_t) d];
  return LAC_SUCCESS;
}

/* The displacement of point q of sub-facet j relative to its master
 * point: the length of its tangential part *t; the normal nq and the
 * point x. */
static int
point_slide (const lac_contact_pair *p, const lac_pairing *P, size_t j,
             size_t q, const double *u, double *t, double *nq, double *x)
{
  const lac_mesh *m = p->mesh;
  const lac_macro *M = p->M;
  int dim = m->dim, status;
  size_t dm = (size_t) dim - 1;
  double us[3], um[3] = { 0, 0, 0 }, du[3], dn = 0, t2 = 0;
  lac_map ms, mm;
  if ((status = u_at (m, M->cell[j], M->face[j], P->xs + q * dm, u, &ms,
                      us)))
    return status;
  if (p->master
      && (status = u_at (m, p->master->cell[P->master[q]],
                         p->master->face[P->master[q]], P->xm + q * dm, u,
                         &mm, um)))
    return status;
  const double *n = P->normal ? P->normal + q * (size_t) dim : ms.normal;
  for (int d = 0; d < dim; d++)
    {
      du[d] = us[d] - um[d];                       /* u_S - u_M */
      dn += du[d] * n[d];
      nq[d] = n[d];
    }
  for (int d = 0; d < dim; d++)
    t2 += (du[d] - dn * n[d]) * (du[d] - dn * n[d]);
  *t = sqrt (t2);
  memcpy (x, ms.x, sizeof ms.x);
  return LAC_SUCCESS;
}

/* Over the points of macro-element mac of pair p: the mean length of
 * the tangential part of their displacement relative to the master (*s,
 * the sliding), their mean normal n and their centroid xc. */
static int
macro_slide (const lac_contact_pair *p, const lac_pairing *P, size_t mac,
             const double *u, double *s, double *n, double *xc)
{
  const lac_macro *M = p->M;
  double w = 0, ws = 0, len = 0;
  memset (xc, 0, 3 * sizeof *xc);
  memset (n, 0, 3 * sizeof *n);
  for (size_t j = M->ptr[mac]; j < M->ptr[mac + 1]; j++)
    for (size_t q = P->ptr[j]; q < P->ptr[j + 1]; q++)
      {
        double t, nq[3] = { 0, 0, 0 }, x[3];
        int status = point_slide (p, P, j, q, u, &t, nq, x);
        if (status)
          return status;
        ws += P->w[q] * t;
        w += P->w[q];
        for (int d = 0; d < 3; d++)
          {
            xc[d] += P->w[q] * x[d];
            n[d] += P->w[q] * nq[d];
          }
      }
  *s = w > 0 ? ws / w : 0.0;
  for (int d = 0; d < 3 && w > 0; d++)
    {
      xc[d] /= w;
      len += n[d] * n[d];
    }
  for (int d = 0; d < 3 && len > 0; d++)
    n[d] /= sqrt (len);
  return LAC_SUCCESS;
}

/* Node-to-segment: the slot of slave node mac, its normal and where it
 * is (its slots are nodes: no sliding measured). */
static void
node_slide (const lac_contact *c, size_t mac, slide *big)
{
  long i = c->mult[mac];
  big->s = NAN;
  memcpy (big->x, c->xpt + 3 * (size_t) i, sizeof big->x);
  memcpy (big->n, c->npt + 3 * (size_t) i, sizeof big->n);
}

/* Where macro-element (node-to-segment: node) big->macro of pair p is,
 * its normal and how far it slid. */
static int
where (const lac_contact_pair *p, const lac_pairing *P,
       const lac_contact *c, const double *u, slide *big)
{
  if (p->nts)
    {
      node_slide (c, big->macro, big);
      return LAC_SUCCESS;
    }
  return macro_slide (p, P, big->macro, u, &big->s, big->n, big->x);
}

/* Over the active macro-elements of pair p (its pairing P and contact
 * data c in the reference shape, cx in the deformed one; the statuses and
 * mean gaps of nw from slot off): in *big the one whose two mean gaps
 * differ the most; in *lost the one that lost the largest area of its
 * contact to no master in the deformed shape (cx has no column for it,
 * or one of a smaller area: it slid off the master's end, where the
 * small-strain model, which keeps the reference pairing, still presses
 * it), with lost->off the part of the pair's active contact lost so (a
 * slide of the size of the displacements loses a part of that order at
 * the edges, which the small-strain model neglects: the friction patch
 * tests slide by 2.5 % of their size); how far each slid, its normal,
 * where it is. */
static int
pair_worst (const lac_contact_pair *p, const lac_pairing *P,
            const lac_contact *c, const lac_contact *cx, size_t off,
            const lac_newton *nw, const double *u, slide *big, slide *lost)
{
  double area = 0, gone = 0;
  int status = LAC_SUCCESS;
  for (size_t i0 = 0; c && i0 < c->k; i0++)
    {
      size_t mac = c->macro[i0];
      long i = cx && mac < cx->nmacro ? cx->mult[mac] : -1;
      slide one = { 0 };
      if (!nw->active[off + mac] || !(c->area[i0] > 0))
        continue;
      one.macro = mac;
      one.off = i < 0 ? 1.0 : fmax (0.0, 1.0 - cx->area[i] / c->area[i0]);
      one.lost = one.off * c->area[i0];
      area += c->area[i0];
      gone += one.lost;
      if (one.lost > lost->lost)
        *lost = one;
      if (i < 0 || !(cx->area[i] > 0))
        continue;
      one.glin = nw->d[off + mac] / c->area[i0];      /* G - C^T U */
      one.gx = cx->G[i] / cx->area[i];                /* at x = X + u */
      one.e = fabs (one.gx - one.glin);
      if (one.e > big->e)
        *big = one;
    }
  if (big->e > 0)
    status = where (p, P, c, u, big);
  if (!status && lost->lost > 0)
    status = where (p, P, c, u, lost);
  lost->r = lost->off;                    /* the macro-element's own part */
  lost->off = area > 0 ? gone / area : 0.0;
  return status;
}

/* The body of the first node of the first sub-facet of macro-element
 * mac (slave), and of the master facet of its first point (SIZE_MAX: an
 * obstacle, or no point). */
static void
bodies_of (const lac_contact_pair *p, const lac_pairing *P,
           const lac_contact *c, size_t mac, const lac_bodies *B,
           size_t *bs, size_t *bm)
{
  const lac_macro *M = p->M;
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  size_t j = p->nts ? 0 : M->ptr[mac];     /* node-to-segment: mac is a node */
  if (!p->nts)
    lac_mesh_facet_nodes (p->mesh, M->cell[j], M->face[j], nodes, &ft);
  *bs = B->node_body[p->nts ? c->inode[mac] : (size_t) nodes[0]];
  *bm = SIZE_MAX;
  if (p->nts && p->master && p->master->n > 0)     /* node-to-segment */
    {
      lac_mesh_facet_nodes (p->mesh, p->master->cell[0],
                            p->master->face[0], nodes, &ft);
      *bm = B->node_body[nodes[0]];
    }
  else if (!p->nts && p->master && P->ptr[j + 1] > P->ptr[j])
    {
      size_t f = P->master[P->ptr[j]];
      lac_mesh_facet_nodes (p->mesh, p->master->cell[f], p->master->face[f],
                            nodes, &ft);
      *bm = B->node_body[nodes[0]];
    }
}

/* big->v: the largest displacement along big->n of a node of the slave's
 * and the master's bodies, the scale of the normal displacements the
 * contact pressure comes from; big->r = e / v. */
static void
scale (const lac_contact_pair *p, const lac_pairing *P, const lac_contact *c,
       const lac_bodies *B, const double *u, slide *big)
{
  const lac_mesh *m = p->mesh;
  size_t bs, bm, dim = (size_t) m->dim;
  bodies_of (p, P, c, big->macro, B, &bs, &bm);
  for (size_t a = 0; a < m->nnodes; a++)
    if (B->node_body[a] == bs || B->node_body[a] == bm)
      {
        double un = 0;
        for (size_t d = 0; d < dim; d++)
          un += u[a * dim + d] * big->n[d];
        big->v = fmax (big->v, fabs (un));
      }
  big->r = big->e / (big->v > 0 ? big->v : HUGE_VAL);
}

/* Pair p's worst columns (pair_worst) with its contact data made again
 * on x = X + u (within delta more than the pair's reach: an interference
 * leaves the surfaces of the deformed shape about delta apart), and the
 * ratio of the worst gap (scale).  A pairing that fails there (but for
 * want of memory) pairs nothing: every active column then faces no
 * master; with an interference, no test (displacements of the size of
 * delta, far beyond the bodies from a delta of about their size on: the
 * shrink fit of chapter 08 with delta = 1e8 is linear, and the
 * interference's own checks hold it, run/lac_run_interference.h). */
static int
pair_check (const lac_contact_pair *p, const lac_pairing *P,
            const lac_contact *c, size_t off, const lac_newton *nw,
            const lac_bodies *B, const double *u, const double *x,
            slide *big, slide *lost)
{
  lac_contact_pair q = *p;
  lac_pairing *Px = NULL;
  lac_contact *cx = NULL;
  int status;
  memset (big, 0, sizeof *big);
  memset (lost, 0, sizeof *lost);
  q.popts.allow_empty = 1;
  q.widened += fabs (p->offset);
  if ((status = lac_contact_pair_build (&q, x, &Px, &cx)) == LAC_ENOMEM)
    {
      lac_contact_free (cx);
      lac_pairing_free (Px);
      return status;
    }
  if (status)
    {
      lac_error_clear ();                  /* nothing paired there */
      lac_contact_free (cx);
      cx = NULL;
    }
  if ((!cx || cx->k == 0) && p->offset != 0)
    {                   /* moved by about delta: the interference's checks */
      lac_contact_free (cx);
      lac_pairing_free (Px);
      return LAC_SUCCESS;
    }
  status = pair_worst (p, P, c, cx, off, nw, u, big, lost);
  if (!status && big->e > 0)
    scale (p, P, c, B, u, big);
  lac_contact_free (cx);
  lac_pairing_free (Px);
  return status;
}

/* "macro-element M at (x) by s" or "slave node N at (x)" into buf. */
static void
what_slid (const lac_contact_pair *p, const lac_contact *c, const slide *b,
           char *buf, size_t size)
{
  if (p->nts)
    snprintf (buf, size, "slave node %zu at (%.6g, %.6g, %.6g)",
              p->mesh->node_tag[c->inode[b->macro]], b->x[0], b->x[1],
              b->x[2]);
  else
    snprintf (buf, size, "macro-element %zu at (%.6g, %.6g, %.6g) by %.3g",
              b->macro, b->x[0], b->x[1], b->x[2], b->s);
}

/* The error of pair p's macro-element that slid off the master. */
static int
off_error (const lac_scene *sc, size_t p, const char *what, const slide *b,
           double tol)
{
  return lac_scene_error (sc, &sc->contact[p].sec, NULL, LAC_EINVAL,
                          "the solution slides %s off the master: in the "
                          "deformed shape %.3g of the pair's contact (%.3g "
                          "of this one's) faces no master surface (more "
                          "than sliding_tolerance = %g), where the "
                          "small-strain model, which keeps the pairing of "
                          "the reference shape, presses all of it; use "
                          "[scene] large_deformation = yes (it pairs the "
                          "deformed shape), or a master surface that "
                          "extends under it", what, b->off, b->r, tol);
}

/* The error of pair p's worst macro-element, placed at its section. */
static int
slid_error (const lac_scene *sc, size_t p, const char *what, const slide *b,
            double tol)
{
  return lac_scene_error (sc, &sc->contact[p].sec, NULL, LAC_EINVAL,
                          "the solution slides %s along the master: its mean "
                          "gap in the deformed shape is %.3g, the "
                          "small-strain one %.3g, %.3g of the bodies' "
                          "displacement along its normal (%.3g) apart "
                          "(more than "
                          "sliding_tolerance = %g): the pairing of the "
                          "reference shape, which a small-strain run keeps, "
                          "no longer holds the points in contact; use "
                          "[scene] large_deformation = yes (it pairs the "
                          "deformed shape), or raise sliding_tolerance",
                          what, b->gx, b->glin, b->r, b->v, tol);
}

int
lac_run_sliding_check (const lac_scene *sc, const lac_mesh *m,
                       const lac_bodies *B, const lac_run_setup *setup,
                       const lac_newton *nw, const double *u, double *ratio)
{
  const lac_contact_set_data *d = &setup->data;
  size_t n = (size_t) m->dim * m->nnodes;
  double *x = lac_malloc ((n + 1) * sizeof *x);
  int status = x ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "coordinates");
  *ratio = 0;
  for (size_t k = 0; x && k < n; k++)
    x[k] = m->x[k] + u[k];                       /* the deformed shape */
  for (size_t p = 0; !status && nw && p < setup->npairs && p < d->n; p++)
    {
      const lac_contact_pair *pr = &setup->pair[p];
      double tol = sc->contact[p].sliding_tolerance > 0
                   ? sc->contact[p].sliding_tolerance : LAC_SLIDING_TOLERANCE;
      slide big, lost;
      char what[160];
      if ((status = pair_check (pr, d->P[p], d->c[p], setup->set.offset[p],
                                nw, B, u, x, &big, &lost)))
        break;
      *ratio = fmax (*ratio, fmax (big.r, lost.off));
      if (lost.off > tol)
        {
          what_slid (pr, d->c[p], &lost, what, sizeof what);
          status = off_error (sc, p, what, &lost, tol);
        }
      else if (big.r > tol)
        {
          what_slid (pr, d->c[p], &big, what, sizeof what);
          status = slid_error (sc, p, what, &big, tol);
        }
    }
  lac_free (x);
  return status;
}
