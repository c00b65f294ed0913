/* lac_cli.c -- helpers of the command line (see lac_cli.h). */
#include "cli/lac_cli.h"

#include <stdio.h>
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
