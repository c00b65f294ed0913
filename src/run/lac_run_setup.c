/* lac_run_setup.c -- stage 2 of a run: the contact set-up
 *                    (see lac_run_setup.h)  [LAC Hyp. 1, §4.4, §4.6, Rem. 3]
 */
#include "run/lac_run_setup.h"

#include <stdio.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "run/lac_run_scene.h"

void
lac_run_setup_clear (lac_run_setup *s)
{
  lac_pairing_free (s->pairing);
  lac_macromesh_free (s->macro);
  lac_free (s->on_contact);
  memset (s, 0, sizeof *s);
}

/* Mark the nodes of the slave and master groups. */
static int
mark_contact_nodes (const lac_mesh *m, const lac_group *gs,
                    const lac_group *gm, lac_run_setup *s)
{
  if (!(s->on_contact = lac_calloc (m->nnodes, 1)))
    LAC_ERROR (LAC_ENOMEM, "contact node marks");
  for (size_t k = 0; k < gs->nnodes; k++)
    s->on_contact[gs->node[k]] = 1;
  for (size_t k = 0; gm && k < gm->nnodes; k++)
    s->on_contact[gm->node[k]] = 1;
  return LAC_SUCCESS;
}

/* The pairing of the slave sub-facets with the master facets or the
 * obstacle [LAC §4.6]. */
static int
pair (const lac_scene *sc, const lac_mesh *m, lac_run_setup *s)
{
  const lac_scene_contact *c = &sc->contact[0];
  lac_pairing_facets S = { m, s->macro->ptr[s->macro->n], s->macro->cell,
                           s->macro->face };
  double t0 = lac_seconds ();
  int status;
  status = s->master.n ? lac_pairing_build (&S, &s->master, &s->pair.popts,
                                            &s->pairing)
                       : lac_obstacle_pairing (&S, &s->obstacle, 0,
                                               &s->pairing);
  s->time_pairing = lac_seconds () - t0;
  if (status)
    return lac_scene_error (sc, &c->sec, NULL, status, "%s",
                            lac_error_message ());
  return LAC_SUCCESS;
}

static void
report (const lac_scene *sc, const lac_run_setup *s, int large,
        char *progress, size_t size)
{
  const lac_scene_contact *c = &sc->contact[0];
  int n = snprintf (progress, size, "%zu macro-elements on '%s' (%zu cells "
                    "cut, %zu nodes added), ", s->macro->n, c->slave,
                    s->macro->ncut, s->macro->nnew);
  char with[200];
  snprintf (with, sizeof with, "%s%s%s", c->master ? "'" : "the rigid "
            "obstacle", c->master ? c->master : "", c->master ? "'" : "");
  if (n < 0 || (size_t) n >= size)
    return;
  if (large)
    snprintf (progress + n, size - (size_t) n, "pairing with %s at every "
              "Newton iteration", with);
  else if (!c->master)                  /* no pairs: every facet covered */
    snprintf (progress + n, size - (size_t) n, "%zu slave facets on the "
              "rigid obstacle (%zu integration points)",
              s->pairing->nslave, s->pairing->npoints);
  else if (s->pairing->nfail)
    snprintf (progress + n, size - (size_t) n, "%zu pairs with %s; %zu "
              "pairs dropped (projection failed)", s->pairing->npairs, with,
              s->pairing->nfail);
  else
    snprintf (progress + n, size - (size_t) n, "%zu pairs with %s",
              s->pairing->npairs, with);
}

int
lac_run_setup_build (const lac_scene *sc, int large, lac_mesh **mesh,
                     lac_run_setup *s, char *progress, size_t size)
{
  const lac_scene_contact *c;
  const lac_group *gs, *gm = NULL;
  double t0;
  int status;
  memset (s, 0, sizeof *s);
  if (sc->ncontact == 0)
    {
      snprintf (progress, size, "no [contact]: skipped");
      return LAC_SUCCESS;
    }
  c = &sc->contact[0];
  if (!lac_run_contact_group (sc, *mesh, "slave", c->slave)
      || (c->master && !lac_run_contact_group (sc, *mesh, "master",
                                               c->master)))
    return LAC_EINVAL;
  t0 = lac_seconds ();
  status = c->method == 0 || large            /* lac: Hypothesis 1 */
           ? lac_macromesh_build (mesh, c->slave, NULL, &s->macro)
           : lac_macromesh_trace (*mesh, c->slave, &s->macro);
  if (status)
    return lac_scene_error (sc, &c->sec, "slave", status, "%s",
                            lac_error_message ());
  s->time_refine = lac_seconds () - t0;
  gs = lac_mesh_group (*mesh, c->slave);
  if (c->master)
    {
      gm = lac_mesh_group (*mesh, c->master);
      s->master = lac_pairing_facets_of (*mesh, gm);
    }
  s->obstacle = (lac_obstacle) { (*mesh)->dim, c->height,
                                 { c->curvature[0], c->curvature[1] },
                                 { c->center[0], c->center[1] },
                                 c->normal == 1 };
  s->pair = (lac_contact_pair) { *mesh, (lac_model) sc->scene.model,
                                 s->macro, s->master.n ? &s->master : NULL,
                                 &s->obstacle, c->epsilon > 0 ? c->epsilon
                                 : LAC_EPSILON_DEFAULT, c->method == 2,
                                 { 0 }, c->interference };
  lac_pairing_opts_init (&s->pair.popts);
  s->pair.popts.dist_abs = c->gap_bound;
  if ((status = mark_contact_nodes (*mesh, gs, gm, s))
      || (!large && (status = pair (sc, *mesh, s))))
    return status;
  report (sc, s, large, progress, size);
  return LAC_SUCCESS;
}
