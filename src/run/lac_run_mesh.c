/* lac_run_mesh.c -- stage 1 of a run: the mesh (see lac_run_mesh.h)
 *                                                                  [LAC §2]
 */
#include "run/lac_run_mesh.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_status.h"
#include "io/lac_mesh_gmsh.h"
#include "run/lac_run_scene.h"

/* ---- checks against the scene ----------------------------------------- */

static int
check_groups (const lac_scene *sc, const lac_mesh *m)
{
  int d = m->dim;
  for (size_t k = 0; k < sc->nmaterial; k++)
    if (sc->material[k].group
        && !lac_run_group (sc, m, &sc->material[k].sec, sc->material[k].group, d,
                        "a material"))
      return LAC_EINVAL;
  for (size_t k = 0; k < sc->ndirichlet; k++)
    if (!lac_run_group (sc, m, &sc->dirichlet[k].sec, sc->dirichlet[k].group, -1,
                     NULL))
      return LAC_EINVAL;
  for (size_t k = 0; k < sc->nload; k++)
    {
      const lac_scene_load *l = &sc->load[k];
      int vol = l->kind == LAC_LOAD_FORCE || l->kind == LAC_LOAD_EXACT_FORCE;
      int point = l->kind == LAC_LOAD_POINT;
      int want = vol ? d : point ? 0 : d - 1;
      const lac_group *g;
      if (l->group && !(g = lac_run_group (sc, m, &l->sec, l->group, want,
                                           vol ? "a volume force" : point
                                           ? "point_force (a point group)"
                                           : l->kind == LAC_LOAD_TOTAL
                                           ? "total_force (a boundary "
                                             "group; force: per unit "
                                             "volume)"
                                           : "a surface load")))
        return LAC_EINVAL;
      if (l->group && point && g->nnodes != 1)
        return lac_scene_error (sc, &l->sec, "group", LAC_EINVAL, "a point "
                                "group of %zu nodes; point_force acts on "
                                "one point", g->nnodes);
    }
  return LAC_SUCCESS;
}

static int
check_mesh (const lac_scene *sc, lac_model model, const lac_mesh *m)
{
  double xmax = 0;
  if (m->dim != lac_model_dim (model))
    return lac_scene_error (sc, &sc->mesh.sec, "file", LAC_EINVAL, "a %dD "
                            "mesh; model = %s needs a %dD mesh", m->dim,
                            lac_model_name (model), lac_model_dim (model));
  if (sc->scene.element != LAC_ELEM_NONE)
    for (size_t c = 0; c < m->ncells; c++)
      if ((int) m->type[c] != sc->scene.element)
        return lac_scene_error (sc, &sc->scene.sec, "element", LAC_EINVAL,
                                "mesh '%s' has %s cells (cell %zu)",
                                sc->mesh.file,
                                lac_refelem_get (m->type[c])->name,
                                m->cell_tag[c]);
  for (size_t a = 0; a < m->nnodes * (size_t) m->dim; a++)
    xmax = fmax (xmax, fabs (m->x[a]));
  if (model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      if (m->x[a * 2] < -1e-12 * xmax)
        return lac_scene_error (sc, &sc->scene.sec, "model", LAC_EINVAL,
                                "node %zu of mesh '%s' has r = x = %g < 0",
                                m->node_tag[a], sc->mesh.file, m->x[a * 2]);
  return check_groups (sc, m);
}

int
lac_run_mesh (const lac_scene *sc, lac_model model, double max_memory,
              lac_mesh **mesh, char *progress, size_t size)
{
  lac_mesh_opts o;
  char msg[700];
  size_t n;
  int status;
  memset (&o, 0, sizeof o);
  o.size = sc->mesh.size;
  o.order = sc->mesh.order;
  o.serendipity = sc->scene.element == LAC_QUAD8
                  || sc->scene.element == LAC_HEX20;
  o.recombine = sc->mesh.recombine > 0;
  o.level = sc->mesh.level;
  o.numbers = sc->mesh.numbers;
  o.flip_inverted = sc->mesh.inverted == 0;
  o.max_memory = max_memory;
  status = lac_mesh_read (sc->mesh.path, &o, mesh);
  if (status)
    {
      char quoted[600];
      lac_run_inner_message (msg, sizeof msg);
      n = (size_t) snprintf (quoted, sizeof quoted, "'%s': ", sc->mesh.path);
      return lac_scene_error (sc, &sc->mesh.sec, "file", status, "%s",
                              strncmp (msg, quoted, n) ? msg : msg + n);
    }
  if ((status = check_mesh (sc, model, *mesh)))
    return status;
  n = (size_t) snprintf (progress, size, "%zu nodes, %zu cells (%s), %zu "
                        "groups", (*mesh)->nnodes, (*mesh)->ncells,
                        (*mesh)->ncells ? lac_refelem_get ((*mesh)->type[0])
                        ->name : "-", (*mesh)->ngroups);
  if ((*mesh)->ndropped && n < size)
    snprintf (progress + n, size - n, "; warning: %zu node%s of the file "
              "in no cell, left out", (*mesh)->ndropped,
              (*mesh)->ndropped > 1 ? "s" : "");
  return LAC_SUCCESS;
}

