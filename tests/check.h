/* check.h -- tiny assertion helpers for the unit tests (gsl_test-like).
 *
 * Each check prints a line only on failure (or always with
 * LAC_TEST_VERBOSE=1); a test ends with `return check_summary ();`, which
 * returns non-zero if any check failed.
 */
#ifndef LAC_CHECK_H
#define LAC_CHECK_H

#include <stddef.h>

void check_rel (double got, double want, double reltol, const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));
void check_abs (double got, double want, double abstol, const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));
void check_int (long got, long want, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));
void check_true (int cond, const char *fmt, ...)
  __attribute__ ((format (printf, 2, 3)));
/* Compare statuses; on mismatch also print lac_error_message(). */
void check_status (int got, int want, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));
/* The stored error message contains `needle`. */
void check_message (const char *needle, const char *fmt, ...)
  __attribute__ ((format (printf, 2, 3)));
int check_summary (void);

/* 1 when the environment asks for the answer table of exercise `name`
 * (LAC_DOC_TABLE=name, e.g. "ex4"): the test then prints the table as the
 * book shows it, which tests/doc-snapshots.sh compares with the book. */
int check_doc_table (const char *name);

/* ---- whole runs (run/lac_run.h), for the tests of the exercises ---- */
#include "io/lac_scene.h"
#include "run/lac_run.h"

/* Run the scene file `scene` with the `nset` overrides `set`, writing no
 * file; NULL (and a failed check naming the scene) on error.  *sc
 * receives the scene, which the run borrows: free both by
 * check_run_done. */
lac_run *check_run_scene (const char *scene, int nset, const char **set,
                          lac_scene **sc);
/* The summary's value of `key` as a number (NAN if it has none). */
double check_run_value (const lac_run *r, const char *key);
void check_run_done (lac_run *r, lac_scene *sc);

#endif
