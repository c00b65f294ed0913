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
