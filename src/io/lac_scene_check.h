/* lac_scene_check.h -- step 4 of reading a scene: defaults that depend on
 * other keys, required keys, conflicts, model-dependent keys, the mesh
 * file (see lac_scene_check.c)
 */
#ifndef LAC_SCENE_CHECK_H
#define LAC_SCENE_CHECK_H

#include "io/lac_scene_types.h"

/* Check and complete sc after lac_scene_parse; the first error stops
 * with a one-line message naming the scene line. */
int lac_scene_finish (lac_scene *sc);

#endif /* LAC_SCENE_CHECK_H */
