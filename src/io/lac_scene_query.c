/* lac_scene_query.c -- messages that point at a scene line, names
 *
 * What the later stages ask of a scene read (lac_scene_query.h): the line
 * of a key, the one-line messages "PATH:LINE: [section] key = 'value':
 * what is wrong" (the reading steps use them too), and the names of the
 * scene's enums for messages and summaries.
 */
#include "io/lac_scene_query.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "fem/lac_exact.h"
#include "io/lac_scene_keys.h"
#include "base/lac_status.h"

int
lac_scene_where_error (const char *path, int line, int status,
                       const char *fmt, ...)
{
  char where[512], msg[768];
  va_list ap;
  if (line > 0)
    snprintf (where, sizeof where, "%s:%d", path, line);
  else
    snprintf (where, sizeof where, "%s",
              line == LAC_SCENE_FROM_SET ? "--set" : path);
  va_start (ap, fmt);
  vsnprintf (msg, sizeof msg, fmt, ap);
  va_end (ap);
  return lac_error_set (status, where, "%s", msg);
}

int
lac_scene_key_line (const lac_scene_section *s, const char *key)
{
  int k = lac_scene_key_index (s->kind, key);
  return k < 0 ? 0 : s->key_line[k];
}

int
lac_scene_error (const lac_scene *sc, const lac_scene_section *s,
                 const char *key, int status, const char *fmt, ...)
{
  char label[300] = "", keypart[400] = "", msg[600];
  int k = (s && key) ? lac_scene_key_index (s->kind, key) : -1;
  int line = (k >= 0) ? s->key_line[k] : 0;
  va_list ap;
  if (s && s->name)
    snprintf (label, sizeof label, "[%s %s]", lac_scene_sections[s->kind].name,
              s->name);
  else if (s)
    snprintf (label, sizeof label, "[%s]", lac_scene_sections[s->kind].name);
  if (k >= 0 && line != 0)
    snprintf (keypart, sizeof keypart, " %s = '%s'", key,
              s->key_raw[k] ? s->key_raw[k] : "");
  else if (key)
    snprintf (keypart, sizeof keypart, " %s", key);
  if (line == 0 && s)
    line = s->line;
  va_start (ap, fmt);
  vsnprintf (msg, sizeof msg, fmt, ap);
  va_end (ap);
  return lac_scene_where_error (sc->path, line, status, "%s%s: %s", label,
                                keypart, msg);
}

const char *
lac_scene_element_name (int element)
{
  for (int k = 0; k < LAC_SCENE_NELEMENTS; k++)
    if ((int) lac_scene_elements[k].type == element)
      return lac_scene_element_names[k];
  return "any";
}

const char *
lac_scene_exact_name (int solution)
{
  return lac_exact_name (solution);
}

int
lac_scene_component (lac_model model, const char *key)
{
  static const char *const keys[3][3] = {
    { "ux", "uy", NULL }, { "ur", "uz", NULL }, { "ux", "uy", "uz" } };
  for (int c = 0; c < 3; c++)
    if (keys[model][c] && strcmp (keys[model][c], key) == 0)
      return c;
  return -1;
}
