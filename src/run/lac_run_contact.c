/* lac_run_contact.c -- where the contact is and what it carries
 *                      (see lac_run_contact.h)       [LAC (16)-(18); §5]
 */
#include "run/lac_run_contact.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "contact/lac_contact_facet.h"
#include "contact/lac_tangential.h"
#include "fem/lac_quadrature.h"

void
lac_run_contact_clear (lac_run_contact *rc)
{
  lac_free (rc->x);
  lac_free (rc->s);
  lac_free (rc->force);
  lac_free (rc->pair_force);
  lac_free (rc->pair_tforce);
  memset (rc, 0, sizeof *rc);
}

/* ---- positions -------------------------------------------------------- */

/* The centroid of macro-element mm (a rule of degree 4 on each facet). */
static int
macro_centroid (const lac_mesh *m, const lac_macro *M, size_t mm,
                lac_quad_cache *qc, double *xc)
{
  int nodes[LAC_MAX_FACE_NODES], dim = m->dim;
  double wsum = 0;
  lac_elem_type ft;
  lac_map mp;
  xc[0] = xc[1] = xc[2] = 0;
  for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
    {
      if (lac_mesh_facet_nodes (m, M->cell[j], M->face[j], nodes, &ft) <= 0)
        LAC_ERROR (LAC_ESANITY, "macro-element %zu: no facet", mm);
      const lac_quad *q = lac_quad_cache_get (qc, lac_refelem_get (ft)->shape,
                                              4);
      if (!q)
        return LAC_ENOMEM;
      for (int p = 0; p < q->n; p++)
        {
          int nn = lac_contact_facet_eval (m, M->cell[j], M->face[j],
                                           q->xi + p * (dim - 1), nodes, &mp);
          if (nn < 0)
            return -nn;
          wsum += q->w[p] * mp.detJ;
          for (int k = 0; k < dim; k++)
            xc[k] += q->w[p] * mp.detJ * mp.x[k];
        }
    }
  for (int k = 0; k < dim; k++)
    xc[k] /= wsum;
  if (dim == 2)
    xc[2] = 0;
  return LAC_SUCCESS;
}

static int
positions (const lac_mesh *m, const lac_run_setup *st, const lac_contact *c,
           lac_run_contact *rc)
{
  lac_quad_cache qc;
  int status = LAC_SUCCESS;
  memset (&qc, 0, sizeof qc);
  for (size_t i = 0; i < 3 * rc->n; i++)
    rc->x[i] = NAN;
  if (c->xpt)                          /* node-to-segment: the nodes */
    {
      for (size_t i = 0; i < c->k; i++)
        memcpy (rc->x + 3 * c->macro[i], c->xpt + 3 * i, 3 * sizeof (double));
      return LAC_SUCCESS;
    }
  for (size_t p = 0; p < st->npairs && !status; p++)
    for (size_t mm = 0; mm < st->macro[p]->n && !status; mm++)
      status = macro_centroid (m, st->macro[p], mm, &qc,
                               rc->x + 3 * (st->set.offset[p] + mm));
  lac_quad_cache_free (&qc);
  return status;
}

/* ---- the curvilinear abscissa (2D) ----------------------------------- */

typedef struct chain
{
  size_t nf;            /* facets                                  */
  int *a, *b;           /* their end nodes                         */
  long *f1, *f2;        /* per node: the (at most two) facets on it */
  double *len;          /* facet lengths                           */
  double *mid;          /* out: abscissa of each facet's middle    */
  char *seen;
} chain;

/* The free (or, closed, any) unseen node of smallest x, then y; -1. */
static long
chain_start (const chain *ch, const lac_mesh *m, int free_only)
{
  long best = -1;
  for (size_t f = 0; f < ch->nf; f++)
    {
      if (ch->seen[f])
        continue;
      for (int e = 0; e < 2; e++)
        {
          int v = e ? ch->b[f] : ch->a[f];
          if (free_only && ch->f2[v] >= 0)
            continue;
          const double *x = m->x + 2 * (size_t) v;
          const double *y = best >= 0 ? m->x + 2 * (size_t) best : x;
          if (best < 0 || x[0] < y[0] || (x[0] == y[0] && x[1] < y[1]))
            best = v;
        }
    }
  return best;
}

/* Walk from node v along unseen facets, s growing from *s. */
static void
chain_walk (chain *ch, long v, double *s)
{
  long f = ch->f1[v];
  if (f >= 0 && ch->seen[f])
    f = ch->f2[v];
  while (f >= 0 && !ch->seen[f])
    {
      ch->seen[f] = 1;
      ch->mid[f] = *s + 0.5 * ch->len[f];
      *s += ch->len[f];
      v = ch->a[f] == v ? ch->b[f] : ch->a[f];
      f = ch->f1[v] == f ? ch->f2[v] : ch->f1[v];
    }
}

static int
chain_fill (chain *ch, const lac_mesh *m, const lac_macro *M,
            const lac_pairing *P)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  for (size_t v = 0; v < m->nnodes; v++)
    ch->f1[v] = ch->f2[v] = -1;
  for (size_t f = 0; f < ch->nf; f++)
    {
      if (lac_mesh_facet_nodes (m, M->cell[f], M->face[f], nodes, &ft) < 2)
        LAC_ERROR (LAC_ESANITY, "slave facet %zu has no end nodes", f);
      ch->a[f] = nodes[0];
      ch->b[f] = nodes[1];
      ch->len[f] = P->measure[f];
      for (int e = 0; e < 2; e++)
        {
          int v = nodes[e];
          if (ch->f1[v] < 0)
            ch->f1[v] = (long) f;
          else
            ch->f2[v] = (long) f;
        }
    }
  return LAC_SUCCESS;
}

/* The abscissae of the macro-elements M of one pair, into rc->s from
 * slot off on (s = 0 at the start of each pair's curve). */
static int
abscissae (const lac_mesh *m, const lac_macro *M, const lac_pairing *P,
           size_t off, lac_run_contact *rc)
{
  chain ch = { M->ptr[M->n], 0, 0, 0, 0, 0, 0, 0 };
  double s = 0;
  long v;
  int status = LAC_SUCCESS;
  ch.a = lac_malloc ((ch.nf + 1) * sizeof *ch.a);
  ch.b = lac_malloc ((ch.nf + 1) * sizeof *ch.b);
  ch.f1 = lac_malloc ((m->nnodes + 1) * sizeof *ch.f1);
  ch.f2 = lac_malloc ((m->nnodes + 1) * sizeof *ch.f2);
  ch.len = lac_malloc ((ch.nf + 1) * sizeof *ch.len);
  ch.mid = lac_malloc ((ch.nf + 1) * sizeof *ch.mid);
  ch.seen = lac_calloc (ch.nf + 1, 1);
  if (!ch.a || !ch.b || !ch.f1 || !ch.f2 || !ch.len || !ch.mid || !ch.seen)
    status = LAC_ERRMSG (LAC_ENOMEM, "abscissae of %zu facets", ch.nf);
  if (!status && !(status = chain_fill (&ch, m, M, P)))
    while ((v = chain_start (&ch, m, 1)) >= 0
           || (v = chain_start (&ch, m, 0)) >= 0)
      chain_walk (&ch, v, &s);
  for (size_t mm = 0; !status && mm < M->n; mm++)
    {
      double num = 0, den = 0;
      for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
        num += ch.mid[j] * ch.len[j], den += ch.len[j];
      rc->s[off + mm] = den > 0 ? num / den : NAN;
    }
  lac_free (ch.a), lac_free (ch.b), lac_free (ch.f1), lac_free (ch.f2);
  lac_free (ch.len), lac_free (ch.mid), lac_free (ch.seen);
  return status;
}

/* ---- forces ------------------------------------------------------------ */

/* n += int_{T^m cap Gamma_C} n^S (model weight), T^m macro-element mm
 * of M paired by P on the nodes of m; against a rigid obstacle the
 * direction of the constraint nu = -n^O (P->normal). */
static int
column_normal (lac_model model, const lac_mesh *m, const lac_macro *M,
               const lac_pairing *P, size_t mm, double *n)
{
  int dim = m->dim, nodes[LAC_MAX_FACE_NODES];
  lac_map mp;
  for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
    for (size_t q = P->ptr[j]; q < P->ptr[j + 1]; q++)
      {
        int nn = lac_contact_facet_eval (m, M->cell[j], M->face[j],
                                         P->xs + q * (dim - 1), nodes, &mp);
        if (nn < 0)
          return -nn;
        double w = P->w[q] * lac_model_weight (model, mp.x);
        const double *nu = P->normal ? P->normal + q * (size_t) dim
                                     : mp.normal;
        for (int k = 0; k < dim; k++)
          n[k] += w * nu[k];
      }
  return LAC_SUCCESS;
}

int
lac_run_pair_force (lac_model model, const lac_mesh *m, const lac_macro *M,
                    const lac_pairing *P, const lac_contact *c, size_t col0,
                    size_t col1, size_t off, const double *lambda,
                    double f[3])
{
  f[0] = f[1] = f[2] = 0;
  for (size_t i = col0; i < col1; i++)
    {
      double n[3] = { 0, 0, 0 };
      int status = column_normal (model, m, M, P, c->macro[i] - off, n);
      if (status)
        return status;
      for (int k = 0; k < 3; k++)
        f[k] += lambda[c->macro[i]] * n[k];
    }
  return LAC_SUCCESS;
}

/* t += int_{T^m cap Gamma_C} t_b for b < ntan (3 values each), the
 * tangent frame of contact/lac_tangential.h. */
static int
column_tangent (lac_model model, const lac_mesh *m, const lac_macro *M,
                const lac_pairing *P, size_t mm, int ntan, double *t)
{
  int dim = m->dim, nodes[LAC_MAX_FACE_NODES];
  double nbar[3] = { 0, 0, 0 }, ref[3] = { 0, 0, 0 }, tb[6];
  lac_map mp;
  int status = column_normal (LAC_PLANE_STRAIN, m, M, P, mm, nbar);
  if (status)
    return status;
  lac_tangential_reference (nbar, ref);
  for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
    for (size_t q = P->ptr[j]; q < P->ptr[j + 1]; q++)
      {
        int nn = lac_contact_facet_eval (m, M->cell[j], M->face[j],
                                         P->xs + q * (dim - 1), nodes, &mp);
        if (nn < 0)
          return -nn;
        double w = P->w[q] * lac_model_weight (model, mp.x);
        lac_tangential_frame (dim, P->normal ? P->normal + q * (size_t) dim
                                             : mp.normal, ref, tb);
        for (int b = 0; b < ntan; b++)
          for (int k = 0; k < 3; k++)
            t[3 * b + k] += w * tb[3 * b + k];
      }
  return LAC_SUCCESS;
}

/* Friction: the tangential force sum_b lambda_t,b int t_b of multiplier i
 * of pair p added to f (3) and to the pair's tangential force. */
static int
tangential_force (lac_model model, const lac_mesh *m,
                  const lac_run_setup *st, const lac_contact *c,
                  const double *lambda_t, size_t i, size_t p, double *f,
                  lac_run_contact *rc)
{
  size_t slot = c->macro[i], nt = (size_t) c->ntan;
  double t[6] = { 0, 0, 0, 0, 0, 0 };
  int status = column_tangent (model, m, st->macro[p], st->data.P[p],
                               slot - st->set.offset[p], c->ntan, t);
  for (size_t b = 0; !status && b < nt; b++)
    for (int k = 0; k < 3; k++)
      {
        double v = lambda_t[slot * nt + b] * t[3 * b + (size_t) k] + 0.0;
        f[k] += v;
        rc->pair_tforce[3 * p + (size_t) k] += v;
      }
  return status;
}

/* f_i = lambda_i n_i (with friction: plus lambda_t,i t_i), the resultant
 * and the resultant of each pair. */
static int
forces (lac_model model, const lac_mesh *m, const lac_run_setup *st,
        const lac_contact *c, const lac_newton *nw, lac_run_contact *rc)
{
  const double *lambda = nw->lambda;
  for (size_t i = 0; i < c->k; i++)
    {
      double *f = rc->force + 3 * i, n[3] = { 0, 0, 0 };
      size_t slot = c->macro[i], p = c->xpt ? 0
                                   : lac_contact_set_pair_of (&st->set, slot);
      int status;
      if (c->xpt)                                  /* collocation */
        for (int k = 0; k < 3; k++)
          n[k] = c->area[i] * c->npt[3 * i + k];
      else if ((status = column_normal (model, m, st->macro[p],
                                        st->data.P[p],
                                        slot - st->set.offset[p], n)))
        return status;
      for (int k = 0; k < 3; k++)
        f[k] = lambda[slot] * n[k] + 0.0;     /* no -0 if lambda = 0 */
      if (c->Ct && (status = tangential_force (model, m, st, c, nw->lambda_t,
                                               i, p, f, rc)))
        return status;
      for (int k = 0; k < 3; k++)
        {
          rc->resultant[k] += f[k];
          rc->pair_force[3 * p + (size_t) k] += f[k];
        }
    }
  return LAC_SUCCESS;
}

/* ---- the summary ------------------------------------------------------- */

/* The axis e (index, sign) nearest to the mean slave normal of the active
 * multipliers, f_i / lambda_i summed (see lac_run_contact.h). */
static void
contact_axis (lac_model model, const lac_run_setup *st, const lac_contact *c,
              const lac_newton *nw, const lac_run_contact *rc, int *axis,
              int *sign)
{
  int dim = lac_model_dim (model);
  double n[3] = { 0, 0, 0 };
  for (size_t i = 0; i < c->k; i++)
    {
      size_t m = c->macro[i];
      for (int k = 0; k < 3 && nw->active[m] && nw->lambda[m] != 0; k++)
        n[k] += rc->force[3 * i + k] / nw->lambda[m];
    }
  *axis = 0;
  for (int k = 1; k < dim; k++)
    if (fabs (n[k]) > fabs (n[*axis]))
      *axis = k;
  if (model == LAC_AXISYMMETRIC)
    *axis = 1;
  *sign = n[*axis] < 0 ? -1 : 1;
  int obstacles = 1;
  for (size_t p = 0; p < st->npairs; p++)
    obstacles &= st->master[p].n == 0;
  if (obstacles)                            /* rigid obstacles below */
    *axis = dim - 1, *sign = -1;
}

static int
summary (lac_model model, const lac_run_setup *st, const lac_contact *c,
         const lac_newton *nw, const lac_run_contact *rc, lac_summary *sum)
{
  static const char *const ax[2][3] = { { "x", "y", "z" }, { "r", "z", "" } };
  int axis, sign, status;
  size_t nact = 0;
  double area = 0, pmax = 0;
  for (size_t i = 0; i < c->k; i++)
    if (nw->active[c->macro[i]])
      {
        nact++;
        area += c->area[i];
        pmax = fmax (pmax, -nw->lambda[c->macro[i]]);
      }
  contact_axis (model, st, c, nw, rc, &axis, &sign);
  if ((status = lac_summary_add (sum, "contact_force", LAC_SUMMARY_REAL,
                                 sign * rc->resultant[axis]))
      || (status = lac_summary_add (sum, "contact_axis", "%s%s",
                                    sign < 0 ? "-" : "+",
                                    ax[model == LAC_AXISYMMETRIC][axis]))
      || (status = lac_summary_add (sum, "contact_area", LAC_SUMMARY_REAL,
                                    area))
      || (status = lac_summary_add (sum, "max_contact_pressure",
                                    LAC_SUMMARY_REAL,
                                    pmax)))
    return status;
  return lac_summary_add (sum, "active_macro_elements", "%zu", nact);
}

/* "what.name = value". */
static int
pair_line (lac_summary *sum, const char *what, const char *name,
           const char *fmt, ...)
{
  char key[300], val[200];
  va_list ap;
  va_start (ap, fmt);
  vsnprintf (val, sizeof val, fmt, ap);
  va_end (ap);
  snprintf (key, sizeof key, "%s.%s", what, name);
  return lac_summary_add (sum, key, "%s", val);
}

/* "what" or "what.name" = "%zu". */
static int
count_line (lac_summary *sum, const char *what, const char *name, size_t n)
{
  return name ? pair_line (sum, what, name, "%zu", n)
              : lac_summary_add (sum, what, "%zu", n);
}

/* Friction's lines of pair p, its columns i0 .. i1 - 1 (name: the
 * pair's, or NULL for the one pair of a scene): the tangential force (a
 * vector) and the macro-elements that stick, slip and are open; for the
 * one pair, its normal force sum lambda_i |T^m_i cap Gamma_C| too (several
 * pairs have it already, contact_normal_force.NAME). */
static int
summary_friction (lac_model model, const lac_contact *c, const lac_newton *nw,
                  const lac_run_contact *rc, size_t p, size_t i0, size_t i1,
                  const char *name, lac_summary *sum)
{
  size_t n[3] = { 0, 0, 0 };
  double fn = 0;
  char key[300];
  int status;
  for (size_t i = i0; i < i1; i++)
    {
      int st = nw->active[c->macro[i]];
      n[st >= 0 && st <= 2 ? st : 0]++;
      fn += nw->lambda[c->macro[i]] * c->area[i];
    }
  if (!name && (status = lac_summary_add (sum, "contact_normal_force",
                                          LAC_SUMMARY_REAL, fn)))
    return status;
  snprintf (key, sizeof key, name ? "friction_force.%s" : "friction_force",
            name);
  if ((status = lac_summary_add_vector (sum, key, rc->pair_tforce + 3 * p,
                                        lac_model_dim (model)))
      || (status = count_line (sum, "stick_macro_elements", name, n[1]))
      || (status = count_line (sum, "slip_macro_elements", name, n[2])))
    return status;
  return count_line (sum, "open_macro_elements", name, n[0]);
}

/* The lines of pair p (columns col[p] .. col[p+1]-1 of c): its force as
 * a vector, its normal force sum lambda_i |T^m_i cap Gamma_C|, area,
 * largest pressure and active macro-elements. */
static int
summary_pair (const lac_scene *sc, lac_model model, const lac_run_setup *st,
              const lac_contact *c, const lac_newton *nw,
              const lac_run_contact *rc, size_t p, lac_summary *sum)
{
  const char *name = sc->contact[p].sec.name;
  size_t nact = 0;
  double area = 0, fn = 0, pmax = 0;
  char key[300];
  int status;
  for (size_t i = st->data.col[p]; i < st->data.col[p + 1]; i++)
    {
      double lam = nw->lambda[c->macro[i]];
      fn += lam * c->area[i];
      if (!nw->active[c->macro[i]])
        continue;
      nact++;
      area += c->area[i];
      pmax = fmax (pmax, -lam);
    }
  snprintf (key, sizeof key, "contact_force.%s", name);
  if ((status = lac_summary_add_vector (sum, key, rc->pair_force + 3 * p,
                                        lac_model_dim (model)))
      || (status = pair_line (sum, "contact_normal_force", name,
                              LAC_SUMMARY_REAL, fn))
      || (status = pair_line (sum, "contact_area", name, LAC_SUMMARY_REAL,
                              area))
      || (status = pair_line (sum, "max_contact_pressure", name,
                              LAC_SUMMARY_REAL, pmax)))
    return status;
  if ((status = pair_line (sum, "active_macro_elements", name, "%zu", nact)))
    return status;
  return c->Ct ? summary_friction (model, c, nw, rc, p, st->data.col[p],
                                   st->data.col[p + 1], name, sum)
               : LAC_SUCCESS;
}

/* Several pairs: the resultant of all as a vector, then each pair's. */
static int
summary_pairs (const lac_scene *sc, lac_model model, const lac_run_setup *st,
               const lac_contact *c, const lac_newton *nw,
               const lac_run_contact *rc, lac_summary *sum)
{
  int status = lac_summary_add_vector (sum, "contact_resultant",
                                       rc->resultant, lac_model_dim (model));
  for (size_t p = 0; p < st->npairs && !status; p++)
    status = summary_pair (sc, model, st, c, nw, rc, p, sum);
  return status;
}

int
lac_run_contact_post (const lac_scene *sc, lac_model model, const lac_mesh *m,
                      const lac_run_setup *setup, const lac_contact *c,
                      const lac_newton *nw, lac_run_contact *rc,
                      lac_summary *sum)
{
  int status;
  memset (rc, 0, sizeof *rc);
  rc->n = c->nmacro;
  rc->k = c->k;
  rc->x = lac_malloc ((3 * rc->n + 1) * sizeof *rc->x);
  rc->s = lac_malloc ((rc->n + 1) * sizeof *rc->s);
  rc->force = lac_calloc (3 * rc->k + 1, sizeof *rc->force);
  rc->pair_force = lac_calloc (3 * setup->npairs, sizeof *rc->pair_force);
  if (!rc->x || !rc->s || !rc->force || !rc->pair_force)
    LAC_ERROR (LAC_ENOMEM, "contact results of %zu macro-elements", rc->n);
  for (size_t i = 0; i < rc->n; i++)
    rc->s[i] = NAN;
  status = positions (m, setup, c, rc);
  for (size_t p = 0; !status && m->dim == 2 && !c->xpt && p < setup->npairs;
       p++)
    status = abscissae (m, setup->macro[p], setup->data.P[p],
                        setup->set.offset[p], rc);
  if (!status && c->Ct && !(rc->pair_tforce = lac_calloc (3 * setup->npairs,
                                                         sizeof (double))))
    status = LAC_ERRMSG (LAC_ENOMEM, "friction forces");
  if (status || (status = forces (model, m, setup, c, nw, rc))
      || (status = summary (model, setup, c, nw, rc, sum)))
    return status;
  if (c->Ct && setup->npairs == 1
      && (status = summary_friction (model, c, nw, rc, 0, 0, c->k, NULL,
                                     sum)))
    return status;
  return setup->npairs > 1 ? summary_pairs (sc, model, setup, c, nw, rc, sum)
                           : LAC_SUCCESS;
}

int
lac_run_pairs_dropped (const lac_contact_set_data *d, const lac_newton *nw,
                       lac_summary *sum)
{
  double lost = 0;
  size_t nfail = lac_contact_set_dropped (d, &lost);
  int status;
  if (nw->widened && (status = lac_summary_add (sum, "pairing_widened",
                                                "%zu", nw->widened)))
    return status;
  if (!nfail)
    return LAC_SUCCESS;
  if ((status = lac_summary_add (sum, "pairs_dropped", "%zu", nfail)))
    return status;
  return lac_summary_add (sum, "area_dropped", LAC_SUMMARY_REAL, lost);
}
