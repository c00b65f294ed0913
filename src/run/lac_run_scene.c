/* lac_run_scene.c -- what a scene names, looked up in the mesh
 *                    (see lac_run_scene.h)                         [LAC §2]
 */
#include "run/lac_run_scene.h"

#include <stdio.h>
#include <string.h>
#include "base/lac_status.h"
#include "base/lac_text.h"

void
lac_run_exact (const lac_scene *sc, lac_model model, lac_exact *e)
{
  const lac_scene_exact *x = &sc->exact;
  lac_exact_params p = { x->a, x->b, x->p, x->E, x->nu, x->tau };
  lac_exact_init (e, x->solution, model, &p);
}

void
lac_run_inner_message (char *buf, size_t size)
{
  lac_text_fit (buf, size, lac_error_message ());
}

/* "body, left, right" */
static void
group_list (const lac_mesh *m, char *buf, size_t size)
{
  size_t len = 0;
  buf[0] = '\0';
  for (size_t g = 0; g < m->ngroups && len + 8 < size; g++)
    {
      int w = snprintf (buf + len, size - len, "%s%s", g ? ", " : "",
                        m->group[g].name);
      if (w < 0 || (size_t) w >= size - len)
        {
          snprintf (buf + len, size - len, ", ...");
          break;
        }
      len += (size_t) w;
    }
  if (m->ngroups == 0)
    snprintf (buf, size, "none");
}

const lac_group *
lac_run_group (const lac_scene *sc, const lac_mesh *m,
               const lac_scene_section *s, const char *name, int dim_want,
               const char *what)
{
  const lac_group *g = lac_mesh_group (m, name);
  char list[400];
  if (!g)
    {
      group_list (m, list, sizeof list);
      lac_scene_error (sc, s, "group", LAC_EINVAL, "no physical group "
                       "of that name in mesh '%s' (groups: %s)",
                       sc->mesh.file, list);
      return NULL;
    }
  if (dim_want >= 0 && g->dim != dim_want)
    {
      lac_scene_error (sc, s, "group", LAC_EINVAL, "group of dimension"
                       " %d; %s needs a group of dimension %d", g->dim, what,
                       dim_want);
      return NULL;
    }
  return g;
}

const lac_group *
lac_run_contact_group (const lac_scene *sc, const lac_mesh *m,
                       const lac_scene_section *s, const char *key,
                       const char *name)
{
  const lac_group *g = lac_mesh_group (m, name);
  if (!g)
    {
      lac_scene_error (sc, s, key, LAC_EINVAL, "no physical "
                       "group of that name in mesh '%s'", sc->mesh.file);
      return NULL;
    }
  if (g->dim != m->dim - 1 || g->n == 0)
    {
      lac_scene_error (sc, s, key, LAC_EINVAL, "%s",
                       g->n == 0 ? "the group has no facets"
                       : "not a group of boundary facets (dimension "
                         "must be the mesh's minus one)");
      return NULL;
    }
  return g;
}

void
lac_run_cell_types (const lac_mesh *m, char *buf, size_t size)
{
  int seen[LAC_NELEM_TYPES] = { 0 };
  size_t len = 0;
  buf[0] = '\0';
  for (size_t c = 0; c < m->ncells; c++)
    seen[m->type[c]] = 1;
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    if (seen[t] && len < size)
      len += (size_t) snprintf (buf + len, size - len, "%s%s", len ? "+" : "",
                                lac_refelem_get ((lac_elem_type) t)->name);
}
