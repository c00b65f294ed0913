/* LAC chapter 08 -- The Taylor patch test            [LAC §5.1, Tables 1-2]
 *
 * Build:        make build/chapters/08-experiments
 * Sample runs:  build/chapters/08-experiments        (from the repository
 *                                                     root: it reads the
 *                                                     chapter's scenes)
 *               build/chapters/08-experiments DIR    (the scenes in DIR)
 * Description:  the Taylor patch test (taylor2d.scene, taylor3d.scene,
 *               level 0) for linear and quadratic elements, with either
 *               body as slave.  The exact pressure n.sigma.n of the
 *               uniform solution is evaluated with lac_exact at a point of
 *               the interface; every multiplier must equal it to rounding.
 *               Each run is the whole pipeline of `lac run` (run/lac_run.h)
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

// @sect A whole run from a program
/* Chapters 01-07 built every piece by hand; here each test is the whole
 * pipeline of `lac run`, called from C: read a scene, run it, read its
 * summary.  A library call that fails stops the program with the one-line
 * message the library stored. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex08: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* One run of DIR/NAME with the overrides SET (no output files): the scene
 * read with its `--set` overrides (lac_scene_read), a run made from it
 * (lac_run_alloc: no output folder, quiet, the strategy auto) and every
 * stage run (lac_run_all).  The scene is returned too: the run borrows
 * it, so it is freed after the run. */
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

/* A value of the run's summary (the lines `lac run` prints, key = value)
 * as a number (NaN if absent). */
static double
value (const lac_run *r, const char *key)
{
  const char *v = lac_run_summary_get (r, key);
  return v ? atof (v) : NAN;
}

// @sect One patch test
/* The whole test is one run of a scene: `lac_scene_read` with the
 * overrides (the element type, which body carries the multipliers),
 * `lac_run_all` for mesh, macro-mesh, pairing, assembly and the active-set
 * loop.  The exact solution is uniform, $\sigma = -p\, e_v \otimes e_v$
 * with $e_v$ the last axis, so the exact multiplier is
 * $\lambda = n\cdot\sigma n = -p$ on every macro-element, whatever its
 * shape: the test is passed when
 * $\max_i |\lambda_i - \lambda| / |\lambda|$ is at rounding level. */
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

  // @sect The exact multiplier, and every multiplier against it
  /* The exact pressure at the middle of the interface (y = 50 in 2D,
   * z = 50 in 3D), normal e_y or e_z: n.sigma.n = -p. */
  lac_exact e;
  lac_run_exact (sc, r->model, &e);
  int dim = e.dim;
  double x[3] = { 25, 25, 25 }, n[3] = { 0, 0, 0 };
  x[dim - 1] = 50;
  n[dim - 1] = 1;
  double lam = lac_exact_normal_stress (&e, x, n);

  /* Every multiplier against it: the multipliers of the run are indexed
   * by macro-element (the slots of the loop), c->macro[i] the slot of
   * multiplier i. */
  const lac_newton *nw = r->sol.newton;
  const lac_contact *c = r->sys.contact;      /* multiplier i: macro[i] */
  double worst = 0;
  for (size_t i = 0; i < c->k; i++)
    worst = fmax (worst, fabs (nw->lambda[c->macro[i]] - lam) / fabs (lam));

  /* One row per run: dofs, multipliers, iterations, the extreme
   * multipliers and whether the worst relative error is below 1e-12; then
   * the run and the scene are freed (the run first: it borrows the
   * scene). */
  printf ("%-7s %-5s %5.0f %5zu %6.0f  %14.10f %14.10f  %s\n", element,
          upper ? "upper" : "lower", value (r, "dofs"), c->k, value (r, "newton_iterations"),
          value (r, "lambda_min"), value (r, "lambda_max"),
          worst < 1e-12 ? "< 1e-12" : "LARGER");
  lac_run_free (r);
  lac_scene_free (sc);
}

// @sect The runs
/* Two elements in 2D (quad4, whose macro-elements gather two segments, and
 * quad8, one macro-element per segment), two in 3D (hex8, each slave face
 * fanned into four triangles, and tet10, each slave face cut into three
 * tri6: chapter 03), each body as slave in turn for the 2D ones.  The 3D
 * runs are the slowest part: level 0 only. */
int
main (int argc, char **argv)
{
  const char *dir = argc > 1 ? argv[1] : "chapters/08-experiments";
  printf ("Taylor patch test, level 0 (exact lambda = n.sigma.n "
          "= -p = -25)\n\n");
  printf ("element slave  dofs  mult  iters      lambda_min     lambda_max"
          "  max rel. err\n");
  taylor (dir, "taylor2d.scene", "quad4", 1);
  taylor (dir, "taylor2d.scene", "quad4", 0);
  taylor (dir, "taylor2d.scene", "quad8", 1);
  taylor (dir, "taylor2d.scene", "quad8", 0);
  taylor (dir, "taylor3d.scene", "hex8", 1);
  taylor (dir, "taylor3d.scene", "tet10", 0);
  return 0;
}
