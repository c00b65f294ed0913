/* lac_scene_keys.h -- the sections and keys a scene file may hold
 *
 * A table describes every section and every key: its name, its type
 * (text, number, integer, boolean, enum, vector, list of numbers: an
 * owned array), the field of the
 * section's struct (lac_scene_types.h) that stores it, its allowed range
 * and the words of a message about a wrong value.  The reading steps
 * (lac_scene_ini.c: typed values; lac_scene_check.c: defaults, required
 * keys, conflicts) and the messages (lac_scene_query.c) all read these
 * tables; adding a key is one table line plus a field.
 *
 * Also here: the defaults of a new section, the lookup and creation of
 * the sections of a scene, and the lists of names that messages show.
 */
#ifndef LAC_SCENE_KEYS_H
#define LAC_SCENE_KEYS_H

#include <stddef.h>
#include "fem/lac_spaces.h"
#include "io/lac_scene_types.h"

typedef enum { K_STR, K_NUM, K_INT, K_BOOL, K_ENUM, K_VEC, K_LIST } key_type;

typedef struct key_spec
{
  const char *name;
  key_type type;
  size_t off;                  /* value field in the section struct       */
  size_t off_n;                /* K_VEC, K_LIST: its int count field      */
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

/* The defaults of a section of this kind (the rest stays as it is: zero
 * for a new section); sets s->kind. */
void lac_scene_section_defaults (int kind, lac_scene_section *s);

int lac_scene_section_kind (const char *type);        /* -1 if unknown */
/* "material steel" -> kind, name ("" if none); type and name point into
 * buf (a copy of sec). */
int lac_scene_split_section (const char *sec, char *buf, size_t size,
                             const char **name);
/* The existing section (kind, name), or NULL. */
lac_scene_section *lac_scene_section_find (lac_scene *sc, int kind,
                                           const char *name);
/* The k-th section of a kind (k ignored for an unnamed kind), NULL past
 * the last; and how many a kind has (1 for an unnamed kind). */
lac_scene_section *lac_scene_section_get (lac_scene *sc, int kind, size_t k);
size_t lac_scene_section_count (const lac_scene *sc, int kind);
/* A new section (NULL: out of memory); a named one goes last. */
lac_scene_section *lac_scene_section_new (lac_scene *sc, int kind,
                                          const char *name, int line);
int lac_scene_key_index (int kind, const char *key);  /* -1 if unknown */
/* "a, b, c" from n names `stride` bytes apart */
void lac_scene_join_names (char *buf, size_t size, const char *const *names,
                           size_t n, size_t stride);
/* "scene, mesh, material NAME, ..." */
void lac_scene_section_list (char *buf, size_t size);

#endif /* LAC_SCENE_KEYS_H */
