/* t957: hard case -- a nearly incompressible material, nu = 0.499
 *                                        [LAC §5.1; issue 6 item 3]
 *
 * 1. The Taylor patch test (t95-hard.h; 8 cells below, 6 above in 2D, 3
 *    and 2 in 3D) with nu = 0.499 in both blocks
 *    (plane strain: lambda_Lame / mu = 2 nu / (1 - 2 nu) = 499).  The
 *    uniform state (sigma_vv = lambda = -25, sigma_zz = -nu p) is a linear
 *    displacement field, which every element reproduces whatever nu: no
 *    locking on the patch test, lambda exact to rounding (1e-10: the
 *    stiffness has eigenvalues 500 times larger than with nu = 0.3).
 * 2. The grazing bump of t953 with nu = 0.499: the active set converges
 *    (at most 15 iterations), complementarity, force balance.
 * Locking of linear elements shows in the error of a solution that is not
 * linear: chapters/11-infsup/hard-cases.sh runs the manufactured solution
 * of chapter 09 (manufactured2d.scene) with nu = 0 and 0.499: relative L2
 * error of u, level 2, tri3 1.6e-2 -> 3.5e-1 (locking), quad4 4.4e-3 ->
 * 1.2e-2, tri6 7.6e-5 -> 3.7e-3.  That is the element, not the contact:
 * not a failure of this test.
 * beta_h uses the H1 norm and does not depend on nu: >= 0.4 (2D), 0.1 (3D).
 */
#include "t95-hard.h"

static void
patch (const char *name, lac_elem_type t, double beta_min)
{
  size_t lo[3] = { 8, 8, 8 }, up[3] = { 6, 6, 6 };
  if (lac_refelem_get (t)->dim == 3)
    lo[0] = lo[1] = lo[2] = 3, up[0] = up[1] = up[2] = 2;
  hard_spec sp;
  hard_taylor (&sp, name, t, lo, t, up, 0);
  sp.lo.nu = sp.up.nu = 0.499;
  sp.show_rcond = 1;
  hard_check_taylor (&sp, 1, 1e-10, beta_min);
}

static void
grazing (const char *name, lac_elem_type t, double beta_min)
{
  hard_spec sp;
  memset (&sp, 0, sizeof sp);
  sp.name = name;
  sp.model = LAC_PLANE_STRAIN;
  sp.nbodies = 1;
  sp.up = (hard_body) { t, { 10, 10, 1 }, { 50, 50, 50 }, { 0, 50, 0 },
                        2000, 0.499, NULL, NULL };
  sp.slave = "ymin";
  sp.ob = (lac_obstacle) { 2, 50.0, { -0.002, 0 }, { 0, 0 }, 0 };
  sp.load = "ymax";
  sp.p = HARD_P;
  sp.fix[sp.nfix++] = (hard_fix) { "xmin", 0, 0 };
  sp.maxit = 15;
  hard h;
  int st = hard_run (&sp, &h);
  double beta = hard_beta (&h), err = -1;
  check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", name,
                h.stage ? h.stage : "-");
  check_true (beta >= beta_min, "%s: beta_h %.4e", name, beta);
  int pass = !st && beta >= beta_min;
  if (!st)
    {
      int fin = hard_finite (&h), cp = hard_complementarity (&h, 1e-8);
      size_t na = lac_newton_nactive (h.s);
      err = hard_err_balance (&h, "body", 1);
      check_true (fin, "%s: finite", name);
      check_true (cp, "%s: complementarity", name);
      check_true (h.s->nhist <= 15, "%s: %zu iterations", name, h.s->nhist);
      check_true (err <= 1e-10, "%s: force balance %.2e", name, err);
      check_true (na > 0 && na < h.c->k, "%s: %zu of %zu active", name, na,
                  h.c->k);
      pass = pass && fin && cp && h.s->nhist <= 15 && err <= 1e-10 && na > 0
        && na < h.c->k;
    }
  hard_row (&h, "force", err, pass);
  hard_free (&h);
}

int
main (void)
{
  lac_init ();
  patch ("nu 0.499 patch, tri3", LAC_TRI3, 0.4);
  patch ("nu 0.499 patch, quad4", LAC_QUAD4, 0.4);
  patch ("nu 0.499 patch, tri6", LAC_TRI6, 0.4);
  patch ("nu 0.499 patch, hex8", LAC_HEX8, 0.1);
  patch ("nu 0.499 patch, tet4", LAC_TET4, 0.1);
  grazing ("nu 0.499 grazing bump, quad4", LAC_QUAD4, 0.3);
  grazing ("nu 0.499 grazing bump, tri3", LAC_TRI3, 0.3);
  lac_finalize ();
  return check_summary ();
}
