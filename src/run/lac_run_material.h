/* lac_run_material.h -- stage 3 of a run: the material of every cell
 *                                                                [LAC (2)]
 * In:  the scene's [material] sections, the mesh.
 * Out: Young's modulus, Poisson's ratio and the law of every cell, as the
 *      linear assembly (fem/lac_assembly.h) and the hyperelastic one
 *      (fem/lac_hyper.h) read them.  A cell in two materials, or in none
 *      without a default material, is an error naming it.
 */
#ifndef LAC_RUN_MATERIAL_H
#define LAC_RUN_MATERIAL_H

#include <stddef.h>
#include "fem/lac_assembly.h"
#include "fem/lac_hyper.h"
#include "io/lac_scene.h"

typedef struct lac_run_material
{
  double *E, *nu;          /* owned, ncells                              */
  char *law;               /* owned, ncells: lac_law of each cell        */
  lac_elastic elastic;     /* points into E, nu (linear assembly)        */
  lac_hyper hyper;         /* points into E, nu, law (large deformation) */
  int nhyper;              /* materials with a neo-Hookean law           */
} lac_run_material;

int lac_run_material_build (const lac_scene *sc, lac_model model,
                            const lac_mesh *m, lac_run_material *mat,
                            char *progress, size_t size);
void lac_run_material_clear (lac_run_material *mat);

#endif /* LAC_RUN_MATERIAL_H */
