/* t952: hard case -- epsilon from 1e-1 down to 1e-8 on a non-conforming case
 *                              [LAC Def. 1, Thm. 2; issue 6 item 3]
 *
 * hard_narrow (t95-hard.h): a rigid slave base of 4 cells (h = 12.5),
 * a master block [0, Lm] with Lm = 25 + delta_f h, so that the slave
 * macro-element [25, 50] is covered on delta = delta_f / 2 of its length
 * (quad4: criterion delta^{3/2}; quad8: 2 delta^{3/2} (1 - 2 delta / 3);
 * hex8 and quad8 computed by lac_admissibility).  For every epsilon:
 *
 *  - the cut macro-element is admissible iff criterion >= epsilon;
 *  - the active set converges in at most 2 iterations, U and lambda are
 *    finite;
 *  - while it is admissible lambda = -25 exactly (1e-9: the cut column of
 *    C is small, rounding is amplified like 1/delta); when it is dropped
 *    the total force still balances the load (1e-10);
 *  - beta_h >= epsilon (Theorem 2 with C = 1: measured beta_h / criterion
 *    is 30 .. 1e5, chapter 11 §7) and beta_h >= 0.5 sqrt(delta) (2D) or
 *    0.2 sqrt(delta) (3D), the measured law beta_h ~ sqrt(delta).
 *
 * delta_f = 1e-5 with epsilon = 1e-8 keeps a multiplier on delta = 5e-6
 * (criterion 1.1e-8): well posed (beta_h = 2.3e-3), the uniform state is
 * the solution; the saddle-point solve must not call it singular (see
 * t951 for the scaling of the multipliers).
 */
#include "t95-hard.h"

static void
sweep (lac_elem_type t, double df, const double *eps, int neps)
{
  const char *tn = lac_refelem_get (t)->name;
  for (int e = 0; e < neps; e++)
    {
      double Lm = 25 + df * 12.5, d = df / 2;
      char name[96];
      snprintf (name, sizeof name, "eps %.0e, %s, delta %.0e", eps[e], tn, d);
      hard_spec sp;
      hard_narrow (&sp, name, t, 4, 3, Lm, eps[e]);
      hard h;
      int st = hard_run (&sp, &h);
      double beta = hard_beta (&h);
      int dim = lac_refelem_get (t)->dim;
      /* the cut macro-elements: covered, not fully */
      double crit = 1;
      size_t ncut = 0, ncov = 0;
      for (size_t m = 0; h.c && m < h.c->nmacro; m++)
        if (h.c->covered[m] > 0)
          {
            ncov++;
            if (h.c->covered[m] < h.c->meas[m] * (1 - 1e-12))
              ncut++, crit = fmin (crit, h.c->crit[m]);
          }
      int kept = crit >= eps[e];
      check_true (ncut > 0, "%s: cut macro-elements", name);
      if (h.c)
        check_int ((long) h.c->k, (long) (kept ? ncov : ncov - ncut),
                   "%s: admissible (criterion %.3e)", name, crit);
      check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", name,
                    h.stage ? h.stage : "-");
      double bmin = fmax (eps[e], (dim == 2 ? 0.5 : 0.2) * sqrt (d));
      if (!kept)
        bmin = dim == 2 ? 0.5 : 0.2;
      check_true (beta >= bmin, "%s: beta_h %.4e >= %.3e", name, beta, bmin);
      int pass = !st && beta >= bmin;
      double err = -1;
      if (!st)
        {
          int fin = hard_finite (&h);
          double ef = hard_err_force (&h, -HARD_P * Lm * (dim == 3 ? 50 : 1));
          err = kept ? hard_err_lambda (&h, -HARD_P) : ef;
          check_true (fin, "%s: finite", name);
          check_true (h.s->nhist <= 2, "%s: %zu iterations", name, h.s->nhist);
          check_true (ef <= 1e-10, "%s: force err %.2e", name, ef);
          if (kept)
            check_true (err <= 1e-9, "%s: lambda err %.2e", name, err);
          pass = pass && fin && h.s->nhist <= 2 && ef <= 1e-10
            && (!kept || err <= 1e-9);
        }
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%s: crit %.3e kept %d k %zu beta %.4e err %.2e rcond %.2e\n",
                name, crit, kept, h.c ? h.c->k : 0, beta, err, h.rcond);
      hard_row (&h, kept ? "lambda" : "force", err, pass);
      hard_free (&h);
    }
}

int
main (void)
{
  lac_init ();
  const double all[8] = { 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8 };
  const double two[2] = { 1e-2, 1e-8 };
  sweep (LAC_QUAD4, 1e-3, all, 8);        /* criterion 1.1e-5 */
  sweep (LAC_QUAD8, 1e-3, two, 2);
  sweep (LAC_HEX8, 1e-3, two, 2);
  sweep (LAC_QUAD4, 1e-5, two, 2);        /* criterion 1.1e-8 */
  lac_finalize ();
  return check_summary ();
}
