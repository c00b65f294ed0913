/* t956: hard case -- Young's modulus contrast of 1e6 between the bodies
 *                                        [LAC §5.1; issue 6 item 3]
 *
 * The Taylor patch test (t95-hard.h; 8 cells below, 6 above in 2D, 3 and
 * 2 in 3D) with E = 2000 in one block and 2e9 in the other (and the other
 * way round),
 * nu = 0.3.  The uniform state sigma_vv = lambda = -25 is still the exact
 * solution (the stress does not depend on E), and it is in the discrete
 * spaces, so lambda stays exact up to rounding amplified by the contrast.
 *
 * The saddle-point matrix mixes stiffnesses 2e9 and 2e3 with the C block:
 * its condition number is about contrast x cond(K) and grows like 1/h^2
 * (measured rcond, quad8, 8/6 cells 5.5e-13, 16/12 1.0e-13, 32/24 2.5e-14),
 * but the problem is not singular: a diagonal (Jacobi) scaling of the
 * saddle matrix removes the contrast.  The solve must not refuse it
 * (LAC_RCOND_MIN = 1e-13 applied to the unscaled matrix does, from 32/24
 * quad8 cells on; the rcond is in the table's status column).  A stiff
 * block held by the contact alone must also be recognised as converged:
 * its rigid translation makes the rounding of K U about 1e-16 ||K|| ||U||,
 * 1e-9 ||F|| for E = 2e9, above the relative residual tolerance 1e-10.
 * Asserted: 1 active-set iteration, finite, lambda and sigma_vv = -25 to
 * 1e-6 (rounding amplified by the contrast: measured 1e-14 with the stiff
 * block below, 4e-10 .. 2e-8 with the stiff block floating above),
 * beta_h >= 0.5 (2D), 0.2 (3D) -- beta_h uses the H1 norm, which does not
 * see E.
 */
#include "t95-hard.h"

static void
contrast_n (const char *name, lac_elem_type t, size_t n, double Elo,
            double Eup, int swap, double beta_min)
{
  size_t lo[3] = { n, n, n }, up[3] = { 3 * n / 4, 3 * n / 4, 3 * n / 4 };
  if (lac_refelem_get (t)->dim == 3)
    lo[0] = lo[1] = lo[2] = 3, up[0] = up[1] = up[2] = 2;
  hard_spec sp;
  hard_taylor (&sp, name, t, lo, t, up, swap);
  sp.lo.E = Elo;
  sp.up.E = Eup;
  sp.show_rcond = 1;
  hard_check_taylor (&sp, 1, 1e-6, beta_min);
}

static void
contrast (const char *name, lac_elem_type t, double Elo, double Eup,
          int swap, double beta_min)
{
  contrast_n (name, t, 8, Elo, Eup, swap, beta_min);
}

int
main (void)
{
  lac_init ();
  contrast ("E 2e9 below / 2e3 above, quad4", LAC_QUAD4, 2e9, 2e3, 0, 0.5);
  contrast ("E 2e3 below / 2e9 above, quad4", LAC_QUAD4, 2e3, 2e9, 0, 0.5);
  contrast ("E 2e9 / 2e3, quad4, slave lower", LAC_QUAD4, 2e9, 2e3, 1, 0.5);
  contrast ("E 2e3 / 2e9, tri6", LAC_TRI6, 2e3, 2e9, 0, 0.5);
  contrast ("E 2e9 / 2e3, quad8", LAC_QUAD8, 2e9, 2e3, 0, 0.5);
  contrast ("E 2e9 / 2e3, hex8", LAC_HEX8, 2e9, 2e3, 0, 0.2);
  contrast ("E 2e3 / 2e9, tet10", LAC_TET10, 2e3, 2e9, 0, 0.2);
  contrast ("E 2e3 / 2e9, hex20", LAC_HEX20, 2e3, 2e9, 1, 0.2);
  /* finer: the condition number of the saddle matrix grows like
   * contrast / h^2 (measured rcond quad8: 5.5e-13, 1.0e-13 for n = 8, 16) */
  contrast_n ("E 2e9 / 2e3, quad8, 32/24 cells", LAC_QUAD8, 32, 2e9, 2e3, 0,
              0.5);
  lac_finalize ();
  return check_summary ();
}
