/* t959: hard case -- no contact at all, and full contact
 *                                       [LAC Alg. 1; issue 6 item 3]
 *
 * 1. Open everywhere: a lower block held on its bottom and an upper block
 *    [0,50] x [51,101] (x [0,50]) clamped on x = 0 (a thick cantilever),
 *    1 mm above it, with a small pressure p = 0.1 on its top (deflection
 *    ~ 1e-3 mm << 1 mm).  Every initial mean gap is positive: the active
 *    set starts empty and stays empty: one iteration, lambda = 0 for every
 *    multiplier, and U is the free solution K^{-1} F (solved here
 *    separately with UMFPACK), to 1e-12.
 * 2. Far apart (gap 5 h, beyond the pairing's reach of one facet
 *    diameter): no pair at all.  With allow_empty the pairing is empty and
 *    the contact stage stops with one clear line (LAC_EADMISS: no
 *    admissible macro-element); without it the pairing stops (EINVAL).
 * 3. Full contact: the Taylor patch test (16 cells below, 12 above, quad4;
 *    8 / 6 tri6): every multiplier active from the start, one iteration,
 *    lambda exact.
 * beta_h >= 0.4 (2D), 0.1 (3D) in 1 and 3 (the interface is matched
 * geometrically in both; the open gap does not enter C).
 */
#include "t95-hard.h"

static void
cantilever (hard_spec *sp, const char *name, lac_elem_type t, double gap)
{
  int dim = lac_refelem_get (t)->dim;
  size_t lo[3] = { 4, 4, 4 }, up[3] = { 3, 3, 3 };
  hard_taylor (sp, name, t, lo, t, up, 0);
  sp->up.shift[dim - 1] += gap;
  sp->p = 0.1;
  sp->nfix = 0;
  for (int c = 0; c < dim; c++)
    {
      sp->fix[sp->nfix++] = (hard_fix) { "up.xmin", c, 0 };
      sp->fix[sp->nfix++] = (hard_fix) { dim == 2 ? "lo.ymin" : "lo.zmin", c,
                                         0 };
    }
}

static void
open_gap (const char *name, lac_elem_type t, double beta_min)
{
  hard_spec sp;
  cantilever (&sp, name, t, 1.0);
  hard h;
  int st = hard_run (&sp, &h);
  double beta = hard_beta (&h), err = -1;
  check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", name,
                h.stage ? h.stage : "-");
  check_true (beta >= beta_min, "%s: beta_h %.4e", name, beta);
  int pass = !st && beta >= beta_min;
  if (!st)
    {
      /* the free solution */
      double *U = calloc (h.ndof, sizeof *U), umax = 0, lmax = 0;
      lac_solver *S = lac_solver_alloc (LAC_SOLVER_UMFPACK);
      int sst = lac_solver_factor (S, h.K);
      if (!sst)
        sst = lac_solver_solve (S, h.F, U);
      check_status (sst, LAC_SUCCESS, "%s: free solution", name);
      err = 0;
      for (size_t j = 0; j < h.ndof; j++)
        {
          err = fmax (err, fabs (h.s->U[j] - U[j]));
          umax = fmax (umax, fabs (U[j]));
        }
      err /= umax;
      for (size_t i = 0; i < h.c->k; i++)
        lmax = fmax (lmax, fabs (h.s->lambda[i]));
      int fin = hard_finite (&h);
      check_true (fin, "%s: finite", name);
      check_int ((long) lac_newton_nactive (h.s), 0, "%s: none active", name);
      check_int ((long) h.s->nhist, 1, "%s: one iteration", name);
      check_true (lmax == 0, "%s: lambda = 0 (max %g)", name, lmax);
      check_true (err <= 1e-12, "%s: U = free solution (%.2e)", name, err);
      check_true (umax < 0.1, "%s: deflection %.3g < gap", name, umax);
      pass = pass && fin && lac_newton_nactive (h.s) == 0 && h.s->nhist == 1
        && lmax == 0 && err <= 1e-12;
      lac_solver_free (S);
      free (U);
    }
  hard_row (&h, "u-u_free", err, pass);
  hard_free (&h);
}

static void
far_apart (const char *name, int allow_empty)
{
  hard_spec sp;
  cantilever (&sp, name, LAC_QUAD4, 5 * 12.5);
  sp.allow_empty = allow_empty;
  hard h;
  int st = hard_run (&sp, &h);
  int want = allow_empty ? LAC_EADMISS : LAC_EINVAL;
  check_status (st, want, "%s: stops", name);
  check_true (h.stage && !strcmp (h.stage, allow_empty ? "contact" : "pairing"),
              "%s: at stage %s", name, h.stage ? h.stage : "-");
  check_true (strlen (h.msg) > 10 && !strchr (h.msg, '\n'),
              "%s: one-line message '%s'", name, h.msg);
  hard_row (&h, NULL, -1, st == want);
  hard_free (&h);
}

static void
full (const char *name, lac_elem_type t, size_t nlo, size_t nup,
      double beta_min)
{
  size_t lo[3] = { nlo, nlo, nlo }, up[3] = { nup, nup, nup };
  hard_spec sp;
  hard_taylor (&sp, name, t, lo, t, up, 0);
  hard_check_taylor (&sp, 1, 1e-12, beta_min);
}

int
main (void)
{
  lac_init ();
  open_gap ("no contact (gap 1 mm), quad4", LAC_QUAD4, 0.4);
  open_gap ("no contact (gap 1 mm), tri6", LAC_TRI6, 0.4);
  open_gap ("no contact (gap 1 mm), hex8", LAC_HEX8, 0.1);
  far_apart ("far apart (gap 5 h), no pair", 0);
  far_apart ("far apart (gap 5 h), allow_empty", 1);
  full ("full contact, quad4 16/12", LAC_QUAD4, 16, 12, 0.4);
  full ("full contact, tri6 8/6", LAC_TRI6, 8, 6, 0.4);
  lac_finalize ();
  return check_summary ();
}
