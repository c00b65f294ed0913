/* t703: the run pipeline -- a uniaxial patch test, exact solutions, errors
 *
 * Scenes are given as strings with paths under tests/bad/ and chapters/,
 * so that their meshes (box.geo, sphere-axi.geo) resolve; no files are
 * written (opts.no_output).
 *   1. uniaxial tension of a plane-strain block, supported by symmetry
 *      conditions only: sigma = (t, 0, nu t, 0) at every node and
 *      u_x = (1 - nu^2) t x / E, exactly, for every element type;
 *   2. the thick cylinder (plane strain) and the thick sphere
 *      (axisymmetric) converge at order 3 in L2 for quadratic elements;
 *   3. errors point at the scene line (missing group) or name the free
 *      rigid motion (singular stiffness).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "run/lac_run.h"
#include "base/lac_status.h"

static const char *uniaxial =
  "[scene]\nmodel = plane_strain\n"
  "[mesh]\nfile = box.geo\n"
  "[material m]\nE = 1000\nnu = 0.25\n"
  "[dirichlet left]\ngroup = left\nsymmetry = x\n"
  "[dirichlet corner]\ngroup = corner\nsymmetry = y\n"
  "[load pull]\ngroup = right\ntraction = 10 0\n";

/* Run a scene string; returns the finished run or NULL (status in *st). */
static lac_run *
run (const char *text, const char *path, size_t nset, const char *const *set,
     int *st, lac_scene **sc)
{
  lac_run_opts o = { NULL, 1, 1, 0, 0, NULL, 0, 0 };
  lac_run *r = NULL;
  *st = lac_scene_read_string (text, path, nset, set, sc);
  if (*st)
    return NULL;
  if (!(r = lac_run_alloc (*sc, &o)))
    {
      *st = LAC_ENOMEM;
      return NULL;
    }
  *st = lac_run_all (r);
  return r;
}

static void
test_uniaxial (const char *element)
{
  char set[64];
  const char *sets[1] = { set };
  lac_scene *sc = NULL;
  lac_run *r;
  int st;
  double t = 10, E = 1000, nu = 0.25, err_s = 0, err_u = 0;
  snprintf (set, sizeof set, "element=%s", element);
  r = run (uniaxial, "tests/bad/t703.scene", 1, sets, &st, &sc);
  check_status (st, LAC_SUCCESS, "uniaxial %s", element);
  if (!st)
    {
      for (size_t a = 0; a < r->mesh->nnodes; a++)
        {
          const double *s = r->res.sigma + 4 * a, want[4] = { t, 0, nu * t, 0 };
          double x = r->mesh->x[2 * a];
          for (int k = 0; k < 4; k++)
            err_s = fmax (err_s, fabs (s[k] - want[k]));
          err_u = fmax (err_u, fabs (r->sol.u[2 * a] - (1 - nu * nu) * t * x / E));
        }
      check_abs (err_s, 0, 1e-9, "uniaxial %s: stress", element);
      check_abs (err_u, 0, 1e-12, "uniaxial %s: u_x", element);
      check_int (r->stage, LAC_NSTAGES, "all stages ran");
      check_true (lac_run_summary_get (r, "time_solve") != NULL,
                  "timings in the summary when asked");
      check_true (lac_run_summary_get (r, "l2_err_u") == NULL,
                  "no errors without [exact]");
      check_int (atol (lac_run_summary_get (r, "dofs")),
                 2 * (long) r->mesh->nnodes, "dofs = 2 nodes");
    }
  lac_run_free (r);
  lac_scene_free (sc);
}

static const char *thick =
  "[scene]\nelement = tri6\n"
  "[mesh]\nfile = sphere-axi.geo\n"
  "[material steel]\nE = 210000\nnu = 0.3\n"
  "[dirichlet axis]\ngroup = axis\nsymmetry = x\n"
  "[dirichlet equator]\ngroup = equator\nsymmetry = y\n"
  "[load inner]\ngroup = inner\npressure = 100\n"
  "[exact]\nsolution = thick_cylinder\na = 20\nb = 40\np = 100\n"
  "E = 210000\nnu = 0.3\n";

/* L2 error at levels 0, 1, 2 with the overrides set[0..nset-1]. */
static void
test_convergence (const char *what, size_t nset, const char **set)
{
  const char *sets[8];
  char level[32];
  double e[3] = { 0, 0, 0 };
  for (int l = 0; l < 3; l++)
    {
      lac_scene *sc = NULL;
      lac_run *r;
      int st;
      memcpy (sets, set, nset * sizeof *set);
      snprintf (level, sizeof level, "level=%d", l);
      sets[nset] = level;
      r = run (thick, "chapters/01-problem/t703.scene", nset + 1, sets, &st,
               &sc);
      check_status (st, LAC_SUCCESS, "%s level %d", what, l);
      if (!st)
        e[l] = r->res.err_l2 / r->res.norm_l2;
      lac_run_free (r);
      lac_scene_free (sc);
    }
  check_true (e[0] / e[1] > 6.5 && e[1] / e[2] > 7, "%s: L2 order 3 "
              "(errors %.3e %.3e %.3e)", what, e[0], e[1], e[2]);
  check_true (e[2] < 5e-4, "%s: small error %.3e", what, e[2]);
}

static void
test_errors (void)
{
  const char *set1[] = { "dirichlet.left.group=leftt" };
  const char *set2[] = { "dirichlet.corner.symmetry=x" };
  lac_scene *sc = NULL;
  lac_run *r;
  int st;
  r = run (uniaxial, "tests/bad/t703.scene", 1, set1, &st, &sc);
  check_status (st, LAC_EINVAL, "missing group");
  check_message ("[dirichlet left] group = 'leftt': no physical group",
                 "missing group message");
  check_int (r ? r->stage : -1, LAC_STAGE_MESH, "stops in the mesh stage");
  lac_run_free (r);
  lac_scene_free (sc);
  r = run (uniaxial, "tests/bad/t703.scene", 1, set2, &st, &sc);
  check_status (st, LAC_ESING, "only u_x fixed: singular");
  check_message ("free: translation along y", "names the free motion");
  lac_run_free (r);
  lac_scene_free (sc);
}

int
main (void)
{
  const char *cyl[] = { "element=tri6" };
  const char *cyl8[] = { "element=quad8" };
  const char *sph[] = { "model=axisymmetric", "exact.solution=thick_sphere",
                        "dirichlet.axis.symmetry=r",
                        "dirichlet.equator.symmetry=z" };
  lac_init ();
  test_uniaxial ("tri3");
  test_uniaxial ("tri6");
  test_uniaxial ("quad4");
  test_uniaxial ("quad8");
  test_uniaxial ("quad9");
  test_convergence ("thick cylinder tri6", 1, cyl);
  test_convergence ("thick cylinder quad8", 1, cyl8);
  test_convergence ("thick sphere tri6", 4, sph);
  test_errors ();
  lac_finalize ();
  return check_summary ();
}
