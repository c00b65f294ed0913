/* lac_run_scene.h -- what a scene names, looked up in the mesh   [LAC §2]
 *
 * The stages of a run (run/lac_run.h) find the groups a scene names, the
 * exact solution it asks for, and word their errors so that they point at
 * the scene line (lac_scene_error).  These lookups are shared by the
 * stages and live below them.
 */
#ifndef LAC_RUN_SCENE_H
#define LAC_RUN_SCENE_H

#include <stddef.h>
#include "fem/lac_exact.h"
#include "fem/lac_mesh.h"
#include "io/lac_scene.h"

/* The [exact] solution of the scene for the model (kind LAC_EXACT_NONE
 * without [exact]). */
void lac_run_exact (const lac_scene *sc, lac_model model, lac_exact *e);
/* The group `name` of key `group` of section s, of dimension dim_want (< 0:
 * any; `what` needs it), or NULL with a message naming the scene line and
 * the groups of the mesh. */
const lac_group *lac_run_group (const lac_scene *sc, const lac_mesh *m,
                                const lac_scene_section *s, const char *name,
                                int dim_want, const char *what);
/* The non-empty facet group `name` of key `key` of the [contact] section
 * s, or NULL with a message naming the scene line. */
const lac_group *lac_run_contact_group (const lac_scene *sc,
                                        const lac_mesh *m,
                                        const lac_scene_section *s,
                                        const char *key, const char *name);
/* The current error message, fitted to buf (base/lac_text.h). */
void lac_run_inner_message (char *buf, size_t size);
/* Distinct cell types of the mesh, "tri6" or "tri6+quad8". */
void lac_run_cell_types (const lac_mesh *m, char *buf, size_t size);

#endif /* LAC_RUN_SCENE_H */
