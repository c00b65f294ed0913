/* lac_run_interference.c -- an interference fit against the chords of its
 *                           surfaces (see lac_run_interference.h)
 *                                                     [LAC (18); §4.6]
 */
#include "run/lac_run_interference.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_status.h"

/* The tolerance of pair p: its interference_tolerance, 0.1 if not
 * given. */
static double
tolerance (const lac_scene *sc, size_t p)
{
  double t = sc->contact[p].interference_tolerance;
  return t > 0 ? t : LAC_INTERFERENCE_TOLERANCE;
}

/* Where column i of pair p is: its node (node-to-segment), else the mean
 * of the vertices of its macro-element's sub-facets. */
static void
where (const lac_contact_pair *p, const lac_contact *c, size_t i,
       double *x)
{
  const lac_mesh *m = p->mesh;
  const lac_macro *M = p->M;
  size_t mac = c->macro[i], n = 0;
  memset (x, 0, 3 * sizeof *x);
  if (c->xpt)
    {
      memcpy (x, c->xpt + 3 * i, 3 * sizeof *x);
      return;
    }
  for (size_t j = M->ptr[mac]; j < M->ptr[mac + 1]; j++)
    {
      int nodes[LAC_MAX_FACE_NODES];
      lac_elem_type ft;
      int k = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], nodes, &ft);
      int nv = lac_refelem_get (ft)->nvertices;
      for (int a = 0; a < nv && a < k; a++, n++)
        for (int d = 0; d < m->dim; d++)
          x[d] += m->x[(size_t) nodes[a] * (size_t) m->dim + (size_t) d];
    }
  for (int d = 0; d < m->dim && n > 0; d++)
    x[d] /= (double) n;
}

/* The largest |g_i| / delta over the columns of pair p (c), into fit if
 * it is the largest so far. */
static void
measure (const lac_contact_pair *pr, size_t p, const lac_contact *c,
         lac_run_fit *fit)
{
  double delta = pr->offset;
  for (size_t i = 0; c && i < c->k; i++)
    {
      double g = c->area[i] > 0 ? c->G[i] / c->area[i] + delta : 0.0;
      if (!fit->measured || fabs (g) / delta > fit->ratio)
        {
          fit->measured = 1;
          fit->ratio = fabs (g) / delta;
          fit->pair = p;
          fit->macro = c->macro[i];
          fit->gap = g;
          where (pr, c, i, fit->x);
        }
    }
}

int
lac_run_interference_check (const lac_scene *sc, const lac_contact_set *set,
                            const lac_contact_set_data *d, lac_run_fit *fit)
{
  memset (fit, 0, sizeof *fit);
  for (size_t p = 0; p < set->n && p < d->n; p++)
    {
      const lac_contact_pair *pr = &set->pair[p];
      lac_run_fit one;
      memset (&one, 0, sizeof one);
      if (!(pr->offset > 0))
        continue;
      measure (pr, p, d->c[p], &one);
      if (one.ratio > tolerance (sc, p))
        return lac_scene_error (sc, &sc->contact[p].sec, "interference",
                                LAC_EINVAL, "the meshes of the two surfaces "
                                "leave a mean gap of %.3g at macro-element "
                                "%zu at (%.6g, %.6g, %.6g) without the "
                                "interference, %.3g of delta = %g (more "
                                "than interference_tolerance = %g): their "
                                "chords do not match, and the fit would be "
                                "off by about as much; use quadratic cells "
                                "(they follow a curve closely), refine, or "
                                "raise interference_tolerance", one.gap,
                                one.macro, one.x[0], one.x[1], one.x[2],
                                one.ratio, pr->offset, tolerance (sc, p));
      if (one.measured && (!fit->measured || one.ratio > fit->ratio))
        *fit = one;
      fit->measured = 1;
    }
  return LAC_SUCCESS;
}

void
lac_run_interference_warning (const lac_scene *sc, const lac_run_fit *fit,
                              char *progress, size_t size)
{
  size_t n = strlen (progress);
  if (!fit->measured || !(fit->ratio > 0.1 * tolerance (sc, fit->pair))
      || n >= size)
    return;
  snprintf (progress + n, size - n, "; warning: [contact %s]: the meshes "
            "leave a mean gap of %.3g without the interference (%.3g of "
            "delta): the fit is off by about as much (quadratic cells, or "
            "refine)", sc->contact[fit->pair].sec.name, fit->gap,
            fit->ratio);
}
