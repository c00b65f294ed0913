/* t706: what a run checks of its contact before it answers: an
 *       interference fit against the chords of the meshes, and the small
 *       sliding of the pairing         [LAC (16)-(18), §4.6; chapter 08]
 *
 * Run through run/lac_run.h, no files written.
 *   1. Interference (run/lac_run_interference.h), the shrink fit of
 *      chapter 08 with quad4 cells (tests/bad/fit-chords.scene): at level
 *      2 the chords leave 0.31 delta, refused (LAC_EINVAL, the key and
 *      what to do in the message: it was solved, lambda a third off);
 *      with interference_tolerance = 0.5 it runs; in large deformation it
 *      is refused as well; at level 3 (0.078 delta) it runs, with
 *      interference_gap in the summary and a warning in the line of the
 *      assemble stage; quad8 cells at level 0 follow the circles (below
 *      0.01: no warning, lambda_min that of chapter 08); flat interfaces
 *      (tests/meshes/stacked2d-rotated.scene with an interference on each
 *      pair) leave nothing but rounding.
 *   2. Small sliding (run/lac_run_sliding.h): two cylinders pressed and
 *      pushed sideways by 30 N/mm (tests/bad/cylinders-sliding.scene) are
 *      refused (LAC_EINVAL, it was solved with a normal force 44 % high);
 *      pushed by 3 N/mm they run; sliding_tolerance = 5 lets the 30 N/mm
 *      through.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "run/lac_run.h"

#define FIT "tests/bad/fit-chords.scene"
#define CYL "tests/bad/cylinders-sliding.scene"

/* Run `scene` with set[0..n) up to stage `upto` (LAC_NSTAGES: all): the
 * status, the run in *r. */
static int
run (const char *scene, int n, const char **set, int upto, lac_scene **sc,
     lac_run **r)
{
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  int st = lac_scene_read (scene, (size_t) n, set, sc);
  *r = NULL;
  if (!st && !(*r = lac_run_alloc (*sc, &o)))
    st = LAC_ENOMEM;
  while (!st && (*r)->stage < upto
         && (st = lac_run_iterate (*r)) == LAC_CONTINUE)
    st = LAC_SUCCESS;
  return st;
}

static void
done (lac_run *r, lac_scene *sc)
{
  lac_run_free (r);
  lac_scene_free (sc);
}

/* The summary's number `key` (NAN: none). */
static double
value (const lac_run *r, const char *key)
{
  return r ? check_run_value (r, key) : NAN;
}

/* `scene` with set[0..n) is refused (LAC_EINVAL) with `words` (two). */
static void
refused (const char *scene, int n, const char **set, const char *w1,
         const char *w2, const char *what)
{
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  check_status (run (scene, n, set, LAC_NSTAGES, &sc, &r), LAC_EINVAL,
                "%s: refused", what);
  check_message (w1, "%s: the message", what);
  check_message (w2, "%s: the message", what);
  done (r, sc);
}

static void
interference (void)
{
  const char *tol[] = { "contact.fit.interference_tolerance=0.5" };
  const char *ld[] = { "scene.large_deformation=yes" };
  const char *l3[] = { "level=3" };
  const char *q8[] = { "element=quad8", "level=0" };
  const char *rot[] = { "contact.lower.interference=0.02",
                        "contact.upper.interference=0.01" };
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  refused (FIT, 0, NULL, "interference_tolerance", "quadratic cells",
           "chords at level 2");
  refused (FIT, 1, ld, "interference_tolerance", "quadratic cells",
           "chords at level 2, large deformation");
  check_status (run (FIT, 1, tol, LAC_NSTAGES, &sc, &r), LAC_SUCCESS,
                "chords at level 2, tolerance 0.5");
  check_rel (value (r, "interference_gap"), 0.312, 1e-2, "chords at level "
             "2: 0.31 delta");
  done (r, sc);
  check_status (run (FIT, 1, l3, LAC_STAGE_SOLVE, &sc, &r), LAC_SUCCESS,
                "chords at level 3");
  check_true (r && strstr (r->progress, "warning: [contact fit]"),
              "chords at level 3: a warning (%s)", r ? r->progress : "");
  check_status (r ? lac_run_all (r) : LAC_EINVAL, LAC_SUCCESS,
                "chords at level 3: the rest of the run");
  double g = value (r, "interference_gap");
  check_true (g > 0.01 && g < 0.1, "chords at level 3: %g delta", g);
  done (r, sc);
  check_status (run (FIT, 2, q8, LAC_STAGE_SOLVE, &sc, &r), LAC_SUCCESS,
                "quad8");
  check_true (r && !strstr (r->progress, "warning"), "quad8: no warning");
  check_status (r ? lac_run_all (r) : LAC_EINVAL, LAC_SUCCESS, "quad8 run");
  check_true (value (r, "interference_gap") < 0.01, "quad8: below 0.01");
  check_rel (value (r, "lambda_min"), -0.2633194270, 1e-9, "quad8: "
             "chapter 08's lambda_min");
  done (r, sc);
  check_status (run ("tests/meshes/stacked2d-rotated.scene", 2, rot,
                     LAC_NSTAGES, &sc, &r), LAC_SUCCESS, "flat fits");
  check_abs (value (r, "interference_gap"), 0, 1e-12, "flat fits: exact");
  done (r, sc);
}

static void
sliding (void)
{
  const char *small[] = { "load.side.total_force=3 0" };
  const char *tol[] = { "contact.c.sliding_tolerance=5" };
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  refused (CYL, 0, NULL, "sliding_tolerance", "large_deformation = yes",
           "cylinders pushed by 30");
  check_status (run (CYL, 1, small, LAC_NSTAGES, &sc, &r), LAC_SUCCESS,
                "cylinders pushed by 3");
  done (r, sc);
  check_status (run (CYL, 1, tol, LAC_NSTAGES, &sc, &r), LAC_SUCCESS,
                "cylinders pushed by 30, tolerance 5");
  done (r, sc);
}

int
main (void)
{
  lac_init ();
  interference ();
  sliding ();
  lac_finalize ();
  return check_summary ();
}
