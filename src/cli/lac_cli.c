/* lac_cli.c -- helpers of the command line (see lac_cli.h). */
#include "cli/lac_cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void
lac_cli_print_error (const char *msg)
{
  fputs ("lac: ", stderr);
  for (const char *p = msg; *p; p++)
    fputc (*p == '\n' || *p == '\r' ? ' ' : *p, stderr);
  fputc ('\n', stderr);
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

double
lac_cli_bytes (const char *s)
{
  static const char suffix[] = "kMGT";
  char *end;
  double v = strtod (s, &end);
  const char *p = *end ? strchr (suffix, *end) : NULL;
  if (end == s || !isfinite (v) || v <= 0)
    return -1;
  if (*end && (!p || end[1] != '\0'))
    return -1;
  for (const char *q = suffix; p && q <= p; q++)
    v *= 1000;
  return v;
}
