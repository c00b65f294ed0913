/* LAC chapter 10 -- Large deformation and Hertz contact
 *                                            [LAC §4.5, §5.4; Hertz 1882]
 *
 * Build:        make build/chapters/10-large-deformation
 * Sample runs:  build/chapters/10-large-deformation      (from the
 *                                                         repository root)
 *               build/chapters/10-large-deformation DIR  (the scenes in DIR)
 * Description:  Part 1: the neo-Hookean law of the ring (lac_hyper_stress)
 *               against Hooke's law under a uniaxial stretch: the same
 *               stress for small strains, not for large ones.  Part 2: a
 *               cylinder pressed on a rigid flat (hertz-cylinder.scene,
 *               quad8, levels 0-3) against Hertz's half-width and peak
 *               pressure, and the contact force against the load.  Each
 *               run is the whole pipeline of `lac run` without output
 *               files.  Short, deterministic output (under a second).
 * Read first:   chapter 07 (the active set), chapter 09 (the pipeline).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "fem/lac_exact.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "run/lac_run_scene.h"
#include "fem/lac_hyper.h"

// @sect Runs from a program
/* Part 2 runs a scene through the whole pipeline of `lac run`, as in
 * chapters 08 and 09.  A library call that fails stops the program with
 * the one-line message the library stored. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex10: %s failed: %s (%s)\n", what, lac_error_message (),
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

// @sect Part 1: neo-Hookean against Hooke
/* The ring of the paper is crushed far beyond small strains, so its
 * bodies follow a hyperelastic law in the reference configuration, the
 * compressible neo-Hookean energy
 * $W = \frac{\mu}{2}(I_1 - 3) - \mu\ln J + \frac{\lambda}{2}(\ln J)^2$
 * with $I_1 = \operatorname{tr}(F^TF)$, $J = \det F$, whose first
 * Piola-Kirchhoff stress is $P = \mu(F - F^{-T}) + \lambda \ln J\, F^{-T}$.
 * Stretch a cube along $x$ with the other two directions held,
 * $F = \mathrm{diag}(1 + e, 1, 1)$: Hooke's law gives
 * $\sigma_{xx} = (\lambda + 2\mu)\, e$; the neo-Hookean $P_{xx}$ agrees to
 * first order in $e$ and departs from it as $e$ grows. */
static void
stretch (void)
{
  // @sect The two laws at one deformation gradient
  /* lac_hyper_lame turns (E, nu) into the Lame constants lambda, mu that
   * both laws share; lac_hyper_stress evaluates P at a given F (and,
   * when its last argument is not NULL, the tangent dP/dF, which the
   * Newton loop needs: exercise 2).  One row per stretch e, from 1e-4 to
   * 0.3. */
  const double E = 1000, nu = 0.3;
  double lam, mu;
  check_status (lac_hyper_lame (E, nu, &lam, &mu), "lac_hyper_lame");
  printf ("Part 1: uniaxial strain F = diag(1 + e, 1, 1), E = %g, nu = %g\n\n",
          E, nu);
  printf ("        e   Hooke sigma_xx   neo-Hookean P_xx   relative difference\n");
  const double es[5] = { 1e-4, 1e-3, 1e-2, 1e-1, 3e-1 };
  for (int k = 0; k < 5; k++)
    {
      double F[9] = { 1 + es[k], 0, 0, 0, 1, 0, 0, 0, 1 }, P[9];
      check_status (lac_hyper_stress (LAC_LAW_NEO_HOOKEAN, E, nu, F, P, NULL),
                    "lac_hyper_stress");
      double hooke = (lam + 2 * mu) * es[k];
      printf ("  %7.0e   %14.6e   %16.6e   %19.3e\n", es[k], hooke, P[0],
              (P[0] - hooke) / hooke);
    }
}

// @sect Part 2: a cylinder on a rigid flat
/* Half a cylinder of radius $R = 10$ (symmetric about $x = 0$), steel,
 * pressed by $P = 700$ N/mm onto the rigid flat $y \le 0$.  Hertz's
 * solution for a load $P$ per unit length, with
 * $E^* = E/(1 - \nu^2)$ on a rigid flat: the contact half-width
 * $a = \sqrt{4PR/(\pi E^*)}$ and the peak pressure $p_0 = 2P/(\pi a)$.
 * The run reports the largest macro-element mean of the pressure
 * (`max_contact_pressure`), the width of the active zone (`contact_area`,
 * of the half model) and the contact force, which must balance the load
 * since the cylinder is held by the contact alone. */
static void
hertz (const char *dir)
{
  // @sect Hertz's numbers, then four levels
  /* The exact half-width and peak pressure first; then quad8 at levels
   * 0-3, one row each: the active macro-elements and the iterations of
   * the loop, the peak pressure and the active half-width a_A against
   * Hertz's (in percent), and the balance of forces. */
  const double pi = acos (-1.0), R = 10, P = 700, E = 2e5, nu = 0.3;
  double Es = E / (1 - nu * nu);
  double a = sqrt (4 * P * R / (pi * Es)), p0 = 2 * P / (pi * a);
  printf ("\nPart 2: hertz-cylinder.scene, quad8: Hertz a = %.5f mm, "
          "p0 = %.2f MPa\n\n", a, p0);
  printf ("  level  dofs  active  iters   p_max (MPa)  err (%%)   "
          "    a_A (mm)  err (%%)   |F - P|/P\n");
  for (int level = 0; level <= 3; level++)
    {
      char s[2][64];
      const char *set[2] = { s[0], s[1] };
      lac_scene *sc = NULL;
      snprintf (s[0], sizeof s[0], "element=quad8");
      snprintf (s[1], sizeof s[1], "level=%d", level);
      lac_run *r = run_scene (dir, "hertz-cylinder.scene", 2, set, &sc);
      /* The scene models the half x >= 0: its contact force is half the
       * load, and contact_area is the half-width of the active zone. */
      double pm = value (r, "max_contact_pressure");
      double aA = value (r, "contact_area");       /* half model: the half-width */
      double F = -2 * value (r, "contact_force");
      printf ("  %5d %5.0f  %6.0f  %5.0f   %11.2f  %7.3f   %13.5f  %7.2f   %9.1e\n",
              level, value (r, "dofs"), value (r, "active"),
              value (r, "newton_iterations"), pm, 100 * (pm / p0 - 1), aA,
              100 * (aA / a - 1), fabs (F - P) / P < 1e-10 ? 0.0 : fabs (F - P) / P);
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
  const char *dir = argc > 1 ? argv[1] : "chapters/10-large-deformation";
  stretch ();
  hertz (dir);
  return 0;
}
