/* lac_number.c -- the numbers a user writes (see lac_number.h)
 *
 * The text is first matched against the decimal syntax of C, so that
 * strtod sees only what it reads the same everywhere (no "nan", "inf",
 * hexadecimal, leading blanks or locale); then strtod's ERANGE tells an
 * overflow (the result is +-HUGE_VAL) from an underflow (a nonzero
 * number below DBL_MIN: a subnormal with fewer significant bits, or 0).
 */
#include "base/lac_number.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const lac_number_spec lac_number_any = { -HUGE_VAL, HUGE_VAL, 0, 0, 0 };

static size_t
digits (const char *s)
{
  size_t n = 0;
  while (s[n] >= '0' && s[n] <= '9')
    n++;
  return n;
}

/* Is s a decimal number as C writes it, with nothing before or after? */
static int
decimal (const char *s)
{
  size_t i = (*s == '+' || *s == '-'), a, b = 0;
  a = digits (s + i);
  i += a;
  if (s[i] == '.')
    {
      b = digits (s + i + 1);
      i += 1 + b;
    }
  if (a + b == 0)
    return 0;
  if (s[i] == 'e' || s[i] == 'E')
    {
      size_t j = i + 1 + (s[i + 1] == '+' || s[i + 1] == '-');
      size_t e = digits (s + j);
      if (e == 0)
        return 0;
      i = j + e;
    }
  return s[i] == '\0';
}

/* Does the literal s (decimal) have a nonzero digit before its exponent? */
static int
nonzero_digits (const char *s)
{
  for (; *s && *s != 'e' && *s != 'E'; s++)
    if (*s >= '1' && *s <= '9')
      return 1;
  return 0;
}

/* A limit as a reader writes it: integers in full, others with %g. */
static void
limit (char *buf, size_t size, double v)
{
  if (v == floor (v) && fabs (v) < 1e15)
    snprintf (buf, size, "%.0f", v);
  else
    snprintf (buf, size, "%g", v);
}

/* "inf", "nan", "infinity" in any case, with a sign. */
static int
non_finite_word (const char *s)
{
  static const char *const w[] = { "inf", "infinity", "nan" };
  s += (*s == '+' || *s == '-');
  for (size_t k = 0; k < 3; k++)
    {
      size_t n = strlen (w[k]), i;
      for (i = 0; i < n && (s[i] | 0x20) == w[k][i]; i++)
        ;
      if (i == n && (s[n] == '\0' || s[n] == '('))
        return 1;
    }
  return 0;
}

/* Read s; 0 with a reason when it is not a finite double. */
static int
read_double (const char *s, double *x, char *why, size_t size)
{
  *x = NAN;
  if (!s || !*s)
    return snprintf (why, size, "empty: expected a number"), 0;
  if (non_finite_word (s))
    return snprintf (why, size, "not a finite number"), 0;
  if (!decimal (s))
    return snprintf (why, size, "not a decimal number such as 12, -0.25 "
                     "or 2.1e5"), 0;
  errno = 0;
  *x = strtod (s, NULL);
  if (errno == ERANGE && fabs (*x) > 1)
    return snprintf (why, size, "beyond the range of a double, about "
                     "%.2g", DBL_MAX), 0;
  if (fabs (*x) < DBL_MIN && nonzero_digits (s))
    return snprintf (why, size, "too small for a double: below %.2g, its "
                     "digits would be lost", DBL_MIN), 0;
  return 1;
}

int
lac_number_check (double x, const lac_number_spec *spec, char *why,
                  size_t size)
{
  const lac_number_spec *sp = spec ? spec : &lac_number_any;
  char lim[32];
  if (!isfinite (x))
    return snprintf (why, size, "not a finite number"), 0;
  if (sp->integer && x != floor (x))
    return snprintf (why, size, "not an integer"), 0;
  if ((sp->open & 1) ? !(x > sp->lo) : !(x >= sp->lo))
    {
      limit (lim, sizeof lim, sp->lo);
      return snprintf (why, size, (sp->open & 1) ? "not above %s"
                       : "below the smallest allowed value %s", lim), 0;
    }
  if ((sp->open & 2) ? !(x < sp->hi) : !(x <= sp->hi))
    {
      limit (lim, sizeof lim, sp->hi);
      return snprintf (why, size, (sp->open & 2) ? "not below %s"
                       : "above the largest allowed value %s", lim), 0;
    }
  if (sp->min_mag > 0 && x != 0 && fabs (x) < sp->min_mag)
    {
      limit (lim, sizeof lim, sp->min_mag);
      return snprintf (why, size, "of magnitude below %s", lim), 0;
    }
  return 1;
}

int
lac_number_parse (const char *s, const lac_number_spec *spec, double *x,
                  char *why, size_t size)
{
  if (size > 0)
    why[0] = '\0';
  if (!read_double (s, x, why, size))
    return 0;
  return lac_number_check (*x, spec, why, size);
}
