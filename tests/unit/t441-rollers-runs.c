/* t441: rollers, reactions and a shrink fit, whole runs
 *                                              [LAC (4), (8), (17), Alg. 1]
 *
 * The scenes of chapter 08 (section 7 and the patch tests), run through
 * run/lac_run.h with no files written.
 *   1. The 2D Taylor patch test turned by 30 degrees
 *      (chapters/08-experiments/taylor2d-rotated.scene), its three faces on
 *      rollers (normal = 0), for tri3, tri6, quad4, quad8, quad9 and the
 *      strategies dense, augmented, split, saddle: every multiplier active
 *      and lambda = -p to 1e-12 (relative); the stress the turned uniform
 *      one, sigma = -p v v^T with v = (-sin 30, cos 30), and u the turned
 *      upright solution, both to 1e-10 of their size; the reactions
 *      (reaction.NAME) zero on the two side rollers and p L (sin 30,
 *      -cos 30) reversed on the bottom one, the applied load, to 1e-10 of
 *      it.
 *   2. The 3D Taylor patch test with every symmetry plane a roller
 *      (normal = 0, frames where two meet at an edge): the errors against
 *      the exact solution 1e-12 as with symmetry planes; the bottom's
 *      reaction p L^2 along +z.
 *   3. A roller on a curved face with a value: the thick sphere
 *      (axisymmetric, tri6) with u.n = u_R(b) on its outer surface and
 *      rollers on the axis and the equator: the exact solution, reached at
 *      order 3 in L2 (levels 1, 2).
 *   4. The shrink fit of chapter 06 (plane strain quad8, a quarter on a
 *      symmetry plane and a roller): every lambda tends to -p of Lame's
 *      formula, the largest error shrinking by more than 6 per level
 *      (levels 0, 1, 2) and below 4e-4 p at level 2.
 *   5. Large deformation: the turned patch test gives the upright one's
 *      lambda_min, max_u (to 1e-10) and Newton iterations (quad4, quad8;
 *      dense, split), and its bottom reaction is the load to 1e-10.
 *   6. Two values along one direction of a roller's node: an error naming
 *      both sections, the node and the direction.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "run/lac_run.h"
#include "base/lac_status.h"

#define PI 3.14159265358979323846

/* Run a scene (a file, or text with path for its mesh) with overrides. */
static lac_run *
run (const char *file, const char *text, const char *path, size_t nset,
     const char *const *set, int *st, lac_scene **sc)
{
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  lac_run *r = NULL;
  *st = file ? lac_scene_read (file, nset, set, sc)
             : lac_scene_read_string (text, path, nset, set, sc);
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

/* The numbers of summary line `key` (n of them); 0 if missing. */
static int
summary_vec (const lac_run *r, const char *key, int n, double *v)
{
  const char *s = lac_run_summary_get (r, key);
  char *end;
  for (int k = 0; k < n; k++)
    {
      if (!s)
        return 0;
      v[k] = strtod (s, &end);
      if (end == s)
        return 0;
      s = end;
    }
  return 1;
}

/* The largest |lambda_m - want| over the slots, and the inactive count. */
static double
lambda_error (const lac_run *r, double want, long *inactive)
{
  const lac_newton *nw = r->sol.newton;
  double e = 0;
  *inactive = 0;
  for (size_t m = 0; nw && m < nw->nslot; m++)
    if (nw->active[m])
      e = fmax (e, fabs (nw->lambda[m] - want));
    else
      (*inactive)++;
  return nw ? e : HUGE_VAL;
}

/* ---- 1. the turned patch test --------------------------------------- */

/* the largest errors of part 1 over every run: lambda, the reactions */
typedef struct worst
{
  double lambda, reaction;
} worst;

static void
turned_patch (const char *element, const char *strategy, worst *w)
{
  char s1[64], s2[80];
  const char *set[3] = { s1, s2, "output.reactions=yes" };
  double p = 25, E = 2000, nu = 0.3, L = 50, c = cos (PI / 6),
    sn = sin (PI / 6), v[2] = { -sn, c };
  lac_scene *sc = NULL;
  int st;
  snprintf (s1, sizeof s1, "element=%s", element);
  snprintf (s2, sizeof s2, "contact.interface.strategy=%s", strategy);
  lac_run *r = run ("chapters/08-experiments/taylor2d-rotated.scene", NULL,
                    NULL, 3, set, &st, &sc);
  check_status (st, LAC_SUCCESS, "turned patch %s %s", element, strategy);
  if (!st)
    {
      long off;
      double el = lambda_error (r, -p, &off), eu = 0, es = 0, umax = 0;
      check_abs (el, 0, 1e-12 * p, "turned %s %s: lambda = -p", element,
                 strategy);
      check_int (off, 0, "turned %s %s: every multiplier active", element,
                 strategy);
      for (size_t a = 0; a < r->mesh->nnodes; a++)
        {
          const double *x = r->mesh->x + 2 * a, *s = r->res.sigma + 4 * a;
          double X = c * x[0] + sn * x[1], Y = -sn * x[0] + c * x[1];
          double ux = nu * (1 + nu) * p * X / E, uy = -(1 - nu * nu) * p * Y / E;
          double want_u[2] = { c * ux - sn * uy, sn * ux + c * uy };
          double want_s[4] = { -p * v[0] * v[0], -p * v[1] * v[1],
                               -nu * p, -p * v[0] * v[1] };
          for (int i = 0; i < 2; i++)
            {
              eu = fmax (eu, fabs (r->sol.u[2 * a + i] - want_u[i]));
              umax = fmax (umax, fabs (want_u[i]));
            }
          for (int k = 0; k < 4; k++)
            es = fmax (es, fabs (s[k] - want_s[k]));
        }
      check_abs (eu, 0, 1e-10 * umax, "turned %s %s: u", element, strategy);
      check_abs (es, 0, 1e-10 * p, "turned %s %s: sigma", element, strategy);
      double R[3][2], W = p * L;
      const char *name[3] = { "reaction.lower_left", "reaction.upper_left",
                              "reaction.bottom" };
      for (int g = 0; g < 3; g++)
        check_true (summary_vec (r, name[g], 2, R[g]), "turned %s %s: %s",
                    element, strategy, name[g]);
      for (int i = 0; i < 2; i++)
        {
          check_abs (R[0][i], 0, 1e-10 * W, "... lower_left carries nothing");
          check_abs (R[1][i], 0, 1e-10 * W, "... upper_left carries nothing");
          check_abs (R[2][i], W * v[i], 1e-10 * W, "... bottom: the load, "
                     "component %d", i);
          w->reaction = fmax (w->reaction, fmax (fabs (R[2][i] - W * v[i]),
                              fmax (fabs (R[0][i]), fabs (R[1][i]))) / W);
        }
      w->lambda = fmax (w->lambda, el / p);
    }
  lac_run_free (r);
  lac_scene_free (sc);
}

/* ---- 2. the 3D patch test on rollers -------------------------------- */

static const char *taylor3d =
  "[scene]\nmodel = 3d\nelement = hex8\nsolver = umfpack\n"
  "[mesh]\nfile = taylor3d.geo\n"
  "[material all]\nE = 2000\nnu = 0.3\n"
  "[dirichlet lower_x0]\ngroup = lower_x0\nnormal = 0\n"
  "[dirichlet upper_x0]\ngroup = upper_x0\nnormal = 0\n"
  "[dirichlet lower_y0]\ngroup = lower_y0\nnormal = 0\n"
  "[dirichlet upper_y0]\ngroup = upper_y0\nnormal = 0\n"
  "[dirichlet bottom]\ngroup = lower_bottom\nnormal = 0\n"
  "[load top]\ngroup = upper_top\npressure = 25\n"
  "[contact interface]\nslave = upper_bottom\nmaster = lower_top\n"
  "[exact]\nsolution = taylor\np = 25\nE = 2000\nnu = 0.3\n"
  "[output]\nreactions = yes\n";

static void
patch3d (const char *element)
{
  char s1[64];
  const char *set[1] = { s1 };
  lac_scene *sc = NULL;
  int st;
  snprintf (s1, sizeof s1, "element=%s", element);
  lac_run *r = run (NULL, taylor3d, "chapters/08-experiments/t441.scene", 1,
                    set, &st, &sc);
  check_status (st, LAC_SUCCESS, "3D patch on rollers, %s", element);
  if (!st)
    {
      double el = atof (lac_run_summary_get (r, "max_rel_err_lambda"));
      double es = atof (lac_run_summary_get (r, "max_rel_err_sigma"));
      double R[3] = { 0, 0, 0 }, W = 25.0 * 50 * 50;
      check_abs (el, 0, 1e-12, "3D rollers %s: lambda", element);
      check_abs (es, 0, 1e-12, "3D rollers %s: sigma", element);
      check_true (summary_vec (r, "reaction.bottom", 3, R), "3D reaction");
      check_abs (R[0], 0, 1e-10 * W, "3D %s: bottom reaction x", element);
      check_abs (R[1], 0, 1e-10 * W, "3D %s: bottom reaction y", element);
      check_abs (R[2], W, 1e-10 * W, "3D %s: bottom reaction z", element);
    }
  lac_run_free (r);
  lac_scene_free (sc);
}

/* ---- 3. a curved roller with a value -------------------------------- */

static double
sphere_error (int level)
{
  /* u_R(b) = p a^3 b 3 (1 - nu) / (2 E (b^3 - a^3)) = 0.075 */
  static const char *text =
    "[scene]\nmodel = axisymmetric\nelement = tri6\n"
    "[mesh]\nfile = sphere-axi.geo\n"
    "[material shell]\ngroup = body\nE = 2000\nnu = 0.3\n"
    "[dirichlet axis]\ngroup = axis\nnormal = 0\n"
    "[dirichlet equator]\ngroup = equator\nnormal = 0\n"
    "[dirichlet outer]\ngroup = outer\nnormal = 0.075\n"
    "[load inner]\ngroup = inner\npressure = 25\n"
    "[exact]\nsolution = thick_sphere\na = 20\nb = 40\np = 25\nE = 2000\n"
    "nu = 0.3\n";
  char s1[32];
  const char *set[1] = { s1 };
  lac_scene *sc = NULL;
  int st;
  double e = HUGE_VAL;
  snprintf (s1, sizeof s1, "mesh.level=%d", level);
  lac_run *r = run (NULL, text, "chapters/01-problem/t441.scene", 1, set,
                    &st, &sc);
  check_status (st, LAC_SUCCESS, "sphere with a curved roller, level %d",
                level);
  if (!st)
    e = atof (lac_run_summary_get (r, "rel_l2_err_u"));
  lac_run_free (r);
  lac_scene_free (sc);
  return e;
}

/* ---- 5. large deformation, turned and upright ------------------------ */

static const char *upright =
  "[scene]\nmodel = plane_strain\nlarge_deformation = yes\n"
  "[mesh]\nfile = taylor2d.geo\n"
  "[material all]\nE = 2000\nnu = 0.3\n"
  "[dirichlet lower_left]\ngroup = lower_left\nsymmetry = x\n"
  "[dirichlet upper_left]\ngroup = upper_left\nsymmetry = x\n"
  "[dirichlet bottom]\ngroup = lower_bottom\nsymmetry = y\n"
  "[load top]\ngroup = upper_top\npressure = 25\n"
  "[contact interface]\nslave = upper_bottom\nmaster = lower_top\n";

static void
large_turned (const char *element, const char *strategy)
{
  char s1[64], s2[80];
  const char *set[4] = { s1, s2, "scene.large_deformation=yes",
                         "output.reactions=yes" };
  const char *key[2] = { "lambda_min", "max_u" };
  lac_scene *sc[2] = { NULL, NULL };
  lac_run *r[2];
  int st[2];
  snprintf (s1, sizeof s1, "element=%s", element);
  snprintf (s2, sizeof s2, "contact.interface.strategy=%s", strategy);
  r[0] = run (NULL, upright, "chapters/08-experiments/t441.scene", 2, set,
              &st[0], &sc[0]);
  r[1] = run ("chapters/08-experiments/taylor2d-rotated.scene", NULL, NULL,
              4, set, &st[1], &sc[1]);
  check_status (st[0], LAC_SUCCESS, "large upright %s %s", element, strategy);
  check_status (st[1], LAC_SUCCESS, "large turned %s %s", element, strategy);
  if (!st[0] && !st[1])
    {
      double v[2], R[2] = { 0, 0 }, W = 25.0 * 50, c = cos (PI / 6);
      for (int k = 0; k < 2; k++)
        {
          for (int i = 0; i < 2; i++)
            v[i] = atof (lac_run_summary_get (r[i], key[k]));
          check_rel (v[1], v[0], 1e-10, "large %s %s: %s as upright",
                     element, strategy, key[k]);
        }
      check_int (atol (lac_run_summary_get (r[1], "newton_iterations")),
                 atol (lac_run_summary_get (r[0], "newton_iterations")),
                 "large %s %s: the Newton iterations as upright", element,
                 strategy);
      check_true (summary_vec (r[1], "reaction.bottom", 2, R), "reaction");
      check_abs (R[0], -W / 2, 1e-10 * W, "large %s: bottom reaction x",
                 element);
      check_abs (R[1], W * c, 1e-10 * W, "large %s: bottom reaction y",
                 element);
    }
  for (int i = 0; i < 2; i++)
    {
      lac_run_free (r[i]);
      lac_scene_free (sc[i]);
    }
}

/* ---- 6. contradictory conditions ------------------------------------- */

static void
contradiction (void)
{
  static const char *text =
    "[scene]\nmodel = plane_strain\n"
    "[mesh]\nfile = taylor2d.geo\n"
    "[material all]\nE = 2000\nnu = 0.3\n"
    "[dirichlet bottom]\ngroup = lower_bottom\nnormal = 0\n"
    "[dirichlet lift]\ngroup = lower_bottom\nuy = 0.5\n";
  lac_scene *sc = NULL;
  int st;
  lac_run *r = run (NULL, text, "chapters/08-experiments/t441.scene", 0,
                    NULL, &st, &sc);
  check_status (st, LAC_EINVAL, "a roller and uy = 0.5 on one face");
  check_message ("[dirichlet lift]", "... names the later section");
  check_message ("[dirichlet bottom], line", "... and the earlier one");
  check_message ("u.(0, 1) = 0.5", "... and the direction");
  lac_run_free (r);
  lac_scene_free (sc);
}

/* ---- 4. the shrink fit ------------------------------------------------ */

static double
shrink_fit_error (int level, double p)
{
  char s1[32];
  const char *set[1] = { s1 };
  lac_scene *sc = NULL;
  int st;
  long off = 0;
  double e = HUGE_VAL;
  snprintf (s1, sizeof s1, "mesh.level=%d", level);
  lac_run *r = run ("chapters/08-experiments/shrink-fit.scene", NULL, NULL, 1,
                    set, &st, &sc);
  check_status (st, LAC_SUCCESS, "shrink fit, level %d", level);
  if (!st)
    e = lambda_error (r, -p, &off) / p;
  check_int (off, 0, "shrink fit level %d: every multiplier active", level);
  lac_run_free (r);
  lac_scene_free (sc);
  return e;
}

int
main (void)
{
  const char *el[5] = { "tri3", "tri6", "quad4", "quad8", "quad9" };
  const char *st[4] = { "dense", "augmented", "split", "saddle" };
  worst w = { 0, 0 };
  lac_init ();
  for (int e = 0; e < 5; e++)
    for (int s = 0; s < 4; s++)
      turned_patch (el[e], st[s], &w);
  printf ("turned patch: max |lambda + p| / p = %.1e, max reaction error / "
          "load = %.1e\n", w.lambda, w.reaction);
  for (int e = 2; e < 4; e++)
    for (int s = 0; s < 3; s += 2)
      large_turned (el[e], st[s]);
  contradiction ();
  patch3d ("hex8");
  patch3d ("tet10");
  double e1 = sphere_error (1), e2 = sphere_error (2);
  check_true (e2 < e1 / 6, "curved roller: order 3 (%.3e, %.3e)", e1, e2);
  check_abs (e2, 0, 2e-4, "curved roller: level 2 close to the exact u");
  /* Lame (plane strain): p = E' delta (c^2 - b^2)(b^2 - a^2)
   *                          / (2 b^3 (c^2 - a^2)), E' = E / (1 - nu^2) */
  double a = 10, b = 20, c = 30, delta = 0.01, Ep = 2000 / (1 - 0.09);
  double p = Ep * delta * (c * c - b * b) * (b * b - a * a)
             / (2 * b * b * b * (c * c - a * a));
  double f[3];
  for (int l = 0; l < 3; l++)
    {
      f[l] = shrink_fit_error (l, p);
      printf ("shrink fit level %d: max |lambda + p| / p = %.3e\n", l, f[l]);
    }
  check_true (f[1] < f[0] / 6 && f[2] < f[1] / 6, "shrink fit converges");
  check_abs (f[2], 0, 4e-4, "shrink fit: Lame's pressure at level 2");
  lac_finalize ();
  return check_summary ();
}
