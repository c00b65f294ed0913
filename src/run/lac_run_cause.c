/* lac_run_cause.c -- a failed solve said with its cause
 *                    (see lac_run_cause.h)            [LAC §5, Alg. 1]
 */
#include "run/lac_run_cause.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_status.h"
#include "fem/lac_mesh_check.h"

/* "cause; what the solver saw: its words", the place (the scene) kept in
 * front; the solver's message stripped of that place. */
static int
restate (const lac_scene *sc, int status, const char *cause)
{
  char words[700];
  const char *msg = lac_error_message ();
  size_t n = strlen (sc->path);
  if (!strncmp (msg, sc->path, n) && !strncmp (msg + n, ": ", 2))
    msg += n + 2;
  snprintf (words, sizeof words, "%s", msg);
  return lac_error_place (status, sc->path, "%s; what the solver saw: %s",
                          cause, words);
}

/* A layer thin to rounding: the flattest cell, if it is LAC_RUN_THIN
 * times wider than thick. */
static int
thin_layer (const lac_scene *sc, const lac_mesh *m, int status)
{
  char cause[400], body[160];
  size_t c;
  double thick, diam, a = lac_mesh_flattest (m, &c, &thick, &diam);
  if (!(a * LAC_RUN_THIN < 1)
      || strstr (lac_error_message (), "held by contact alone"))
    return status;                  /* a rigid motion: its message holds */
  if (m->body[c] >= 0)
    snprintf (body, sizeof body, "body '%s'", m->group[m->body[c]].name);
  else
    snprintf (body, sizeof body, "the body of cell %zu", m->cell_tag[c]);
  snprintf (cause, sizeof cause, "%s has cells %.2g times wider than thick "
            "(cell %zu: %.3g thick, %.3g across), which make its stiffness "
            "singular to rounding (its condition grows like the square of "
            "that ratio): make the layer thicker, or leave it out",
            body, 1 / a, m->cell_tag[c], thick, diam);
  return restate (sc, status, cause);
}

/* Small strain: the loop stopped at its limit with settled statuses, and
 * a pair's delta is so far beyond its macro-elements that the rounding
 * of the gaps, about DBL_EPSILON delta / h, is near the tolerance. */
static int
far_interference (const lac_scene *sc, const lac_run_setup *setup,
                  const lac_newton *nw, int status)
{
  const lac_contact *c = setup->data.all;
  const lac_newton_record *r = nw->nhist ? &nw->hist[nw->nhist - 1] : NULL;
  double worst = 0, tol = nw->opts.tol > 0 ? nw->opts.tol : 1e-10;
  size_t pw = 0;
  char cause[600];
  if (!c || !r || r->nchanged != 0)
    return status;
  for (size_t p = 0; p < setup->npairs; p++)
    for (size_t i = setup->data.col[p]; i < setup->data.col[p + 1]; i++)
      {
        double h = setup->pair[p].mesh->dim == 3 ? sqrt (c->size[i])
                   : c->size[i];
        double ratio = h > 0 ? sc->contact[p].interference / h : 0;
        if (ratio > worst)
          worst = ratio, pw = p;
      }
  if (!(DBL_EPSILON * worst > 0.1 * tol))
    return status;
  snprintf (cause, sizeof cause, "[contact %s] interference = %g is %.2g "
            "times the size of its macro-elements: the statuses settled and"
            " the equilibrium residual is at rounding (%.1e), but the "
            "stopping test of the loop asks the mean gaps |d_i| / (|T_i| "
            "h_i) to be below %g, and they carry the rounding of "
            "displacements of the size of the interference, about %.1e; an"
            " interference is an overlap small against the bodies",
            sc->contact[pw].sec.name, sc->contact[pw].interference, worst,
            r->residual, tol, DBL_EPSILON * worst);
  return restate (sc, status, cause);
}

/* Large deformation: a pair with an interference and no facet pair left
 * at the failed step; 1 if found (*status: the restated failure). */
static int
separated (const lac_scene *sc, const lac_run_nl *nl, int *status)
{
  const lac_contact_set_data *d = &nl->model->data;
  double t = nl->log.next < nl->log.nfactor ? nl->log.factor[nl->log.next]
                                            : 1;
  char cause[600];
  for (size_t p = 0; d->P && p < d->n && p < sc->ncontact; p++)
    {
      double delta = sc->contact[p].interference;
      if (!(delta > 0) || (d->P[p] && d->P[p]->npoints > 0))
        continue;
      snprintf (cause, sizeof cause, "[contact %s] interference = %g: at "
                "load factor %g the pair has no facet pair left; in large "
                "deformation its surfaces move apart by t delta = %g, and "
                "the pairing reaches about one facet: keep the interference "
                "below the size of the facets of its surfaces",
                sc->contact[p].sec.name, delta, t, t * delta);
      *status = restate (sc, *status, cause);
      return 1;
    }
  return 0;
}

int
lac_run_cause (const lac_scene *sc, const lac_mesh *m,
               const lac_run_setup *setup, const lac_newton *nw,
               const lac_run_nl *nl, int status)
{
  if (nl && nl->model && separated (sc, nl, &status))
    return status;
  if (status == LAC_EMAXITER && nw && setup)
    return far_interference (sc, setup, nw, status);
  if (status == LAC_ESING && m)
    return thin_layer (sc, m, status);
  return status;
}
