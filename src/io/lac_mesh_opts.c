/* lac_mesh_opts.c -- the numbers a .geo receives (see lac_mesh_opts.h)
 *
 * [mesh] numbers = "n=28, m=3" reaches gmsh as "-setnumber n 28": gmsh
 * reads any strtod text there (nan, inf, 1e400) and converts the counts a
 * script computes from it to int without a word, so a count above
 * INT_MAX or nan meshes a curve with 2 nodes: a 17-node mesh, exit
 * status 0.  The names and values are checked here once, for the scene
 * reader (lac_scene_check.c, whose message names the line) and for the
 * gmsh session (lac_mesh_gmsh_session.c, the library's own callers).
 */
#include "io/lac_mesh_opts.h"

#include <stdio.h>
#include <string.h>

#include "base/lac_number.h"

/* What separates the pairs: blanks (any white space) and commas. */
#define SEP " \t\n\r\v\f,"

static int
ident_char (char c, int first)
{
  return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')
         || (!first && c >= '0' && c <= '9');
}

/* One "NAME=VALUE" of len bytes at p into *o; 0 with why. */
static int
one_pair (const char *p, size_t len, const lac_mesh_number *prev,
          int nprev, lac_mesh_number *o, char *why, size_t size)
{
  static const lac_number_spec spec = { -LAC_MESH_NUMBER_MAX,
                                        LAC_MESH_NUMBER_MAX, 0, 0, 0 };
  char val[64], reason[160];
  size_t nl = 0;
  while (nl < len && ident_char (p[nl], nl == 0))
    nl++;
  if (nl == 0 || nl >= len || p[nl] != '=')
    return snprintf (why, size, "'%.*s': expected NAME=VALUE, NAME letters, "
                     "digits and _ (not a digit first)", (int) len, p), 0;
  if (nl > LAC_MESH_NUMBER_NAME)
    return snprintf (why, size, "'%.20s...': a name of %zu characters, at "
                     "most %d", p, nl, LAC_MESH_NUMBER_NAME), 0;
  memcpy (o->name, p, nl);
  o->name[nl] = '\0';
  if (strcmp (o->name, "level") == 0)
    return snprintf (why, size, "'%.*s': level is set by [mesh] level",
                     (int) len, p), 0;
  for (int k = 0; k < nprev; k++)
    if (strcmp (prev[k].name, o->name) == 0)
      return snprintf (why, size, "'%s' given twice", o->name), 0;
  if (len - nl - 1 >= sizeof val)
    return snprintf (why, size, "'%s': a value of %zu characters is not a "
                     "number", o->name, len - nl - 1), 0;
  snprintf (val, sizeof val, "%.*s", (int) (len - nl - 1), p + nl + 1);
  if (!lac_number_parse (val, &spec, &o->value, reason, sizeof reason))
    return snprintf (why, size, "%s = '%s': %s; a .geo number is finite and "
                     "at most %.0f in magnitude (gmsh makes a count beyond 32 "
                     "bits, or nan, into 2)", o->name, val, reason,
                     LAC_MESH_NUMBER_MAX), 0;
  return 1;
}

int
lac_mesh_numbers_split (const char *numbers, lac_mesh_number *out,
                        char *why, size_t size)
{
  int n = 0;
  for (const char *p = numbers; p && *(p += strspn (p, SEP));)
    {
      size_t len = strcspn (p, SEP);
      if (n == LAC_MESH_MAX_NUMBERS)
        return snprintf (why, size, "more than %d NAME=VALUE pairs",
                         LAC_MESH_MAX_NUMBERS), -1;
      if (!one_pair (p, len, out, n, &out[n], why, size))
        return -1;
      n++;
      p += len;
    }
  return n;
}
