/* lac_run_conflict.c -- contradictions of a scene on its mesh
 *                       (see lac_run_conflict.h)                  [LAC §2]
 *
 * Both checks are linear in the size of the groups (plus a sort of the
 * faces of the mesh for the second), so that a scene of many sections
 * costs what its groups cost.
 */
#include "run/lac_run_conflict.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "run/lac_run_scene.h"

/* ---- Dirichlet values ------------------------------------------------- */

/* The component names of a model: ux uy (uz), axisymmetric ur uz. */
static const char *
component (lac_model model, int c)
{
  static const char *const xyz[3] = { "ux", "uy", "uz" }, *rz[2] =
    { "ur", "uz" };
  return model == LAC_AXISYMMETRIC ? rz[c] : xyz[c];
}

/* What section k imposes at node a: fixed[c] and val[c]. */
static void
imposed (const lac_scene *sc, size_t k, const lac_exact *e,
         const lac_mesh *m, size_t a, int *fixed, double *val)
{
  const lac_scene_dirichlet *bc = &sc->dirichlet[k];
  if (bc->kind == LAC_BC_EXACT)
    lac_exact_u (m->x + (size_t) m->dim * a, (void *) e, val);
  for (int c = 0; c < m->dim; c++)
    {
      fixed[c] = bc->kind == LAC_BC_EXACT || bc->fixed[c];
      if (bc->kind != LAC_BC_EXACT)
        val[c] = bc->value[c];
    }
}

/* Node a (its tag) and where it is, for a message. */
static void
node_words (const lac_mesh *m, size_t a, char *buf, size_t size)
{
  const double *x = m->x + (size_t) m->dim * a;
  size_t tag = m->node_tag ? m->node_tag[a] : a;
  if (m->dim == 3)
    snprintf (buf, size, "node %zu at (%g, %g, %g)", tag, x[0], x[1], x[2]);
  else
    snprintf (buf, size, "node %zu at (%g, %g)", tag, x[0], x[1]);
}

/* Do v (section k) and w (section j) contradict each other?  With load
 * steps, a value ramped by one and imposed whole by the other differs
 * at every step but the last. */
static int
differ (const lac_scene *sc, size_t k, double v, size_t j, double w)
{
  return v != w || (sc->scene.large_deformation && v != 0
                    && sc->dirichlet[k].ramp != sc->dirichlet[j].ramp);
}

static int
dirichlet_conflict (const lac_scene *sc, lac_model model, const lac_mesh *m,
                    size_t k, size_t j, size_t a, int c, double v, double w)
{
  char node[160];
  int ramp = sc->scene.large_deformation && v == w;
  node_words (m, a, node, sizeof node);
  return lac_scene_error (sc, &sc->dirichlet[k].sec, "group", LAC_EINVAL,
                          "imposes %s = %g%s at %s, where [dirichlet %s] "
                          "(line %d) imposes %s = %g%s: contradictory "
                          "conditions; give each node one value",
                          component (model, c), v, ramp
                          ? (sc->dirichlet[k].ramp ? " ramped" : " whole")
                          : "", node, sc->dirichlet[j].sec.name,
                          sc->dirichlet[j].sec.line, component (model, c), w,
                          ramp ? (sc->dirichlet[j].ramp ? " ramped"
                                  : " whole") : "");
}

/* Every dof keeps the first section that fixes it (owner, 1-based) and
 * its value; a later section with another value is an error. */
static int
dirichlet_values (const lac_scene *sc, lac_model model, const lac_mesh *m)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  size_t *owner = lac_calloc (ndof + 1, sizeof *owner);
  double *value = lac_malloc ((ndof + 1) * sizeof *value), val[3];
  int fixed[3], status = LAC_SUCCESS;
  lac_exact e;
  if (!owner || !value)
    status = LAC_ERRMSG (LAC_ENOMEM, "the Dirichlet values of %zu dofs",
                         ndof);
  lac_run_exact (sc, model, &e);
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      const lac_group *g = lac_mesh_group (m, sc->dirichlet[k].group);
      for (size_t i = 0; g && i < g->nnodes && !status; i++)
        {
          size_t a = g->node[i];
          imposed (sc, k, &e, m, a, fixed, val);
          for (int c = 0; c < m->dim && !status; c++)
            {
              size_t d = (size_t) m->dim * a + (size_t) c;
              if (!fixed[c])
                continue;
              if (!owner[d])
                owner[d] = k + 1, value[d] = val[c];
              else if (differ (sc, k, val[c], owner[d] - 1, value[d]))
                status = dirichlet_conflict (sc, model, m, k, owner[d] - 1,
                                             a, c, val[c], value[d]);
            }
        }
    }
  lac_free (owner);
  lac_free (value);
  return status;
}

/* ---- surface loads inside a body -------------------------------------- */

typedef struct face_key
{
  int v[4];            /* vertices, sorted, padded with -1 */
  size_t cell;
  int face;
} face_key;

static int
key_order (const void *a, const void *b)
{
  const face_key *p = a, *q = b;
  for (int i = 0; i < 4; i++)
    if (p->v[i] != q->v[i])
      return p->v[i] < q->v[i] ? -1 : 1;
  return 0;
}

static void
make_key (const lac_mesh *m, size_t c, int f, face_key *k)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  for (int i = 0; i < 4; i++)
    k->v[i] = i < nv ? m->conn[m->ptr[c] + (size_t) re->face_node[f][i]]
                     : -1;
  for (int i = 1; i < nv; i++)
    for (int j = i; j > 0 && k->v[j - 1] > k->v[j]; j--)
      {
        int t = k->v[j];
        k->v[j] = k->v[j - 1];
        k->v[j - 1] = t;
      }
  k->cell = c;
  k->face = f;
}

/* Every face of every cell, sorted by vertices (interior faces twice). */
static face_key *
all_faces (const lac_mesh *m, size_t *n)
{
  face_key *k;
  *n = 0;
  for (size_t c = 0; c < m->ncells; c++)
    *n += (size_t) lac_refelem_get (m->type[c])->nfaces;
  if (!(k = lac_malloc ((*n + 1) * sizeof *k)))
    LAC_ERROR_NULL (LAC_ENOMEM, "the %zu faces of the mesh", *n);
  *n = 0;
  for (size_t c = 0; c < m->ncells; c++)
    for (int f = 0; f < lac_refelem_get (m->type[c])->nfaces; f++)
      make_key (m, c, f, &k[(*n)++]);
  qsort (k, *n, sizeof *k, key_order);
  return k;
}

static int
surface_load (const lac_scene_load *l)
{
  return l->group && (l->kind == LAC_LOAD_PRESSURE
                      || l->kind == LAC_LOAD_TRACTION
                      || l->kind == LAC_LOAD_TOTAL
                      || l->kind == LAC_LOAD_EXACT_TRACTION
                      || l->kind == LAC_LOAD_EXACT_TANGENTIAL);
}

/* The facets of group `name` (of the load or roller of section sec) are
 * each a face of one cell only. */
static int
on_boundary (const lac_scene *sc, const lac_scene_section *sec,
             const char *name, const char *what, const lac_mesh *m,
             const face_key *faces, size_t nf)
{
  const lac_group *g = lac_mesh_group (m, name);
  for (size_t e = 0; g && e < g->n; e++)
    {
      face_key k;
      const face_key *hit;
      if (g->face[e] < 0)
        continue;
      make_key (m, g->cell[e], g->face[e], &k);
      hit = bsearch (&k, faces, nf, sizeof *faces, key_order);
      while (hit && hit > faces && !key_order (hit - 1, &k))
        hit--;
      if (hit && hit + 1 < faces + nf && !key_order (hit + 1, &k))
        return lac_scene_error (sc, sec, "group", LAC_EINVAL, "facet %zu "
                                "of the group lies between cells %zu and %zu:"
                                " it is inside the body; a %s acts on the "
                                "boundary (as a contact surface does)", e + 1,
                                m->cell_tag[hit->cell],
                                m->cell_tag[hit[1].cell], what);
    }
  return LAC_SUCCESS;
}

/* Surface loads and rollers (their outward normals) on the boundary. */
static int
loads_on_boundary (const lac_scene *sc, const lac_mesh *m)
{
  face_key *faces = NULL;
  size_t nf = 0;
  int status = LAC_SUCCESS;
  for (size_t k = 0; k < sc->nload + sc->ndirichlet && !status; k++)
    {
      const lac_scene_load *l = k < sc->nload ? &sc->load[k] : NULL;
      const lac_scene_dirichlet *d = l ? NULL : &sc->dirichlet[k - sc->nload];
      if (l ? !surface_load (l) : d->kind != LAC_BC_NORMAL)
        continue;
      if (!faces && !(faces = all_faces (m, &nf)))
        return LAC_ENOMEM;
      status = l ? on_boundary (sc, &l->sec, l->group, "surface load", m,
                                faces, nf)
                 : on_boundary (sc, &d->sec, d->group, "condition along the "
                                "outward normal", m, faces, nf);
    }
  lac_free (faces);
  return status;
}

int
lac_run_conflicts (const lac_scene *sc, lac_model model, const lac_mesh *m)
{
  int status = dirichlet_values (sc, model, m);
  return status ? status : loads_on_boundary (sc, m);
}
