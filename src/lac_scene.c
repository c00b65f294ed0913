/* lac_scene.c -- reading and checking scene files (see lac_scene.h)
 *
 * Four steps:
 *   1. capture: inih splits the text into (section, key, value) entries; our
 *      reader feeds it one line at a time, so it knows every line number,
 *      and it records the [section] headers itself (inih does not report
 *      them);
 *   2. overrides: --set KEY=VALUE replaces or adds entries;
 *   3. build: headers and entries, in file order, are checked against the
 *      section and key tables below and stored in typed structs;
 *   4. finish: defaults, required keys, conflicts, model-dependent keys.
 * The first error stops the run with a one-line message naming the line.
 *
 * References: inih, https://github.com/benhoyt/inih (BSD-3-Clause).
 */
#include "lac_scene.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ini.h>
#include "lac_linalg.h"
#include "lac_mem.h"
#include "lac_status.h"

/* ---- tables ----------------------------------------------------------- */

typedef enum { K_STR, K_NUM, K_INT, K_BOOL, K_ENUM, K_VEC } key_type;

typedef struct key_spec
{
  const char *name;
  key_type type;
  size_t off;                  /* value field in the section struct       */
  size_t off_n;                /* K_VEC: its int count field              */
  const char *const *enums;    /* K_ENUM: NULL-terminated names           */
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
       SEC_EXACT, SEC_OUTPUT, NSEC };

static const char *const model_names[] =
  { "plane_strain", "axisymmetric", "3d", NULL };      /* lac_model order */
static const char *const solver_names[] =
  { "dense", "umfpack", "cholmod", NULL };   /* lac_solver_kind order */
static const char *const element_names[] =
  { "tri3", "tri6", "quad4", "quad8", "quad9",
    "tet4", "tet10", "hex8", "hex20", "hex27", NULL };
static const char *const inverted_names[] = { "flip", "reject", NULL };
static const char *const symmetry_names[] = { "x", "y", "z", "r", NULL };
static const char *const exact_names[] =
  { "thick_sphere", "thick_cylinder", NULL };   /* lac_exact_kind order */

/* element name -> type, dimension, order, recombine, serendipity */
static const struct
{
  lac_elem_type type;
  int dim, order, recombine, serendipity;
} element_info[] = {
  { LAC_TRI3, 2, 1, 0, 0 }, { LAC_TRI6, 2, 2, 0, 0 },
  { LAC_QUAD4, 2, 1, 1, 0 }, { LAC_QUAD8, 2, 2, 1, 1 },
  { LAC_QUAD9, 2, 2, 1, 0 }, { LAC_TET4, 3, 1, 0, 0 },
  { LAC_TET10, 3, 2, 0, 0 }, { LAC_HEX8, 3, 1, 1, 0 },
  { LAC_HEX20, 3, 2, 1, 1 }, { LAC_HEX27, 3, 2, 1, 0 },
};

#define F(T, f) offsetof (T, f)
#define STR(T, f) { #f, K_STR, F (T, f), 0, NULL, 0, 0, 0, "text" }
#define NUM(T, f, lo, hi, open, ex) \
  { #f, K_NUM, F (T, f), 0, NULL, lo, hi, open, ex }
#define INT(T, f, lo, hi, ex) { #f, K_INT, F (T, f), 0, NULL, lo, hi, 0, ex }
#define BOOL(T, f) { #f, K_BOOL, F (T, f), 0, NULL, 0, 0, 0, "yes or no" }
#define ENUM(T, f, names) { #f, K_ENUM, F (T, f), 0, names, 0, 0, 0, NULL }
#define VEC(T, f, n) { #f, K_VEC, F (T, f), F (T, n), NULL, 0, 0, 0, \
                       "2 or 3 numbers" }

static const key_spec scene_keys[] = {
  STR (lac_scene_main, title),
  ENUM (lac_scene_main, model, model_names),
  ENUM (lac_scene_main, element, element_names),
  ENUM (lac_scene_main, solver, solver_names),
  STR (lac_scene_main, out),
};
static const key_spec mesh_keys[] = {
  STR (lac_scene_mesh, file),
  NUM (lac_scene_mesh, size, 0, HUGE_VAL, 1, "a number > 0"),
  INT (lac_scene_mesh, order, 1, 2, "1 or 2"),
  INT (lac_scene_mesh, level, 0, 12, "an integer in 0..12"),
  BOOL (lac_scene_mesh, recombine),
  ENUM (lac_scene_mesh, inverted, inverted_names),
};
static const key_spec material_keys[] = {
  STR (lac_scene_material, group),
  NUM (lac_scene_material, E, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_material, nu, -1, 0.5, 3, "a number in (-1, 0.5)"),
};
static const key_spec dirichlet_keys[] = {
  STR (lac_scene_dirichlet, group),
  NUM (lac_scene_dirichlet, ux, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_dirichlet, uy, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_dirichlet, uz, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_dirichlet, ur, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  BOOL (lac_scene_dirichlet, clamp),
  ENUM (lac_scene_dirichlet, symmetry, symmetry_names),
  BOOL (lac_scene_dirichlet, exact),
};
static const key_spec load_keys[] = {
  STR (lac_scene_load, group),
  NUM (lac_scene_load, pressure, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  VEC (lac_scene_load, traction, ntraction),
  VEC (lac_scene_load, force, nforce),
};
static const key_spec exact_keys[] = {
  ENUM (lac_scene_exact, solution, exact_names),
  NUM (lac_scene_exact, a, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_exact, b, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_exact, p, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_exact, E, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_exact, nu, -1, 0.5, 3, "a number in (-1, 0.5)"),
};
static const key_spec output_keys[] = {
  BOOL (lac_scene_output, vtu),
  BOOL (lac_scene_output, csv),
  BOOL (lac_scene_output, matrix),
};

#define NK(a) ((int) (sizeof a / sizeof a[0]))
static const section_spec sections[NSEC] = {
  { "scene", 0, scene_keys, NK (scene_keys) },
  { "mesh", 0, mesh_keys, NK (mesh_keys) },
  { "material", 1, material_keys, NK (material_keys) },
  { "dirichlet", 1, dirichlet_keys, NK (dirichlet_keys) },
  { "load", 1, load_keys, NK (load_keys) },
  { "exact", 0, exact_keys, NK (exact_keys) },
  { "output", 0, output_keys, NK (output_keys) },
};

/* --set aliases */
static const struct { const char *alias, *key; } aliases[] = {
  { "element", "scene.element" }, { "model", "scene.model" },
  { "solver", "scene.solver" }, { "out", "scene.out" },
  { "level", "mesh.level" }, { "order", "mesh.order" },
  { "size", "mesh.size" },
};

/* ---- step 1: capture -------------------------------------------------- */

typedef struct raw_entry
{
  char *sec;     /* owned: normalized "type name" of the current header */
  char *key;     /* owned */
  char *val;     /* owned */
  int line;      /* file line or LAC_SCENE_FROM_SET */
  int order;     /* position in the file (--set additions: last)   */
} raw_entry;

typedef struct raw
{
  const char *text;           /* borrowed: the file contents          */
  size_t pos;                 /* reader position in text              */
  int lineno;                 /* lines served so far                  */
  char *cursec;               /* owned: current header, "" before any */
  raw_entry *e;               /* owned, ne: entries                   */
  size_t ne, cape;
  raw_entry *h;               /* owned, nh: headers (key, val NULL)   */
  size_t nh, caph;
  int err_line;               /* first capture error (0: none)        */
  int err_status;
  char err[256];
} raw;

static char *
trim (char *s)
{
  char *end;
  while (isspace ((unsigned char) *s))
    s++;
  end = s + strlen (s);
  while (end > s && isspace ((unsigned char) end[-1]))
    *--end = '\0';
  return s;
}

/* "  material   steel " -> "material steel" (owned copy, NULL on ENOMEM) */
static char *
normalize_section (const char *s)
{
  char *out = lac_malloc (strlen (s) + 1), *o = out;
  int blank = 0;
  if (!out)
    return NULL;
  for (; *s; s++)
    {
      if (isspace ((unsigned char) *s))
        { blank = (o != out); continue; }
      if (blank)
        *o++ = ' ';
      blank = 0;
      *o++ = *s;
    }
  *o = '\0';
  return out;
}

static void
capture_error (raw *r, int line, int status, const char *msg)
{
  if (r->err_line == 0 || line < r->err_line)
    {
      r->err_line = line;
      r->err_status = status;
      snprintf (r->err, sizeof r->err, "%s", msg);
    }
}

static int
push (raw_entry **a, size_t *n, size_t *cap, raw_entry x)
{
  if (*n == *cap)
    {
      size_t c = *cap ? 2 * *cap : 16;
      raw_entry *p = lac_realloc (*a, c * sizeof *p);
      if (!p)
        return LAC_ENOMEM;
      *a = p;
      *cap = c;
    }
  (*a)[(*n)++] = x;
  return LAC_SUCCESS;
}

/* A [header] line: remember it (normalized) as the current section. */
static void
capture_header (raw *r, const char *line)
{
  const char *close = strchr (line, ']');
  char *inner, *sec;
  raw_entry h = { NULL, NULL, NULL, r->lineno, r->lineno };
  if (!close)
    return;                    /* inih reports the syntax error */
  inner = lac_malloc ((size_t) (close - line));
  if (!inner)
    { capture_error (r, r->lineno, LAC_ENOMEM, "out of memory"); return; }
  memcpy (inner, line + 1, (size_t) (close - line - 1));
  inner[close - line - 1] = '\0';
  sec = normalize_section (inner);
  lac_free (inner);
  h.sec = lac_strdup (sec ? sec : "");
  lac_free (r->cursec);
  r->cursec = sec;
  if (!sec || !h.sec || push (&r->h, &r->nh, &r->caph, h))
    {
      lac_free (h.sec);
      capture_error (r, r->lineno, LAC_ENOMEM, "out of memory");
    }
}

/* inih's fgets-like reader: one line of r->text per call, leading blanks
 * removed (so that inih never sees a continuation line) and `#` comments
 * after a blank cut. */
static char *
reader (char *str, int num, void *stream)
{
  raw *r = stream;
  const char *s = r->text + r->pos, *nl;
  size_t len, full;
  char *t, *hash;
  if (*s == '\0')
    return NULL;
  nl = strchr (s, '\n');
  full = nl ? (size_t) (nl - s) : strlen (s);
  r->pos += full + (nl ? 1 : 0);
  r->lineno++;
  if (r->lineno == 1 && full >= 3 && memcmp (s, "\xEF\xBB\xBF", 3) == 0)
    s += 3, full -= 3;                         /* UTF-8 byte order mark */
  while (full > 0 && isspace ((unsigned char) *s))
    s++, full--;
  len = full;
  if (len + 2 > (size_t) num)
    {
      char msg[96];
      snprintf (msg, sizeof msg, "line too long (at most %d characters)",
                num - 3);
      capture_error (r, r->lineno, LAC_EINVAL, msg);
      len = 0;
    }
  memcpy (str, s, len);
  str[len] = '\0';
  for (t = str; (hash = strchr (t, '#')) != NULL; t = hash + 1)
    if (hash == str || isspace ((unsigned char) hash[-1]))
      {
        *hash = '\0';
        break;
      }
  if (str[0] == '[')
    capture_header (r, str);
  strcat (str, "\n");
  return str;
}

static int
handler (void *user, const char *section, const char *name,
         const char *value)
{
  raw *r = user;
  raw_entry e = { NULL, NULL, NULL, r->lineno, r->lineno };
  (void) section;              /* ours is normalized and not truncated */
  e.sec = lac_strdup (r->cursec ? r->cursec : "");
  e.key = lac_strdup (name);
  e.val = lac_strdup (value ? value : "");
  if (!e.sec || !e.key || !e.val || push (&r->e, &r->ne, &r->cape, e))
    {
      lac_free (e.sec), lac_free (e.key), lac_free (e.val);
      capture_error (r, r->lineno, LAC_ENOMEM, "out of memory");
      return 0;
    }
  return 1;
}

static void
raw_free (raw *r)
{
  for (size_t k = 0; k < r->ne; k++)
    lac_free (r->e[k].sec), lac_free (r->e[k].key), lac_free (r->e[k].val);
  for (size_t k = 0; k < r->nh; k++)
    lac_free (r->h[k].sec);
  lac_free (r->e);
  lac_free (r->h);
  lac_free (r->cursec);
}

/* Store "PATH:LINE: message" ("--set: message" for overrides). */
static int
where_error (const char *path, int line, int status, const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));

static int
where_error (const char *path, int line, int status, const char *fmt, ...)
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

static int
capture (raw *r, const char *path)
{
  int ret = ini_parse_stream (reader, r, handler, r);
  if (ret > 0 && (r->err_line == 0 || ret < r->err_line))
    return where_error (path, ret, LAC_EINVAL, "syntax error: expected"
                        " '[section]' or 'key = value'");
  if (ret < 0 && r->err_line == 0)
    return where_error (path, 0, LAC_ENOMEM, "cannot parse (inih status %d)",
                        ret);
  if (r->err_line)
    return where_error (path, r->err_line, r->err_status, "%s", r->err);
  return LAC_SUCCESS;
}

/* ---- sections: lookup and creation ------------------------------------ */

static int
section_kind (const char *type)
{
  for (int k = 0; k < NSEC; k++)
    if (strcmp (sections[k].name, type) == 0)
      return k;
  return -1;
}

/* "material steel" -> kind, name ("" if none); type and name point into
 * buf (a copy of sec). */
static int
split_section (const char *sec, char *buf, size_t size, const char **name)
{
  char *sp;
  snprintf (buf, size, "%s", sec);
  sp = strchr (buf, ' ');
  *name = "";
  if (sp)
    {
      *sp = '\0';
      *name = sp + 1;
    }
  return section_kind (buf);
}

static void
set_defaults (int kind, lac_scene_section *s)
{
  switch (kind)
    {
    case SEC_SCENE:
      {
        lac_scene_main *m = (lac_scene_main *) s;
        m->model = LAC_PLANE_STRAIN;
        m->element = LAC_ELEM_NONE;
        m->solver = LAC_SOLVER_CHOLMOD;
        break;
      }
    case SEC_MESH:
      {
        lac_scene_mesh *m = (lac_scene_mesh *) s;
        m->size = 1;
        m->recombine = -1;
        break;
      }
    case SEC_MATERIAL:
      ((lac_scene_material *) s)->E = ((lac_scene_material *) s)->nu = NAN;
      break;
    case SEC_EXACT:
      ((lac_scene_exact *) s)->solution = LAC_EXACT_NONE;
      break;
    case SEC_OUTPUT:
      ((lac_scene_output *) s)->vtu = ((lac_scene_output *) s)->csv = 1;
      break;
    default:
      break;
    }
  s->kind = kind;
}

static lac_scene_section *
singleton (lac_scene *sc, int kind)
{
  switch (kind)
    {
    case SEC_SCENE: return &sc->scene.sec;
    case SEC_MESH: return &sc->mesh.sec;
    case SEC_EXACT: return &sc->exact.sec;
    case SEC_OUTPUT: return &sc->output.sec;
    default: return NULL;
    }
}

/* Named sections: count, k-th, and one more (zeroed) at the end. */
static size_t
named_count (const lac_scene *sc, int kind)
{
  return kind == SEC_MATERIAL ? sc->nmaterial
         : kind == SEC_DIRICHLET ? sc->ndirichlet : sc->nload;
}

static lac_scene_section *
named_at (lac_scene *sc, int kind, size_t k)
{
  return kind == SEC_MATERIAL ? &sc->material[k].sec
         : kind == SEC_DIRICHLET ? &sc->dirichlet[k].sec : &sc->load[k].sec;
}

#define GROW(arr, n)                                                    \
  do {                                                                  \
    void *p_ = lac_realloc ((arr), ((n) + 1) * sizeof *(arr));          \
    if (!p_)                                                            \
      return NULL;                                                      \
    (arr) = p_;                                                         \
    memset (&(arr)[(n)], 0, sizeof *(arr));                             \
    s = &(arr)[(n)++].sec;                                              \
  } while (0)

static lac_scene_section *
named_grow (lac_scene *sc, int kind)
{
  lac_scene_section *s;
  if (kind == SEC_MATERIAL)
    GROW (sc->material, sc->nmaterial);
  else if (kind == SEC_DIRICHLET)
    GROW (sc->dirichlet, sc->ndirichlet);
  else
    GROW (sc->load, sc->nload);
  return s;
}

/* The existing section (kind, name), or NULL. */
static lac_scene_section *
section_find (lac_scene *sc, int kind, const char *name)
{
  if (!sections[kind].named)
    {
      lac_scene_section *s = singleton (sc, kind);
      return s->line ? s : NULL;
    }
  for (size_t k = 0; k < named_count (sc, kind); k++)
    if (strcmp (named_at (sc, kind, k)->name, name) == 0)
      return named_at (sc, kind, k);
  return NULL;
}

static lac_scene_section *
section_new (lac_scene *sc, int kind, const char *name, int line)
{
  lac_scene_section *s;
  if (!sections[kind].named)
    {
      s = singleton (sc, kind);
      s->line = line;
      return s;
    }
  if (!(s = named_grow (sc, kind)))
    return NULL;
  set_defaults (kind, s);
  s->line = line;
  s->name = lac_strdup (name);   /* freed with the scene even if NULL */
  return s->name ? s : NULL;
}

static int
key_index (int kind, const char *key)
{
  for (int k = 0; k < sections[kind].nkeys; k++)
    if (strcmp (sections[kind].keys[k].name, key) == 0)
      return k;
  return -1;
}

/* "a, b, c" from a table of names */
static void
join_names (char *buf, size_t size, const char *const *names, size_t n,
            size_t stride)
{
  size_t len = 0;
  buf[0] = '\0';
  for (size_t k = 0; k < n; k++)
    {
      const char *s = *(const char *const *) ((const char *) names
                                              + k * stride);
      int w = snprintf (buf + len, size - len, "%s%s", k ? ", " : "", s);
      if (w < 0 || (size_t) w >= size - len)
        break;
      len += (size_t) w;
    }
}

static void
section_list (char *buf, size_t size)
{
  size_t len = 0;
  for (int k = 0; k < NSEC && len < size; k++)
    {
      int w = snprintf (buf + len, size - len, "%s%s%s", k ? ", " : "",
                        sections[k].name, sections[k].named ? " NAME" : "");
      if (w < 0)
        break;
      len += (size_t) w;
    }
}

/* ---- step 2: overrides ------------------------------------------------ */

static int
set_one (raw *r, const char *path, const char *arg)
{
  char buf[512], keybuf[512], sec[600];
  char *eq, *key, *val, *dot, *last;
  int kind, status;
  raw_entry e = { NULL, NULL, NULL, LAC_SCENE_FROM_SET, INT_MAX };
  int found = 0;
  snprintf (buf, sizeof buf, "%s", arg);
  if (!(eq = strchr (buf, '=')))
    return lac_error_set (LAC_EINVAL, "--set", "'%s': expected KEY=VALUE "
                          "(e.g. mesh.level=2)", arg);
  *eq = '\0';
  key = trim (buf);
  val = trim (eq + 1);
  for (size_t k = 0; k < sizeof aliases / sizeof aliases[0]; k++)
    if (strcmp (key, aliases[k].alias) == 0)
      key = (char *) aliases[k].key;
  snprintf (keybuf, sizeof keybuf, "%s", key);
  if (!(dot = strchr (keybuf, '.')))
    return lac_error_set (LAC_EINVAL, "--set", "'%s': expected SECTION.KEY"
                          "=VALUE, TYPE.NAME.KEY=VALUE or an alias (element,"
                          " model, solver, out, level, order, size)", arg);
  *dot = '\0';
  if ((kind = section_kind (keybuf)) < 0)
    {
      char list[256];
      section_list (list, sizeof list);
      return lac_error_set (LAC_EINVAL, "--set", "'%s': unknown section '%s'"
                            " (sections: %s)", arg, keybuf, list);
    }
  last = strrchr (dot + 1, '.');
  if (sections[kind].named ? (!last || last == dot + 1) : last != NULL)
    return lac_error_set (LAC_EINVAL, "--set", "'%s': expected %s", arg,
                          sections[kind].named ? "TYPE.NAME.KEY=VALUE, as in"
                          " material.steel.E=3000" : "SECTION.KEY=VALUE");
  if (sections[kind].named)
    {
      *last = '\0';
      snprintf (sec, sizeof sec, "%s %s", keybuf, dot + 1);
      key = last + 1;
    }
  else
    {
      snprintf (sec, sizeof sec, "%s", keybuf);
      key = dot + 1;
    }

  /* The section: named ones must exist, unnamed ones are created. */
  {
    size_t k;
    for (k = 0; k < r->nh && strcmp (r->h[k].sec, sec) != 0; k++)
      ;
    if (k == r->nh && sections[kind].named)
      return lac_error_set (LAC_EINVAL, "--set", "'%s': no section [%s] in "
                            "%s", arg, sec, path);
    if (k == r->nh)
      {
        raw_entry h = { lac_strdup (sec), NULL, NULL, LAC_SCENE_FROM_SET,
                        INT_MAX };
        if (!h.sec || push (&r->h, &r->nh, &r->caph, h))
          {
            lac_free (h.sec);
            return lac_error_set (LAC_ENOMEM, "--set", "out of memory");
          }
      }
  }

  /* Replace the entry, or add one. */
  for (size_t k = 0; k < r->ne; k++)
    if (strcmp (r->e[k].sec, sec) == 0 && strcmp (r->e[k].key, key) == 0)
      {
        char *v = lac_strdup (val);
        if (!v)
          return lac_error_set (LAC_ENOMEM, "--set", "out of memory");
        lac_free (r->e[k].val);
        r->e[k].val = v;
        r->e[k].line = LAC_SCENE_FROM_SET;
        found = 1;
      }
  if (found)
    return LAC_SUCCESS;
  e.sec = lac_strdup (sec);
  e.key = lac_strdup (key);
  e.val = lac_strdup (val);
  status = (!e.sec || !e.key || !e.val) ? LAC_ENOMEM
           : push (&r->e, &r->ne, &r->cape, e);
  if (status)
    {
      lac_free (e.sec), lac_free (e.key), lac_free (e.val);
      return lac_error_set (LAC_ENOMEM, "--set", "out of memory");
    }
  return LAC_SUCCESS;
}

/* ---- step 3: build ---------------------------------------------------- */

static int
parse_number (const char *s, double *x)
{
  char *end;
  errno = 0;
  *x = strtod (s, &end);
  return end != s && *end == '\0' && errno != ERANGE && isfinite (*x);
}

static int
parse_bool (const char *s, int *b)
{
  static const char *const yes[] = { "yes", "true", "on", "1" };
  static const char *const no[] = { "no", "false", "off", "0" };
  for (size_t k = 0; k < 4; k++)
    {
      if (strcmp (s, yes[k]) == 0)
        return *b = 1, 1;
      if (strcmp (s, no[k]) == 0)
        return *b = 0, 1;
    }
  return 0;
}

static int
in_range (const key_spec *ks, double x)
{
  if ((ks->open & 1) ? x <= ks->lo : x < ks->lo)
    return 0;
  if ((ks->open & 2) ? x >= ks->hi : x > ks->hi)
    return 0;
  return 1;
}

/* Convert the value of key k of section s and store it.  */
static int
store_value (lac_scene *sc, lac_scene_section *s, int k, const char *val)
{
  const key_spec *ks = &sections[s->kind].keys[k];
  char *base = (char *) s;
  double x;
  switch (ks->type)
    {
    case K_STR:
      {
        char **f = (char **) (base + ks->off);
        if (val[0] == '\0')
          return lac_scene_error (sc, s, ks->name, LAC_EINVAL,
                                  "expected a value");
        lac_free (*f);
        if (!(*f = lac_strdup (val)))
          LAC_ERROR (LAC_ENOMEM, "out of memory");
        return LAC_SUCCESS;
      }
    case K_NUM:
    case K_INT:
      if (!parse_number (val, &x) || !in_range (ks, x)
          || (ks->type == K_INT && x != floor (x)))
        return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s",
                                ks->expect);
      if (ks->type == K_INT)
        *(int *) (base + ks->off) = (int) x;
      else
        *(double *) (base + ks->off) = x;
      return LAC_SUCCESS;
    case K_BOOL:
      if (!parse_bool (val, (int *) (base + ks->off)))
        return lac_scene_error (sc, s, ks->name, LAC_EINVAL,
                                "expected yes or no");
      return LAC_SUCCESS;
    case K_ENUM:
      for (int j = 0; ks->enums[j]; j++)
        if (strcmp (val, ks->enums[j]) == 0)
          {
            *(int *) (base + ks->off) = j;
            return LAC_SUCCESS;
          }
      {
        char list[256];
        size_t n = 0;
        while (ks->enums[n])
          n++;
        join_names (list, sizeof list, ks->enums, n, sizeof ks->enums[0]);
        return lac_scene_error (sc, s, ks->name, LAC_EINVAL,
                                "expected one of: %s", list);
      }
    case K_VEC:
      {
        double *v = (double *) (base + ks->off);
        int *n = (int *) (base + ks->off_n);
        char buf[256], *tok, *save = NULL;
        snprintf (buf, sizeof buf, "%s", val);
        *n = 0;
        for (tok = strtok_r (buf, " \t,", &save); tok;
             tok = strtok_r (NULL, " \t,", &save))
          if (*n == 3 || !parse_number (tok, &v[(*n)++]))
            return lac_scene_error (sc, s, ks->name, LAC_EINVAL,
                                    "expected %s", ks->expect);
        if (*n < 2)
          return lac_scene_error (sc, s, ks->name, LAC_EINVAL,
                                  "expected %s", ks->expect);
        return LAC_SUCCESS;
      }
    }
  LAC_ERROR (LAC_ESANITY, "key type %d", (int) ks->type);
}

static int
build_header (lac_scene *sc, const raw_entry *h)
{
  char buf[512], list[256];
  const char *name;
  int kind = split_section (h->sec, buf, sizeof buf, &name);
  lac_scene_section *s;
  if (kind < 0)
    {
      section_list (list, sizeof list);
      return where_error (sc->path, h->line, LAC_EINVAL, "[%s]: unknown "
                          "section (sections: %s)", h->sec, list);
    }
  if (sections[kind].named && !name[0])
    return where_error (sc->path, h->line, LAC_EINVAL, "[%s]: needs a name,"
                        " as in [%s NAME]", h->sec, buf);
  if (!sections[kind].named && name[0])
    return where_error (sc->path, h->line, LAC_EINVAL, "[%s]: [%s] takes no"
                        " name", h->sec, buf);
  if ((s = section_find (sc, kind, name)) != NULL)
    return where_error (sc->path, h->line, LAC_EINVAL, "[%s]: section given"
                        " twice (first at line %d)", h->sec, s->line);
  if (!section_new (sc, kind, name, h->line))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  return LAC_SUCCESS;
}

static int
build_entry (lac_scene *sc, const raw_entry *e)
{
  char buf[512], list[256];
  const char *name;
  int kind, k;
  lac_scene_section *s;
  if (e->sec[0] == '\0')
    return where_error (sc->path, e->line, LAC_EINVAL, "%s = '%s': key "
                        "outside any [section]", e->key, e->val);
  kind = split_section (e->sec, buf, sizeof buf, &name);
  if (kind < 0 || !(s = section_find (sc, kind, name)))
    LAC_ERROR (LAC_ESANITY, "entry of unknown section [%s]", e->sec);
  if ((k = key_index (kind, e->key)) < 0)
    {
      join_names (list, sizeof list, &sections[kind].keys[0].name,
                  (size_t) sections[kind].nkeys, sizeof (key_spec));
      return where_error (sc->path, e->line, LAC_EINVAL, "[%s] %s: unknown "
                          "key (keys of [%s]: %s)", e->sec, e->key, buf, list);
    }
  if (s->key_line[k] > 0 && e->line > 0)
    return where_error (sc->path, e->line, LAC_EINVAL, "[%s] %s: key given "
                        "twice (first at line %d)", e->sec, e->key,
                        s->key_line[k]);
  s->key_line[k] = e->line;
  lac_free (s->key_raw[k]);
  if (!(s->key_raw[k] = lac_strdup (e->val)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  return store_value (sc, s, k, e->val);
}

/* Headers and entries in file order (--set ones last). */
static int
build (lac_scene *sc, const raw *r)
{
  size_t ih = 0, ie = 0;
  int status = LAC_SUCCESS;
  while (status == LAC_SUCCESS && (ih < r->nh || ie < r->ne))
    {
      long long lh = ih < r->nh ? r->h[ih].order : (long long) INT_MAX + 1;
      long long le = ie < r->ne ? r->e[ie].order : (long long) INT_MAX + 1;
      if (lh <= le)
        status = build_header (sc, &r->h[ih++]);
      else
        status = build_entry (sc, &r->e[ie++]);
    }
  return status;
}

/* ---- step 4: finish --------------------------------------------------- */

static int
given (const lac_scene_section *s, const char *key)
{
  return lac_scene_key_line (s, key) != 0;
}

static int
require (const lac_scene *sc, const lac_scene_section *s, const char *key,
         const char *what)
{
  if (given (s, key))
    return LAC_SUCCESS;
  return lac_scene_error (sc, s, NULL, LAC_EINVAL, "missing key '%s' (%s)",
                          key, what);
}

static int
finish_scene (lac_scene *sc)
{
  lac_scene_main *m = &sc->scene;
  int dim = lac_model_dim ((lac_model) m->model);
  if (!m->title && !(m->title = lac_strdup (sc->basename)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  if (m->element != LAC_ELEM_NONE && element_info[m->element].dim != dim)
    return lac_scene_error (sc, &m->sec, "element", LAC_EINVAL,
                            "a %dD element; model = %s needs %s",
                            element_info[m->element].dim,
                            model_names[m->model], dim == 2
                            ? "tri3, tri6, quad4, quad8 or quad9"
                            : "tet4, tet10, hex8, hex20 or hex27");
  /* Store the element as an lac_elem_type from here on. */
  if (m->element != LAC_ELEM_NONE)
    m->element = element_info[m->element].type;
  return LAC_SUCCESS;
}

static int
finish_mesh (lac_scene *sc)
{
  lac_scene_mesh *m = &sc->mesh;
  FILE *f;
  size_t len;
  int el = -1, status;
  if (m->sec.line == 0)
    return where_error (sc->path, 0, LAC_EINVAL, "no [mesh] section (a "
                        "scene needs [mesh] file = NAME.geo or NAME.msh)");
  if ((status = require (sc, &m->sec, "file", ".geo or .msh file")))
    return status;
  for (size_t k = 0; k < sizeof element_info / sizeof element_info[0]; k++)
    if ((int) element_info[k].type == sc->scene.element)
      el = (int) k;
  if (el >= 0 && given (&m->sec, "order")
      && m->order != element_info[el].order)
    return lac_scene_error (sc, &m->sec, "order", LAC_EINVAL, "contradicts "
                            "[scene] element = %s (order %d)",
                            element_names[el], element_info[el].order);
  if (el >= 0 && given (&m->sec, "recombine")
      && m->recombine != element_info[el].recombine)
    return lac_scene_error (sc, &m->sec, "recombine", LAC_EINVAL,
                            "contradicts [scene] element = %s",
                            element_names[el]);
  if (el >= 0)
    {
      m->order = element_info[el].order;
      m->recombine = element_info[el].recombine;
    }

  /* The file, relative to the scene's directory. */
  len = strlen (sc->dir) + strlen (m->file) + 2;
  if (!(m->path = lac_malloc (len)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  if (m->file[0] == '/')
    snprintf (m->path, len, "%s", m->file);
  else
    snprintf (m->path, len, "%s/%s", sc->dir, m->file);
  if (!(f = fopen (m->path, "r")))
    return lac_scene_error (sc, &m->sec, "file", LAC_EIO, "cannot open %s "
                            "(%s)", m->path, strerror (errno));
  fclose (f);
  return LAC_SUCCESS;
}

static int
finish_materials (lac_scene *sc)
{
  int status;
  const lac_scene_material *nogroup = NULL;
  if (sc->nmaterial == 0)
    return where_error (sc->path, 0, LAC_EINVAL, "no [material NAME] "
                        "section (one per body: group, E, nu)");
  for (size_t k = 0; k < sc->nmaterial; k++)
    {
      const lac_scene_material *m = &sc->material[k];
      if ((status = require (sc, &m->sec, "E", "Young's modulus > 0"))
          || (status = require (sc, &m->sec, "nu", "Poisson's ratio in "
                                "(-1, 0.5)")))
        return status;
      if (!m->group && nogroup)
        return lac_scene_error (sc, &m->sec, NULL, LAC_EINVAL, "no group, "
                                "like [material %s]: give each a group",
                                nogroup->sec.name);
      if (!m->group)
        nogroup = m;
      for (size_t j = 0; j < k && m->group; j++)
        if (sc->material[j].group
            && strcmp (sc->material[j].group, m->group) == 0)
          return lac_scene_error (sc, &m->sec, "group", LAC_EINVAL,
                                  "group already used by [material %s]",
                                  sc->material[j].sec.name);
    }
  return LAC_SUCCESS;
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

static int
finish_dirichlet (lac_scene *sc, lac_scene_dirichlet *d)
{
  static const char *const comp[] = { "ux", "uy", "uz", "ur" };
  const double *val[] = { &d->ux, &d->uy, &d->uz, &d->ur };
  lac_model model = (lac_model) sc->scene.model;
  int ncomp = 0, status, c;
  if ((status = require (sc, &d->sec, "group", "physical group")))
    return status;
  for (int k = 0; k < 4; k++)
    if (given (&d->sec, comp[k]))
      {
        if ((c = lac_scene_component (model, comp[k])) < 0)
          return lac_scene_error (sc, &d->sec, comp[k], LAC_EINVAL,
                                  "not a component of model = %s (use %s)",
                                  model_names[model], model == LAC_AXISYMMETRIC
                                  ? "ur, uz" : model == LAC_SOLID3D
                                  ? "ux, uy, uz" : "ux, uy");
        d->fixed[c] = 1;
        d->value[c] = *val[k];
        ncomp++;
      }
  d->kind = LAC_BC_COMPONENTS;
  if (given (&d->sec, "clamp") && d->clamp)
    d->kind = LAC_BC_CLAMP;
  if (given (&d->sec, "symmetry"))
    {
      static const int axis[3][4] = {   /* x y z r -> component or -1 */
        { 0, 1, -1, -1 }, { -1, -1, 1, 0 }, { 0, 1, 2, -1 } };
      if ((c = axis[model][d->symmetry]) < 0)
        return lac_scene_error (sc, &d->sec, "symmetry", LAC_EINVAL,
                                "not an axis of model = %s (use %s)",
                                model_names[model], model == LAC_AXISYMMETRIC
                                ? "r or z" : model == LAC_SOLID3D
                                ? "x, y or z" : "x or y");
      if (d->kind != LAC_BC_COMPONENTS)
        return lac_scene_error (sc, &d->sec, "symmetry", LAC_EINVAL,
                                "give only one of clamp, symmetry, exact");
      d->kind = LAC_BC_SYMMETRY;
      d->fixed[c] = 1;
      d->value[c] = 0;
    }
  if (given (&d->sec, "exact") && d->exact)
    {
      if (d->kind != LAC_BC_COMPONENTS)
        return lac_scene_error (sc, &d->sec, "exact", LAC_EINVAL,
                                "give only one of clamp, symmetry, exact");
      if (sc->exact.sec.line == 0)
        return lac_scene_error (sc, &d->sec, "exact", LAC_EINVAL,
                                "needs an [exact] section");
      d->kind = LAC_BC_EXACT;
    }
  if (d->kind != LAC_BC_COMPONENTS && d->kind != LAC_BC_SYMMETRY && ncomp)
    return lac_scene_error (sc, &d->sec, NULL, LAC_EINVAL, "give either "
                            "components (ux, ...) or clamp/exact, not both");
  if (d->kind == LAC_BC_SYMMETRY && ncomp)
    return lac_scene_error (sc, &d->sec, "symmetry", LAC_EINVAL,
                            "give either components (ux, ...) or symmetry, "
                            "not both");
  if (d->kind == LAC_BC_CLAMP)
    for (c = 0; c < 3; c++)
      d->fixed[c] = c < lac_model_dim (model), d->value[c] = 0;
  if (d->kind == LAC_BC_COMPONENTS && ncomp == 0)
    return lac_scene_error (sc, &d->sec, NULL, LAC_EINVAL, "nothing to "
                            "impose: give ux/uy/uz (ur/uz), clamp = yes, "
                            "symmetry = AXIS or exact = yes");
  return LAC_SUCCESS;
}

static int
finish_load (lac_scene *sc, lac_scene_load *l)
{
  int dim = lac_model_dim ((lac_model) sc->scene.model), nkind = 0;
  nkind += given (&l->sec, "pressure");
  nkind += given (&l->sec, "traction");
  nkind += given (&l->sec, "force");
  if (nkind != 1)
    return lac_scene_error (sc, &l->sec, NULL, LAC_EINVAL, "give exactly "
                            "one of pressure, traction, force");
  if (given (&l->sec, "pressure"))
    l->kind = LAC_LOAD_PRESSURE;
  else if (given (&l->sec, "traction"))
    {
      l->kind = LAC_LOAD_TRACTION;
      if (l->ntraction != dim)
        return lac_scene_error (sc, &l->sec, "traction", LAC_EINVAL,
                                "expected %d numbers for model = %s", dim,
                                model_names[sc->scene.model]);
      memcpy (l->vec, l->traction, sizeof l->vec);
    }
  else
    {
      l->kind = LAC_LOAD_FORCE;
      if (l->nforce != dim)
        return lac_scene_error (sc, &l->sec, "force", LAC_EINVAL,
                                "expected %d numbers for model = %s", dim,
                                model_names[sc->scene.model]);
      memcpy (l->vec, l->force, sizeof l->vec);
    }
  if (l->kind != LAC_LOAD_FORCE)
    return require (sc, &l->sec, "group", "boundary physical group");
  return LAC_SUCCESS;
}

static int
finish_exact (lac_scene *sc)
{
  static const char *const keys[] = { "a", "b", "p", "E", "nu" };
  lac_scene_exact *x = &sc->exact;
  int status, model = sc->scene.model;
  if (x->sec.line == 0)
    return LAC_SUCCESS;
  if ((status = require (sc, &x->sec, "solution", "thick_sphere or "
                         "thick_cylinder")))
    return status;
  for (int k = 0; k < 5; k++)
    if ((status = require (sc, &x->sec, keys[k], "a number")))
      return status;
  if (x->a >= x->b)
    return lac_scene_error (sc, &x->sec, "b", LAC_EINVAL, "expected b > a "
                            "= %g", x->a);
  if (x->solution == LAC_EXACT_THICK_SPHERE && model == LAC_PLANE_STRAIN)
    return lac_scene_error (sc, &x->sec, "solution", LAC_EINVAL, "needs "
                            "model = axisymmetric or 3d");
  if (x->solution == LAC_EXACT_THICK_CYLINDER && model == LAC_AXISYMMETRIC)
    return lac_scene_error (sc, &x->sec, "solution", LAC_EINVAL, "needs "
                            "model = plane_strain or 3d");
  return LAC_SUCCESS;
}

static int
finish (lac_scene *sc)
{
  int status;
  if ((status = finish_scene (sc)) || (status = finish_mesh (sc))
      || (status = finish_exact (sc)) || (status = finish_materials (sc)))
    return status;
  for (size_t k = 0; k < sc->ndirichlet; k++)
    if ((status = finish_dirichlet (sc, &sc->dirichlet[k])))
      return status;
  for (size_t k = 0; k < sc->nload; k++)
    if ((status = finish_load (sc, &sc->load[k])))
      return status;
  return LAC_SUCCESS;
}

/* ---- public ----------------------------------------------------------- */

static int
set_names (lac_scene *sc, const char *path)
{
  const char *slash = strrchr (path, '/'), *base = slash ? slash + 1 : path;
  size_t n = strlen (base);
  sc->path = lac_strdup (path);
  if (!slash)
    sc->dir = lac_strdup (".");
  else if (slash == path)
    sc->dir = lac_strdup ("/");
  else if ((sc->dir = lac_malloc ((size_t) (slash - path) + 1)) != NULL)
    {
      memcpy (sc->dir, path, (size_t) (slash - path));
      sc->dir[slash - path] = '\0';
    }
  if (n > 6 && strcmp (base + n - 6, ".scene") == 0)
    n -= 6;
  if ((sc->basename = lac_malloc (n + 1)) != NULL)
    {
      memcpy (sc->basename, base, n);
      sc->basename[n] = '\0';
    }
  if (!sc->path || !sc->dir || !sc->basename)
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  return LAC_SUCCESS;
}

int
lac_scene_read_string (const char *text, const char *path, size_t nset,
                       const char *const *set, lac_scene **out)
{
  raw r;
  lac_scene *sc;
  int status;
  *out = NULL;
  memset (&r, 0, sizeof r);
  r.text = text;
  if (!(sc = lac_calloc (1, sizeof *sc)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  set_defaults (SEC_SCENE, &sc->scene.sec);
  set_defaults (SEC_MESH, &sc->mesh.sec);
  set_defaults (SEC_EXACT, &sc->exact.sec);
  set_defaults (SEC_OUTPUT, &sc->output.sec);
  status = set_names (sc, path);
  if (!status)
    status = capture (&r, path);
  for (size_t k = 0; k < nset && !status; k++)
    status = set_one (&r, path, set[k]);
  if (!status)
    status = build (sc, &r);
  if (!status)
    status = finish (sc);
  raw_free (&r);
  if (status)
    lac_scene_free (sc);
  else
    *out = sc;
  return status;
}

int
lac_scene_read (const char *path, size_t nset, const char *const *set,
                lac_scene **out)
{
  FILE *f;
  char *text = NULL, *p;
  size_t len = 0, cap = 0, n;
  int status;
  *out = NULL;
  if (!(f = fopen (path, "r")))
    return lac_error_set (LAC_EIO, path, "cannot open scene file (%s)",
                          strerror (errno));
  do
    {
      if (cap - len < 4096)
        {
          cap = cap ? 2 * cap : 8192;
          if (!(p = lac_realloc (text, cap)))
            {
              lac_free (text);
              fclose (f);
              LAC_ERROR (LAC_ENOMEM, "out of memory reading %s", path);
            }
          text = p;
        }
      n = fread (text + len, 1, cap - len - 1, f);
      len += n;
    }
  while (n > 0);
  status = ferror (f) ? errno : 0;
  fclose (f);
  text[len] = '\0';
  if (status)
    status = lac_error_set (LAC_EIO, path, "cannot read scene file (%s)",
                            strerror (status));
  else
    status = lac_scene_read_string (text, path, nset, set, out);
  lac_free (text);
  return status;
}

static void
section_free (lac_scene_section *s)
{
  const section_spec *sp = &sections[s->kind];
  for (int k = 0; k < sp->nkeys; k++)
    {
      lac_free (s->key_raw[k]);
      if (sp->keys[k].type == K_STR)
        lac_free (*(char **) ((char *) s + sp->keys[k].off));
    }
  lac_free (s->name);
}

void
lac_scene_free (lac_scene *sc)
{
  if (!sc)
    return;
  section_free (&sc->scene.sec);
  section_free (&sc->mesh.sec);
  section_free (&sc->exact.sec);
  section_free (&sc->output.sec);
  lac_free (sc->mesh.path);
  for (size_t k = 0; k < sc->nmaterial; k++)
    section_free (&sc->material[k].sec);
  for (size_t k = 0; k < sc->ndirichlet; k++)
    section_free (&sc->dirichlet[k].sec);
  for (size_t k = 0; k < sc->nload; k++)
    section_free (&sc->load[k].sec);
  lac_free (sc->material);
  lac_free (sc->dirichlet);
  lac_free (sc->load);
  lac_free (sc->path);
  lac_free (sc->dir);
  lac_free (sc->basename);
  lac_free (sc);
}

int
lac_scene_key_line (const lac_scene_section *s, const char *key)
{
  int k = key_index (s->kind, key);
  return k < 0 ? 0 : s->key_line[k];
}

int
lac_scene_error (const lac_scene *sc, const lac_scene_section *s,
                 const char *key, int status, const char *fmt, ...)
{
  char label[300] = "", keypart[400] = "", msg[600];
  int k = (s && key) ? key_index (s->kind, key) : -1;
  int line = (k >= 0) ? s->key_line[k] : 0;
  va_list ap;
  if (s && s->name)
    snprintf (label, sizeof label, "[%s %s]", sections[s->kind].name,
              s->name);
  else if (s)
    snprintf (label, sizeof label, "[%s]", sections[s->kind].name);
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
  return where_error (sc->path, line, status, "%s%s: %s", label, keypart,
                      msg);
}

const char *
lac_scene_element_name (int element)
{
  for (size_t k = 0; k < sizeof element_info / sizeof element_info[0]; k++)
    if ((int) element_info[k].type == element)
      return element_names[k];
  return "any";
}

const char *
lac_scene_exact_name (int solution)
{
  return solution >= 0 && solution < 2 ? exact_names[solution] : "none";
}
