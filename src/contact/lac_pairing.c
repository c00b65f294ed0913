/* lac_pairing.c -- the pairing: driver and result              [LAC §4.6]
 *
 * lac_pairing_build gathers the two facet lists and runs the advancing
 * front that decides which (slave, master) pairs overlap (pass 1,
 * lac_pairing_search.c), then computes the integration points of every
 * pair found, slave facet by slave facet, straight into the result (pass
 * 2, here).  The geometry of one pair is in lac_pairing_geom.c.
 *
 * Two passes keep the memory at the size of the result: the front visits
 * slave facets in its own order, while the result is stored by slave index;
 * pass 1 keeps only (slave, master), pass 2 recomputes the (cheap) overlap
 * polygons, counts the points to allocate the result exactly, and does the
 * (costly) projections once.
 */
#include "contact/lac_pairing.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "contact/lac_pairing_geom.h"
#include "contact/lac_pairing_search.h"
#include "base/lac_mem.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

/* ---- the result (pass 2) ------------------------------------------------ */

/* Sort the masters of slave s (pm[pbeg[s] ..], a handful) by index. */
static void
sort_pairs (lac_pairing_search *W, size_t s)
{
  size_t *a = W->pm + W->pbeg[s];
  for (size_t i = 1; i < W->pcnt[s]; i++)
    {
      size_t v = a[i], j = i;
      for (; j > 0 && a[j - 1] > v; j--)
        a[j] = a[j - 1];
      a[j] = v;
    }
}

/* The rules.  Two sets: `lo` of opts.degree and `hi` of
 * opts.degree_nonaffine, each with `sub` on the pieces of an overlap (line
 * in 2D, triangle in 3D) and `tri`/`quad` on whole facets (the slave's own
 * rule); `hi` serves the pairs with a quadrangle that is not a
 * parallelogram, whose chart map is not affine (the integrands are then
 * not polynomials: see rule_sub and rule_full).  And more accurate ones for the measures |T^s| (degree
 * + 4: on a curved facet the surface element is not a polynomial, and
 * |T^s| is the reference the coverage is compared with). */
typedef struct ruleset
{
  lac_quad *sub;      /* owned: line (2D) or triangle (3D)                */
  lac_quad *tri;      /* owned: whole triangles (3D)                      */
  lac_quad *quad;     /* owned: whole quadrangles (3D)                    */
} ruleset;

typedef struct rules
{
  ruleset lo, hi;
  lac_quad *meas[3];  /* owned: measures of lines, triangles, quadrangles */
} rules;

static void
rules_free (rules *R)
{
  ruleset *set[2] = { &R->lo, &R->hi };
  for (int k = 0; k < 2; k++)
    lac_quad_free (set[k]->sub), lac_quad_free (set[k]->tri),
      lac_quad_free (set[k]->quad);
  for (int k = 0; k < 3; k++)
    lac_quad_free (R->meas[k]);
}

/* The rules of one set, of the given degree (checked by the caller). */
static int
ruleset_alloc (ruleset *S, int sdim, int degree)
{
  S->sub = lac_quad_alloc (sdim == 2 ? LAC_SHAPE_LINE : LAC_SHAPE_TRI, degree);
  if (sdim == 3)
    {
      S->tri = lac_quad_alloc (LAC_SHAPE_TRI, degree);
      S->quad = lac_quad_alloc (LAC_SHAPE_QUAD, degree);
    }
  if (!S->sub || (sdim == 3 && (!S->tri || !S->quad)))
    LAC_ERROR (LAC_ENOMEM, "quadrature rules of degree %d", degree);
  return LAC_SUCCESS;
}

static int
rules_alloc (rules *R, int sdim, int degree, int degree_hi)
{
  static const lac_shape shp[3] = {
    LAC_SHAPE_LINE, LAC_SHAPE_TRI, LAC_SHAPE_QUAD
  };
  int k0 = sdim == 2 ? 0 : 1, k1 = sdim == 2 ? 1 : 3, status;
  memset (R, 0, sizeof *R);
  for (int k = k0; k < k1; k++)
    if (degree > lac_quad_max_degree (shp[k])
        || degree_hi > lac_quad_max_degree (shp[k]))
      LAC_ERROR (LAC_EINVAL, "no %s rule of degree %d for the pairing (at "
                 "most %d)", k == 0 ? "line"
                 : k == 1 ? "triangle" : "quadrangle",
                 degree > degree_hi ? degree : degree_hi,
                 lac_quad_max_degree (shp[k]));
  if ((status = ruleset_alloc (&R->lo, sdim, degree))
      || (status = ruleset_alloc (&R->hi, sdim, degree_hi)))
    return status;
  for (int k = k0; k < k1; k++)
    {
      int dm = degree + 4, dmax = lac_quad_max_degree (shp[k]);
      R->meas[k] = lac_quad_alloc (shp[k], dm > dmax ? dmax : dm);
      if (!R->meas[k])
        LAC_ERROR (LAC_ENOMEM, "quadrature rules of degree %d", dm);
    }
  return LAC_SUCCESS;
}

/* The rules of the pair in work: on the pieces of the overlap, `lo` if
 * both charts are affine; on the whole slave facet (its reference cell,
 * where phi^S and the slave map are polynomials), `lo` if the master's
 * chart is affine. */
static const lac_quad *
rule_sub (const rules *R, const lac_pairing_search *W)
{
  return (W->sf.affine && W->mf.affine ? &R->lo : &R->hi)->sub;
}

static const lac_quad *
rule_full (const rules *R, const lac_pairing_search *W)
{
  const ruleset *S = W->mf.affine ? &R->lo : &R->hi;
  if (W->sf.sdim == 2)
    return S->sub;
  return W->sf.re->shape == LAC_SHAPE_TRI ? S->tri : S->quad;
}

static const lac_quad *
rule_meas (const rules *R, const lac_pairing_facet *f)
{
  return R->meas[f->re->shape == LAC_SHAPE_LINE ? 0
                 : f->re->shape == LAC_SHAPE_TRI ? 1 : 2];
}

/* |T^s| with the facet's own rule: sum_q w_q |dx/dxi|(xi_q). */
static int
facet_measure (const lac_pairing_facet *f, const lac_quad *q, double *meas)
{
  lac_map m;
  int status;
  *meas = 0;
  for (int p = 0; p < q->n; p++)
    {
      if ((status = lac_map_face (f->re, f->sdim, f->xe, q->xi + p * q->dim,
                                  &m)))
        return status;
      *meas += q->w[p] * m.detJ;
    }
  return LAC_SUCCESS;
}

static lac_pairing *
result_alloc (size_t ns, size_t npairs, size_t npts, int dim)
{
  size_t d = (size_t) dim - 1;
  lac_pairing *P = lac_calloc (1, sizeof *P);
  if (!P)
    return NULL;
  P->dim = dim;
  P->nslave = ns;
  P->ptr = lac_calloc (ns + 1, sizeof *P->ptr);
  P->xs = lac_malloc ((npts * d + 1) * sizeof *P->xs);
  P->xm = lac_malloc ((npts * d + 1) * sizeof *P->xm);
  P->master = lac_malloc ((npts + 1) * sizeof *P->master);
  P->w = lac_malloc ((npts + 1) * sizeof *P->w);
  P->gap = lac_malloc ((npts + 1) * sizeof *P->gap);
  P->covered = lac_calloc (ns + 1, sizeof *P->covered);
  P->measure = lac_calloc (ns + 1, sizeof *P->measure);
  P->lost = lac_calloc (ns + 1, sizeof *P->lost);
  P->pair_ptr = lac_calloc (ns + 1, sizeof *P->pair_ptr);
  P->pair_master = lac_malloc ((npairs + 1) * sizeof *P->pair_master);
  P->pair_measure = lac_malloc ((npairs + 1) * sizeof *P->pair_measure);
  P->pair_pt = lac_calloc (npairs + 1, sizeof *P->pair_pt);
  if (!P->ptr || !P->xs || !P->xm || !P->master || !P->w || !P->gap
      || !P->covered || !P->measure || !P->lost || !P->pair_ptr || !P->pair_master
      || !P->pair_measure || !P->pair_pt)
    {
      lac_pairing_free (P);
      return NULL;
    }
  return P;
}

/* The points of pair (s, m), appended to P.  A failed projection drops
 * the pair: counted in P->nfail, its part of slave facet s in P->lost. */
static int
fill_pair (lac_pairing_search *W, lac_pairing *P, const rules *R, size_t s,
           size_t m)
{
  double poly[2 * LAC_PAIRING_MAXPOLY];
  int np, npts, status;
  size_t d = (size_t) P->dim - 1, k = P->npoints;
  if ((status = lac_pairing_side_facet (&W->M, m, &W->mf, "master")))
    return status;
  if (lac_pairing_overlap (&W->sf, &W->mf, lac_pairing_gap_bound (W),
                           W->o->facing, poly, &np) != LAC_PAIRING_OVERLAP)
    return LAC_ERRMSG (LAC_ESANITY, "pair (slave, master %zu) changed between "
                       "the two passes", m);
  status = lac_pairing_points (&W->sf, &W->mf, np, poly, rule_sub (R, W),
                               rule_full (R, W),
                               P->xs + k * d, P->xm + k * d, P->w + k,
                               P->gap + k, &npts);
  if (status)
    {
      P->nfail++;
      P->lost[s] += lac_pairing_overlap_fraction (&W->sf, np, poly)
                    * P->measure[s];
      lac_error_clear ();
      return LAC_SUCCESS;
    }
  double meas = 0;
  for (size_t p = k; p < k + (size_t) npts; p++)
    P->master[p] = m, meas += P->w[p];
  P->pair_master[P->npairs] = m;
  P->pair_measure[P->npairs] = meas;
  P->npairs++;
  P->pair_pt[P->npairs] = k + (size_t) npts;
  P->npoints = k + (size_t) npts;
  return LAC_SUCCESS;
}

/* Count the points of every pair (to allocate the result exactly). */
static int
count_points (lac_pairing_search *W, const rules *R, size_t *npts)
{
  double poly[2 * LAC_PAIRING_MAXPOLY];
  int np, status;
  *npts = 0;
  for (size_t s = 0; s < W->S.f->n; s++)
    {
      if (W->pcnt[s] == 0)
        continue;
      if ((status = lac_pairing_side_facet (&W->S, s, &W->sf, "slave")))
        return status;
      for (size_t q = W->pbeg[s]; q < W->pbeg[s] + W->pcnt[s]; q++)
        {
          if ((status = lac_pairing_side_facet (&W->M, W->pm[q], &W->mf,
                                                "master")))
            return status;
          lac_pairing_overlap (&W->sf, &W->mf, lac_pairing_gap_bound (W),
                               W->o->facing, poly, &np);
          *npts += (size_t) lac_pairing_npoints (&W->sf, np, poly,
                                                 rule_sub (R, W),
                                                 rule_full (R, W));
        }
    }
  return LAC_SUCCESS;
}

/* Pass 2: the result, slave facet by slave facet, pairs sorted by master. */
static int
make_result (lac_pairing_search *W, const rules *R, lac_pairing **out)
{
  size_t ns = W->S.f->n, npts;
  int status;
  if ((status = count_points (W, R, &npts)))
    return status;
  lac_pairing *P = result_alloc (ns, W->np, npts, W->S.sdim);
  if (!P)
    LAC_ERROR (LAC_ENOMEM, "pairing of %zu pairs and %zu points", W->np, npts);
  P->nmaster = W->M.f->n;
  for (size_t s = 0; s < ns; s++)
    {
      if ((status = lac_pairing_side_facet (&W->S, s, &W->sf, "slave"))
          || (status = facet_measure (&W->sf, rule_meas (R, &W->sf),
                                      P->measure + s)))
        break;
      sort_pairs (W, s);
      for (size_t q = W->pbeg[s]; q < W->pbeg[s] + W->pcnt[s] && !status; q++)
        status = fill_pair (W, P, R, s, W->pm[q]);
      if (status)
        break;
      for (size_t p = P->ptr[s]; p < P->npoints; p++)
        P->covered[s] += P->w[p];
      P->ptr[s + 1] = P->npoints;
      P->pair_ptr[s + 1] = P->npairs;
    }
  if (status)
    {
      lac_pairing_free (P);
      return status;
    }
  P->ntests = W->ntests, P->nseeds = W->nseeds;
  *out = P;
  return LAC_SUCCESS;
}

/* ---- public functions --------------------------------------------------- */

void
lac_pairing_opts_init (lac_pairing_opts *o)
{
  memset (o, 0, sizeof *o);       /* the defaults of lac_pairing_types.h */
  o->dist_rel = 1.0;
}

lac_pairing_facets
lac_pairing_facets_of (const lac_mesh *m, const lac_group *g)
{
  lac_pairing_facets f = { m, g ? g->n : 0, g ? g->cell : NULL,
                           g ? g->face : NULL };
  return f;
}

void
lac_pairing_free (lac_pairing *P)
{
  if (!P)
    return;
  lac_free (P->ptr), lac_free (P->xs), lac_free (P->xm);
  lac_free (P->master), lac_free (P->w), lac_free (P->gap);
  lac_free (P->normal);
  lac_free (P->covered), lac_free (P->measure), lac_free (P->lost);
  lac_free (P->pair_ptr), lac_free (P->pair_master);
  lac_free (P->pair_measure), lac_free (P->pair_pt);
  lac_free (P);
}

double
lac_pairing_total (const lac_pairing *P)
{
  double s = 0;
  for (size_t i = 0; P && i < P->nslave; i++)
    s += P->covered[i];
  return s;
}

/* Check the arguments of lac_pairing_build. */
static int
check_input (const lac_pairing_facets *slave, const lac_pairing_facets *master,
             const lac_pairing_opts *o)
{
  const lac_pairing_facets *f[2] = { slave, master };
  const char *what[2] = { "slave", "master" };
  for (int k = 0; k < 2; k++)
    {
      if (!f[k] || !f[k]->mesh)
        LAC_ERROR (LAC_EINVAL, "no %s facet list (or no mesh)", what[k]);
      if (f[k]->n == 0)
        LAC_ERROR (LAC_EINVAL, "the %s facet list is empty: is the contact "
                   "group name right?", what[k]);
      if (!f[k]->cell || !f[k]->face)
        LAC_ERROR (LAC_EINVAL, "the %s facet list has no cell/face arrays",
                   what[k]);
    }
  if (slave->mesh->dim != master->mesh->dim)
    LAC_ERROR (LAC_EINVAL, "slave mesh is %d-D, master mesh %d-D",
               slave->mesh->dim, master->mesh->dim);
  if (o->degree < 0 || o->degree_nonaffine < 0 || !(o->dist_rel >= 0)
      || !(o->dist_abs >= 0) || !isfinite (o->facing))
    LAC_ERROR (LAC_EINVAL, "bad options: degree %d, degree_nonaffine %d, "
               "dist_rel %g, dist_abs %g, facing %g", o->degree,
               o->degree_nonaffine, o->dist_rel, o->dist_abs, o->facing);
  return LAC_SUCCESS;
}

/* The message when no pair was found: say which filter removed them. */
static int
empty_error (const lac_pairing_search *W, const lac_pairing *P)
{
  const lac_pairing_opts *o = W->o;
  if (P && P->nfail)
    LAC_ERROR (LAC_EMAXITER, "no pair: the projections of all %zu "
               "overlapping pairs onto the master failed", P->nfail);
  if (W->nfacing)
    LAC_ERROR (LAC_EINVAL, "no slave facet overlaps a master facet that faces "
               "it: %zu nearby (slave, master) pairs have -n_s.n_m <= %g; are "
               "the outward normals opposite (slave and master of two "
               "different bodies, facets oriented out of their cells)?",
               W->nfacing, o->facing);
  if (W->nfar)
    LAC_ERROR (LAC_EINVAL, "no pair: %zu overlapping (slave, master) pairs "
               "are farther apart than the gap bound (dist_rel %g x facet "
               "size + dist_abs %g)", W->nfar, o->dist_rel, o->dist_abs);
  LAC_ERROR (LAC_EINVAL, "no slave facet overlaps a master facet within the "
             "gap bound (dist_rel %g x facet size + dist_abs %g; %zu slave, "
             "%zu master facets, %zu tests): are the surfaces apart, or the "
             "wrong groups?", o->dist_rel, o->dist_abs, W->S.f->n, W->M.f->n,
             W->ntests);
}

/* lac_pairing_build: pair the slave facets with the master facets.
 *                                                          [LAC §4.6]
 *
 *   Step 1: gather both sides (facet nodes, vertex adjacency) and the
 *           bucket grid of the master facets.
 *   Step 2: the advancing front finds the overlapping pairs (pass 1).
 *   Step 3: the integration points of every pair, by slave facet (pass 2).
 *
 *   [in]  slave, master  facet lists (borrowed for the call only)
 *   [in]  opts           options, NULL for the defaults
 *   [out] out            the pairing, to free with lac_pairing_free
 *   returns LAC_SUCCESS; LAC_EINVAL (empty list, bad facet, no pair at all
 *           unless opts->allow_empty, or opts->allow_apart and nothing
 *           within reach); LAC_ESING (degenerate facet);
 *           LAC_ENOMEM
 */
int
lac_pairing_build (const lac_pairing_facets *slave,
                   const lac_pairing_facets *master,
                   const lac_pairing_opts *opts, lac_pairing **out)
{
  lac_pairing_opts o;
  lac_pairing_search W;
  rules R;
  lac_pairing *P = NULL;
  int status;

  memset (&W, 0, sizeof W);
  memset (&R, 0, sizeof R);
  *out = NULL;
  if (opts)
    o = *opts;
  else
    lac_pairing_opts_init (&o);
  if ((status = check_input (slave, master, &o)))
    return status;
  int sdim = slave->mesh->dim;
  if (o.degree == 0)
    o.degree = sdim == 2 ? 5 : 4;
  if (o.degree_nonaffine == 0)
    {
      int dmax = lac_quad_max_degree (sdim == 2 ? LAC_SHAPE_LINE
                                      : LAC_SHAPE_TRI);
      o.degree_nonaffine = o.degree + 14 > dmax ? dmax : o.degree + 14;
    }
  if ((status = rules_alloc (&R, sdim, o.degree, o.degree_nonaffine))
      || (status = lac_pairing_search_init (&W, slave, master, &o)))
    goto done;                                                   /* step 1 */
  if ((status = lac_pairing_search_run (&W)))                    /* step 2 */
    goto done;
  if ((status = make_result (&W, &R, &P)))                       /* step 3 */
    goto done;
  if (P->npairs == 0 && !o.allow_empty
      && !(o.allow_apart && W.nfacing == 0 && P->nfail == 0))
    {
      status = empty_error (&W, P);
      lac_pairing_free (P);
      goto done;
    }
  *out = P;
done:
  lac_pairing_search_free (&W);
  rules_free (&R);
  return status;
}
