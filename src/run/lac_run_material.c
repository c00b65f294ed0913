/* lac_run_material.c -- stage 3 of a run: the material of every cell
 *                       (see lac_run_material.h)                 [LAC (2)]
 */
#include "run/lac_run_material.h"

#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

void
lac_run_material_clear (lac_run_material *mat)
{
  lac_free (mat->E);
  lac_free (mat->nu);
  lac_free (mat->law);
  memset (mat, 0, sizeof *mat);
}

/* E, nu of the cells of the materials with a group; owner[c] = the
 * material of cell c (-1: none yet), *dflt = the material without group
 * (NULL if none). */
static int
material_groups (const lac_scene *sc, const lac_mesh *m,
                 lac_run_material *mat, int *owner,
                 const lac_scene_material **dflt)
{
  *dflt = NULL;
  for (size_t c = 0; c < m->ncells; c++)
    owner[c] = -1;
  for (size_t k = 0; k < sc->nmaterial; k++)
    {
      const lac_scene_material *mt = &sc->material[k];
      const lac_group *g;
      if (!mt->group)
        {
          *dflt = mt;
          continue;
        }
      g = lac_mesh_group (m, mt->group);
      for (size_t j = 0; j < g->n; j++)
        {
          size_t c = g->cell[j];
          if (owner[c] >= 0)
            return lac_scene_error (sc, &mt->sec, "group", LAC_EINVAL,
                                    "cell %zu is also in [material %s]",
                                    m->cell_tag[c],
                                    sc->material[owner[c]].sec.name);
          owner[c] = (int) k;
          mat->E[c] = mt->E;
          mat->nu[c] = mt->nu;
          mat->law[c] = (char) mt->law;
        }
    }
  return LAC_SUCCESS;
}

int
lac_run_material_build (const lac_scene *sc, lac_model model,
                        const lac_mesh *m, lac_run_material *mat,
                        char *progress, size_t size)
{
  const lac_scene_material *dflt = NULL;
  int *owner, status;
  mat->E = lac_malloc (m->ncells * sizeof *mat->E);
  mat->nu = lac_malloc (m->ncells * sizeof *mat->nu);
  mat->law = lac_calloc (m->ncells, 1);
  owner = lac_malloc (m->ncells * sizeof *owner);
  if (!mat->E || !mat->nu || !mat->law || !owner)
    {
      lac_free (owner);
      LAC_ERROR (LAC_ENOMEM, "material arrays for %zu cells", m->ncells);
    }
  if ((status = material_groups (sc, m, mat, owner, &dflt)))
    {
      lac_free (owner);
      return status;
    }
  for (size_t c = 0; c < m->ncells; c++)
    if (owner[c] < 0 && dflt)
      {
        owner[c] = (int) (dflt - sc->material);
        mat->E[c] = dflt->E;
        mat->nu[c] = dflt->nu;
        mat->law[c] = (char) dflt->law;
      }
    else if (owner[c] < 0)
      {
        const char *body = m->body[c] >= 0 ? m->group[m->body[c]].name : NULL;
        lac_free (owner);
        if (body)
          return lac_error_set (LAC_EINVAL, sc->path, "cell %zu of mesh '%s'"
                                " (group '%s') has no material: add a "
                                "[material NAME] with group = %s",
                                m->cell_tag[c], sc->mesh.file, body, body);
        return lac_error_set (LAC_EINVAL, sc->path, "cell %zu of mesh '%s' "
                              "is in no volume physical group and has no "
                              "material: add a [material NAME] without group",
                              m->cell_tag[c], sc->mesh.file);
      }
  lac_free (owner);
  mat->elastic.model = model;
  mat->elastic.E = mat->E;
  mat->elastic.nu = mat->nu;
  mat->hyper.model = model;
  mat->hyper.E = mat->E;
  mat->hyper.nu = mat->nu;
  mat->hyper.law = mat->law;
  int nh = 0;
  for (size_t k = 0; k < sc->nmaterial; k++)
    nh += sc->material[k].law != 0;
  mat->nhyper = nh;
  snprintf (progress, size, "%zu material%s, %s",
            sc->nmaterial, sc->nmaterial > 1 ? "s" : "",
            nh == (int) sc->nmaterial ? "neo-Hookean"
            : nh ? "neo-Hookean and linear elastic"
            : sc->scene.large_deformation ? "linear elastic (Saint "
              "Venant-Kirchhoff)" : "linear elastic");
  return LAC_SUCCESS;
}

