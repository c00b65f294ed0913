/* t420: the manufactured solutions of [LAC §5.3] and their loads
 *
 * grad u against finite differences of u, the body force from the Hessians
 * against finite differences of sigma (f = -div sigma) for several
 * materials, and against the hand derivation for E = 1, nu = 0 (sigma =
 * eps):  2D  f = (0.05 (x-1/2) + 0.6 y (x-1/2),  0.3 y^2 + 0.05 (1 + y));
 *        3D  f = (-0.1 z^2 - 0.2 x y + 0.002 x, -0.1 z^2 - 0.2 x y + 0.002 y,
 *                 0.4 (1 + 0.01 z) - 0.2 z (x + y)).
 * The gap closes on the contact side (u_v = the obstacle's height there),
 * and the contact pressure n.sigma.n there is negative (compression).
 */
#include <math.h>
#include "check.h"
#include "fem/lac_exact.h"
#include "base/lac_status.h"

static double
rnd (unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return (double) ((*s >> 8) & 0xffff) / 65535.0;
}

static void
check_solution (int kind, lac_model model, double E, double nu)
{
  lac_exact_params par = { 0, 0, 0, E, nu, 0 };
  lac_exact e;
  lac_exact_init (&e, kind, model, &par);
  int d = e.dim;
  unsigned seed = 7;
  const double hs = 1e-5;
  for (int t = 0; t < 20; t++)
    {
      double x[3], g[9], f[3], u1[3], u2[3], s1[6], s2[6];
      for (int k = 0; k < d; k++)
        x[k] = rnd (&seed);
      lac_exact_grad (x, &e, g);
      lac_exact_force (x, &e, f);
      for (int j = 0; j < d; j++)                    /* grad u by FD */
        {
          double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
          xp[j] += hs, xm[j] -= hs;
          lac_exact_u (xp, &e, u1);
          lac_exact_u (xm, &e, u2);
          for (int i = 0; i < d; i++)
            check_abs (g[i * d + j], (u1[i] - u2[i]) / (2 * hs), 1e-8,
                       "%s: du_%d/dx_%d", lac_exact_name (kind), i, j);
        }
      double divs[3] = { 0, 0, 0 };                  /* div sigma by FD */
      static const int v2[2][2] = { { 0, 3 }, { 3, 1 } };
      static const int v3[3][3] = { { 0, 3, 5 }, { 3, 1, 4 }, { 5, 4, 2 } };
      for (int j = 0; j < d; j++)
        {
          double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
          xp[j] += hs, xm[j] -= hs;
          lac_exact_sigma (xp, &e, s1);
          lac_exact_sigma (xm, &e, s2);
          for (int i = 0; i < d; i++)
            {
              int v = d == 2 ? v2[i][j] : v3[i][j];
              divs[i] += (s1[v] - s2[v]) / (2 * hs);
            }
        }
      for (int i = 0; i < d; i++)
        check_abs (f[i], -divs[i], 1e-7 * (1 + E), "%s E=%g nu=%g: f_%d = -div sigma",
                   lac_exact_name (kind), E, nu, i);
      if (E == 1 && nu == 0)
        {
          double X = x[0], Y = x[1], Z = x[2], want[3];
          if (d == 2)
            {
              want[0] = 0.05 * (X - 0.5) + 0.6 * Y * (X - 0.5);
              want[1] = 0.3 * Y * Y + 0.05 * (1 + Y);
            }
          else
            {
              want[0] = -0.1 * Z * Z - 0.2 * X * Y + 0.002 * X;
              want[1] = -0.1 * Z * Z - 0.2 * X * Y + 0.002 * Y;
              want[2] = 0.4 * (1 + 0.01 * Z) - 0.2 * Z * (X + Y);
            }
          for (int i = 0; i < d; i++)
            check_abs (f[i], want[i], 1e-15, "%s: f_%d by hand", lac_exact_name (kind), i);
        }
      /* the contact side v = 0: gap closed, compression */
      double xc[3] = { x[0], x[1], 0 }, n[3] = { 0, 0, 0 }, u[3];
      xc[d - 1] = 0;
      n[d - 1] = -1;
      lac_exact_u (xc, &e, u);
      double h = d == 2 ? -0.05 * (x[0] - 0.5) * (x[0] - 0.5)
                        : -0.2 * (1 + x[0] * x[0] + x[1] * x[1]) - 0.3;
      check_abs (u[d - 1], h, 1e-15, "%s: gap closed", lac_exact_name (kind));
      check_true (lac_exact_normal_stress (&e, xc, n) < 0, "%s: compression",
                  lac_exact_name (kind));
    }
}

int
main (void)
{
  lac_init ();
  int k2 = lac_exact_find ("manufactured2d"), k3 = lac_exact_find ("manufactured3d");
  check_true (k2 >= 0 && k3 >= 0, "solutions in the table");
  check_solution (k2, LAC_PLANE_STRAIN, 1, 0);
  check_solution (k2, LAC_PLANE_STRAIN, 2000, 0.3);
  check_solution (k3, LAC_SOLID3D, 1, 0);
  check_solution (k3, LAC_SOLID3D, 7, 0.25);
  lac_finalize ();
  return check_summary ();
}
