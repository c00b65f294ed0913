/* lac_run_roller.c -- the Dirichlet conditions node by node, and the
 *                     frames of the rollers (see lac_run_roller.h)
 *                                                        [LAC (4), (8)]
 */
#include "run/lac_run_roller.h"

#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_frames.h"
#include "run/lac_run_scene.h"

void
lac_run_conditions_clear (lac_run_conditions *cs)
{
  lac_free (cs->ptr);
  lac_free (cs->c);
  memset (cs, 0, sizeof *cs);
}

/* ---- the conditions node by node --------------------------------------- */

/* The conditions of section k at node a (its normal n for `normal`) into
 * c (room for 3); their number. */
static int
section_at (const lac_scene *sc, size_t k, const lac_mesh *m,
            const lac_exact *e, size_t a, const double *n,
            lac_run_condition *c)
{
  const lac_scene_dirichlet *bc = &sc->dirichlet[k];
  double val[3] = { 0, 0, 0 };
  int count = 0;
  if (bc->kind == LAC_BC_NORMAL)
    {
      c[0] = (lac_run_condition) { k, { n[0], n[1], n[2] }, bc->normal };
      return 1;
    }
  if (bc->kind == LAC_BC_EXACT)
    lac_exact_u (m->x + (size_t) m->dim * a, (void *) e, val);
  for (int i = 0; i < m->dim; i++)
    if (bc->kind == LAC_BC_EXACT || bc->fixed[i])
      {
        lac_run_condition *ci = &c[count++];
        *ci = (lac_run_condition) { k, { 0, 0, 0 }, bc->kind == LAC_BC_EXACT
                                    ? val[i] : bc->value[i] };
        ci->d[i] = 1;
      }
  return count;
}

/* The outward normals of every `normal` section's group (3 per node of
 * the group), NULL for the other sections. */
static int
section_normals (const lac_scene *sc, const lac_mesh *m, double **normal)
{
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      const lac_scene_dirichlet *bc = &sc->dirichlet[k];
      const lac_group *g = lac_mesh_group (m, bc->group);
      int status;
      if (bc->kind != LAC_BC_NORMAL)
        continue;
      if (!(normal[k] = lac_malloc ((3 * g->nnodes + 1) * sizeof **normal)))
        LAC_ERROR (LAC_ENOMEM, "normals of group '%s'", g->name);
      if ((status = lac_frames_normals (m, g, normal[k])))
        {
          char msg[600];
          lac_run_inner_message (msg, sizeof msg);
          return lac_scene_error (sc, &bc->sec, "group", status, "%s", msg);
        }
    }
  return LAC_SUCCESS;
}

/* Count (fill = 0) or write (fill = 1) the conditions of every section at
 * the wanted nodes; pos[a]: the next place of node a. */
static void
visit (const lac_scene *sc, const lac_mesh *m, const lac_exact *e,
       const char *want, double *const *normal, size_t *pos,
       lac_run_condition *out)
{
  lac_run_condition c[3];
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      const lac_group *g = lac_mesh_group (m, sc->dirichlet[k].group);
      for (size_t i = 0; i < g->nnodes; i++)
        {
          size_t a = g->node[i];
          if (want && !want[a])
            continue;
          int nc = section_at (sc, k, m, e, a, normal[k] ? normal[k] + 3 * i
                               : NULL, c);
          if (out)
            memcpy (out + pos[a], c, (size_t) nc * sizeof *c);
          pos[a] += (size_t) nc;
        }
    }
}

int
lac_run_conditions_build (const lac_scene *sc, lac_model model,
                          const lac_mesh *m, const char *want,
                          lac_run_conditions *out)
{
  double **normal = lac_calloc (sc->ndirichlet + 1, sizeof *normal);
  size_t *pos = lac_calloc (m->nnodes + 1, sizeof *pos);
  lac_exact e;
  int status = normal && pos ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "Dirichlet conditions");
  memset (out, 0, sizeof *out);
  lac_run_exact (sc, model, &e);
  if (!status)
    status = section_normals (sc, m, normal);
  if (!status)
    {
      visit (sc, m, &e, want, normal, pos, NULL);            /* count */
      out->nnodes = m->nnodes;
      out->ptr = lac_malloc ((m->nnodes + 1) * sizeof *out->ptr);
      if (out->ptr)
        {
          out->ptr[0] = 0;
          for (size_t a = 0; a < m->nnodes; a++)
            out->ptr[a + 1] = out->ptr[a] + pos[a], pos[a] = out->ptr[a];
          out->c = lac_malloc ((out->ptr[m->nnodes] + 1) * sizeof *out->c);
        }
      if (!out->ptr || !out->c)
        status = LAC_ERRMSG (LAC_ENOMEM, "Dirichlet conditions");
      else
        visit (sc, m, &e, want, normal, pos, out->c);        /* write */
    }
  for (size_t k = 0; normal && k < sc->ndirichlet; k++)
    lac_free (normal[k]);
  lac_free (normal);
  lac_free (pos);
  if (status)
    lac_run_conditions_clear (out);
  return status;
}

/* ---- the frames of the rollers ----------------------------------------- */

/* Conditions i and j of node a contradict each other: a message naming
 * both sections; R and w: the frame of the conditions before j. */
static int
contradiction (const lac_scene *sc, const lac_mesh *m, size_t a,
               const lac_run_condition *cj, const lac_run_condition *ci,
               const double *R, const double *w)
{
  const double *x = m->x + (size_t) m->dim * a;
  double implied = 0;
  char where[200];
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++)
      implied += cj->d[i] * R[3 * i + k] * w[k];
  if (m->dim == 3)
    snprintf (where, sizeof where, "node %zu at (%g, %g, %g), u.(%.3g, %.3g, "
              "%.3g)", m->node_tag[a], x[0], x[1], x[2], cj->d[0], cj->d[1],
              cj->d[2]);
  else
    snprintf (where, sizeof where, "node %zu at (%g, %g), u.(%.3g, %.3g)",
              m->node_tag[a], x[0], x[1], cj->d[0], cj->d[1]);
  return lac_scene_error (sc, &sc->dirichlet[cj->sec].sec, "group",
                          LAC_EINVAL, "imposes %s = %g, where the conditions "
                          "before it (among them [dirichlet %s], line %d) "
                          "impose %g: contradictory conditions; give each "
                          "direction one value", where, cj->v,
                          sc->dirichlet[ci ? ci->sec : cj->sec].sec.name,
                          sc->dirichlet[ci ? ci->sec : cj->sec].sec.line,
                          implied);
}

/* Node a's frame from its conditions; its fixed axes and values into dir. */
static int
node_frame (const lac_scene *sc, const lac_mesh *m, size_t a,
            const lac_run_conditions *cs, lac_frames *fr, lac_dirichlet *dir)
{
  size_t n = cs->ptr[a + 1] - cs->ptr[a], bad, with;
  const lac_run_condition *c = cs->c + cs->ptr[a];
  double *d = lac_malloc ((3 * n + 1) * sizeof *d), R[9], w[3];
  double *v = lac_malloc ((n + 1) * sizeof *v);
  char *indep = lac_malloc (n + 1);
  int rank = 0, status = d && v && indep ? LAC_SUCCESS
    : LAC_ERRMSG (LAC_ENOMEM, "frame of node %zu", m->node_tag[a]);
  for (size_t j = 0; !status && j < n; j++)
    memcpy (d + 3 * j, c[j].d, sizeof c[j].d), v[j] = c[j].v;
  if (!status && lac_frames_basis (m->dim, n, d, v, R, w, indep, &rank, &bad,
                                   &with))
    status = contradiction (sc, m, a, &c[bad], with < n ? &c[with] : NULL,
                            R, w);
  if (!status)
    status = lac_frames_set (fr, a, R);
  for (int k = 0; !status && k < rank; k++)      /* q_k . u = w_k */
    status = lac_dirichlet_add (dir, (size_t) m->dim * a + (size_t) k, w[k]);
  lac_free (d);
  lac_free (v);
  lac_free (indep);
  return status;
}

/* A rigid plate may not hold a node with a frame (run/lac_run_plate.h
 * ties the components along the axes). */
static int
plates_apart (const lac_scene *sc, const lac_mesh *m,
              const lac_run_conditions *cs, const lac_frames *fr)
{
  for (size_t k = 0; k < sc->nload; k++)
    {
      const lac_group *g = sc->load[k].plate
                           ? lac_mesh_group (m, sc->load[k].group) : NULL;
      for (size_t i = 0; g && i < g->nnodes; i++)
        {
          size_t a = g->node[i], j = cs->ptr[a];
          if (!lac_frames_of (fr, a))
            continue;
          while (sc->dirichlet[cs->c[j].sec].kind != LAC_BC_NORMAL)
            j++;
          return lac_scene_error (sc, &sc->load[k].sec, "plate", LAC_EINVAL,
                                  "node %zu of the plate also has a "
                                  "condition along a normal ([dirichlet %s]"
                                  ", line %d): a rigid plate and a roller "
                                  "on one node are not supported",
                                  m->node_tag[a],
                                  sc->dirichlet[cs->c[j].sec].sec.name,
                                  sc->dirichlet[cs->c[j].sec].sec.line);
        }
    }
  return LAC_SUCCESS;
}

/* The nodes of the `normal` groups (flags), or NULL if there is none. */
static char *
roller_nodes (const lac_scene *sc, const lac_mesh *m, int *status)
{
  char *want = NULL;
  *status = LAC_SUCCESS;
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      const lac_group *g = lac_mesh_group (m, sc->dirichlet[k].group);
      if (sc->dirichlet[k].kind != LAC_BC_NORMAL)
        continue;
      if (!want && !(want = lac_calloc (m->nnodes + 1, 1)))
        {
          *status = LAC_ERRMSG (LAC_ENOMEM, "roller nodes");
          return NULL;
        }
      for (size_t i = 0; i < g->nnodes; i++)
        want[g->node[i]] = 1;
    }
  return want;
}

int
lac_run_rollers (const lac_scene *sc, lac_model model, const lac_mesh *m,
                 lac_dirichlet *dir)
{
  lac_run_conditions cs = { 0, NULL, NULL };
  lac_frames *fr = NULL;
  int status;
  char *want = roller_nodes (sc, m, &status);
  if (!want)
    return status;
  if (!(status = lac_run_conditions_build (sc, model, m, want, &cs))
      && !(fr = lac_frames_alloc (m->dim, m->nnodes)))
    status = LAC_ENOMEM;
  if (!status)               /* the entries of those nodes are replaced */
    {
      size_t j = 0;
      for (size_t i = 0; i < dir->n; i++)
        if (!want[dir->dof[i] / (size_t) m->dim])
          dir->dof[j] = dir->dof[i], dir->val[j++] = dir->val[i];
      dir->n = j;
    }
  for (size_t a = 0; !status && a < m->nnodes; a++)
    if (want[a])
      status = node_frame (sc, m, a, &cs, fr, dir);
  if (!status)
    status = plates_apart (sc, m, &cs, fr);
  if (!status)
    {
      lac_frames_free (dir->frames);
      dir->frames = fr;
      fr = NULL;
    }
  lac_frames_free (fr);
  lac_run_conditions_clear (&cs);
  lac_free (want);
  return status;
}
