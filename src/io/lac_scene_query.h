/* lac_scene_query.h -- what the later stages ask of a scene read
 *
 * A scene keeps the line of every key (lac_scene_types.h), so that a
 * message about a value -- from the checks of lac_scene_check.c or from a
 * stage of the run that finds the value unusable (a group the mesh does
 * not have) -- names the file, the line and the key:
 *
 *   PATH:LINE: [section name] key = 'value': what is wrong
 *
 * and the names of the scene's enums, for messages and summaries.
 */
#ifndef LAC_SCENE_QUERY_H
#define LAC_SCENE_QUERY_H

#include "fem/lac_material.h"
#include "io/lac_scene_types.h"

/* Line of `key` in section s: > 0 file line, LAC_SCENE_FROM_SET, 0 absent
 * (then the section header line is a better place to point at). */
int lac_scene_key_line (const lac_scene_section *s, const char *key);

/* Store "PATH:LINE: [section name] key = 'raw': <fmt...>" as the error
 * message (key may be NULL for the section itself) and return status. */
int lac_scene_error (const lac_scene *sc, const lac_scene_section *s,
                     const char *key, int status, const char *fmt, ...)
  __attribute__ ((format (printf, 5, 6)));

/* Store "PATH:LINE: message" ("--set: message" for LAC_SCENE_FROM_SET,
 * "PATH: message" for line 0) and return status: the message of an
 * entry that belongs to no section yet. */
int lac_scene_where_error (const char *path, int line, int status,
                           const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));

/* Names for messages and summaries. */
const char *lac_scene_element_name (int element);    /* "tri6", "any" */
const char *lac_scene_exact_name (int solution);     /* "thick_sphere" */

/* 1 if a [contact] section asks for friction (friction > 0): then every
 * pair gets the tangential multipliers of friction, mu = 0 where not
 * given (frictionless pairs of a frictional scene). */
int lac_scene_friction (const lac_scene *sc);

/* Model component index of a displacement key for the model ("ux", "ur",
 * "uz", ...), or -1 if the key does not apply to the model. */
int lac_scene_component (lac_model model, const char *key);

/* The factor f(t) of a [load] or [dirichlet] section at the load factor
 * t of [steps]: its curve t0 f0 t1 f1 ... (ncurve numbers, the times
 * increasing), linear between two pairs and constant beyond the ends;
 * without a curve (NULL), t if ramp, else 1. */
double lac_scene_factor (const double *curve, int ncurve, int ramp,
                         double t);

#endif /* LAC_SCENE_QUERY_H */
