/* lac_scene_internal.h -- internal: shared by the lac_scene*.c files
 *
 * Not part of the public interface: only lac_scene.c (tables, sections,
 * the public functions), lac_scene_ini.c (steps 1-3: the INI text, --set
 * overrides, typed values) and lac_scene_check.c (step 4: defaults,
 * required keys, conflicts) include it.
 */
#ifndef LAC_SCENE_INTERNAL_H
#define LAC_SCENE_INTERNAL_H

#include <stddef.h>
#include "io/lac_scene.h"

/* ---- the section and key tables (lac_scene.c) ------------------------- */

typedef enum { K_STR, K_NUM, K_INT, K_BOOL, K_ENUM, K_VEC } key_type;

typedef struct key_spec
{
  const char *name;
  key_type type;
  size_t off;                  /* value field in the section struct       */
  size_t off_n;                /* K_VEC: its int count field              */
  const char *const *enums;    /* K_ENUM: names, ending with NULL, ...    */
  size_t stride;               /* ... `stride` bytes apart                */
  double lo, hi;               /* K_NUM, K_INT: allowed range             */
  int open;                    /* 1: lo excluded, 2: hi excluded          */
  const char *expect;          /* for messages: "a number > 0"            */
} key_spec;

typedef struct section_spec
{
  const char *name;
  int named;                   /* [name NAME] */
  const key_spec *keys;
  int nkeys;
} section_spec;

enum { SEC_SCENE, SEC_MESH, SEC_MATERIAL, SEC_DIRICHLET, SEC_LOAD,
       SEC_EXACT, SEC_OUTPUT, SEC_CONTACT, SEC_STEPS, NSEC };

extern const section_spec lac_scene_sections[NSEC];

/* [scene] element names -> type, dimension, order, recombine, serendipity */
#define LAC_SCENE_NELEMENTS 10
typedef struct lac_scene_element_spec
{
  lac_elem_type type;
  int dim, order, recombine, serendipity;
} lac_scene_element_spec;

extern const lac_scene_element_spec lac_scene_elements[LAC_SCENE_NELEMENTS];
extern const char *const lac_scene_element_names[];   /* same order */
extern const char *const lac_scene_model_names[];     /* lac_model order */

/* ---- sections and messages (lac_scene.c) ------------------------------ */

/* Store "PATH:LINE: message" ("--set: message" for overrides). */
int lac_scene_where_error (const char *path, int line, int status,
                           const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));

int lac_scene_section_kind (const char *type);        /* -1 if unknown */
/* "material steel" -> kind, name ("" if none); type and name point into
 * buf (a copy of sec). */
int lac_scene_split_section (const char *sec, char *buf, size_t size,
                             const char **name);
/* The existing section (kind, name), or NULL. */
lac_scene_section *lac_scene_section_find (lac_scene *sc, int kind,
                                           const char *name);
/* A new section (NULL: out of memory). */
lac_scene_section *lac_scene_section_new (lac_scene *sc, int kind,
                                          const char *name, int line);
int lac_scene_key_index (int kind, const char *key);  /* -1 if unknown */
/* "a, b, c" from n names `stride` bytes apart */
void lac_scene_join_names (char *buf, size_t size, const char *const *names,
                           size_t n, size_t stride);
/* "scene, mesh, material NAME, ..." */
void lac_scene_section_list (char *buf, size_t size);

/* ---- the steps -------------------------------------------------------- */

/* Steps 1-3 (lac_scene_ini.c): capture the INI text, apply the overrides,
 * build the typed sections of sc. */
int lac_scene_parse (lac_scene *sc, const char *text, const char *path,
                     size_t nset, const char *const *set);
/* Step 4 (lac_scene_check.c): defaults, required keys, conflicts,
 * model-dependent keys, the mesh file. */
int lac_scene_finish (lac_scene *sc);

#endif /* LAC_SCENE_INTERNAL_H */
