/* LAC chapter 09 -- Self-included spheres and convergence rates
 *                                          [LAC §5.2-§5.3, Tables 3-6]
 *
 * Build:        make build/chapters/09-spheres-rates
 * Sample runs:  build/chapters/09-spheres-rates        (from the repository
 *                                                       root: it reads the
 *                                                       chapter's scenes)
 *               build/chapters/09-spheres-rates DIR    (the scenes in DIR)
 * Description:  Part 1: the self-included spheres in the axisymmetric
 *               model (spheres-axi.scene): the exact lambda = sigma_RR(30)
 *               of the Lame solution by hand and by lac_exact, then the
 *               multipliers of tri6 and quad8 at levels 0-2 and the ratio
 *               by which their largest relative error falls from one level
 *               to the next.  Part 2: the 2D manufactured solution
 *               (manufactured2d.scene), quad4 and quad8 at levels 1-3: the
 *               L2 errors of u and lambda, and the part e_P0 of the latter
 *               that no multiplier constant per macro-element can remove.
 *               Each run is the whole pipeline of `lac run` without output
 *               files.  Short, deterministic output.
 * Read first:   chapter 08 (the patch test: the same pipeline).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "fem/lac_exact.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "run/lac_run_scene.h"

// @sect Runs from a program
/* As in chapter 08, each case is the whole pipeline of `lac run` called
 * from C: a scene read with its overrides, run, its summary read.  A
 * library call that fails stops the program with the one-line message the
 * library stored. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex09: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* One run of DIR/NAME with the overrides SET (no output files): the scene
 * read (lac_scene_read), a run made from it (lac_run_alloc) and every
 * stage run (lac_run_all).  The scene is returned too: the run borrows
 * it. */
static lac_run *
run_scene (const char *dir, const char *name, int nset, const char **set,
           lac_scene **sc)
{
  char path[512];
  lac_run_opts o = { NULL, 0, 1, LAC_STRATEGY_AUTO, 0, NULL, 0, 0 };
  lac_run *r = NULL;
  snprintf (path, sizeof path, "%s/%s", dir, name);
  check_status (lac_scene_read (path, nset, set, sc), path);
  if (!(r = lac_run_alloc (*sc, &o)))
    check_status (LAC_ENOMEM, "lac_run_alloc");
  check_status (lac_run_all (r), path);
  return r;
}

/* A value of the run's summary (key = value) as a number (NaN if
 * absent). */
static double
value (const lac_run *r, const char *key)
{
  const char *v = lac_run_summary_get (r, key);
  return v ? atof (v) : NAN;
}

// @sect Part 1: the self-included spheres
/* Two shells $20 \le R \le 30$ and $30 \le R \le 40$ of the same
 * material are one Lam\'e thick sphere, $a = 20$, $b = 40$, pressed by
 * $p = 25$ inside:
 * $\sigma_{RR}(R) = -\frac{p a^3}{b^3 - a^3}\big(\frac{b^3}{R^3} - 1\big)$,
 * and the exact multiplier is its value on the interface, $R = 30$.  The
 * largest relative error of the multipliers should fall as the levels
 * double the cells along the interface. */
static void
spheres (const char *dir)
{
  // @sect The exact multiplier, by hand and by the library
  /* Lame's thick sphere a = 20, b = 40, inner pressure p = 25: sigma_RR(R)
   * = -p a^3 / (b^3 - a^3) (b^3 / R^3 - 1). */
  double a = 20, b = 40, p = 25, R = 30;
  double hand = -p * a * a * a / (b * b * b - a * a * a)
                * (b * b * b / (R * R * R) - 1);
  printf ("Part 1: self-included spheres, axisymmetric (spheres-axi.scene)\n");
  printf ("  lambda = sigma_RR(30) by hand: %.10f\n", hand);

  // @sect Three levels per element
  /* tri6 and quad8 at levels 0, 1, 2 (each level halves the cells): per
   * run the largest relative error of the multipliers against the exact
   * one (the summary's max_rel_err_lambda), and from the second level on
   * the factor by which it fell.  The first run also asks the library for
   * the exact value (lac_exact_normal_stress on the run's exact solution),
   * which must be the number computed by hand above. */
  const char *el[2] = { "tri6", "quad8" };
  for (int k = 0; k < 2; k++)
    {
      double prev = NAN;
      for (int level = 0; level <= 2; level++)
        {
          char s[2][64];
          const char *set[2] = { s[0], s[1] };
          lac_scene *sc = NULL;
          snprintf (s[0], sizeof s[0], "element=%s", el[k]);
          snprintf (s[1], sizeof s[1], "level=%d", level);
          lac_run *r = run_scene (dir, "spheres-axi.scene", 2, set, &sc);
          if (k == 0 && level == 0)
            {
              /* the same value from the library, on the equator (r, z) =
               * (30, 0) with the radial normal */
              lac_exact e;
              double x[2] = { R, 0 }, n[2] = { 1, 0 };
              lac_run_exact (sc, r->model, &e);
              printf ("  lambda by lac_exact:           %.10f\n\n",
                      lac_exact_normal_stress (&e, x, n));
              printf ("  element level  dofs  mult     lambda_min     "
                      "lambda_max  max rel. err  ratio\n");
            }
          double err = value (r, "max_rel_err_lambda");
          printf ("  %-7s %5d %5.0f %5.0f  %13.10f  %13.10f     %.3e",
                  el[k], level, value (r, "dofs"), value (r, "multipliers"),
                  value (r, "lambda_min"), value (r, "lambda_max"), err);
          if (level > 0)
            printf ("  %5.2f", prev / err);
          printf ("\n");
          prev = err;
          lac_run_free (r);
          lac_scene_free (sc);
        }
    }
}

// @sect Part 2: what a constant multiplier cannot do
/* On the unit square pressed onto the parabola $y = -0.05(x - \frac12)^2$
 * the exact pressure is $\lambda(x) = -0.05(x-\frac12)^2 - 0.01$, not a
 * constant.  A multiplier constant on each of the $N$ macro-elements can at
 * best be the mean $\Pi_0\lambda$ on each: its error
 * $e_{P0} = \|\lambda - \Pi_0\lambda\|_{0,\Gamma_C}$ has a closed form
 * (exercise 2),
 * $e_{P0} = \frac{0.05}{N^2}\sqrt{\frac{5N^2 - 4}{180}}$,
 * and the error the run reports, `l2_err_lambda`, cannot be below it. */
static void
manufactured (const char *dir)
{
  printf ("\nPart 2: manufactured2d.scene, exact lambda = -0.05 (x - 1/2)^2 - 0.01\n\n");
  printf ("  element level  dofs  mult   l2_err_u    l2_err_lambda  e_P0 (N = mult)\n");

  // @sect The errors against the bound of a constant multiplier
  /* quad4 and quad8 at levels 1-3: the L2 errors of u and of lambda the
   * run computes against the manufactured solution, and e_P0
   * for the run's N macro-elements (all active here).  quad8 at level L
   * has the macro-elements of quad4 at level L + 1 (one seg3 against two
   * gathered seg2), hence the same N one row apart. */
  const char *el[2] = { "quad4", "quad8" };
  for (int k = 0; k < 2; k++)
    for (int level = 1; level <= 3; level++)
      {
        char s[2][64];
        const char *set[2] = { s[0], s[1] };
        lac_scene *sc = NULL;
        snprintf (s[0], sizeof s[0], "element=%s", el[k]);
        snprintf (s[1], sizeof s[1], "level=%d", level);
        lac_run *r = run_scene (dir, "manufactured2d.scene", 2, set, &sc);
        double N = value (r, "multipliers");
        double ep0 = 0.05 / (N * N) * sqrt ((5 * N * N - 4) / 180);
        printf ("  %-7s %5d %5.0f %5.0f  %.4e     %.4e   %.4e\n", el[k], level,
                value (r, "dofs"), N, value (r, "l2_err_u"),
                value (r, "l2_err_lambda"), ep0);
        lac_run_free (r);
        lac_scene_free (sc);
      }
}

// @sect The main program
/* The scenes are read from this chapter's folder, or from the folder
 * given on the command line. */
int
main (int argc, char **argv)
{
  const char *dir = argc > 1 ? argv[1] : "chapters/09-spheres-rates";
  spheres (dir);
  manufactured (dir);
  return 0;
}
