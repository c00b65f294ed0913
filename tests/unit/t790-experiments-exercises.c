/* t790-experiments-exercises.c -- the answers of
 * chapters/08-experiments/exercises.md                 [LAC §5.1]
 *
 * Everything is computed here from small runs of the chapter's scenes
 * (run/lac_run.h, no files written) and compared with closed forms.
 *
 * Exercise 1 (the Taylor patch test, level 0 and 1): multipliers
 *   floor(k/2) for seg2 slave facets (quad4, tri3), k for seg3 (quad8,
 *   tri6) with k = 3, 4, 5, 7 slave cells; n_s^2 (hex8) and 2 n_s^2 (tet4)
 *   in 3D; the dofs of hex8 3 [(n_l+1)^3 + (n_u+1)^3 + n_s^2] = 594, 615,
 *   2259, 2331 (one new node per slave face), of quad4 82 with either
 *   slave; every multiplier -25 to 1e-12, one iteration.
 * Exercise 2 (plane strain, level 0): the corner (50, 100) of the upper
 *   square moves by (0.24375, -1.1375) with quad4, tri6, quad9 (1e-12).
 * Exercise 3 (quad4 level 1, lower slave): LAC below 1e-14, node-to-segment
 *   8.6e-2 (lambda from -25.8 to -22.8).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "base/lac_status.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"

#define D8 "chapters/08-experiments/"

/* ---- exercise 1 ------------------------------------------------------ */

/* The patch test with ELEMENT at LEVEL, the upper or the lower body as
 * slave: its multipliers, dofs; every lambda -25, one iteration. */
static void
taylor (const char *scene, const char *element, int level, int upper,
        long mult, long dofs)
{
  char s[4][64];
  const char *set[4] = { s[0], s[1], s[2], s[3] };
  lac_scene *sc;
  snprintf (s[0], sizeof s[0], "element=%s", element);
  snprintf (s[1], sizeof s[1], "level=%d", level);
  snprintf (s[2], sizeof s[2], "contact.interface.slave=%s",
            upper ? "upper_bottom" : "lower_top");
  snprintf (s[3], sizeof s[3], "contact.interface.master=%s",
            upper ? "lower_top" : "upper_bottom");
  lac_run *r = check_run_scene (scene, 4, set, &sc);
  if (!r)
    return;
  const char *side = upper ? "upper" : "lower";
  const lac_newton *nw = r->sol.newton;
  const lac_contact *c = r->sys.contact;
  check_int ((long) c->k, mult, "ex1 %s level %d %s: multipliers", element,
             level, side);
  if (dofs > 0)
    check_int ((long) check_run_value (r, "dofs"), dofs,
               "ex1 %s level %d %s: dofs", element, level, side);
  check_int ((long) check_run_value (r, "newton_iterations"), 1,
             "ex1 %s level %d %s: one iteration", element, level, side);
  for (size_t i = 0; i < c->k; i++)
    check_rel (nw->lambda[c->macro[i]], -25, 1e-12, "ex1 %s level %d %s: lambda_%zu",
               element, level, side, i);
  check_run_done (r, sc);
}

static void
exercise1 (void)
{
  /* slave cells along the interface: level 0 upper 3, lower 4; level 1
   * upper 5, lower 7 */
  const long k[2][2] = { { 3, 4 }, { 5, 7 } };
  const char *lin[2] = { "quad4", "tri3" }, *quad[2] = { "quad8", "tri6" };
  for (int level = 0; level < 2; level++)
    for (int up = 0; up < 2; up++)
      {
        long ks = k[level][up ? 0 : 1];
        for (int e = 0; e < 2; e++)
          {
            taylor (D8 "taylor2d.scene", lin[e], level, up, ks / 2,
                    e == 0 && level == 0 ? 2 * (25 + 16) : 0);
            taylor (D8 "taylor2d.scene", quad[e], level, up, ks, 0);
          }
        long nl = k[level][1], nu = k[level][0];
        long hex8 = 3 * ((nl + 1) * (nl + 1) * (nl + 1)
                         + (nu + 1) * (nu + 1) * (nu + 1) + ks * ks);
        taylor (D8 "taylor3d.scene", "hex8", level, up, ks * ks, hex8);
        taylor (D8 "taylor3d.scene", "tet4", level, up, 2 * ks * ks, 0);
      }
  /* the quoted numbers themselves */
  check_int (3 * (125 + 64 + 9), 594, "ex1: hex8 level 0 upper");
  check_int (3 * (125 + 64 + 16), 615, "ex1: hex8 level 0 lower");
  check_int (3 * (512 + 216 + 25), 2259, "ex1: hex8 level 1 upper");
  check_int (3 * (512 + 216 + 49), 2331, "ex1: hex8 level 1 lower");
}

/* ---- exercise 2 ------------------------------------------------------ */

/* The top right corner (50, 100) of the upper square, plane strain:
 * u = (nu (1 + nu) p / E x, -(1 - nu^2) p / E y) = (0.24375, -1.1375). */
static void
exercise2 (void)
{
  const double p = 25, E = 2000, nu = 0.3;
  double ux = nu * (1 + nu) * p / E * 50, uy = -(1 - nu * nu) * p / E * 100;
  check_rel (ux, 0.24375, 1e-14, "ex2: u_x = 0.24375");
  check_rel (uy, -1.1375, 1e-14, "ex2: u_y = -1.1375");
  const char *el[3] = { "quad4", "tri6", "quad9" };
  for (int e = 0; e < 3; e++)
    {
      char s[64];
      const char *set[1] = { s };
      lac_scene *sc;
      snprintf (s, sizeof s, "element=%s", el[e]);
      lac_run *r = check_run_scene (D8 "taylor2d.scene", 1, set, &sc);
      if (!r)
        continue;
      const lac_mesh *m = r->mesh;
      size_t best = 0;
      double dbest = INFINITY;
      for (size_t a = 0; a < m->nnodes; a++)
        {
          double d = hypot (m->x[2 * a] - 50, m->x[2 * a + 1] - 100);
          if (d < dbest)
            dbest = d, best = a;
        }
      check_true (dbest < 1e-12, "ex2 %s: a node at (50, 100)", el[e]);
      check_rel (r->sol.u[2 * best], ux, 1e-12, "ex2 %s: u_x", el[e]);
      check_rel (r->sol.u[2 * best + 1], uy, 1e-12, "ex2 %s: u_y", el[e]);
      check_run_done (r, sc);
    }
}

/* ---- exercise 3 ------------------------------------------------------ */

/* quad4 level 1, the lower body as slave: LAC below 1e-14, node-to-segment
 * lambda in [-25.81, -22.85], error 8.6e-2. */
static double
taylor_method (const char *method, double *lmin, double *lmax)
{
  char s[64];
  const char *set[5] = { "element=quad4", "level=1",
                         "contact.interface.slave=lower_top",
                         "contact.interface.master=upper_bottom", s };
  lac_scene *sc;
  snprintf (s, sizeof s, "contact.interface.method=%s", method);
  lac_run *r = check_run_scene (D8 "taylor2d.scene", 5, set, &sc);
  if (!r)
    return NAN;
  double err = check_run_value (r, "max_rel_err_lambda");
  *lmin = check_run_value (r, "lambda_min");
  *lmax = check_run_value (r, "lambda_max");
  check_run_done (r, sc);
  return err;
}

static void
exercise3 (void)
{
  double lmin, lmax;
  double e = taylor_method ("lac", &lmin, &lmax);
  check_true (e < 1e-14, "ex3: lac error %g below 1e-14", e);
  e = taylor_method ("nts", &lmin, &lmax);
  check_rel (e, 8.6e-2, 0.01, "ex3: nts error 8.6e-2");
  check_rel (lmin, -25.8, 0.002, "ex3: nts lambda_min -25.8");
  check_rel (lmax, -22.8, 0.003, "ex3: nts lambda_max -22.8");
}

int
main (void)
{
  exercise1 ();
  exercise2 ();
  exercise3 ();
  return check_summary ();
}
