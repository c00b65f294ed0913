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

/* Room for a message before lac_error_place escapes and fits it: a
 * value quoted from --set, a path, the words around them. */
#define ROOM 8192

int
lac_scene_where_error (const char *path, int line, int status,
                       const char *fmt, ...)
{
  char where[4200], msg[ROOM];
  va_list ap;
  if (line > 0)
    snprintf (where, sizeof where, "%.4096s:%d", path, line);
  else
    snprintf (where, sizeof where, "%.4096s",
              line == LAC_SCENE_FROM_SET ? "--set" : path);
  va_start (ap, fmt);
  vsnprintf (msg, sizeof msg, fmt, ap);
  va_end (ap);
  return lac_error_place (status, where, "%s", msg);
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
  char msg[ROOM];
  int k = (s && key) ? lac_scene_key_index (s->kind, key) : -1;
  int line = (k >= 0) ? s->key_line[k] : 0;
  size_t n = 0;
  va_list ap;
  if (s && s->name)
    n = (size_t) snprintf (msg, sizeof msg, "[%s %.512s]",
                           lac_scene_sections[s->kind].name, s->name);
  else if (s)
    n = (size_t) snprintf (msg, sizeof msg, "[%s]",
                           lac_scene_sections[s->kind].name);
  if (k >= 0 && line != 0)
    n += (size_t) snprintf (msg + n, sizeof msg - n, " %s = '%.2048s'", key,
                            s->key_raw[k] ? s->key_raw[k] : "");
  else if (key)
    n += (size_t) snprintf (msg + n, sizeof msg - n, " %s", key);
  n += (size_t) snprintf (msg + n, sizeof msg - n, ": ");
  if (line == 0 && s)
    line = s->line;
  va_start (ap, fmt);
  vsnprintf (msg + n, sizeof msg - n, fmt, ap);
  va_end (ap);
  return lac_scene_where_error (sc->path, line, status, "%s", msg);
}

int
lac_scene_friction (const lac_scene *sc)
{
  for (size_t k = 0; k < sc->ncontact; k++)
    if (sc->contact[k].friction > 0)
      return 1;
  return 0;
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

double
lac_scene_factor (const double *curve, int ncurve, int ramp, double t)
{
  int n = ncurve / 2, k = 1;
  if (!curve || n < 1)
    return ramp ? t : 1.0;
  if (t <= curve[0])
    return curve[1];
  if (t >= curve[2 * (n - 1)])
    return curve[2 * (n - 1) + 1];
  while (curve[2 * k] < t)           /* t in [t_{k-1}, t_k] */
    k++;
  double t0 = curve[2 * k - 2], f0 = curve[2 * k - 1];
  double t1 = curve[2 * k], f1 = curve[2 * k + 1];
  return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
}
