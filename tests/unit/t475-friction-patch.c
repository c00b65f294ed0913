/* t475: the frictional patch tests and the stick limit of a block
 *                            [LAC (16)-(18) with friction; solve/lac_friction.h]
 *
 * 1. Full stick (tests/friction/patch2d-stick.scene, patch3d-stick.scene):
 *    two blocks with non-matching interface meshes under the uniform
 *    stress sigma_yy = -p, sigma_xy = tau (3D: sigma_zz, sigma_xz), p = 25,
 *    tau = 5 < mu p = 10 (the [exact] solution taylor_shear: its tractions
 *    on the sides and the top, its displacement on the bottom), the upper
 *    block held by the contact alone: for tri3, quad4, tri6, quad8,
 *    quad9 (level 1) and tet4, hex8, tet10, hex20, hex27 (level 0),
 *    lambda_n = -25 and the tangential traction lambda_t = -tau along x
 *    (the slave is the upper block, normal -y: its tangent is +x and the
 *    traction sigma n on it is (-tau, p)) on every macro-element, every
 *    macro-element sticking, one iteration, and the von Mises stress
 *    sqrt(3 tau^2 + ...) of the uniform field at every node, all to 1e-12.
 * 2. Driven slip (patch2d-slip.scene, patch3d-slip.scene): mu = 0.05, the
 *    upper block moved by 2 mm (3D: (2, 1)) on its top: every macro-element
 *    in contact slips and |lambda_t| = mu |lambda_n| to 1e-12, lambda_t
 *    opposed to the slip, in at most 10 iterations.
 * 3. The stick limit (block-pull.scene): a block pressed by P = 200 N/mm
 *    and pulled by T on a rigid flat, mu = 0.3: T = 50 < mu P converges,
 *    the friction force is -T to 1e-12; T = 62 > mu P = 60 has no static
 *    solution: LAC_ESING, the message names the block and the slip.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "contact/lac_contact.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "solve/lac_friction.h"

#define F "tests/friction/"

/* von Mises of sigma = [[0, t], [t, -p]] in plane strain (sigma_zz = -nu p)
 * or sigma = -p e_z e_z + t (e_x e_z + e_z e_x) in 3D. */
static double
vm_exact (int dim, double p, double t, double nu)
{
  double sx = 0, sy = dim == 2 ? -p : 0, sz = dim == 2 ? -nu * p : -p;
  return sqrt (0.5 * ((sx - sy) * (sx - sy) + (sy - sz) * (sy - sz)
                      + (sz - sx) * (sz - sx)) + 3 * t * t);
}

/* The run of SCENE with its element and level set (NULL if it failed,
 * reported by check_run_scene); *sc for check_run_done. */
static lac_run *
run_at (const char *scene, const char *element, int level, lac_scene **sc)
{
  char s[2][64];
  const char *set[2] = { s[0], s[1] };
  snprintf (s[0], sizeof s[0], "element=%s", element);
  snprintf (s[1], sizeof s[1], "level=%d", level);
  return check_run_scene (scene, 2, set, sc);
}

static void
stick (const char *scene, const char *element, int level, int dim)
{
  lac_scene *sc;
  lac_run *r = run_at (scene, element, level, &sc);
  if (!r)
    return;
  const lac_newton *nw = r->sol.newton;
  const lac_contact *c = r->sys.contact;
  size_t nt = (size_t) c->ntan;
  double vm = vm_exact (dim, 25, 5, 0.3), worst = 0;
  check_int ((long) nt, dim - 1, "%s %s: tangential components", scene,
             element);
  check_int ((long) check_run_value (r, "newton_iterations"), 1,
             "%s %s: one iteration", scene, element);
  for (size_t i = 0; i < c->k; i++)
    {
      size_t m = c->macro[i];
      check_rel (nw->lambda[m], -25, 1e-12, "%s %s: lambda_n %zu", scene,
                 element, i);
      check_abs (nw->lambda_t[m * nt] / 25, -5.0 / 25, 1e-12,
                 "%s %s: lambda_t %zu", scene, element, i);
      if (nt == 2)
        check_abs (nw->lambda_t[m * nt + 1] / 25, 0, 1e-12,
                   "%s %s: lambda_t2 %zu", scene, element, i);
      check_int (nw->active[m], LAC_FRICTION_STICK, "%s %s: %zu sticks",
                 scene, element, i);
    }
  for (size_t a = 0; a < r->mesh->nnodes; a++)
    worst = fmax (worst, fabs (r->res.vm[a] - vm) / vm);
  check_true (worst <= 1e-12, "%s %s: von Mises off by %.1e", scene,
              element, worst);
  check_run_done (r, sc);
}

static void
slip (const char *scene, const char *element, int level)
{
  lac_scene *sc;
  lac_run *r = run_at (scene, element, level, &sc);
  if (!r)
    return;
  const lac_newton *nw = r->sol.newton;
  const lac_contact *c = r->sys.contact;
  size_t nt = (size_t) c->ntan, nslip = 0, nact = 0;
  double worst = 0;
  check_true (check_run_value (r, "max_iterations_per_step") <= 10
              || check_run_value (r, "newton_iterations") <= 10,
              "%s %s: %g iterations", scene, element,
              check_run_value (r, "newton_iterations"));
  for (size_t i = 0; i < c->k; i++)
    {
      size_t m = c->macro[i];
      double lt = 0, dot = 0;
      if (!nw->active[m])
        continue;
      nact++;
      nslip += nw->active[m] == LAC_FRICTION_SLIP;
      for (size_t b = 0; b < nt; b++)
        {
          lt += nw->lambda_t[m * nt + b] * nw->lambda_t[m * nt + b];
          dot += nw->lambda_t[m * nt + b] * nw->slip_conv[m * nt + b];
        }
      worst = fmax (worst, fabs (sqrt (lt) - 0.05 * fabs (nw->lambda[m]))
                           / fabs (nw->lambda[m]));
      check_true (dot < 0, "%s %s: lambda_t opposed to the slip at %zu",
                  scene, element, i);
    }
  check_true (nact > 0 && nslip == nact, "%s %s: %zu of %zu slip", scene,
              element, nslip, nact);
  check_true (worst <= 1e-12, "%s %s: |lambda_t| - mu |lambda_n| off by "
              "%.1e of |lambda_n|", scene, element, worst);
  check_run_done (r, sc);
}

static void
pull (void)
{
  const char *ok[] = { "load.top.traction=2.5 -10" };
  const char *off[] = { "load.top.traction=3.1 -10" };
  lac_scene *sc = NULL;
  lac_run *r = check_run_scene ("chapters/15-friction/block-pull.scene", 1, ok, &sc);
  if (r)
    {
      const char *v = lac_run_summary_get (r, "friction_force");
      double fx = v ? atof (v) : NAN;
      check_rel (fx, -50, 1e-12, "block: friction force = -T");
      check_run_done (r, sc);
    }
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  sc = NULL;
  int st = lac_scene_read ("chapters/15-friction/block-pull.scene", 1, off, &sc);
  lac_run *r2 = st ? NULL : lac_run_alloc (sc, &o);
  if (r2)
    st = lac_run_all (r2);
  check_status (st, LAC_ESING, "block pulled beyond mu P");
  check_message ("no static solution with friction: body 'block'",
                 "the message names the block");
  check_message ("every macro-element in contact with it slips",
                 "and says why");
  lac_run_free (r2);
  lac_scene_free (sc);
}

int
main (void)
{
  static const char *e2[] = { "tri3", "quad4", "tri6", "quad8", "quad9" };
  static const char *e3[] = { "tet4", "hex8", "tet10", "hex20", "hex27" };
  for (int k = 0; k < 5; k++)
    {
      stick (F "patch2d-stick.scene", e2[k], 1, 2);
      slip (F "patch2d-slip.scene", e2[k], 1);
    }
  for (int k = 0; k < 5; k++)
    {
      stick (F "patch3d-stick.scene", e3[k], 0, 3);
      slip (F "patch3d-slip.scene", e3[k], 0);
    }
  pull ();
  return check_summary ();
}
