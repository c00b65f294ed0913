/* skeleton.c -- chapter 08, exercise 2: a start for your own program
 *
 * Copy it with
 *   make exercise NAME=corner FROM=chapters/08-experiments/skeleton.c
 * edit exercises/corner/main.c, then
 *   make build/exercises/corner && build/exercises/corner
 * (from the repository root).  As given, it runs the 2D patch test with
 * quad4 and prints the displacement of the node nearest to a point; the
 * TODO lines are yours.
 */
#include <math.h>
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
main (void)
{
  /* The scene and its overrides, as `lac run ... --set KEY=VALUE`. */
  const char *set[1] = { "element=quad4" };     /* TODO: other elements */
  lac_scene *sc = NULL;
  check_status (lac_scene_read ("chapters/08-experiments/taylor2d.scene", 1,
                                set, &sc), "lac_scene_read");
  /* The whole pipeline of `lac run`, without output files. */
  lac_run_opts o = { NULL, 0, 1, LAC_STRATEGY_AUTO, 0, NULL, 0, 0 };
  lac_run *r = lac_run_alloc (sc, &o);
  if (!r)
    check_status (LAC_ENOMEM, "lac_run_alloc");
  check_status (lac_run_all (r), "lac_run_all");

  /* The node nearest to the point p; its displacement is
   * r->sol.u[dim * node + component]. */
  double p[2] = { 50, 100 };                    /* TODO: your point */
  const lac_mesh *m = r->mesh;
  size_t best = 0;
  double dbest = INFINITY;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double d = hypot (m->x[2 * a] - p[0], m->x[2 * a + 1] - p[1]);
      if (d < dbest)
        dbest = d, best = a;
    }
  printf ("node %zu at (%g, %g): u = (%.10e, %.10e)\n", best,
          m->x[2 * best], m->x[2 * best + 1], r->sol.u[2 * best],
          r->sol.u[2 * best + 1]);
  /* TODO: the exact displacement (c_x x, c_y y) and the difference */

  lac_run_free (r);
  lac_scene_free (sc);
  return 0;
}
