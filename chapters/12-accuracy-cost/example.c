/* LAC chapter 12 -- What accuracy costs: errors, rates and times
 *                                                   [LAC §5.3, Tables 5-6]
 *
 * Build:        make  (builds it as build/chapters/12-accuracy-cost)
 * Sample runs:  build/chapters/12-accuracy-cost         (from the
 *                                 repository root: it reads the scenes of
 *                                 chapter 09)
 *               build/chapters/12-accuracy-cost --time  (adds the times)
 *               build/chapters/12-accuracy-cost --time DIR  (scenes in DIR)
 * Description:  Part 1: the manufactured problem in 2D
 *               (manufactured2d.scene) with quad4 and quad8 at levels 2
 *               and 3: the relative L2 error of u, the L2 error of lambda
 *               on Gamma_C, and the observed rates between the two levels,
 *               in h (log err / log h) and in dofs (log err / log dofs,
 *               -rate_h / 2 in 2D).  Part 2: quad8 at level 1 (450
 *               dofs: small enough for the dense strategy, whose time
 *               grows like dofs^3) with three contact strategies of
 *               chapter 07: the same
 *               errors to the printed digits, whatever the strategy.
 *               Without --time the output is deterministic; with --time
 *               each row also gets the time of its stages, mesh to post
 *               (r->time, seconds on a monotonic clock), which depends on
 *               the machine and its load.
 * Read first:   chapter 09 (the manufactured problem, "Convergence rates").
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_status.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "solve/lac_strategy.h"

// @sect One run: its errors and its time
/* Every row of this program is one run of the manufactured problem of
 * chapter 09 through the whole pipeline of `lac run`, with a chosen
 * element, level and contact strategy.  A library call that fails stops
 * the program with the one-line message the library stored. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex10: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* What one run gives: its size, its errors and its time. */
typedef struct result
{
  double h, dofs, err_u, err_lam, seconds;
} result;

/* A value of the run's summary (key = value) as a number (NaN if
 * absent). */
static double
value (const lac_run *r, const char *key)
{
  const char *v = lac_run_summary_get (r, key);
  return v ? atof (v) : NAN;
}

/* manufactured2d.scene with ELEMENT at LEVEL and STRATEGY, no files.  The
 * strategy is an option of the run (lac_run_opts, as `--strategy` of
 * `lac run`), not a key of the scene.  The run keeps the time of each of
 * its stages in r->time (a monotonic clock): their sum from the mesh to
 * the post-processing is the time of the run without its output. */
static result
run (const char *dir, const char *element, int level, int strategy)
{
  char path[512], s[2][64];
  const char *set[2] = { s[0], s[1] };
  lac_scene *sc = NULL;
  lac_run_opts o = { NULL, 0, 1, strategy, 0, NULL, 0, 0 };
  lac_run *r = NULL;
  snprintf (path, sizeof path, "%s/manufactured2d.scene", dir);
  snprintf (s[0], sizeof s[0], "element=%s", element);
  snprintf (s[1], sizeof s[1], "level=%d", level);
  check_status (lac_scene_read (path, 2, set, &sc), path);
  if (!(r = lac_run_alloc (sc, &o)))
    check_status (LAC_ENOMEM, "lac_run_alloc");
  check_status (lac_run_all (r), path);
  result x = { value (r, "h"), value (r, "dofs"), value (r, "rel_l2_err_u"),
               value (r, "l2_err_lambda"), 0 };
  for (int st = LAC_STAGE_MESH; st < LAC_STAGE_OUTPUT; st++)
    x.seconds += r->time[st];
  lac_run_free (r);
  lac_scene_free (sc);
  return x;
}

/* One row: h, dofs, the two errors and, with --time, the seconds (the
 * only number that depends on the machine). */
static void
print_row (const char *label, int level, const result *x, int timed)
{
  printf ("%-9s %5d  %.4e %6.0f  %.4e  %.4e", label, level, x->h, x->dofs,
          x->err_u, x->err_lam);
  if (timed)
    printf ("  %8.3f", x->seconds);
  printf ("\n");
}

// @sect Part 1: two levels, the observed rates
/* From level 2 to level 3 the cells halve: a rate is the slope of
 * log(error) against log(h) between the two, or against log(dofs) (in 2D
 * dofs grow like $h^{-2}$, so a rate in dofs is minus half the rate in
 * h).  Chapter 09 fits the rates over five levels (rates.sh); two levels
 * are enough to see them here. */
static void
rates (const char *dir, int timed)
{
  const char *el[2] = { "quad4", "quad8" };
  printf ("Part 1: manufactured2d, levels 2 and 3\n\n");
  printf ("element   level  h           dofs  rel_err_u   err_lambda%s\n",
          timed ? "  time (s)" : "");
  result x[2][2];
  for (int e = 0; e < 2; e++)
    for (int l = 0; l < 2; l++)
      {
        x[e][l] = run (dir, el[e], 2 + l, LAC_STRATEGY_AUTO);
        print_row (el[e], 2 + l, &x[e][l], timed);
      }
  // @sect The rates from the two rows of each element
  printf ("\nobserved rates, level 2 -> 3   in h: u  lambda    "
          "in dofs: u  lambda\n");
  for (int e = 0; e < 2; e++)
    {
      double lh = log (x[e][1].h / x[e][0].h);
      double ld = log (x[e][1].dofs / x[e][0].dofs);
      double lu = log (x[e][1].err_u / x[e][0].err_u);
      double ll = log (x[e][1].err_lam / x[e][0].err_lam);
      printf ("%-9s                        %5.2f  %5.2f           "
              "%5.2f  %5.2f\n", el[e], lu / lh, ll / lh, lu / ld, ll / ld);
    }
}

// @sect Part 2: the strategy changes the time, not the answer
/* quad8 at level 1 (450 dofs, so that dense is still affordable) with
 * three strategies of chapter 07 (section 4): dense (an LU of the whole
 * saddle matrix), schur (one Cholesky factor of K) and augmented (a
 * factor of K + C_A W C_A^T per active set).  The errors agree to every
 * printed digit; only the times, with --time, differ. */
static void
strategies (const char *dir, int timed)
{
  const int kind[3] = { LAC_STRATEGY_DENSE, LAC_STRATEGY_SCHUR,
                        LAC_STRATEGY_AUGMENTED };
  printf ("\nPart 2: quad8 level 1, three strategies\n\n");
  printf ("strategy  level  h           dofs  rel_err_u   err_lambda%s\n",
          timed ? "  time (s)" : "");
  for (int k = 0; k < 3; k++)
    {
      result x = run (dir, "quad8", 1, kind[k]);
      print_row (lac_strategy_name ((lac_strategy_kind) kind[k]), 1, &x,
                 timed);
    }
}

// @sect The main program
/* --time adds the times; another argument is the folder of the scenes
 * (chapter 09's by default). */
int
main (int argc, char **argv)
{
  const char *dir = "chapters/09-spheres-rates";
  int timed = 0;
  for (int k = 1; k < argc; k++)
    if (!strcmp (argv[k], "--time"))
      timed = 1;
    else
      dir = argv[k];
  rates (dir, timed);
  strategies (dir, timed);
  return 0;
}
