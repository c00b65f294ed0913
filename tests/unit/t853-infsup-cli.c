/* t853: the `lac infsup` subcommand (lac_cli_infsup)          [LAC (10)]
 *
 * Called in-process with stdout and stderr redirected to temporary files:
 *   1. taylor2d.scene --set level=1: exit 0, "beta_h = 1.0177" (the
 *      chapter's table 1), "multipliers = 2", the norm and path lines; the
 *      same beta with --sparse (1e-6);
 *   2. narrow2d.scene --vector: one "mu" line per multiplier, and the
 *      least stable multiplier is the cut macro-element's;
 *   3. --norm energy on taylor2d (the upper block is held by contact
 *      alone, K is singular): exit 1 with a message naming the H1 norm;
 *   4. a scene without [contact]: exit 1, "no [contact] section";
 *   5. bad command lines: exit 2 (--norm foo, no scene, unknown option);
 *      --help: exit 0 and the help text.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "cli/lac_cli_infsup.h"
#include "base/lac_status.h"

static char out[1 << 16], err[1 << 14];

static void
slurp (FILE *f, char *buf, size_t size)
{
  size_t n;
  rewind (f);
  n = fread (buf, 1, size - 1, f);
  buf[n] = '\0';
  fclose (f);
}

/* Run lac_cli_infsup on a NULL-terminated argument list ("infsup" first). */
static int
run (const char *const *args)
{
  char *argv[32];
  int argc = 0, so, se, ret;
  FILE *fo = tmpfile (), *fe = tmpfile ();
  while (args[argc] && argc < 31)
    argv[argc] = (char *) args[argc], argc++;
  argv[argc] = NULL;
  fflush (stdout);
  fflush (stderr);
  so = dup (1);
  se = dup (2);
  dup2 (fileno (fo), 1);
  dup2 (fileno (fe), 2);
  ret = lac_cli_infsup (argc, argv);
  fflush (stdout);
  fflush (stderr);
  dup2 (so, 1);
  dup2 (se, 2);
  close (so);
  close (se);
  slurp (fo, out, sizeof out);
  slurp (fe, err, sizeof err);
  return ret;
}

/* The value of "key = value" in out (NAN if absent). */
static double
value (const char *key)
{
  char pat[64];
  snprintf (pat, sizeof pat, "\n%s = ", key);
  const char *p = strncmp (out, pat + 1, strlen (pat + 1)) == 0 ? out - 1
                  : strstr (out, pat);
  return p ? atof (p + strlen (pat)) : NAN;
}

int
main (void)
{
  lac_init ();
  /* 1. */
  const char *a1[] = { "infsup", "chapters/08-experiments/taylor2d.scene",
                       "--set", "level=1", "--quiet", NULL };
  check_int (run (a1), 0, "taylor2d: exit status (stderr: %s)", err);
  double beta = value ("beta_h");
  check_abs (beta, 1.01769, 1e-4, "taylor2d level 1: beta_h");
  check_abs (value ("multipliers"), 2, 0, "taylor2d level 1: multipliers");
  check_true (strstr (out, "norm = h1") != NULL, "norm line");
  check_true (strstr (out, "path = dense") != NULL, "path line");
  check_true (err[0] == '\0', "--quiet: nothing on stderr (%s)", err);
  const char *a1s[] = { "infsup", "chapters/08-experiments/taylor2d.scene",
                        "--set=level=1", "--quiet", "--sparse", NULL };
  check_int (run (a1s), 0, "taylor2d --sparse: exit status");
  check_rel (value ("beta_h"), beta, 1e-6, "--sparse: same beta_h");
  check_true (strstr (out, "path = sparse") != NULL, "path = sparse");
  /* 2. */
  const char *a2[] = { "infsup", "chapters/11-infsup/narrow2d.scene",
                       "--vector", "--quiet", NULL };
  check_int (run (a2), 0, "narrow2d: exit status (stderr: %s)", err);
  size_t nmu = 0;
  for (const char *p = out; (p = strstr (p, "\nmu ")); p++)
    nmu++;
  check_abs ((double) nmu, value ("multipliers"), 0, "--vector: one line per "
             "multiplier");
  check_true (strstr (out, "least_stable = 1 (macro-element 1)") != NULL,
              "narrow2d: the cut macro-element is the least stable");
  /* 3. */
  const char *a3[] = { "infsup", "chapters/08-experiments/taylor2d.scene",
                       "--norm", "energy", "--quiet", NULL };
  check_int (run (a3), 1, "--norm energy on a floating body: exit 1");
  check_true (strstr (err, "lac: ") == err && strstr (err, "H1 norm")
              && strstr (err, "not positive definite"), "energy: message %s",
              err);
  check_true (strstr (out, "beta_h") == NULL, "energy: no beta_h printed");
  /* 4. */
  const char *a4[] = { "infsup", "chapters/01-problem/sphere-axi.scene",
                       NULL };
  check_int (run (a4), 1, "scene without [contact]: exit 1");
  check_true (strstr (err, "no [contact] section") != NULL
              && strchr (err, '\n') == err + strlen (err) - 1,
              "no contact: one clear line: %s", err);
  /* 5. */
  const char *a5[] = { "infsup", "x.scene", "--norm", "foo", NULL };
  check_int (run (a5), 2, "--norm foo: exit 2");
  check_true (strstr (err, "expected h1 or energy") != NULL, "%s", err);
  const char *a6[] = { "infsup", "--dense", NULL };
  check_int (run (a6), 2, "no scene: exit 2");
  const char *a7[] = { "infsup", "x.scene", "--frobnicate", NULL };
  check_int (run (a7), 2, "unknown option: exit 2");
  const char *a8[] = { "infsup", "--help", NULL };
  check_int (run (a8), 0, "--help: exit 0");
  check_true (strstr (out, "usage: lac infsup SCENE") == out, "help text");
  lac_finalize ();
  return check_summary ();
}
