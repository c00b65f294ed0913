/* scene_keys.c -- print the sections and keys a scene file may hold
 *
 *   scene_keys      one line "SECTION KEY" per key of the tables of
 *                   src/io/lac_scene_keys.c, in their order
 *
 * tests/cases-doc.sh compares these lines with the keys that
 * chapters/01-problem/scene-format.md and `lac --help` describe, so that
 * neither can name a key the program refuses or leave out one it reads.
 */
#include <stdio.h>
#include "io/lac_scene_keys.h"

int
main (void)
{
  for (int s = 0; s < NSEC; s++)
    for (int k = 0; k < lac_scene_sections[s].nkeys; k++)
      printf ("%s %s\n", lac_scene_sections[s].name,
              lac_scene_sections[s].keys[k].name);
  return 0;
}
