/* lac_scene_ini.h -- steps 1-3 of reading a scene: the INI text, the
 * --set overrides, the typed values (see lac_scene_ini.c)
 */
#ifndef LAC_SCENE_INI_H
#define LAC_SCENE_INI_H

#include <stddef.h>
#include "io/lac_scene_types.h"

/* Capture the INI text (inih), apply the nset overrides "KEY=VALUE",
 * build the typed sections of sc (their defaults set for the unnamed
 * ones).  path names the file in messages.  The first error stops with a
 * one-line message naming the line. */
int lac_scene_parse (lac_scene *sc, const char *text, const char *path,
                     size_t nset, const char *const *set);

#endif /* LAC_SCENE_INI_H */
