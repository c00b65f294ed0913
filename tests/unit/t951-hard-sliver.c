/* t951: hard case -- a slave macro-element overlapped on a sliver
 *                         [LAC Def. 1, Thm. 2, App. A; issue 6 item 3]
 *
 * The non-conforming set-up of t470 (t95-hard.h, hard_narrow): the slave is
 * the top of a rigid base of 4 cells (h = 12.5; quad4: two macro-elements
 * [0,25] and [25,50]), the master the bottom of a block [0, Lm] pressed
 * with p = 25.  The master ends 1e-8 h into a slave element:
 *
 *   Lm = 25 + 1e-8 h   macro-element [25,50] covered on delta = 5e-9 of its
 *                      length; criterion phibar sqrt(delta) = delta^{3/2}
 *                      = 3.5e-13 (quad4), 2e-12 (quad8), 1e-12 (hex8)
 *   Lm = 50 - 1e-8 h   the last macro-element covered on 1 - 5e-9
 *
 * Expected:
 *  - default epsilon (1e-2): the sliver is not admissible (Definition 1),
 *    the solution is finite, one active-set iteration, the total contact
 *    force balances the load exactly and lambda = -25 Lm / 25 on [0,25]
 *    (2D: relative error 5e-9 = delta against the uniform -25; 3D: 1.4e-8,
 *    the unsupported strip perturbs the neighbouring multipliers);
 *  - epsilon = 1e-14 (below the criterion): the sliver keeps its
 *    multiplier.  The discrete problem is well posed (beta_h = 7.3e-5 in
 *    2D, ~ sqrt(delta): chapter 11, §5), and its solution is the uniform
 *    state: lambda = -25 on both macro-elements.  The test asserts that
 *    the active set converges (1 iteration), U and lambda are finite and
 *    lambda is -25 to 1e-6, beta_h >= 0.5 sqrt(delta_macro).
 *    (Dividing each column of C and G by the covered area -- unknowns
 *    a_i lambda_i -- solves these systems with rcond 2.8e-8 for every
 *    delta down to 1e-9 and lambda exact to 3e-8 at delta = 1e-8.)
 *  - the master ending 1e-8 h short: every macro admissible, lambda exact
 *    to 1e-12.
 */
#include "t95-hard.h"

#define H 12.5

static void
sliver (const char *name, lac_elem_type t, double Lm, double eps,
        int kept, double beta_min, double tol)
{
  hard_spec sp;
  hard_narrow (&sp, name, t, 4, 3, Lm, eps);
  hard h;
  int st = hard_run (&sp, &h);
  double beta = hard_beta (&h);
  int dim = h.dim;
  double want_force = -HARD_P * Lm * (dim == 3 ? 50 : 1);
  check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", name,
                h.stage ? h.stage : "-");
  check_true (beta >= beta_min, "%s: beta_h %.4e >= %.2e", name, beta,
              beta_min);
  /* the admissible set: the sliver is kept iff its criterion >= eps */
  size_t covered = 0;
  for (size_t mm = 0; h.c && mm < h.c->nmacro; mm++)
    covered += h.c->covered[mm] > 0;
  if (h.c)
    check_int ((long) h.c->k, (long) (kept ? covered : covered - (dim == 3 ? 4 : 1)),
               "%s: admissible macro-elements", name);
  double err = -1;
  int pass = !st && beta >= beta_min;
  if (!st)
    {
      int fin = hard_finite (&h);
      double ef = hard_err_force (&h, want_force);
      err = hard_err_lambda (&h, -HARD_P);
      check_true (fin, "%s: U, lambda finite", name);
      check_true (h.s->nhist <= 2, "%s: %zu active-set iterations", name,
                  h.s->nhist);
      check_true (ef <= 1e-10, "%s: total force err %.2e", name, ef);
      check_true (err <= tol, "%s: lambda err %.2e <= %.0e", name, err, tol);
      pass = pass && fin && h.s->nhist <= 2 && ef <= 1e-10 && err <= tol;
    }
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: st %d k %zu beta %.4e err %.2e rcond %.2e %s\n", name, st,
            h.c ? h.c->k : 0, beta, err, h.rcond, h.msg);
  hard_row (&h, "lambda", err, pass);
  hard_free (&h);
}

int
main (void)
{
  lac_init ();
  double in = 25 + 1e-8 * H, out = 50 - 1e-8 * H;
  double d = 1e-8 * H / 25;           /* covered fraction of the macro */
  /* dropped by the default epsilon: lambda = -25 Lm / 25, err = d */
  sliver ("sliver 1e-8 h, quad4, eps 1e-2", LAC_QUAD4, in, 0, 0, 0.5, 2 * d);
  sliver ("sliver 1e-8 h, hex8, eps 1e-2", LAC_HEX8, in, 0, 0, 0.2, 10 * d);
  /* kept: well posed, uniform solution */
  sliver ("sliver 1e-8 h, quad4, eps 1e-14", LAC_QUAD4, in, 1e-14, 1,
          0.5 * sqrt (d), 1e-6);
  sliver ("sliver 1e-8 h, quad8, eps 1e-14", LAC_QUAD8, in, 1e-14, 1,
          0.5 * sqrt (d), 1e-6);
  sliver ("sliver 1e-8 h, hex8, eps 1e-14", LAC_HEX8, in, 1e-14, 1,
          0.2 * sqrt (d), 1e-6);
  /* the master 1e-8 h short of the end: nearly full */
  sliver ("1 - 1e-8 h covered, quad4", LAC_QUAD4, out, 1e-14, 1, 0.5, 1e-12);
  sliver ("1 - 1e-8 h covered, quad8", LAC_QUAD8, out, 1e-14, 1, 0.4, 1e-12);
  sliver ("1 - 1e-8 h covered, hex8", LAC_HEX8, out, 1e-14, 1, 0.15, 1e-12);
  lac_finalize ();
  return check_summary ();
}
