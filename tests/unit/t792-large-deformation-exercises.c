/* t792-large-deformation-exercises.c -- the answers of
 * chapters/10-large-deformation/exercises.md      [LAC §4.5, §5.4; Hertz]
 *
 * Exercise 1 (Hertz, cylinder): a = sqrt(4 P R / (pi E*)), p0 = 2 P /
 *   (pi a): 0.20138 mm and 2212.93 MPa on the rigid flat (E* = E / (1 -
 *   nu^2)), 0.28479 mm and 1564.78 MPa on the steel block (E* halved);
 *   hertz-cylinder.scene quad8 level 2: max_contact_pressure within 0.1 %
 *   of p0, contact_force = -P/2 (half model) to 1e-9.
 * Exercise 2 (the neo-Hookean law at F = I): the tangent A of
 *   lac_hyper_stress is Hooke's tensor lambda d_iJ d_kL + mu (d_ik d_JL +
 *   d_iL d_Jk) to 1e-12, P = 0; under F = diag(1 + e, 1, 1), P_xx =
 *   mu ((1 + e) - 1 / (1 + e)) + lambda ln(1 + e) / (1 + e) (1e-12), and
 *   the relative difference with Hooke's (lambda + 2 mu) e is -0.0832 at
 *   e = 0.1 (1e-3).
 * Exercise 3 (frame indifference): a rigid rotation F = R gives P = 0 for
 *   both laws (1e-12); R times a stretch gives R times the stretch's P.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "base/lac_status.h"
#include "fem/lac_hyper.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"

#define D10 "chapters/10-large-deformation/"

/* ---- exercise 1 ------------------------------------------------------ */

static void
exercise1 (void)
{
  const double pi = acos (-1.0), P = 700, R = 10, E = 2e5, nu = 0.3;
  const double Es[2] = { E / (1 - nu * nu), E / (2 * (1 - nu * nu)) };
  const double a_want[2] = { 0.20138, 0.28479 }, p_want[2] = { 2212.93, 1564.78 };
  double p0 = 0;
  for (int k = 0; k < 2; k++)
    {
      double a = sqrt (4 * P * R / (pi * Es[k])), p = 2 * P / (pi * a);
      check_rel (a, a_want[k], 2e-5, "ex1: a (%s)", k ? "block" : "rigid");
      check_rel (p, p_want[k], 2e-6, "ex1: p0 (%s)", k ? "block" : "rigid");
      if (k == 0)
        p0 = p;
    }
  const char *set[2] = { "element=quad8", "level=2" };
  lac_scene *sc;
  lac_run *r = check_run_scene (D10 "hertz-cylinder.scene", 2, set, &sc);
  if (!r)
    return;
  check_rel (check_run_value (r, "max_contact_pressure"), p0, 1e-3,
             "ex1: p_max");
  check_rel (check_run_value (r, "contact_force"), -P / 2, 1e-9,
             "ex1: contact force");
  check_run_done (r, sc);
}

/* ---- exercises 2 and 3 ------------------------------------------------ */

static void
stress (lac_law law, const double *F, double *P, double *A)
{
  check_status (lac_hyper_stress (law, 1000, 0.3, F, P, A), LAC_SUCCESS,
                "lac_hyper_stress");
}

static void
exercise2 (void)
{
  double lam, mu, P[9], A[81];
  check_status (lac_hyper_lame (1000, 0.3, &lam, &mu), LAC_SUCCESS, "lame");
  const double I[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  stress (LAC_LAW_NEO_HOOKEAN, I, P, A);
  for (int i = 0; i < 3; i++)
    for (int J = 0; J < 3; J++)
      {
        check_true (fabs (P[i * 3 + J]) < 1e-12, "ex2: P(I)_%d%d", i, J);
        for (int k = 0; k < 3; k++)
          for (int L = 0; L < 3; L++)
            {
              double h = lam * I[i * 3 + J] * I[k * 3 + L]
                         + mu * (I[i * 3 + k] * I[J * 3 + L]
                                 + I[i * 3 + L] * I[J * 3 + k]);
              check_true (fabs (A[((i * 3 + J) * 3 + k) * 3 + L] - h)
                          < 1e-12 * (lam + 2 * mu),
                          "ex2: A(I)_%d%d%d%d", i, J, k, L);
            }
      }
  double e = 0.1, F[9] = { 1 + e, 0, 0, 0, 1, 0, 0, 0, 1 };
  stress (LAC_LAW_NEO_HOOKEAN, F, P, NULL);
  double pxx = mu * ((1 + e) - 1 / (1 + e)) + lam * log (1 + e) / (1 + e);
  check_rel (P[0], pxx, 1e-12, "ex2: P_xx(e = 0.1)");
  check_rel ((P[0] - (lam + 2 * mu) * e) / ((lam + 2 * mu) * e), -0.0832,
             1e-3, "ex2: -8.3 %% from Hooke at e = 0.1");
}

static void
exercise3 (void)
{
  const double t = 0.5, c = cos (t), s = sin (t);
  const double Rm[9] = { c, -s, 0, s, c, 0, 0, 0, 1 };
  const double U[9] = { 1.2, 0, 0, 0, 0.9, 0, 0, 0, 1.05 };
  for (int law = 0; law < 2; law++)
    {
      double P[9], PU[9], F[9];
      stress ((lac_law) law, Rm, P, NULL);
      for (int k = 0; k < 9; k++)
        check_true (fabs (P[k]) < 1e-12, "ex3 %s: P(R)[%d] = %g",
                    lac_law_name ((lac_law) law), k, P[k]);
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
          {
            F[i * 3 + j] = 0;
            for (int k = 0; k < 3; k++)
              F[i * 3 + j] += Rm[i * 3 + k] * U[k * 3 + j];
          }
      stress ((lac_law) law, U, PU, NULL);
      stress ((lac_law) law, F, P, NULL);
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
          {
            double rp = 0;
            for (int k = 0; k < 3; k++)
              rp += Rm[i * 3 + k] * PU[k * 3 + j];
            check_true (fabs (P[i * 3 + j] - rp) < 1e-12 * 1000,
                        "ex3 %s: P(RU) = R P(U) [%d%d]",
                        lac_law_name ((lac_law) law), i, j);
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
