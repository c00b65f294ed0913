/* lac_run_roller.c -- the Dirichlet conditions node by node, and the
 *                     frames of the rollers (see lac_run_roller.h)
 *                                                        [LAC (4), (8)]
 */
#include "run/lac_run_roller.h"

#include <math.h>
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

/* The conditions of a section other than `normal` at node a into c (room
 * for 3); their number. */
static int
section_at (const lac_scene *sc, size_t k, const lac_mesh *m,
            const lac_exact *e, size_t a, lac_run_condition *c)
{
  const lac_scene_dirichlet *bc = &sc->dirichlet[k];
  double val[3] = { 0, 0, 0 };
  int count = 0;
  if (bc->kind == LAC_BC_EXACT)
    lac_exact_u (m->x + (size_t) m->dim * a, (void *) e, val);
  for (int i = 0; i < m->dim; i++)
    if (bc->kind == LAC_BC_EXACT || bc->fixed[i])
      {
        lac_run_condition *ci = &c[count++];
        *ci = (lac_run_condition) { k, { 0, 0, 0 }, bc->kind == LAC_BC_EXACT
                                    ? val[i] : bc->value[i], 0, 0 };
        ci->d[i] = 1;
      }
  return count;
}

/* The rollers: the `normal` sections' groups and the smooth pieces of
 * their faces at every node (fem/lac_frames.h). */
typedef struct rollers
{
  size_t ng;            /* groups                                        */
  size_t *sec;          /* owned, ng: the section of each group          */
  lac_face_pieces P;    /* owned                                         */
} rollers;

static void
rollers_clear (rollers *r)
{
  lac_free (r->sec);
  lac_face_pieces_clear (&r->P);
}

/* The section of piece p: that of its first group. */
static size_t
piece_section (const rollers *r, size_t p)
{
  return r->sec[r->P.grp[r->P.gptr[p]]];
}

/* The sections that share piece p (one face, smooth at node a) give it
 * one value, or an error naming two of them. */
static int
piece_values (const lac_scene *sc, const lac_mesh *m, const rollers *r,
              size_t a, size_t p)
{
  const lac_scene_dirichlet *b0 = &sc->dirichlet[piece_section (r, p)];
  for (size_t j = r->P.gptr[p] + 1; j < r->P.gptr[p + 1]; j++)
    {
      const lac_scene_dirichlet *bj = &sc->dirichlet[r->sec[r->P.grp[j]]];
      double scale = fmax (fabs (b0->normal), fabs (bj->normal));
      const double *x = m->x + (size_t) m->dim * a;
      char where[200];
      if (!(fabs (bj->normal - b0->normal) > 1e-9 * scale))
        continue;
      if (m->dim == 3)
        snprintf (where, sizeof where, "node %zu at (%g, %g, %g)",
                  m->node_tag[a], x[0], x[1], x[2]);
      else
        snprintf (where, sizeof where, "node %zu at (%g, %g)",
                  m->node_tag[a], x[0], x[1]);
      return lac_scene_error (sc, &bj->sec, "group", LAC_EINVAL, "imposes "
                              "u.n = %g at %s, where [dirichlet %s] (line "
                              "%d) imposes %g on the same face (their "
                              "facets there turn by less than %g degrees, "
                              "the corner rule): contradictory conditions; "
                              "give the face one value", bj->normal, where,
                              b0->sec.name, b0->sec.line, b0->normal,
                              LAC_MESH_CORNER_DEG);
    }
  return LAC_SUCCESS;
}

/* The pieces of the `normal` sections' faces, and their values. */
static int
rollers_find (const lac_scene *sc, const lac_mesh *m, rollers *r)
{
  const lac_group **g = lac_calloc (sc->ndirichlet + 1, sizeof *g);
  int status = LAC_SUCCESS;
  memset (r, 0, sizeof *r);
  if (!g || !(r->sec = lac_malloc ((sc->ndirichlet + 1) * sizeof *r->sec)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the rollers' groups");
  for (size_t k = 0; !status && k < sc->ndirichlet; k++)
    if (sc->dirichlet[k].kind == LAC_BC_NORMAL)
      {
        r->sec[r->ng] = k;
        g[r->ng++] = lac_mesh_group (m, sc->dirichlet[k].group);
      }
  if (!status && r->ng
      && (status = lac_frames_pieces (m, r->ng, g, &r->P)))
    {
      char msg[600];
      lac_run_inner_message (msg, sizeof msg);
      status = lac_scene_error (sc, &sc->dirichlet[r->sec[r->P.failed]].sec,
                                "group", status, "%s", msg);
    }
  for (size_t a = 0; !status && r->ng && a < m->nnodes; a++)
    for (size_t p = r->P.ptr[a]; !status && p < r->P.ptr[a + 1]; p++)
      status = piece_values (sc, m, r, a, p);
  lac_free (g);
  return status;
}

/* Count (out NULL) or write the conditions of the `normal` section k at
 * node a, from pos[a] on: one per piece of the face there whose first
 * section it is (a piece two sections share: the first one's). */
static void
roller_at (const lac_scene *sc, size_t k, const rollers *r, size_t a,
           size_t *pos, lac_run_condition *out)
{
  for (size_t p = r->P.ptr[a]; p < r->P.ptr[a + 1]; p++)
    if (piece_section (r, p) == k)
      {
        const double *n = r->P.normal + 3 * p;
        if (out)
          out[pos[a]] = (lac_run_condition) { k, { n[0], n[1], n[2] },
                                              sc->dirichlet[k].normal,
                                              r->P.tilt[p], r->P.end[p] };
        pos[a]++;
      }
}

/* Count (out NULL) or write the conditions of every section at the wanted
 * nodes; pos[a]: the next place of node a. */
static void
visit (const lac_scene *sc, const lac_mesh *m, const lac_exact *e,
       const char *want, const rollers *r, size_t *pos,
       lac_run_condition *out)
{
  lac_run_condition c[3];
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      const lac_group *g = lac_mesh_group (m, sc->dirichlet[k].group);
      int roller = sc->dirichlet[k].kind == LAC_BC_NORMAL;
      for (size_t i = 0; i < g->nnodes; i++)
        {
          size_t a = g->node[i];
          int nc;
          if (want && !want[a])
            continue;
          if (roller)
            {
              roller_at (sc, k, r, a, pos, out);
              continue;
            }
          nc = section_at (sc, k, m, e, a, c);
          for (int j = 0; out && j < nc; j++)
            out[pos[a] + (size_t) j] = c[j];
          pos[a] += (size_t) nc;
        }
    }
}

int
lac_run_conditions_build (const lac_scene *sc, lac_model model,
                          const lac_mesh *m, const char *want,
                          lac_run_conditions *out)
{
  size_t *pos = lac_calloc (m->nnodes + 1, sizeof *pos);
  rollers r;
  lac_exact e;
  int status = rollers_find (sc, m, &r);
  memset (out, 0, sizeof *out);
  lac_run_exact (sc, model, &e);
  if (!status && !pos)
    status = LAC_ERRMSG (LAC_ENOMEM, "Dirichlet conditions");
  if (!status)
    {
      visit (sc, m, &e, want, &r, pos, NULL);                /* count */
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
        visit (sc, m, &e, want, &r, pos, out->c);            /* write */
    }
  rollers_clear (&r);
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

/* Is condition c left out of the rigid-motion check: a roller where its
 * piece of a curved face ends (fem/lac_frames.h)? */
static int
left_out (const lac_run_condition *c)
{
  return c->end && c->tilt > 0;
}

/* The n conditions c into d, v and idx (idx[j]: the condition in place
 * j): in their order (check = 0), or with those the rigid-motion check
 * leaves out last (check = 1).  Returns the number left out. */
static size_t
fill (const lac_run_condition *c, size_t n, int check, double *d, double *v,
      size_t *idx)
{
  size_t j = 0, nout = 0;
  for (int last = 0; last < 2; last++)
    for (size_t i = 0; i < n; i++)
      if ((check && left_out (&c[i])) == last)
        {
          memcpy (d + 3 * j, c[i].d, sizeof c[i].d);
          v[j] = c[i].v, idx[j++] = i;
          nout += (size_t) left_out (&c[i]);
        }
  return nout;
}

/* Node a's frame from its conditions, in their order (a contradiction is
 * an error naming both sections), then with the conditions the
 * rigid-motion check leaves out last (the same fixed span: its first
 * axes are those the check counts); its fixed axes and values into dir,
 * and what the check sees of it into fr. */
static int
node_frame (const lac_scene *sc, const lac_mesh *m, size_t a,
            const lac_run_conditions *cs, lac_frames *fr, lac_dirichlet *dir)
{
  size_t n = cs->ptr[a + 1] - cs->ptr[a], bad, with;
  const lac_run_condition *c = cs->c + cs->ptr[a];
  double *d = lac_malloc ((3 * n + 1) * sizeof *d), R[9], w[3], tilt = 0;
  double *v = lac_malloc ((n + 1) * sizeof *v);
  size_t *idx = lac_malloc ((n + 1) * sizeof *idx);
  char *indep = lac_malloc (n + 1);
  int rank = 0, counted = 0, status = d && v && idx && indep ? LAC_SUCCESS
    : LAC_ERRMSG (LAC_ENOMEM, "frame of node %zu", m->node_tag[a]);
  if (!status)
    fill (c, n, 0, d, v, idx);
  if (!status && lac_frames_basis (m->dim, n, d, v, R, w, indep, &rank, &bad,
                                   &with))
    status = contradiction (sc, m, a, &c[bad], with < n ? &c[with] : NULL,
                            R, w);
  if (!status && fill (c, n, 1, d, v, idx) > 0)
    status = lac_frames_basis (m->dim, n, d, v, R, w, indep, &rank, &bad,
                               &with);
  for (size_t j = 0; !status && j < n; j++)     /* what the check counts */
    if (indep[j] && !left_out (&c[idx[j]]))
      counted++, tilt += c[idx[j]].tilt * c[idx[j]].tilt;
  if (!status)
    status = lac_frames_set (fr, a, R);
  if (!status && (tilt > 0 || counted < rank))
    status = lac_frames_set_check (fr, a, tilt, counted);
  for (int k = 0; !status && k < rank; k++)      /* q_k . u = w_k */
    status = lac_dirichlet_add (dir, (size_t) m->dim * a + (size_t) k, w[k]);
  lac_free (d), lac_free (v), lac_free (idx), lac_free (indep);
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
