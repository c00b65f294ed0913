/* t003: the one checked parser of the numbers users write (lac_number.h):
 *       decimal syntax only, finite doubles, ranges, and a reason naming
 *       the limit each refused text broke; the .geo numbers built on it
 *       (lac_mesh_numbers_split). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "base/lac_number.h"
#include "io/lac_mesh_opts.h"

/* s is refused by spec with a reason containing `needle`. */
static void
refused (const char *s, const lac_number_spec *spec, const char *needle)
{
  char why[200];
  double x;
  int ok = lac_number_parse (s, spec, &x, why, sizeof why);
  check_true (!ok && strstr (why, needle) != NULL, "'%s' refused with '%s':"
              " got %d, '%s'", s, needle, ok, why);
}

static void
accepted (const char *s, const lac_number_spec *spec, double want)
{
  char why[200];
  double x = NAN;
  int ok = lac_number_parse (s, spec, &x, why, sizeof why);
  check_true (ok && x == want, "'%s' = %g: got %d, %g, '%s'", s, want, ok, x,
              why);
}

static void
test_syntax (void)
{
  accepted ("12", NULL, 12);
  accepted ("-0.25", NULL, -0.25);
  accepted ("+2.1e5", NULL, 2.1e5);
  accepted (".5", NULL, 0.5);
  accepted ("5.", NULL, 5);
  accepted ("1e308", NULL, 1e308);
  accepted ("0e-400", NULL, 0);            /* an exact zero stays zero */
  accepted ("2.2250738585072014e-308", NULL, 2.2250738585072014e-308);
  refused ("", NULL, "empty");
  refused ("nan", NULL, "not a finite number");
  refused ("-Inf", NULL, "not a finite number");
  refused ("infinity", NULL, "not a finite number");
  refused ("NaN(123)", NULL, "not a finite number");
  refused ("0x10", NULL, "not a decimal number");
  refused (" 12", NULL, "not a decimal number");
  refused ("12 ", NULL, "not a decimal number");
  refused ("1e", NULL, "not a decimal number");
  refused ("1.2.3", NULL, "not a decimal number");
  refused ("e5", NULL, "not a decimal number");
  refused ("-", NULL, "not a decimal number");
  refused ("1e400", NULL, "beyond the range of a double");
  refused ("-1e400", NULL, "beyond the range of a double");
  refused ("4.9e-324", NULL, "too small for a double");
  refused ("1e-400", NULL, "too small for a double");
}

static void
test_ranges (void)
{
  static const lac_number_spec level = { 0, 12, 0, 1, 0 };
  static const lac_number_spec positive = { 0, HUGE_VAL, 1, 0, 1e-30 };
  static const lac_number_spec nu = { -1, 0.5, 3, 0, 0 };
  static const lac_number_spec geo = { -2147483647.0, 2147483647.0, 0, 0,
                                       0 };
  accepted ("12", &level, 12);
  accepted ("1.2e1", &level, 12);
  refused ("13", &level, "above the largest allowed value 12");
  refused ("-1", &level, "below the smallest allowed value 0");
  refused ("1.5", &level, "not an integer");
  refused ("3e9", &level, "above the largest allowed value 12");
  refused ("0", &positive, "not above 0");
  refused ("1e-31", &positive, "of magnitude below 1e-30");
  refused ("0.5", &nu, "not below 0.5");
  refused ("-1", &nu, "not above -1");
  accepted ("2147483647", &geo, 2147483647.0);
  refused ("3e9", &geo, "above the largest allowed value 2147483647");
  refused ("-2147483648", &geo, "below the smallest allowed value "
           "-2147483647");
}

static void
test_geo_numbers (void)
{
  lac_mesh_number n[LAC_MESH_MAX_NUMBERS];
  char why[400], many[400] = "";
  int k = lac_mesh_numbers_split ("n=28, m=-3.5 ,r=1e-3", n, why, sizeof why);
  check_int (k, 3, "three pairs: %s", why);
  check_true (k == 3 && !strcmp (n[0].name, "n") && n[0].value == 28
              && !strcmp (n[1].name, "m") && n[1].value == -3.5
              && n[2].value == 1e-3, "the pairs read back");
  check_int (lac_mesh_numbers_split ("n=1\nm=2\r\v", n, why, sizeof why), 2,
             "pairs separated by any white space (found by fuzz_numbers)");
  check_int (lac_mesh_numbers_split (NULL, n, why, sizeof why), 0, "none");
  check_int (lac_mesh_numbers_split (" ,, ", n, why, sizeof why), 0,
             "blanks");
  static const char *const bad[][2] = {
    { "n=nan", "not a finite number" }, { "n=1e400", "beyond the range" },
    { "n=3e9", "above the largest allowed value 2147483647" },
    { "n=x", "not a decimal number" }, { "n=", "empty" },
    { "n", "expected NAME=VALUE" }, { "2n=3", "expected NAME=VALUE" },
    { "n=1 n=2", "'n' given twice" }, { "level=3", "[mesh] level" },
    { "a234567890123456789012345678901234567890123456789012345678901234=1",
      "a name of 64 characters" } };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
    {
      k = lac_mesh_numbers_split (bad[i][0], n, why, sizeof why);
      check_true (k == -1 && strstr (why, bad[i][1]), "'%s' refused with "
                  "'%s': %d, '%s'", bad[i][0], bad[i][1], k, why);
    }
  for (int i = 0; i <= LAC_MESH_MAX_NUMBERS; i++)
    snprintf (many + strlen (many), sizeof many - strlen (many), "v%d=%d ",
              i, i);
  k = lac_mesh_numbers_split (many, n, why, sizeof why);
  check_true (k == -1 && strstr (why, "more than 16"), "17 pairs: %d, '%s'",
              k, why);
}

int
main (void)
{
  test_syntax ();
  test_ranges ();
  test_geo_numbers ();
  return check_summary ();
}
