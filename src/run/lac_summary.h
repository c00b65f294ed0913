/* lac_summary.h -- the summary of a run: "name = value" lines
 *
 * The summary is what a run prints on stdout and writes to summary.txt:
 * one line per quantity, in fixed formats, made to be compared (no paths,
 * no solver name, no timings unless asked), so that the same scene gives
 * the same summary with every solver up to rounding.  Every real is
 * written with LAC_SUMMARY_REAL, 17 significant digits: enough for any
 * double to read back as itself, so that a sum of printed values (the
 * balance of a body: its contact forces, loads and reactions) can be
 * checked to rounding from the text alone.
 *
 * Ownership: the lines are owned by the summary; lac_summary_clear frees
 * them (the struct itself is the caller's, zero-initialised).
 */
#ifndef LAC_SUMMARY_H
#define LAC_SUMMARY_H

#include <stddef.h>

/* The printf format of a real of the summary (17 significant digits). */
#define LAC_SUMMARY_REAL "%.16e"

typedef struct lac_summary
{
  size_t n, cap;
  char **key, **val;       /* owned, n lines                              */
} lac_summary;

/* Append "key = value" (value from a printf format). */
int lac_summary_add (lac_summary *s, const char *key, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));
/* Append "key = x y" (dim 2) or "key = x y z" (dim 3), each component
 * with LAC_SUMMARY_REAL (a zero printed as +0). */
int lac_summary_add_vector (lac_summary *s, const char *key, const double *v,
                            int dim);
/* The value of `key`, NULL if absent. */
const char *lac_summary_get (const lac_summary *s, const char *key);
void lac_summary_clear (lac_summary *s);

#endif /* LAC_SUMMARY_H */
