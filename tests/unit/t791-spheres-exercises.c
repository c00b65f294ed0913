/* t791-spheres-exercises.c -- the answers of
 * chapters/09-spheres-rates/exercises.md               [LAC §5.2-§5.3]
 *
 * Everything is computed here from small runs of the chapter's scenes
 * (run/lac_run.h, no files written) and compared with closed forms.
 *
 * Exercise 1 (the spheres, axisymmetric, quad8 level 2): the closed forms
 *   lambda = -925/189, u_R(20) = 0.2, u_R(40) = 0.075 against lac_exact
 *   (1e-14); the run: lambda_min, lambda_max within 1e-4 of lambda,
 *   u_r_inner within 1e-5, contact_area = 1800 pi within 1e-5,
 *   contact_force = 900 pi lambda within 1e-4.
 * Exercise 2 (manufactured2d): e_P0 = 0.05 sqrt((5N^2 - 4) / 180) / N^2
 *   (2.0306e-3, 1.0351e-3, 5.2002e-4 for N = 4, 8, 16) against
 *   sqrt(l2_err_lambda^2 - e_avg^2) of quad4 levels 1, 2 (N = 4, 8) and
 *   quad8 levels 1, 2 (N = 8, 16), e_avg from the multipliers and the
 *   means of the exact pressure (1e-6); l2_err_lambda at most 4 % above
 *   e_P0; quad8 level 1 and quad4 level 2: the same lambda error within
 *   4 %, u error 15 times smaller (within 5 %).
 * Exercise 3 (manufactured2d, levels 1-3): the observed rate of the L2
 *   error of u, log2(e_l / e_{l+1}), is 2.00 for quad4 and 3.00 for quad8
 *   (within 0.05); the rate of l2_err_lambda is 1 (within 0.05).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "base/lac_status.h"
#include "fem/lac_exact.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"

#define D9 "chapters/09-spheres-rates/"

/* ---- exercise 1 ------------------------------------------------------ */

static void
exercise1 (void)
{
  const double lam = -925.0 / 189.0, pi = acos (-1.0);
  /* the closed forms against the library's Lame solution */
  lac_exact_params par = { 20, 40, 25, 2000, 0.3, 0 };
  lac_exact e;
  lac_exact_init (&e, LAC_EXACT_THICK_SPHERE, LAC_AXISYMMETRIC, &par);
  double x30[2] = { 30, 0 }, n[2] = { 1, 0 }, u[2];
  check_rel (lac_exact_normal_stress (&e, x30, n), lam, 1e-14,
             "ex1: lambda = -925/189");
  check_rel (lam, -4.894179894, 1e-10, "ex1: -4.894179894");
  double x20[2] = { 0, 20 }, x40[2] = { 40 * sin (0.3), 40 * cos (0.3) };
  lac_exact_u (x20, &e, u);
  check_rel (hypot (u[0], u[1]), 0.2, 1e-14, "ex1: u_R(20) = 0.2");
  lac_exact_u (x40, &e, u);
  check_rel (hypot (u[0], u[1]), 0.075, 1e-14, "ex1: u_R(40) = 0.075");

  const char *set[2] = { "element=quad8", "level=2" };
  lac_scene *sc;
  lac_run *r = check_run_scene (D9 "spheres-axi.scene", 2, set, &sc);
  if (!r)
    return;
  check_rel (check_run_value (r, "lambda_min"), lam, 1e-4, "ex1: lambda_min");
  check_rel (check_run_value (r, "lambda_max"), lam, 1e-4, "ex1: lambda_max");
  check_true (check_run_value (r, "max_rel_err_lambda") < 1e-4,
              "ex1: max_rel_err_lambda %g",
              check_run_value (r, "max_rel_err_lambda"));
  check_rel (check_run_value (r, "u_r_inner"), 0.2, 1e-5, "ex1: u_r_inner");
  check_rel (check_run_value (r, "contact_area"), 1800 * pi, 1e-5,
             "ex1: contact_area = 2 pi R^2");
  check_rel (check_run_value (r, "contact_force"), 900 * pi * lam, 1e-4,
             "ex1: contact_force = pi R^2 lambda");
  check_rel (900 * pi * lam, -13838.0, 1e-5, "ex1: -13838.0");
  check_run_done (r, sc);
}

/* ---- exercise 2 ------------------------------------------------------ */

static double
ep0 (double N)
{
  return 0.05 * sqrt ((5 * N * N - 4) / 180) / (N * N);
}

typedef struct man
{
  double err_lam, e_p0, err_u;
  long N;
} man;

/* manufactured2d with ELEMENT at LEVEL: e_P0 = sqrt(err^2 - e_avg^2),
 * e_avg^2 = sum_i |T^i cap Gamma_C| (lambda_i - mean exact_i)^2. */
static man
manufactured (const char *element, int level)
{
  char s[2][64];
  const char *set[2] = { s[0], s[1] };
  lac_scene *sc;
  man x = { NAN, NAN, NAN, 0 };
  snprintf (s[0], sizeof s[0], "element=%s", element);
  snprintf (s[1], sizeof s[1], "level=%d", level);
  lac_run *r = check_run_scene (D9 "manufactured2d.scene", 2, set, &sc);
  if (!r)
    return x;
  const lac_newton *nw = r->sol.newton;
  const lac_contact *c = r->sys.contact;
  double avg2 = 0;
  for (size_t i = 0; i < c->k; i++)
    {
      double d = nw->lambda[c->macro[i]] - r->res.mult.exact[i];
      avg2 += c->area[i] * d * d;
    }
  x.err_lam = check_run_value (r, "l2_err_lambda");
  x.e_p0 = sqrt (x.err_lam * x.err_lam - avg2);
  x.err_u = check_run_value (r, "rel_l2_err_u");
  x.N = (long) c->k;
  check_run_done (r, sc);
  return x;
}

static void
exercise2 (void)
{
  check_rel (ep0 (4), 2.0306e-3, 1e-4, "ex2: e_P0(4)");
  check_rel (ep0 (8), 1.0351e-3, 1e-4, "ex2: e_P0(8)");
  check_rel (ep0 (16), 5.2002e-4, 1e-4, "ex2: e_P0(16)");
  const char *el[2] = { "quad4", "quad8" };
  const long N[2][2] = { { 4, 8 }, { 8, 16 } };
  man m[2][2];
  for (int e = 0; e < 2; e++)
    for (int l = 0; l < 2; l++)
      {
        m[e][l] = manufactured (el[e], l + 1);
        check_int (m[e][l].N, N[e][l], "ex2 %s level %d: N", el[e], l + 1);
        check_rel (m[e][l].e_p0, ep0 ((double) N[e][l]), 1e-6,
                   "ex2 %s level %d: e_P0", el[e], l + 1);
        check_true (m[e][l].err_lam >= m[e][l].e_p0
                    && m[e][l].err_lam <= 1.04 * m[e][l].e_p0,
                    "ex2 %s level %d: err_lambda %g within 4 %% above e_P0 %g",
                    el[e], l + 1, m[e][l].err_lam, m[e][l].e_p0);
      }
  check_rel (m[1][0].err_lam, m[0][1].err_lam, 0.04,
             "ex2: quad8 level 1 and quad4 level 2, same lambda error");
  check_rel (m[0][1].err_u / m[1][0].err_u, 15.0, 0.05,
             "ex2: quad8's u error 15 times smaller (%g)",
             m[0][1].err_u / m[1][0].err_u);
}

/* ---- exercise 3 ------------------------------------------------------ */

static void
exercise3 (void)
{
  const char *el[2] = { "quad4", "quad8" };
  const double pu[2] = { 2.0, 3.0 };
  for (int e = 0; e < 2; e++)
    {
      double eu[3], el_[3];
      for (int l = 0; l < 3; l++)
        {
          char s[2][64];
          const char *set[2] = { s[0], s[1] };
          lac_scene *sc;
          snprintf (s[0], sizeof s[0], "element=%s", el[e]);
          snprintf (s[1], sizeof s[1], "level=%d", l + 1);
          lac_run *r = check_run_scene (D9 "manufactured2d.scene", 2, set,
                                        &sc);
          if (!r)
            return;
          eu[l] = check_run_value (r, "l2_err_u");
          el_[l] = check_run_value (r, "l2_err_lambda");
          check_run_done (r, sc);
        }
      for (int l = 0; l < 2; l++)
        {
          double ru = log2 (eu[l] / eu[l + 1]), rl = log2 (el_[l] / el_[l + 1]);
          check_true (fabs (ru - pu[e]) < 0.05, "ex3 %s levels %d-%d: rate of u"
                      " %.3f, want %.0f", el[e], l + 1, l + 2, ru, pu[e]);
          check_true (fabs (rl - 1) < 0.05, "ex3 %s levels %d-%d: rate of "
                      "lambda %.3f, want 1", el[e], l + 1, l + 2, rl);
        }
    }
}

int
main (void)
{
  exercise1 ();
  exercise2 ();
  exercise3 ();
  return check_summary ();
}
