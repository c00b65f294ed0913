/* lac_mesh_geo_check.c -- the counts a .geo writes as numbers
 * (see lac_mesh_geo_check.h)
 *
 * A small scanner of the .geo language: blanks, line ends (counted),
 * comments (// and slash-star) and strings are skipped; an identifier
 * "Transfinite" followed by "Curve" or "Line", a list in braces and "="
 * starts a count, which ends at ";" or at the word "Using".  One pass,
 * linear in the text.
 */
#include "io/lac_mesh_geo_check.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_number.h"
#include "base/lac_status.h"

typedef struct scan
{
  const char *p, *end;
  long line;
} scan;

static int
ident_char (char c)
{
  return c == '_' || isalnum ((unsigned char) c);
}

/* Skip blanks, line ends, comments and strings. */
static void
skip_space (scan *c)
{
  while (c->p < c->end)
    {
      if (*c->p == '\n')
        c->line++, c->p++;
      else if (*c->p == ' ' || *c->p == '\t' || *c->p == '\r')
        c->p++;
      else if (c->p + 1 < c->end && c->p[0] == '/' && c->p[1] == '/')
        while (c->p < c->end && *c->p != '\n')
          c->p++;
      else if (c->p + 1 < c->end && c->p[0] == '/' && c->p[1] == '*')
        {
          for (c->p += 2; c->p + 1 < c->end
               && !(c->p[0] == '*' && c->p[1] == '/'); c->p++)
            c->line += *c->p == '\n';
          c->p = c->p + 2 <= c->end ? c->p + 2 : c->end;
        }
      else if (*c->p == '"')
        {
          for (c->p++; c->p < c->end && *c->p != '"'; c->p++)
            c->line += *c->p == '\n';
          c->p += c->p < c->end;
        }
      else
        break;
    }
}

/* The identifier at c->p (skipped): 1 if it is w1 or w2 (may be NULL). */
static int
word (scan *c, const char *w1, const char *w2)
{
  const char *s = c->p;
  size_t n;
  while (c->p < c->end && ident_char (*c->p))
    c->p++;
  n = (size_t) (c->p - s);
  return (n == strlen (w1) && !memcmp (s, w1, n))
         || (w2 && n == strlen (w2) && !memcmp (s, w2, n));
}

/* The count of a "Transfinite Curve {...} =" at c->p: checked if it is a
 * number (an expression is gmsh's to evaluate). */
static int
count (const char *path, scan *c)
{
  static const lac_number_spec spec = { 2, 2147483647.0, 0, 1, 0 };
  const char *s = c->p, *e;
  char text[64], why[160];
  long line = c->line;
  double x;
  for (e = s; e < c->end && *e != ';' && *e != '\n'
       && !(e > s && !ident_char (e[-1]) && c->end - e >= 5
            && !memcmp (e, "Using", 5)); e++)  /* the text has no NUL */
    ;
  while (e > s && isspace ((unsigned char) e[-1]))
    e--;
  if (e == s || (size_t) (e - s) >= sizeof text)
    return LAC_SUCCESS;
  snprintf (text, sizeof text, "%.*s", (int) (e - s), s);
  if (lac_number_parse (text, NULL, &x, why, sizeof why)
      ? lac_number_check (x, &spec, why, sizeof why) : isnan (x))
    return LAC_SUCCESS;
  return lac_error_set (LAC_EINVAL, "lac_mesh_read", "'%s': line %ld: "
                        "Transfinite Curve {...} = %s: %s; gmsh 4.8 makes a "
                        "count that is not an integer from 2 to 2147483647 "
                        "into another without a word", path, line, text,
                        why);
}

/* After "Transfinite": "Curve" or "Line", "{...}", "=", the count. */
static int
statement (const char *path, scan *c)
{
  int depth = 0;
  skip_space (c);
  if (!(c->p < c->end && word (c, "Curve", "Line")))
    return LAC_SUCCESS;
  skip_space (c);
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
  skip_space (c);
  if (c->p >= c->end || *c->p != '=' || (c->p + 1 < c->end && c->p[1] == '='))
    return LAC_SUCCESS;
  c->p++;
  skip_space (c);
  return count (path, c);
}

int
lac_geo_check_text (const char *path, const char *text, size_t len)
{
  scan c = { text, text + len, 1 };
  int status = LAC_SUCCESS;
  while (!status && (skip_space (&c), c.p < c.end))
    if (ident_char (*c.p))
      {
        int digit_first = isdigit ((unsigned char) *c.p);
        if (word (&c, "Transfinite", NULL) && !digit_first)
          status = statement (path, &c);
      }
    else
      c.p++;
  return status;
}

int
lac_geo_check (const char *path, double max_bytes)
{
  char *text = NULL;
  size_t len = 0;
  int status = lac_input_read (path, max_bytes, "--max-memory", &text, &len);
  if (!status)
    status = lac_geo_check_text (path, text, len);
  lac_free (text);
  return status;
}
