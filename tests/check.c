/* check.c -- see check.h */
#include "check.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_status.h"

static int nfail, npass;

static void
report (int ok, const char *fmt, va_list ap, const char *fmt2, ...)
{
  va_list ap2;
  if (ok)
    npass++;
  else
    nfail++;
  if (ok && !getenv ("LAC_TEST_VERBOSE"))
    return;
  printf ("%s: ", ok ? "PASS" : "FAIL");
  vprintf (fmt, ap);
  va_start (ap2, fmt2);
  vprintf (fmt2, ap2);
  va_end (ap2);
  printf ("\n");
}

void
check_rel (double got, double want, double reltol, const char *fmt, ...)
{
  va_list ap;
  double err = want != 0 ? fabs (got - want) / fabs (want) : fabs (got);
  int ok = isfinite (got) && err <= reltol;
  va_start (ap, fmt);
  report (ok, fmt, ap, " (got %.17g, want %.17g, rel err %.3g > %.3g)",
          got, want, err, reltol);
  va_end (ap);
}

void
check_abs (double got, double want, double abstol, const char *fmt, ...)
{
  va_list ap;
  double err = fabs (got - want);
  int ok = isfinite (got) && err <= abstol;
  va_start (ap, fmt);
  report (ok, fmt, ap, " (got %.17g, want %.17g, abs err %.3g > %.3g)",
          got, want, err, abstol);
  va_end (ap);
}

void
check_int (long got, long want, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  report (got == want, fmt, ap, " (got %ld, want %ld)", got, want);
  va_end (ap);
}

void
check_true (int cond, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  report (cond, fmt, ap, "%s", "");
  va_end (ap);
}

void
check_status (int got, int want, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  report (got == want, fmt, ap, " (status %d, want %d; message: %s)", got,
          want, lac_error_message ());
  va_end (ap);
}

void
check_message (const char *needle, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  report (strstr (lac_error_message (), needle) != NULL, fmt, ap,
          " (message \"%s\" lacks \"%s\")", lac_error_message (), needle);
  va_end (ap);
}

int
check_summary (void)
{
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%d passed, %d failed\n", npass, nfail);
  return nfail != 0;
}

int
check_doc_table (const char *name)
{
  const char *t = getenv ("LAC_DOC_TABLE");
  return t && strcmp (t, name) == 0;
}

/* ---- whole runs --------------------------------------------------------- */

lac_run *
check_run_scene (const char *scene, int nset, const char **set,
                 lac_scene **sc)
{
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  lac_run *r = NULL;
  *sc = NULL;
  int st = lac_scene_read (scene, nset, set, sc);
  if (!st && !(r = lac_run_alloc (*sc, &o)))
    st = LAC_ENOMEM;
  if (!st)
    st = lac_run_all (r);
  check_status (st, LAC_SUCCESS, "%s %s", scene, nset ? set[0] : "");
  if (st)
    {
      check_run_done (r, *sc);
      *sc = NULL;
      return NULL;
    }
  return r;
}

double
check_run_value (const lac_run *r, const char *key)
{
  const char *v = lac_run_summary_get (r, key);
  return v ? atof (v) : NAN;
}

void
check_run_done (lac_run *r, lac_scene *sc)
{
  lac_run_free (r);
  lac_scene_free (sc);
}
