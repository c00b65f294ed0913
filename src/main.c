/* main.c -- the lac command line (placeholder until the scene runner lands). */
#include <stdio.h>
#include <string.h>
#include "lac_status.h"

int
main (int argc, char **argv)
{
  if (argc > 1 && strcmp (argv[1], "--help") == 0)
    {
      printf ("usage: lac run SCENE [options]\n");
      return 0;
    }
  fprintf (stderr, "lac: no command (try lac --help)\n");
  return 2;
}
