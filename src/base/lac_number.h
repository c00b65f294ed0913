/* lac_number.h -- the numbers a user writes, parsed once and checked
 *
 * Every number lac takes from a user goes through lac_number_parse: the
 * values of a scene and of --set, the numbers a .geo script receives
 * ([mesh] numbers), the options of the command line.  strtod alone
 * accepts "nan", "inf", "0x1p3" and " 12", turns 1e400 into infinity and
 * 4.9e-324 into a number with one significant bit, and tells none of it
 * apart from a typo; each caller used to check a different part of that.
 * Here the text must be a decimal number as C writes it (sign, digits,
 * point, exponent; nothing before or after), finite as a double, and in
 * the range of the caller's spec; on failure the reason says which limit
 * was broken, in words: "1e400 is beyond the range of a double (1.8e308)",
 * "3000000000 is above the largest allowed value 2147483647".
 *
 * Nothing is stored in lac_error_message: the caller puts the reason in a
 * message that names the place (the scene line, the option).
 */
#ifndef LAC_NUMBER_H
#define LAC_NUMBER_H

#include <stddef.h>

typedef struct lac_number_spec
{
  double lo, hi;      /* allowed range                                  */
  int open;           /* 1: lo excluded, 2: hi excluded, 3: both        */
  int integer;        /* 1: no fraction                                 */
  double min_mag;     /* > 0: a nonzero value of smaller magnitude is
                         refused                                        */
} lac_number_spec;

/* Any finite double. */
extern const lac_number_spec lac_number_any;

/* *x = the number written in s, within spec (NULL: lac_number_any).
 * Returns 1, or 0 with the reason in why (size bytes, one line, naming
 * the text and the limit it broke); *x is then the value read, or NAN
 * when s is not a number at all. */
int lac_number_parse (const char *s, const lac_number_spec *spec, double *x,
                      char *why, size_t size);

/* The range part alone: is the double x within spec?  1, or 0 with the
 * limit it broke in why. */
int lac_number_check (double x, const lac_number_spec *spec, char *why,
                      size_t size);

#endif /* LAC_NUMBER_H */
