/* lac_cli.c -- helpers of the command line (see lac_cli.h). */
#include "cli/lac_cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_status.h"
#include "io/lac_mesh_opts.h"

void
lac_cli_print_error (const char *msg)
{
  fputs ("lac: ", stderr);
  for (const char *p = msg; *p; p++)
    fputc (*p == '\n' || *p == '\r' ? ' ' : *p, stderr);
  fputc ('\n', stderr);
}

int
lac_cli_flush_stdout (void)
{
  errno = 0;
  if (fflush (stdout) == 0 && !ferror (stdout))
    return 0;
  fprintf (stderr, "lac: cannot write to stdout: %s\n",
           strerror (errno ? errno : EIO));
  return LAC_CLI_FAILURE;
}

void
lac_cli_print_failure (const char *place, int status)
{
  const char *m = lac_error_message ();
  char *msg = NULL;
  size_t n;
  if (!*m)
    m = lac_strerror (status);
  if (place && !lac_error_placed ()
      && (msg = malloc (n = strlen (place) + strlen (m) + 3)) != NULL)
    snprintf (msg, n, "%s: %s", place, m);
  lac_cli_print_error (msg ? msg : m);
  free (msg);
}

int
lac_cli_usage_error (const char *cmd, const char *what, const char *arg)
{
  if (cmd)
    fprintf (stderr, "lac: %s: %s%s%s (try lac %s --help)\n", cmd, what,
             arg ? " " : "", arg ? arg : "", cmd);
  else
    fprintf (stderr, "lac: %s%s%s (try lac --help)\n", what, arg ? " " : "",
             arg ? arg : "");
  return LAC_CLI_USAGE;
}

const char *
lac_cli_option_value (int argc, char **argv, int *k, const char *name,
                      int *missing)
{
  size_t n = strlen (name);
  if (strncmp (argv[*k], name, n) != 0)
    return NULL;
  if (argv[*k][n] == '=')
    return argv[*k] + n + 1;
  if (argv[*k][n] != '\0')
    return NULL;
  if (*k + 1 >= argc)
    {
      *missing = 1;
      return NULL;
    }
  return argv[++*k];
}

int
lac_cli_bytes (const char *s, double min, double max, double *bytes,
               char *why, size_t size)
{
  static const char suffix[] = "kMGT";
  static const lac_number_spec positive = { 0, HUGE_VAL, 1, 0, 0 };
  char num[64];
  size_t n = strlen (s);
  const char *p = n ? strchr (suffix, s[n - 1]) : NULL;
  double scale = 1;
  if (p && *p)
    {
      n--;
      for (const char *q = suffix; q <= p; q++)
        scale *= 1000;
    }
  if (n >= sizeof num)
    return snprintf (why, size, "not a size"), 0;
  snprintf (num, sizeof num, "%.*s", (int) n, s);
  if (!lac_number_parse (num, &positive, bytes, why, size))
    return 0;
  *bytes *= scale;
  if (!isfinite (*bytes))
    return snprintf (why, size, "beyond the range of a double"), 0;
  if (*bytes < min)
    return snprintf (why, size, "%.3g bytes, below the smallest allowed "
                     "size %.3g bytes", *bytes, min), 0;
  if (*bytes > max)
    return snprintf (why, size, "%.3g bytes, above the largest allowed "
                     "size %.3g bytes", *bytes, max), 0;
  return 1;
}

int
lac_cli_max_memory (const char *cmd, const char *s, double *bytes)
{
  char why[200], what[500];
  if (lac_cli_bytes (s, LAC_MESH_RUN_BYTES_MIN, LAC_MESH_MEMORY_MAX, bytes,
                     why, sizeof why))
    return 1;
  snprintf (what, sizeof what, "--max-memory '%.64s': %s; expected a size "
            "such as 8G, 500M or 2e9, at least 100M (what a run of lac "
            "needs before any mesh) and at most 1000000T (more than any "
            "address space)", s, why);
  lac_cli_usage_error (cmd, what, NULL);
  return 0;
}

int
lac_cli_number (const char *cmd, const char *option, const char *s,
                const lac_number_spec *spec, double *x)
{
  char what[512], why[200];
  if (lac_number_parse (s, spec, x, why, sizeof why))
    return 1;
  snprintf (what, sizeof what, "%s '%.200s': %s", option, s, why);
  lac_cli_usage_error (cmd, what, NULL);
  return 0;
}
