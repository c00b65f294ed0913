/* lac_mesh_geo_check.c -- the counts of a .geo's transfinite curves
 * (see lac_mesh_geo_check.h)
 *
 * One pass over the script (lac_mesh_geo_expr.h skips blanks, comments
 * and strings, and counts the lines): an identifier "Transfinite"
 * followed by "Curve" or "Line", a list in braces and "=" starts a count,
 * which ends at ";" or at the word "Using"; an identifier followed by
 * "=" is an assignment, whose value (when lac can tell it) is kept for
 * the counts after it; If, For, Macro, Function open a block that EndIf,
 * EndFor, Return close, and DefineConstant[...] is one too.
 */
#include "io/lac_mesh_geo_check.h"
#include "io/lac_mesh_geo_expr.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_number.h"
#include "base/lac_status.h"

/* The identifier at c->p (skipped): 1 if it is w1 or w2 (may be NULL). */
static int
word (lac_geo_scan *c, const char *w1, const char *w2)
{
  const char *s = c->p;
  size_t n;
  while (c->p < c->end && lac_geo_ident_char (*c->p))
    c->p++;
  n = (size_t) (c->p - s);
  return (n == strlen (w1) && !memcmp (s, w1, n))
         || (w2 && n == strlen (w2) && !memcmp (s, w2, n));
}

/* The count of a "Transfinite Curve {...} =" at c->p: a number from 2 to
 * 2147483647 when it is written as one; when it is computed and lac can
 * evaluate it (lac_mesh_geo_expr.h), a finite value of magnitude at most
 * 2147483647 (gmsh truncates a fraction and takes 2 below 2, as its
 * documentation says; beyond 32 bits it takes 2 too, without a word). */
static int
count (const char *path, lac_geo_scan *c, lac_geo_vars *v)
{
  static const lac_number_spec spec = { 2, 2147483647.0, 0, 1, 0 };
  const char *s = c->p, *e, *stop;
  char text[64], why[160];
  long line = c->line;
  double x;
  lac_geo_scan t = *c;
  for (e = s; e < c->end && *e != ';' && *e != '\n'
       && !(e > s && !lac_geo_ident_char (e[-1]) && c->end - e >= 5
            && !memcmp (e, "Using", 5)); e++)  /* the text has no NUL */
    ;
  for (stop = e; e > s && isspace ((unsigned char) e[-1]);)
    e--;
  if (e == s)
    return LAC_SUCCESS;
  snprintf (text, sizeof text, "%.*s%s", (int) (e - s < 48 ? e - s : 44), s,
            e - s < 48 ? "" : " ...");
  x = NAN;
  if (e - s < 48 && lac_number_parse (text, NULL, &x, why, sizeof why))
    {
      if (lac_number_check (x, &spec, why, sizeof why))
        return LAC_SUCCESS;
    }
  else if (!isnan (x))
    ;                          /* a number beyond a double: why says so */
  else if (!lac_geo_expr (&t, v, &x) || (lac_geo_skip (&t), t.p != stop)
           || (isfinite (x) && fabs (x) <= 2147483647.0))
    return LAC_SUCCESS;        /* fine, or beyond what lac can evaluate */
  else
    snprintf (why, sizeof why, "it computes to %g, %s", x, isfinite (x)
              ? "beyond 32-bit integers (2147483647)" : "not a finite "
              "number");
  return lac_error_set (LAC_EINVAL, "lac_mesh_read", "'%s': line %ld: "
                        "Transfinite Curve {...} = %s: %s; gmsh 4.8 makes a "
                        "count that is not an integer from 2 to 2147483647 "
                        "into another without a word", path, line, text,
                        why);
}

/* After "Transfinite": "Curve" or "Line", "{...}", "=", the count. */
static int
statement (const char *path, lac_geo_scan *c, lac_geo_vars *v)
{
  int depth = 0;
  lac_geo_skip (c);
  if (!(c->p < c->end && word (c, "Curve", "Line")))
    return LAC_SUCCESS;
  lac_geo_skip (c);
  if (c->p >= c->end || *c->p != '{')
    return LAC_SUCCESS;
  for (; c->p < c->end; c->p++)
    {
      depth += (*c->p == '{') - (*c->p == '}');
      c->line += *c->p == '\n';
      if (depth == 0)
        break;
    }
  c->p += c->p < c->end;
  lac_geo_skip (c);
  if (c->p >= c->end || *c->p != '=' || (c->p + 1 < c->end && c->p[1] == '='))
    return LAC_SUCCESS;
  c->p++;
  lac_geo_skip (c);
  return count (path, c, v);
}

/* After the name (s, len) of an assignment "NAME = EXPR" (or "NAME +=
 * ...", "NAME++"): its value for the counts after it.  In a block (If,
 * For, Macro, DefineConstant) lac does not know whether or how often it
 * runs: the variable becomes unknown, unless the scene gives it (a
 * default set under If (!Exists(NAME)) does not run then). */
static void
assignment (lac_geo_scan *c, lac_geo_vars *v, const char *s, size_t len,
            int block)
{
  lac_geo_var *x = lac_geo_vars_find (v, s, len);
  int plain = *c->p == '=' && !(c->p + 1 < c->end && c->p[1] == '=');
  double y = 0;
  int known;
  if (block && x && x->scene)
    return;
  if (!plain)                                     /* +=, -=, ++, ... */
    {
      lac_geo_vars_set (v, s, len, 0, 0, 0);
      return;
    }
  c->p++;
  known = !block && lac_geo_expr (c, v, &y)
          && (lac_geo_skip (c), c->p < c->end && *c->p == ';');
  lac_geo_vars_set (v, s, len, y, known, 0);
}

/* Does the identifier (s, len) open (+1) or close (-1) a block? */
static int
block_change (const char *s, size_t len)
{
  static const char *const open[] = { "If", "For", "Macro", "Function" };
  static const char *const close[] = { "EndIf", "EndFor", "Return" };
  for (size_t k = 0; k < 4; k++)
    if (strlen (open[k]) == len && !memcmp (open[k], s, len))
      return 1;
  for (size_t k = 0; k < 3; k++)
    if (strlen (close[k]) == len && !memcmp (close[k], s, len))
      return -1;
  return 0;
}

/* The scene's numbers: `level` (always exported) and [mesh] numbers. */
static void
scene_vars (const lac_mesh_opts *o, lac_geo_vars *v)
{
  lac_mesh_number num[LAC_MESH_MAX_NUMBERS];
  char why[160];
  int n;
  if (!o)
    return;
  lac_geo_vars_set (v, "level", 5, o->level, 1, 1);
  n = lac_mesh_numbers_split (o->numbers, num, why, sizeof why);
  for (int k = 0; k < n; k++)
    lac_geo_vars_set (v, num[k].name, strlen (num[k].name), num[k].value, 1,
                      1);
}

/* DefineConstant[ NAME = {VALUE, ...}, ... ]: each NAME takes VALUE
 * unless it exists (the scene gives it), which lac does not follow: the
 * NAMEs the scene does not give become unknown. */
static void
define_constant (lac_geo_scan *c, lac_geo_vars *v)
{
  int depth = 0;
  lac_geo_skip (c);
  if (c->p >= c->end || *c->p != '[')
    return;
  while (c->p < c->end)
    {
      const char *s = c->p;
      if (!lac_geo_ident_char (*c->p))
        {
          depth += (*c->p == '[' || *c->p == '{')
                   - (*c->p == ']' || *c->p == '}');
          c->p++;
          if (depth == 0)
            return;
          lac_geo_skip (c);
          continue;
        }
      while (c->p < c->end && lac_geo_ident_char (*c->p))
        c->p++;
      lac_geo_skip (c);
      if (depth == 1 && c->p < c->end && *c->p == '=')
        assignment (c, v, s, (size_t) (c->p - s), 1);
    }
}

/* One identifier at c->p: a count, an assignment, a block. */
static int
identifier (const char *path, lac_geo_scan *c, lac_geo_vars *v, int *block)
{
  const char *s = c->p;
  int digit_first = isdigit ((unsigned char) *c->p), change;
  size_t len;
  if (word (c, "Transfinite", NULL) && !digit_first)
    return statement (path, c, v);
  len = (size_t) (c->p - s);
  if (digit_first)
    return LAC_SUCCESS;
  if ((change = block_change (s, len)))
    *block = *block + change > 0 ? *block + change : 0;
  else if (len == 14 && !memcmp (s, "DefineConstant", 14))
    define_constant (c, v);
  else if ((lac_geo_skip (c), c->p + 1 < c->end) && strchr ("=+-*/", *c->p)
           && (c->p[0] == '=' || c->p[1] == '=' || c->p[1] == c->p[0]))
    assignment (c, v, s, len, *block > 0);
  return LAC_SUCCESS;
}

int
lac_geo_check_text (const char *path, const char *text, size_t len,
                    const lac_mesh_opts *o)
{
  lac_geo_scan c = { text, text + len, 1 };
  lac_geo_vars *v = lac_calloc (1, sizeof *v);
  int status = LAC_SUCCESS, block = 0;
  if (!v)
    LAC_ERROR (LAC_ENOMEM, "the variables of '%s'", path);
  scene_vars (o, v);
  while (!status && (lac_geo_skip (&c), c.p < c.end))
    if (lac_geo_ident_char (*c.p))
      status = identifier (path, &c, v, &block);
    else
      c.p++;
  lac_free (v);
  return status;
}

int
lac_geo_check (const char *path, const lac_mesh_opts *o)
{
  char *text = NULL;
  size_t len = 0;
  int status = lac_input_read (path, o->max_memory, "--max-memory", &text,
                               &len);
  if (!status)
    status = lac_geo_check_text (path, text, len, o);
  lac_free (text);
  return status;
}
