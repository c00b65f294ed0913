/* LAC chapter 08 -- Numerical experiments: patch test and spheres
 *                                          [LAC §5.1-§5.2, Tables 1-4]
 *
 * Build:        make  (builds it as build/chapters/08-experiments)
 * Sample runs:  build/chapters/08-experiments        (from the repository
 *                                                     root: it reads the
 *                                                     chapter's scenes)
 *               build/chapters/08-experiments DIR    (the scenes in DIR)
 * Description:  Part 1: the Taylor patch test (taylor2d.scene,
 *               taylor3d.scene, level 0) for a linear and a quadratic
 *               element, with either body as slave.  The exact pressure
 *               n.sigma.n of the uniform solution is evaluated with
 *               lac_exact at a point of the interface; every multiplier
 *               must equal it to rounding.  Part 2: the self-included
 *               spheres in the axisymmetric model (spheres-axi.scene):
 *               the exact lambda = sigma_RR(30) of the Lame solution by
 *               hand and by lac_exact, then the multipliers of tri6 and
 *               quad8 at levels 0-2 and the ratio by which their largest
 *               relative error falls from one level to the next.  Each
 *               run is the whole pipeline of `lac run` (run/lac_run.h)
 *               without output files.  Short, deterministic output.
 * Read first:   chapters 06 (the sign of lambda) and 07 (the active set).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "fem/lac_exact.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "run/lac_run_scene.h"

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex08: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* One run of DIR/NAME with the overrides SET (no output files).  The
 * scene is returned too: the run borrows it. */
static lac_run *
run_scene (const char *dir, const char *name, int nset, const char **set,
           lac_scene **sc)
{
  char path[512];
  lac_run_opts o = { NULL, 0, 1, LAC_STRATEGY_AUTO, 0, NULL };
  lac_run *r = NULL;
  snprintf (path, sizeof path, "%s/%s", dir, name);
  check_status (lac_scene_read (path, nset, set, sc), path);
  if (!(r = lac_run_alloc (*sc, &o)))
    check_status (LAC_ENOMEM, "lac_run_alloc");
  check_status (lac_run_all (r), path);
  return r;
}

/* A summary value as a number (NaN if absent). */
static double
value (const lac_run *r, const char *key)
{
  const char *v = lac_run_summary_get (r, key);
  return v ? atof (v) : NAN;
}

// @sect Part 1: the Taylor patch test
static void
taylor (const char *dir, const char *scene, const char *element, int upper)
{
  const char *slave = upper ? "upper_bottom" : "lower_top";
  const char *master = upper ? "lower_top" : "upper_bottom";
  char s[3][64];
  const char *set[3] = { s[0], s[1], s[2] };
  lac_scene *sc = NULL;
  snprintf (s[0], sizeof s[0], "element=%s", element);
  snprintf (s[1], sizeof s[1], "contact.interface.slave=%s", slave);
  snprintf (s[2], sizeof s[2], "contact.interface.master=%s", master);
  lac_run *r = run_scene (dir, scene, 3, set, &sc);

  /* The exact pressure at the middle of the interface (y = 50 in 2D,
   * z = 50 in 3D), normal e_y or e_z: n.sigma.n = -p. */
  lac_exact e;
  lac_run_exact (sc, r->model, &e);
  int dim = e.dim;
  double x[3] = { 25, 25, 25 }, n[3] = { 0, 0, 0 };
  x[dim - 1] = 50;
  n[dim - 1] = 1;
  double lam = lac_exact_normal_stress (&e, x, n);

  /* Every multiplier against it. */
  const lac_newton *nw = r->sol.newton;
  const lac_contact *c = r->sys.contact;      /* multiplier i: macro[i] */
  double worst = 0;
  for (size_t i = 0; i < c->k; i++)
    worst = fmax (worst, fabs (nw->lambda[c->macro[i]] - lam) / fabs (lam));
  printf ("%-7s %-5s %5.0f %5zu %6.0f  %14.10f %14.10f  %s\n", element,
          upper ? "upper" : "lower", value (r, "dofs"), c->k, value (r, "newton_iterations"),
          value (r, "lambda_min"), value (r, "lambda_max"),
          worst < 1e-12 ? "< 1e-12" : "LARGER");
  lac_run_free (r);
  lac_scene_free (sc);
}

// @sect Part 2: the self-included spheres
static void
spheres (const char *dir)
{
  /* Lame's thick sphere a = 20, b = 40, inner pressure p = 25: sigma_RR(R)
   * = -p a^3 / (b^3 - a^3) (b^3 / R^3 - 1). */
  double a = 20, b = 40, p = 25, R = 30;
  double hand = -p * a * a * a / (b * b * b - a * a * a)
                * (b * b * b / (R * R * R) - 1);
  printf ("\nPart 2: self-included spheres, axisymmetric (spheres-axi.scene)\n");
  printf ("  lambda = sigma_RR(30) by hand: %.10f\n", hand);

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

int
main (int argc, char **argv)
{
  const char *dir = argc > 1 ? argv[1] : "chapters/08-experiments";
  printf ("Part 1: Taylor patch test, level 0 (exact lambda = n.sigma.n "
          "= -p = -25)\n\n");
  printf ("element slave  dofs  mult  iters      lambda_min     lambda_max"
          "  max rel. err\n");
  taylor (dir, "taylor2d.scene", "quad4", 1);
  taylor (dir, "taylor2d.scene", "quad4", 0);
  taylor (dir, "taylor2d.scene", "quad8", 1);
  taylor (dir, "taylor2d.scene", "quad8", 0);
  taylor (dir, "taylor3d.scene", "hex8", 1);
  taylor (dir, "taylor3d.scene", "tet10", 0);
  spheres (dir);
  return 0;
}
