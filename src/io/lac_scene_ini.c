/* lac_scene_ini.c -- steps 1-3 of reading a scene (see lac_scene.h)
 *
 *   1. capture: inih splits the text into (section, key, value) entries; our
 *      reader feeds it one line at a time, so it knows every line number,
 *      and it records the [section] headers itself (inih does not report
 *      them);
 *   2. overrides: --set KEY=VALUE replaces or adds entries;
 *   3. build: headers and entries, in file order, are checked against the
 *      section and key tables (lac_scene_keys.c) and stored in typed structs:
 *      text, numbers, integers, booleans, enums, vectors.
 * Step 4 (defaults, required keys, conflicts) is in lac_scene_check.c.
 *
 * References: inih, https://github.com/benhoyt/inih (BSD-3-Clause).
 */
#include "io/lac_scene_ini.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ini.h>
#include "io/lac_scene_keys.h"
#include "io/lac_scene_query.h"
#include "base/lac_mem.h"
#include "base/lac_number.h"
#include "base/lac_status.h"

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
  if (lac_grow (a, *n + 1, cap, sizeof **a, 16))
    return LAC_ENOMEM;
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

static int
capture (raw *r, const char *path)
{
  int ret = ini_parse_stream (reader, r, handler, r);
  if (ret > 0 && (r->err_line == 0 || ret < r->err_line))
    return lac_scene_where_error (path, ret, LAC_EINVAL, "syntax error: "
                                  "expected '[section]' or 'key = value'");
  if (ret < 0 && r->err_line == 0)
    return lac_scene_where_error (path, 0, LAC_ENOMEM, "cannot parse (inih "
                                  "status %d)", ret);
  if (r->err_line)
    return lac_scene_where_error (path, r->err_line, r->err_status, "%s",
                                  r->err);
  return LAC_SUCCESS;
}

/* ---- step 2: overrides ------------------------------------------------ */

/* "KEY=VALUE" (or "ALIAS=VALUE") -> the section as a header would name it
 * ("type" or "type name", in sec), the key (in keyout), the value (in
 * buf) and the section kind. */
static int
set_split (const char *arg, char buf[512], char sec[600], char keyout[512],
           const char **val, int *kind)
{
  char keybuf[512], *eq, *dot, *last;
  const char *key;
  const section_spec *sp;
  if (strlen (arg) >= 512)              /* the buffers below: never cut */
    return lac_error_set (LAC_EINVAL, "--set", "'%.40s...': %zu characters,"
                          " at most 511 (a scene line holds at most 197)",
                          arg, strlen (arg));
  snprintf (buf, 512, "%s", arg);
  if (!(eq = strchr (buf, '=')))
    return lac_error_set (LAC_EINVAL, "--set", "'%s': expected KEY=VALUE "
                          "(e.g. mesh.level=2)", arg);
  *eq = '\0';
  key = trim (buf);
  *val = trim (eq + 1);
  for (size_t k = 0; k < sizeof aliases / sizeof aliases[0]; k++)
    if (strcmp (key, aliases[k].alias) == 0)
      key = aliases[k].key;
  snprintf (keybuf, sizeof keybuf, "%s", key);
  if (!(dot = strchr (keybuf, '.')))
    return lac_error_set (LAC_EINVAL, "--set", "'%s': expected SECTION.KEY"
                          "=VALUE, TYPE.NAME.KEY=VALUE or an alias (element,"
                          " model, solver, out, level, order, size)", arg);
  *dot = '\0';
  if ((*kind = lac_scene_section_kind (keybuf)) < 0)
    {
      char list[256];
      lac_scene_section_list (list, sizeof list);
      return lac_error_set (LAC_EINVAL, "--set", "'%s': unknown section '%s'"
                            " (sections: %s)", arg, keybuf, list);
    }
  sp = &lac_scene_sections[*kind];
  last = strrchr (dot + 1, '.');
  if (sp->named ? (!last || last == dot + 1) : last != NULL)
    return lac_error_set (LAC_EINVAL, "--set", "'%s': expected %s", arg,
                          sp->named ? "TYPE.NAME.KEY=VALUE, as in"
                          " material.steel.E=3000" : "SECTION.KEY=VALUE");
  if (sp->named)
    {
      *last = '\0';
      snprintf (sec, 600, "%s %s", keybuf, dot + 1);
      snprintf (keyout, 512, "%s", last + 1);
    }
  else
    {
      snprintf (sec, 600, "%s", keybuf);
      snprintf (keyout, 512, "%s", dot + 1);
    }
  return LAC_SUCCESS;
}

/* The section of an override: named ones must exist, unnamed ones are
 * created. */
static int
set_header (raw *r, const char *path, const char *arg, const char *sec,
            int kind)
{
  size_t k;
  raw_entry h = { NULL, NULL, NULL, LAC_SCENE_FROM_SET, INT_MAX };
  for (k = 0; k < r->nh && strcmp (r->h[k].sec, sec) != 0; k++)
    ;
  if (k < r->nh)
    return LAC_SUCCESS;
  if (lac_scene_sections[kind].named)
    return lac_error_set (LAC_EINVAL, "--set", "'%s': no section [%s] in "
                          "%s", arg, sec, path);
  h.sec = lac_strdup (sec);
  if (!h.sec || push (&r->h, &r->nh, &r->caph, h))
    {
      lac_free (h.sec);
      return lac_error_set (LAC_ENOMEM, "--set", "out of memory");
    }
  return LAC_SUCCESS;
}

/* Replace the entry (sec, key), or add one. */
static int
set_entry (raw *r, const char *sec, const char *key, const char *val)
{
  raw_entry e = { NULL, NULL, NULL, LAC_SCENE_FROM_SET, INT_MAX };
  int found = 0, status;
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

static int
set_one (raw *r, const char *path, const char *arg)
{
  char buf[512], sec[600], key[512];
  const char *val = NULL;
  int kind = -1, status;
  if ((status = set_split (arg, buf, sec, key, &val, &kind))
      || (status = set_header (r, path, arg, sec, kind)))
    return status;
  return set_entry (r, sec, key, val);
}

/* ---- step 3: build ---------------------------------------------------- */

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

/* A value that must be > 0: at least 1 / LAC_SCENE_NUM_MAX. */
static int
positive (const key_spec *ks)
{
  return ks->type != K_VEC && ks->type != K_LIST && ks->lo == 0
         && (ks->open & 1);
}

/* |x| <= LAC_SCENE_NUM_MAX, and x >= 1 / LAC_SCENE_NUM_MAX for a value
 * that must be > 0 (see lac_scene_types.h). */
static int
in_scale (const key_spec *ks, double x)
{
  return fabs (x) <= LAC_SCENE_NUM_MAX
         && (!positive (ks) || x >= 1 / LAC_SCENE_NUM_MAX);
}

/* why: what the number is besides (a double's overflow or underflow), or
 * NULL. */
static int
out_of_scale (lac_scene *sc, lac_scene_section *s, const key_spec *ks,
              double x, const char *why)
{
  char range[64];
  if (fabs (x) > LAC_SCENE_NUM_MAX)
    snprintf (range, sizeof range, "at most %g", LAC_SCENE_NUM_MAX);
  else
    snprintf (range, sizeof range, "at least %g", 1 / LAC_SCENE_NUM_MAX);
  return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s of "
                          "magnitude %s%s%s%s: products with the other values"
                          " of the scene could overflow or vanish in double "
                          "precision", ks->expect, range, why ? " (it is " : "",
                          why ? why : "", why ? ")" : "");
}

/* The number val of key ks into *x: a finite double (lac_number.h), in
 * the key's range, within LAC_SCENE_NUM_MAX; a message naming the limit
 * broken otherwise. */
static int
store_number (lac_scene *sc, lac_scene_section *s, const key_spec *ks,
              const char *val, double *x)
{
  lac_number_spec range = { ks->lo, ks->hi, ks->open, ks->type == K_INT, 0 };
  char why[160];
  if (!lac_number_parse (val, NULL, x, why, sizeof why))
    {
      if (isinf (*x) || (!isnan (*x) && positive (ks)))
        return out_of_scale (sc, s, ks, isinf (*x) ? *x : 0, why);
      return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s: %s",
                              ks->expect, why);
    }
  if (ks->type != K_VEC && ks->type != K_LIST
      && !lac_number_check (*x, &range, why, sizeof why))
    return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s: %s",
                            ks->expect, why);
  if (ks->type != K_INT && !in_scale (ks, *x))
    return out_of_scale (sc, s, ks, *x, NULL);
  return LAC_SUCCESS;
}

/* The j-th name of an enum key (NULL past the last). */
static const char *
enum_name (const key_spec *ks, int j)
{
  return *(const char *const *) ((const char *) ks->enums
                                 + (size_t) j * ks->stride);
}

static int
store_enum (lac_scene *sc, lac_scene_section *s, const key_spec *ks,
            const char *val)
{
  char list[256];
  size_t n = 0;
  for (int j = 0; enum_name (ks, j); j++)
    if (strcmp (val, enum_name (ks, j)) == 0)
      {
        *(int *) ((char *) s + ks->off) = j;
        return LAC_SUCCESS;
      }
  while (enum_name (ks, (int) n))
    n++;
  lac_scene_join_names (list, sizeof list, ks->enums, n, ks->stride);
  return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected one of: %s",
                          list);
}

static int
store_vec (lac_scene *sc, lac_scene_section *s, const key_spec *ks,
           const char *val)
{
  double *v = (double *) ((char *) s + ks->off);
  int *n = (int *) ((char *) s + ks->off_n), status;
  char buf[256], *tok, *save = NULL;
  if (strlen (val) >= sizeof buf)
    return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s: a "
                            "value of %zu characters is not that", ks->expect,
                            strlen (val));
  snprintf (buf, sizeof buf, "%s", val);
  *n = 0;
  for (tok = strtok_r (buf, " \t,", &save); tok;
       tok = strtok_r (NULL, " \t,", &save))
    if (*n == 3)
      return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s: "
                              "more than 3", ks->expect);
    else if ((status = store_number (sc, s, ks, tok, &v[(*n)++])))
      return status;
  if (*n < 1)             /* the count is checked against the model later */
    return lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s",
                            ks->expect);
  return LAC_SUCCESS;
}

/* Number k (0-based) of a list, the token tok: a finite double within
 * LAC_SCENE_NUM_MAX; a message that names it otherwise. */
static int
list_number (lac_scene *sc, lac_scene_section *s, const key_spec *ks,
             const char *tok, size_t k, double *x)
{
  char why[160];
  if (!lac_number_parse (tok, NULL, x, why, sizeof why))
    return isinf (*x) ? out_of_scale (sc, s, ks, *x, why)
           : lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s: "
                              "number %zu, '%.40s': %s", ks->expect, k + 1,
                              tok, why);
  return in_scale (ks, *x) ? LAC_SUCCESS : out_of_scale (sc, s, ks, *x, NULL);
}

/* A list of numbers (K_LIST) into an owned array: blanks or commas
 * between them, each a number as store_number reads one; what the list
 * means (pairs, order) is checked with the rest (lac_scene_check.c). */
static int
store_list (lac_scene *sc, lac_scene_section *s, const key_spec *ks,
            const char *val)
{
  double **v = (double **) ((char *) s + ks->off);
  int *n = (int *) ((char *) s + ks->off_n), status = LAC_SUCCESS;
  char *buf = lac_strdup (val), *tok, *save = NULL;
  size_t cap = 0, len = 0;
  double *x = NULL;
  if (!buf)
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  for (tok = strtok_r (buf, " \t,", &save); tok && !status;
       tok = strtok_r (NULL, " \t,", &save))
    if (len >= INT_MAX || lac_grow (&x, len + 1, &cap, sizeof *x, 8))
      status = LAC_ERRMSG (LAC_ENOMEM, "a list of %zu numbers", len + 1);
    else
      status = list_number (sc, s, ks, tok, len, &x[len]), len++;
  lac_free (buf);
  if (!status && len == 0)
    status = lac_scene_error (sc, s, ks->name, LAC_EINVAL, "expected %s",
                              ks->expect);
  if (status)
    {
      lac_free (x);
      return status;
    }
  lac_free (*v);              /* given twice (a --set): the last one */
  *v = x;
  *n = (int) len;
  return LAC_SUCCESS;
}

/* Convert the value of key k of section s and store it.  */
static int
store_value (lac_scene *sc, lac_scene_section *s, int k, const char *val)
{
  const key_spec *ks = &lac_scene_sections[s->kind].keys[k];
  char *base = (char *) s;
  double x;
  int status;
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
      if ((status = store_number (sc, s, ks, val, &x)))
        return status;
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
      return store_enum (sc, s, ks, val);
    case K_VEC:
      return store_vec (sc, s, ks, val);
    case K_LIST:
      return store_list (sc, s, ks, val);
    }
  LAC_ERROR (LAC_ESANITY, "key type %d", (int) ks->type);
}

/* The headers by their normalized name ("material steel"): an
 * open-addressing table of the first header of each name, so that the
 * section of an entry and a header given twice are found in constant
 * time.  A scene of n sections is read in time linear in n (a search
 * through the sections for each entry made 100,000 sections take 137 s). */
typedef struct heads
{
  size_t *slot;     /* owned, size: 1 + header index, 0 for empty        */
  size_t size;      /* a power of 2, at least twice the headers          */
  int *kind;        /* owned, nh: the kind of each header's section      */
  size_t *index;    /* owned, nh: its index among the sections of kind   */
} heads;

static size_t
name_hash (const char *s)
{
  size_t h = 14695981039346656037u;               /* FNV-1a */
  for (; *s; s++)
    h = (h ^ (unsigned char) *s) * 1099511628211u;
  return h;
}

/* The index of the first header named sec, or r->nh if none. */
static size_t
heads_find (const heads *H, const raw *r, const char *sec)
{
  for (size_t i = name_hash (sec) & (H->size - 1); H->slot[i];
       i = (i + 1) & (H->size - 1))
    if (strcmp (r->h[H->slot[i] - 1].sec, sec) == 0)
      return H->slot[i] - 1;
  return r->nh;
}

static int
heads_init (heads *H, const raw *r)
{
  H->size = 16;
  while (H->size < 2 * r->nh)
    H->size *= 2;
  H->slot = lac_calloc (H->size, sizeof *H->slot);
  H->kind = lac_calloc (r->nh + 1, sizeof *H->kind);
  H->index = lac_calloc (r->nh + 1, sizeof *H->index);
  if (!H->slot || !H->kind || !H->index)
    LAC_ERROR (LAC_ENOMEM, "the index of %zu sections", r->nh);
  for (size_t k = 0; k < r->nh; k++)
    if (heads_find (H, r, r->h[k].sec) == r->nh)
      {
        size_t i = name_hash (r->h[k].sec) & (H->size - 1);
        while (H->slot[i])
          i = (i + 1) & (H->size - 1);
        H->slot[i] = k + 1;
      }
  return LAC_SUCCESS;
}

static void
heads_free (heads *H)
{
  lac_free (H->slot);
  lac_free (H->kind);
  lac_free (H->index);
}

/* Header k of r: a new section of sc. */
static int
build_header (lac_scene *sc, const raw *r, heads *H, size_t k)
{
  const raw_entry *h = &r->h[k];
  char buf[512], list[256];
  const char *name;
  int kind = lac_scene_split_section (h->sec, buf, sizeof buf, &name);
  size_t first = heads_find (H, r, h->sec);
  if (kind < 0)
    {
      lac_scene_section_list (list, sizeof list);
      return lac_scene_where_error (sc->path, h->line, LAC_EINVAL, "[%s]: "
                                    "unknown section (sections: %s)", h->sec,
                                    list);
    }
  if (lac_scene_sections[kind].named && !name[0])
    return lac_scene_where_error (sc->path, h->line, LAC_EINVAL, "[%s]: needs "
                                  "a name, as in [%s NAME]", h->sec, buf);
  if (!lac_scene_sections[kind].named && name[0])
    return lac_scene_where_error (sc->path, h->line, LAC_EINVAL, "[%s]: [%s] "
                                  "takes no name", h->sec, buf);
  if (first != k)
    return lac_scene_where_error (sc->path, h->line, LAC_EINVAL, "[%s]: "
                                  "section given twice (first at line %d)",
                                  h->sec, r->h[first].line);
  if (!lac_scene_section_new (sc, kind, name, h->line))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  H->kind[k] = kind;
  H->index[k] = lac_scene_section_count (sc, kind) - 1;
  return LAC_SUCCESS;
}

static int
build_entry (lac_scene *sc, const raw *r, const heads *H,
             const raw_entry *e)
{
  char buf[512], list[256];
  const char *name;
  size_t h;
  int kind, k;
  lac_scene_section *s;
  if (e->sec[0] == '\0')
    return lac_scene_where_error (sc->path, e->line, LAC_EINVAL, "%s = '%s': "
                                  "key outside any [section]", e->key,
                                  e->val);
  if ((h = heads_find (H, r, e->sec)) == r->nh
      || !(s = lac_scene_section_get (sc, kind = H->kind[h], H->index[h])))
    LAC_ERROR (LAC_ESANITY, "entry of unknown section [%s]", e->sec);
  if ((k = lac_scene_key_index (kind, e->key)) < 0)
    {
      const section_spec *sp = &lac_scene_sections[kind];
      lac_scene_split_section (e->sec, buf, sizeof buf, &name);
      lac_scene_join_names (list, sizeof list, &sp->keys[0].name,
                            (size_t) sp->nkeys, sizeof (key_spec));
      return lac_scene_where_error (sc->path, e->line, LAC_EINVAL, "[%s] %s: "
                                    "unknown key (keys of [%s]: %s)", e->sec,
                                    e->key, buf, list);
    }
  if (s->key_line[k] > 0 && e->line > 0)
    return lac_scene_where_error (sc->path, e->line, LAC_EINVAL, "[%s] %s: "
                                  "key given twice (first at line %d)",
                                  e->sec, e->key, s->key_line[k]);
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
  heads H = { 0 };
  int status = heads_init (&H, r);
  while (status == LAC_SUCCESS && (ih < r->nh || ie < r->ne))
    {
      long long lh = ih < r->nh ? r->h[ih].order : (long long) INT_MAX + 1;
      long long le = ie < r->ne ? r->e[ie].order : (long long) INT_MAX + 1;
      if (lh <= le)
        status = build_header (sc, r, &H, ih++);
      else
        status = build_entry (sc, r, &H, &r->e[ie++]);
    }
  heads_free (&H);
  return status;
}

/* ---- steps 1-3 -------------------------------------------------------- */

int
lac_scene_parse (lac_scene *sc, const char *text, const char *path,
                 size_t nset, const char *const *set)
{
  raw r;
  int status;
  memset (&r, 0, sizeof r);
  r.text = text;
  status = capture (&r, path);
  for (size_t k = 0; k < nset && !status; k++)
    status = set_one (&r, path, set[k]);
  if (!status)
    status = build (sc, &r);
  raw_free (&r);
  return status;
}
