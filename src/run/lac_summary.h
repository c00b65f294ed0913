/* lac_summary.h -- the summary of a run: "name = value" lines
 *
 * The summary is what a run prints on stdout and writes to summary.txt:
 * one line per quantity, in fixed formats, made to be compared (no paths,
 * no solver name, no timings unless asked), so that the same scene gives
 * the same summary with every solver up to rounding.
 *
 * Ownership: the lines are owned by the summary; lac_summary_clear frees
 * them (the struct itself is the caller's, zero-initialised).
 */
#ifndef LAC_SUMMARY_H
#define LAC_SUMMARY_H

#include <stddef.h>

typedef struct lac_summary
{
  size_t n, cap;
  char **key, **val;       /* owned, n lines                              */
} lac_summary;

/* Append "key = value" (value from a printf format). */
int lac_summary_add (lac_summary *s, const char *key, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));
/* The value of `key`, NULL if absent. */
const char *lac_summary_get (const lac_summary *s, const char *key);
void lac_summary_clear (lac_summary *s);

#endif /* LAC_SUMMARY_H */
