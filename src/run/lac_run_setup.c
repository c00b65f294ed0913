/* lac_run_setup.c -- stage 2 of a run: the contact set-up
 *                    (see lac_run_setup.h)  [LAC Hyp. 1, §4.4, §4.6, Rem. 3]
 */
#include "run/lac_run_setup.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_clock.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "run/lac_run_scene.h"

void
lac_run_setup_clear (lac_run_setup *s)
{
  lac_contact_set_data_clear (&s->data);
  lac_contact_set_clear (&s->set);
  for (size_t p = 0; s->macro && p < s->npairs; p++)
    lac_macromesh_free (s->macro[p]);
  lac_free (s->macro);
  lac_free (s->master);
  lac_free (s->obstacle);
  lac_free (s->pair);
  lac_free (s->on_contact);
  memset (s, 0, sizeof *s);
}

int
lac_run_setup_error (const lac_scene *sc, const lac_run_setup *s,
                     const char *key, int status)
{
  size_t p = s->data.failed < sc->ncontact ? s->data.failed : 0;
  return lac_scene_error (sc, &sc->contact[p].sec, key, status, "%s",
                          lac_error_message ());
}

/* Mark the nodes of every slave and master group. */
static int
mark_contact_nodes (const lac_scene *sc, const lac_mesh *m, lac_run_setup *s)
{
  if (!(s->on_contact = lac_calloc (m->nnodes, 1)))
    LAC_ERROR (LAC_ENOMEM, "contact node marks");
  for (size_t p = 0; p < sc->ncontact; p++)
    {
      const lac_scene_contact *c = &sc->contact[p];
      const lac_group *gs = lac_mesh_group (m, c->slave);
      const lac_group *gm = c->master ? lac_mesh_group (m, c->master) : NULL;
      for (size_t k = 0; k < gs->nnodes; k++)
        s->on_contact[gs->node[k]] = 1;
      for (size_t k = 0; gm && k < gm->nnodes; k++)
        s->on_contact[gm->node[k]] = 1;
    }
  return LAC_SUCCESS;
}

/* ---- the roles of the facets ------------------------------------------- */

/* A slave facet: cell * LAC_MAX_FACES + face, and its pair. */
typedef struct role
{
  size_t key, pair;
} role;

static int
cmp_role (const void *a, const void *b)
{
  const role *p = a, *q = b;
  return p->key < q->key ? -1 : p->key > q->key;
}

/* No facet is the slave of one pair and the master of another (or of its
 * own): the same interface would be constrained twice. */
static int
check_roles (const lac_scene *sc, const lac_mesh *m)
{
  size_t n = 0, k = 0;
  for (size_t p = 0; p < sc->ncontact; p++)
    n += lac_mesh_group (m, sc->contact[p].slave)->n;
  role *r = lac_malloc ((n + 1) * sizeof *r);
  if (!r)
    LAC_ERROR (LAC_ENOMEM, "roles of %zu slave facets", n);
  for (size_t p = 0; p < sc->ncontact; p++)
    {
      const lac_group *g = lac_mesh_group (m, sc->contact[p].slave);
      for (size_t e = 0; e < g->n; e++, k++)
        r[k] = (role) { g->cell[e] * LAC_MAX_FACES + (size_t) g->face[e], p };
    }
  qsort (r, n, sizeof *r, cmp_role);
  int status = LAC_SUCCESS;
  for (size_t q = 0; q < sc->ncontact && !status; q++)
    {
      const lac_scene_contact *c = &sc->contact[q];
      const lac_group *g = c->master ? lac_mesh_group (m, c->master) : NULL;
      for (size_t e = 0; g && e < g->n && !status; e++)
        {
          role key = { g->cell[e] * LAC_MAX_FACES + (size_t) g->face[e], 0 };
          const role *hit = bsearch (&key, r, n, sizeof *r, cmp_role);
          if (hit)
            status = lac_scene_error (sc, &c->sec, "master", LAC_EINVAL,
                                      "its facet of cell %zu (face %d) is "
                                      "a slave facet of [contact %s]: one "
                                      "interface would be constrained "
                                      "twice", m->cell_tag[g->cell[e]],
                                      g->face[e],
                                      sc->contact[hit->pair].sec.name);
        }
    }
  lac_free (r);
  return status;
}

/* ---- one body on both sides of a pair ---------------------------------- */

/* The root of node a in the union-find forest up (path halving). */
static size_t
root (size_t *up, size_t a)
{
  while (up[a] != a)
    a = up[a] = up[up[a]];
  return a;
}

/* up: the nodes joined through the cells, so that two nodes of one body
 * (a connected component of the mesh, as in fem/lac_rigid.h) have one
 * root. */
static void
join_bodies (const lac_mesh *m, size_t *up)
{
  for (size_t a = 0; a < m->nnodes; a++)
    up[a] = a;
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t q = m->ptr[c] + 1; q < m->ptr[c + 1]; q++)
      {
        size_t r0 = root (up, (size_t) m->conn[m->ptr[c]]);
        size_t r1 = root (up, (size_t) m->conn[q]);
        if (r0 != r1)
          up[r1] = r0;
      }
}

/* The root of the body of cell c. */
static size_t
body_of (const lac_mesh *m, size_t *up, size_t c)
{
  return root (up, (size_t) m->conn[m->ptr[c]]);
}

/* A pair whose slave and master groups hold facets of one body: a body
 * thinner than a facet whose two faces are slave and master of one pair
 * (two interfaces joined into one group each) is paired through itself
 * or through its neighbour, a gap as deep as it is thin that no
 * displacement closes; the loop then ends blaming a load. */
static int
check_bodies (const lac_scene *sc, const lac_mesh *m)
{
  size_t *up = lac_malloc ((m->nnodes + 1) * sizeof *up);
  size_t *side = lac_malloc ((m->nnodes + 1) * sizeof *side);
  int status = up && side ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "the bodies of %zu nodes",
                             m->nnodes);
  if (!status)
    join_bodies (m, up);
  for (size_t p = 0; !status && p < sc->ncontact; p++)
    {
      const lac_scene_contact *c = &sc->contact[p];
      const lac_group *gs = lac_mesh_group (m, c->slave);
      const lac_group *gm = c->master ? lac_mesh_group (m, c->master) : NULL;
      for (size_t a = 0; gm && a < m->nnodes; a++)
        side[a] = SIZE_MAX;                   /* root -> a slave facet */
      for (size_t e = 0; gm && e < gs->n; e++)
        side[body_of (m, up, gs->cell[e])] = e;
      for (size_t e = 0; gm && e < gm->n && !status; e++)
        {
          size_t f = side[body_of (m, up, gm->cell[e])];
          int b = m->body[gm->cell[e]];
          if (f == SIZE_MAX)
            continue;
          status = lac_scene_error (sc, &c->sec, "master", LAC_EINVAL,
                                    "its facet of cell %zu (face %d) and the"
                                    " slave facet of cell %zu (face %d) are "
                                    "on one body%s%s%s: a pair's slave and "
                                    "master must be different bodies, or "
                                    "the body is paired through its own "
                                    "thickness; give each interface its own"
                                    " [contact] section",
                                    m->cell_tag[gm->cell[e]], gm->face[e],
                                    m->cell_tag[gs->cell[f]], gs->face[f],
                                    b >= 0 ? " '" : "",
                                    b >= 0 ? m->group[b].name : "",
                                    b >= 0 ? "'" : "");
        }
    }
  lac_free (up);
  lac_free (side);
  return status;
}

/* ---- the macro-meshes ---------------------------------------------------- */

/* The pair whose slave group a message about macro-meshes names (the
 * last one named: the second of two groups that share a facet), else
 * the first pair. */
static size_t
named_pair (const lac_scene *sc, const char *msg)
{
  for (size_t p = sc->ncontact; p-- > 0;)
    {
      char q[300];
      snprintf (q, sizeof q, "'%s'", sc->contact[p].slave);
      if (strstr (msg, q))
        return p;
    }
  return 0;
}

/* The macro-meshes of every slave group: the LAC ones in one pass
 * (lac_macromesh_build_set, the mesh refined), then the raw traces of
 * the comparison methods (p0, nts) on the mesh refined. */
static int
build_macros (const lac_scene *sc, int large, lac_mesh **mesh,
              lac_run_setup *s)
{
  size_t n = 0, np = sc->ncontact, *which = lac_malloc (np * sizeof *which);
  const char **name = lac_malloc (np * sizeof *name);
  lac_macro_opts *opt = lac_calloc (np, sizeof *opt);
  lac_macro **M = lac_calloc (np, sizeof *M);
  int status = which && name && opt && M ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "macro-meshes of %zu pairs", np);
  for (size_t p = 0; !status && p < np; p++)
    if (sc->contact[p].method == 0 || large)      /* lac: Hypothesis 1 */
      {
        which[n] = p;
        name[n] = sc->contact[p].slave;
        opt[n++].hex_cut = sc->contact[p].hex_cut;
      }
  if (!status && n > 0
      && (status = lac_macromesh_build_set (mesh, n, name, opt, M)))
    status = lac_scene_error (sc, &sc->contact[named_pair
                                               (sc, lac_error_message ())].sec,
                              "slave", status, "%s", lac_error_message ());
  for (size_t j = 0; !status && j < n; j++)
    s->macro[which[j]] = M[j];
  for (size_t p = 0; !status && p < np; p++)
    if (!s->macro[p]
        && (status = lac_macromesh_trace (*mesh, sc->contact[p].slave,
                                          &s->macro[p])))
      status = lac_scene_error (sc, &sc->contact[p].sec, "slave", status,
                                "%s", lac_error_message ());
  lac_free (which), lac_free (name), lac_free (opt), lac_free (M);
  return status;
}

/* ---- the pairs ----------------------------------------------------------- */

/* Pair p of the set: its master facets (on the refined mesh) or its
 * obstacle, epsilon, method and pairing options. */
static void
make_pair (const lac_scene *sc, const lac_mesh *m, size_t p,
           lac_run_setup *s)
{
  const lac_scene_contact *c = &sc->contact[p];
  if (c->master)
    s->master[p] = lac_pairing_facets_of (m, lac_mesh_group (m, c->master));
  s->obstacle[p] = (lac_obstacle) { m->dim, c->height,
                                    { c->curvature[0], c->curvature[1] },
                                    { c->center[0], c->center[1] },
                                    c->normal == 1 };
  s->pair[p] = (lac_contact_pair) { m, (lac_model) sc->scene.model,
                                    s->macro[p], s->master[p].n
                                    ? &s->master[p] : NULL, &s->obstacle[p],
                                    c->epsilon > 0 ? c->epsilon
                                    : LAC_EPSILON_DEFAULT, c->method == 2,
                                    { 0 }, c->interference, 0, /* g0 - delta */
                                    lac_scene_friction (sc), c->friction };
  lac_pairing_opts_init (&s->pair[p].popts);
  s->pair[p].popts.dist_abs = c->gap_bound;
}

/* The pairing of every pair's slave sub-facets with its master facets or
 * obstacle [LAC §4.6]. */
static int
pair (const lac_scene *sc, lac_run_setup *s)
{
  double t0 = lac_seconds ();
  int status = lac_contact_set_pairing (&s->set, NULL, &s->data);
  s->time_pairing = lac_seconds () - t0;
  return status ? lac_run_setup_error (sc, s, NULL, status) : LAC_SUCCESS;
}

/* The progress line of one pair (as it always was). */
static void
report_one (const lac_scene *sc, const lac_run_setup *s, int large,
            char *progress, size_t size)
{
  const lac_scene_contact *c = &sc->contact[0];
  const lac_macro *M = s->macro[0];
  const lac_pairing *P = s->data.P ? s->data.P[0] : NULL;
  int n = snprintf (progress, size, "%zu macro-elements on '%s' (%zu cells "
                    "cut, %zu nodes added), ", M->n, c->slave, M->ncut,
                    M->nnew);
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
              "rigid obstacle (%zu integration points)", P->nslave,
              P->npoints);
  else if (P->nfail)
    snprintf (progress + n, size - (size_t) n, "%zu pairs with %s; %zu "
              "pairs dropped (projection failed)", P->npairs, with, P->nfail);
  else
    snprintf (progress + n, size - (size_t) n, "%zu pairs with %s",
              P->npairs, with);
}

/* The progress line of several pairs. */
static void
report (const lac_scene *sc, const lac_run_setup *s, int large,
        char *progress, size_t size)
{
  size_t nm = 0, ncut = 0, npairs = 0, nfail = 0;
  if (s->npairs == 1)
    {
      report_one (sc, s, large, progress, size);
      return;
    }
  for (size_t p = 0; p < s->npairs; p++)
    {
      const lac_pairing *P = s->data.P ? s->data.P[p] : NULL;
      nm += s->macro[p]->n;
      ncut += s->macro[p]->ncut;
      npairs += P ? (P->npairs ? P->npairs : P->nslave) : 0;
      nfail += P ? P->nfail : 0;
    }
  int n = snprintf (progress, size, "%zu contact pairs, %zu macro-elements "
                    "(%zu cells cut, %zu nodes added), ", s->npairs, nm,
                    ncut, s->macro[0]->nnew);
  if (n < 0 || (size_t) n >= size)
    return;
  if (large)
    snprintf (progress + n, size - (size_t) n, "pairing at every Newton "
              "iteration");
  else
    n += snprintf (progress + n, size - (size_t) n, "%zu facet pairs%s",
                   npairs, nfail ? " (some dropped: projection failed)" : "");
  for (size_t p = 0; !large && p < s->npairs; p++)   /* apart (set.h) */
    if (sc->contact[p].master && s->data.P[p]->npairs == 0
        && n >= 0 && (size_t) n < size)
      n += snprintf (progress + n, size - (size_t) n, "; [contact %s] has "
                     "nothing within reach (paired again if the solution "
                     "closes the gap)", sc->contact[p].sec.name);
}

/* The arrays of n pairs. */
static int
setup_alloc (size_t n, lac_run_setup *s)
{
  s->npairs = n;
  s->macro = lac_calloc (n, sizeof *s->macro);
  s->master = lac_calloc (n, sizeof *s->master);
  s->obstacle = lac_calloc (n, sizeof *s->obstacle);
  s->pair = lac_calloc (n, sizeof *s->pair);
  if (!s->macro || !s->master || !s->obstacle || !s->pair)
    LAC_ERROR (LAC_ENOMEM, "contact set-up of %zu pairs", n);
  return LAC_SUCCESS;
}

int
lac_run_setup_build (const lac_scene *sc, int large, lac_mesh **mesh,
                     lac_run_setup *s, char *progress, size_t size)
{
  double t0;
  int status;
  memset (s, 0, sizeof *s);
  if (sc->ncontact == 0)
    {
      snprintf (progress, size, "no [contact]: skipped");
      return LAC_SUCCESS;
    }
  for (size_t p = 0; p < sc->ncontact; p++)
    {
      const lac_scene_contact *c = &sc->contact[p];
      if (!lac_run_contact_group (sc, *mesh, &c->sec, "slave", c->slave)
          || (c->master && !lac_run_contact_group (sc, *mesh, &c->sec,
                                                   "master", c->master)))
        return LAC_EINVAL;
    }
  if ((status = check_roles (sc, *mesh))
      || (status = check_bodies (sc, *mesh))
      || (status = setup_alloc (sc->ncontact, s)))
    return status;
  t0 = lac_seconds ();
  if ((status = build_macros (sc, large, mesh, s)))
    return status;
  s->time_refine = lac_seconds () - t0;
  for (size_t p = 0; p < s->npairs; p++)
    make_pair (sc, *mesh, p, s);
  if ((status = lac_contact_set_init (&s->set, s->pair, s->npairs)))
    return lac_scene_error (sc, &sc->contact[0].sec, "method", status, "%s",
                            lac_error_message ());
  if ((status = mark_contact_nodes (sc, *mesh, s))
      || (!large && (status = pair (sc, s))))
    return status;
  report (sc, s, large, progress, size);
  return LAC_SUCCESS;
}
