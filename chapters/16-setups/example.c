/* LAC chapter 16 -- Contact set-ups: a compound ring
 *                             [LAC §2, (16)-(18); Timoshenko & Goodier §28]
 *
 * Build:        make build/chapters/16-setups
 * Sample runs:  build/chapters/16-setups        (from the repository root:
 *                                               it reads compound.scene)
 *               build/chapters/16-setups DIR    (the scene in DIR)
 * Description:  three rings shrunk on one another (compound.scene, a 60
 *               degree sector, quad8, plane strain): two contact pairs,
 *               the middle ring the master of one and the slave of the
 *               other, each pair with its own interference; a pressure in
 *               the bore; a symmetry plane at theta = 0 and an inclined
 *               roller at theta = 60 degrees, whose reactions the run
 *               reports.  Lame's solution ring by ring gives the two fit
 *               pressures; the program compares every multiplier of each
 *               pair with them at three levels, each pair's force with
 *               the resultant of its pressure, and checks that the
 *               supports balance the bore pressure.  Short, deterministic
 *               output.
 * Read first:   chapter 06 (C, G, the sign of lambda), chapter 08 (a run
 *               from a program).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"

/* The data of compound.scene and compound.geo. */
static const double E = 2000, NU = 0.3, PB = 1;  /* bore pressure         */
static const double R[4] = { 10, 20, 30, 40 };    /* a, b, c, d            */
static const double DELTA[2] = { 0.01, 0.005 };  /* at b (fit12), c (fit23) */
static const double THETA = 60;                  /* degrees                */

// @sect Lame's rings, one after the other
/* A ring $r_0 < r < r_1$ under a pressure $q_0$ inside and $q_1$ outside
 * has $\sigma_{rr} = A - B/r^2$, $\sigma_{\theta\theta} = A + B/r^2$ with
 * $A = (q_0 r_0^2 - q_1 r_1^2)/(r_1^2 - r_0^2)$,
 * $B = (q_0 - q_1)\, r_0^2 r_1^2/(r_1^2 - r_0^2)$, and the radial
 * displacement
 * $u(r) = \frac{r}{E'}\big((1 - \nu')A + (1 + \nu')B/r^2\big)$, with
 * $E' = E/(1-\nu^2)$ and $\nu' = \nu/(1-\nu)$ in plane strain. */
static double
lame_u (double r, double r0, double r1, double q0, double q1)
{
  double Ep = E / (1 - NU * NU), nup = NU / (1 - NU);
  double A = (q0 * r0 * r0 - q1 * r1 * r1) / (r1 * r1 - r0 * r0);
  double B = (q0 - q1) * r0 * r0 * r1 * r1 / (r1 * r1 - r0 * r0);
  return r / Ep * ((1 - nup) * A + (1 + nup) * B / (r * r));
}

/* The gaps that the fit pressures $p_1$ (at $b$) and $p_2$ (at $c$) must
 * close: the outer ring's bore grows, the inner ring's rim shrinks, and
 * together they take up the interference,
 * $u_{k+1}(r_k) - u_k(r_k) = \delta_k$.  The residual of both. */
static void
fit_residual (const double p[2], double res[2])
{
  res[0] = lame_u (R[1], R[1], R[2], p[0], p[1])
         - lame_u (R[1], R[0], R[1], PB, p[0]) - DELTA[0];
  res[1] = lame_u (R[2], R[2], R[3], p[1], 0)
         - lame_u (R[2], R[1], R[2], p[0], p[1]) - DELTA[1];
}

/* Displacements are linear in the pressures, so the residual is affine:
 * its value at 0 and two differences give the 2 x 2 system, solved by
 * Cramer's rule. */
static void
fit_pressures (double p[2])
{
  double z[2] = { 0, 0 }, e0[2] = { 1, 0 }, e1[2] = { 0, 1 };
  double f[2], c0[2], c1[2];
  fit_residual (z, f);
  fit_residual (e0, c0);
  fit_residual (e1, c1);
  for (int k = 0; k < 2; k++)
    c0[k] -= f[k], c1[k] -= f[k];
  double det = c0[0] * c1[1] - c1[0] * c0[1];
  p[0] = (-f[0] * c1[1] + c1[0] * f[1]) / det;
  p[1] = (-c0[0] * f[1] + f[0] * c0[1]) / det;
}

// @sect A run from a program
/* As in chapter 08: the scene read with its overrides, the whole pipeline
 * of `lac run` without files, the summary read back.  A library call that
 * fails stops the program with the message the library stored. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex16: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

static lac_run *
run_scene (const char *path, int level, lac_scene **sc)
{
  char s[32];
  const char *set[1] = { s };
  lac_run_opts o = { NULL, 0, 1, LAC_STRATEGY_AUTO, 0, NULL, 0, 0 };
  snprintf (s, sizeof s, "level=%d", level);
  check_status (lac_scene_read (path, 1, set, sc), path);
  lac_run *r = lac_run_alloc (*sc, &o);
  if (!r)
    check_status (LAC_ENOMEM, "lac_run_alloc");
  check_status (lac_run_all (r), path);
  return r;
}

/* A vector of the summary ("reaction.cut1 = Rx Ry"); 0 if absent. */
static void
vec (const lac_run *r, const char *key, double v[2])
{
  const char *s = lac_run_summary_get (r, key);
  v[0] = v[1] = 0;
  if (!s || sscanf (s, "%lf %lf", &v[0], &v[1]) != 2)
    check_status (LAC_EINVAL, key);
}

// @sect The multipliers, pair by pair
/* The loop of Algorithm 1 sees one vector of multipliers; the columns of
 * pair $p$ in the contact data of the run are col[p] .. col[p+1] - 1,
 * column $i$ the multiplier of slot macro[i] (chapter 16, section 1).
 * For each pair, the extreme multipliers and the largest relative
 * distance to $-p_k$. */
static double
pair_error (const lac_run *r, size_t p, double pk, double *lmin, double *lmax,
            size_t *n)
{
  const lac_contact *c = r->sys.contact;
  const size_t *col = r->setup.data.col;
  const double *lambda = r->sol.newton->lambda;
  double worst = 0;
  *lmin = INFINITY;
  *lmax = -INFINITY;
  *n = col[p + 1] - col[p];
  for (size_t i = col[p]; i < col[p + 1]; i++)
    {
      double l = lambda[c->macro[i]];
      *lmin = fmin (*lmin, l);
      *lmax = fmax (*lmax, l);
      worst = fmax (worst, fabs (l + pk) / pk);
    }
  return worst;
}

// @sect One level
/* The two pairs against Lame, then the forces.  A uniform pressure $q$ on
 * an arc of radius $\rho$ from $\theta = 0$ to $\Theta$ has the resultant
 * $q\rho\,(\sin\Theta,\ 1 - \cos\Theta)$, whatever the polygon or the
 * curved cells between the arc's two end points: this is the force each
 * pair's master exerts on its slave ring, inward, and the bore pressure's
 * force on the whole, outward.  The supports take the rest:
 * reaction.cut0 + reaction.cut1 + the bore's resultant = 0.  The cut at
 * $\Theta$ carries the hoop force $N = \int_a^d \sigma_{\theta\theta}\,dr
 * = [r\sigma_{rr}]_a^d = a\,p_b$ along its normal: the fits are
 * self-equilibrated and add nothing to it. */
static void
level_row (const char *path, int level, const double pk[2])
{
  lac_scene *sc = NULL;
  lac_run *r = run_scene (path, level, &sc);
  double t = THETA * acos (-1.0) / 180, s[2] = { sin (t), 1 - cos (t) };
  static const char *name[2] = { "fit12", "fit23" };
  for (size_t p = 0; p < 2; p++)
    {
      double lmin, lmax, f[2];
      size_t n;
      double err = pair_error (r, p, pk[p], &lmin, &lmax, &n);
      char key[64];
      snprintf (key, sizeof key, "contact_force.%s", name[p]);
      vec (r, key, f);
      double fe = hypot (f[0] + pk[p] * R[p + 1] * s[0],
                         f[1] + pk[p] * R[p + 1] * s[1])
                  / (pk[p] * R[p + 1] * hypot (s[0], s[1]));
      printf ("%5d  %-5s %4zu  %10.6f  %10.6f  %9.2e  %9.2e\n", level,
              name[p], n, lmin, lmax, err, fe);
    }
  double r0[2], r1[2];
  vec (r, "reaction.cut0", r0);
  vec (r, "reaction.cut1", r1);
  double bal = hypot (r0[0] + r1[0] + PB * R[0] * s[0],
                      r0[1] + r1[1] + PB * R[0] * s[1]);
  double N = hypot (r1[0], r1[1]);
  printf ("       cut0 (%7.4f, %7.4f)  cut1 (%7.4f, %7.4f)  |N - a p| %s  "
          "balance %s\n", r0[0] + 0.0, r0[1], r1[0], r1[1],
          fabs (N - PB * R[0]) < 1e-10 ? "< 1e-10" : "LARGER",
          bal < 1e-10 ? "< 1e-10" : "LARGER");
  lac_run_free (r);
  lac_scene_free (sc);
}

// @sect The main program
/* The closed form once, then levels 0, 1, 2: 14, 28, 56 multipliers.
 * The multipliers close in on the two fit pressures; the contact forces
 * and the reactions are the resultants of the pressures at every level. */
int
main (int argc, char **argv)
{
  char path[512];
  double pk[2];
  snprintf (path, sizeof path, "%s/compound.scene",
            argc > 1 ? argv[1] : "chapters/16-setups");
  fit_pressures (pk);
  printf ("compound ring: delta = %g at r = %g, %g at r = %g; p = %g in the "
          "bore\n", DELTA[0], R[1], DELTA[1], R[2], PB);
  printf ("Lame: p12 = %.7f, p23 = %.7f; the cut at 60 degrees carries "
          "a p = %g\n\n", pk[0], pk[1], PB * R[0]);
  printf ("level  pair  mult  lambda_min  lambda_max  max|l+p|/p  force err\n");
  for (int level = 0; level <= 2; level++)
    level_row (path, level, pk);
  return 0;
}
