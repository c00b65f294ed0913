/* exercise.c -- the starting point of an exercise with code
 *
 *   make exercise NAME=mywork            (a copy in exercises/mywork/main.c,
 *                                         built as build/exercises/mywork)
 *   build/exercises/mywork SCENE [KEY=VALUE ...]
 *
 * As given, it runs SCENE with the overrides KEY=VALUE (those of
 * `lac run SCENE --set KEY=VALUE`) through the whole pipeline of `lac run`,
 * without output files, and prints the summary lines.  Everything of the
 * run is then in `r` (src/run/lac_run.h): the mesh r->mesh, the
 * displacement r->sol.u, the multipliers r->sol.newton->lambda, the
 * contact matrices r->sys.contact.  The chapters' skeletons
 * (chapters/NN-name/skeleton*.c) are the same program aimed at one
 * exercise.
 */
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "exercise: %s failed: %s (%s)\n", what,
           lac_error_message (), lac_strerror (status));
  exit (1);
}

int
main (int argc, char **argv)
{
  if (argc < 2)
    {
      fprintf (stderr, "usage: %s SCENE [KEY=VALUE ...]\n", argv[0]);
      return 2;
    }
  lac_scene *sc = NULL;
  check_status (lac_scene_read (argv[1], argc - 2, (const char **) argv + 2,
                                &sc), argv[1]);
  lac_run_opts o = { NULL, 0, 1, LAC_STRATEGY_AUTO, 0, NULL, 0, 0 };
  lac_run *r = lac_run_alloc (sc, &o);
  if (!r)
    check_status (LAC_ENOMEM, "lac_run_alloc");
  check_status (lac_run_all (r), "lac_run_all");

  /* TODO: your computation on r */
  const char *keys[] = { "dofs", "multipliers", "newton_iterations",
                         "lambda_min", "lambda_max", "max_u" };
  for (size_t k = 0; k < sizeof keys / sizeof *keys; k++)
    {
      const char *v = lac_run_summary_get (r, keys[k]);
      if (v)
        printf ("%s = %s\n", keys[k], v);
    }
  lac_run_free (r);
  lac_scene_free (sc);
  return 0;
}
