/* fuzz_numbers -- libFuzzer harness: the numbers users write
 *                                                   (chapter 01, bad-input.md)
 *
 * Input: a first byte choosing what reads the rest (a NUL byte ends it):
 *   0  lac_number_parse, with the ranges of a few scene keys;
 *   1  lac_mesh_numbers_split, as [mesh] numbers;
 *   2  one --set KEY=VALUE on tests/bad/box.scene;
 *   3  lac_geo_check_text, as a .geo script.
 * Checked, besides one line of text for a failure (fuzz_check.h): a number
 * accepted is finite, within its range, and read back the same from
 * %.17g; a text strtod reads as a normal double in the decimal syntax is
 * accepted; the .geo numbers are identifiers with finite values of at
 * most 2^31 - 1; a scene read is within the bounds of its keys.
 */
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_check.h"
#include "base/lac_number.h"
#include "io/lac_mesh_geo_check.h"
#include "io/lac_mesh_opts.h"
#include "io/lac_scene.h"

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

static void
fail (const char *what, const char *input)
{
  fprintf (stderr, "fuzz_numbers: %s: '%.200s'\n", what, input);
  abort ();
}

/* Does strtod read all of s as a normal, finite double, without a range
 * error (an underflow to 0 is one)? */
static int
plain_double (const char *s)
{
  char *end;
  double x;
  if (!*s || strpbrk (s, "xXnNiIpP \t\n\v\f\r"))
    return 0;
  errno = 0;
  x = strtod (s, &end);
  return *end == '\0' && errno == 0 && isfinite (x)
         && (x == 0 || fabs (x) >= 2.3e-308);
}

static void
numbers (const char *s)
{
  static const lac_number_spec spec[] = {
    { -HUGE_VAL, HUGE_VAL, 0, 0, 0 }, { 0, 12, 0, 1, 0 },
    { 0, HUGE_VAL, 1, 0, 1e-30 }, { -1, 0.5, 3, 0, 0 } };
  char why[200], back[64];
  double x, y;
  for (size_t k = 0; k < sizeof spec / sizeof spec[0]; k++)
    {
      int ok = lac_number_parse (s, &spec[k], &x, why, sizeof why);
      if (ok && (!isfinite (x) || x < spec[k].lo || x > spec[k].hi
                 || (spec[k].integer && x != floor (x))))
        fail ("accepted out of range", s);
      if (!ok && (!*why || strchr (why, '\n')))
        fail ("refused without a one-line reason", s);
      if (ok)
        {
          snprintf (back, sizeof back, "%.17g", x);
          if (!lac_number_parse (back, &spec[k], &y, why, sizeof why)
              || y != x)
            fail ("not read back the same", s);
        }
      if (k == 0 && !ok && plain_double (s)
          && strspn (s, "+-0123456789.eE") == strlen (s))
        fail ("a plain double refused", s);
    }
}

static void
geo_numbers (const char *s)
{
  lac_mesh_number n[LAC_MESH_MAX_NUMBERS];
  char why[400];
  int k = lac_mesh_numbers_split (s, n, why, sizeof why);
  if (k < 0 && (!*why || strchr (why, '\n')))
    fail ("numbers refused without a one-line reason", s);
  for (int i = 0; i < k; i++)
    if (!isfinite (n[i].value) || fabs (n[i].value) > LAC_MESH_NUMBER_MAX
        || !n[i].name[0] || strspn (n[i].name, "_abcdefghijklmnopqrstuvwxyz"
                                    "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789")
                            != strlen (n[i].name))
      fail ("a bad .geo number accepted", s);
}

/* Every number of a scene read is within the bounds of its key. */
static void
scene_bounds (const lac_scene *sc, const char *s)
{
  double big = LAC_SCENE_NUM_MAX;
  if (!(sc->mesh.size > 0 && sc->mesh.size <= big))
    fail ("mesh size out of bounds", s);
  for (size_t k = 0; k < sc->nmaterial; k++)
    if (!(sc->material[k].E >= 1 / big && sc->material[k].E <= big
          && sc->material[k].nu > -1 && sc->material[k].nu < 0.5))
      fail ("material out of bounds", s);
  for (size_t k = 0; k < sc->nload; k++)
    for (int i = 0; i < 3; i++)
      if (!(fabs (sc->load[k].vec[i]) <= big)
          || !(fabs (sc->load[k].pressure) <= big))
        fail ("load out of bounds", s);
  for (size_t k = 0; k < sc->ndirichlet; k++)
    for (int i = 0; i < 3; i++)
      if (!(fabs (sc->dirichlet[k].value[i]) <= big))
        fail ("Dirichlet value out of bounds", s);
}

static void
one_set (const char *s)
{
  static const char box[] =
    "[scene]\nmodel = plane_strain\nelement = tri6\n[mesh]\nfile = box.geo\n"
    "[material steel]\ngroup = body\nE = 1000\nnu = 0.3\n"
    "[dirichlet left]\ngroup = left\nclamp = yes\n"
    "[load pull]\ngroup = right\ntraction = 10 0\n";
  const char *set[1] = { s };
  lac_scene *sc = NULL;
  int status = lac_scene_read_string (box, "tests/bad/fuzz.scene", 1, set,
                                      &sc);
  if ((status == LAC_SUCCESS) != (sc != NULL))
    abort ();
  fuzz_check_message (status);
  if (sc)
    scene_bounds (sc, s);
  lac_scene_free (sc);
}

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  char text[4096];
  int status;
  if (size < 1)
    return 0;
  snprintf (text, sizeof text, "%.*s", (int) (size - 1 < 4095 ? size - 1
                                                : 4095), (const char *) data
            + 1);
  switch (data[0] % 4)
    {
    case 0:
      numbers (text);
      break;
    case 1:
      geo_numbers (text);
      break;
    case 2:
      one_set (text);
      break;
    default:
      status = lac_geo_check_text ("fuzz.geo", (const char *) data + 1,
                                   size - 1, NULL);
      fuzz_check_message (status);
    }
  lac_error_clear ();
  return 0;
}
