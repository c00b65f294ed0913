/* t955: hard case -- initial penetration        [LAC (18); issue 6 item 3]
 *
 * The master overlaps the slave by g0 > 0 at the start (mean gaps G < 0),
 * on non-matching meshes (4 cells below, 3 above):
 *
 * 1. Taylor, floating upper block pushed down into the lower one by
 *    g0 = 1e-3 h and 0.1 h (h = 12.5 in 2D, 16.7 in 3D): the solution pushes
 *    the bodies apart -- the upper block's bottom ends g0 above the lower
 *    block's top, i.e. u_v(upper bottom) - u_v(lower top) = g0 (both are
 *    constant in the uniform state), and lambda = -25 exactly.
 * 2. Both ends held (lower bottom and upper top: u_v = 0; symmetry on
 *    x = 0 (and y = 0)), no load: the overlap g0 is squeezed out of the
 *    two blocks (total height 100): uniaxial stress, sigma_vv = lambda
 *    = -E' g0 / 100, E' = E / (1 - nu^2) in plane strain, E in 3D.
 * 3. A rigid flat obstacle 0.1 h above the bottom of a floating block:
 *    the block is lifted by 0.1 h, lambda = -25.
 *
 * Asserted: converged in at most 2 iterations (all active from the start:
 * G < 0), finite, lambda to 1e-10 of the exact value, the separation
 * (cases 1 and 3) to 1e-10 g0, beta_h >= 0.4 (2D), 0.1 (3D).
 */
#include "t95-hard.h"

/* mean of component comp over the nodes of a group */
static double
mean_u (const hard *h, const char *group, int comp)
{
  const lac_group *g = lac_mesh_group (h->m, group);
  double s = 0;
  for (size_t q = 0; q < g->nnodes; q++)
    s += h->s->U[g->node[q] * (size_t) h->dim + (size_t) comp];
  return s / (double) g->nnodes;
}

static void
finish (hard *h, double lambda, const char *lo_top, const char *up_bot,
        double sep, double beta_min)
{
  const char *name = h->sp->name;
  double beta = hard_beta (h), err = -1;
  check_status (h->status, LAC_SUCCESS, "%s: solved (stage %s)", name,
                h->stage ? h->stage : "-");
  check_true (beta >= beta_min, "%s: beta_h %.4e >= %.2g", name, beta,
              beta_min);
  int pass = !h->status && beta >= beta_min;
  if (!h->status)
    {
      int fin = hard_finite (h);
      err = hard_err_lambda (h, lambda);
      double es = 0;
      if (up_bot)
        {
          double s = mean_u (h, up_bot, h->dim - 1)
            - (lo_top ? mean_u (h, lo_top, h->dim - 1) : 0.0);
          es = fabs (s - sep) / sep;
          check_true (es <= 1e-10, "%s: separation %.6e (want %.6e)", name, s,
                      sep);
        }
      check_true (fin, "%s: finite", name);
      check_true (h->s->nhist <= 2, "%s: %zu iterations", name, h->s->nhist);
      check_true (err <= 1e-10, "%s: lambda err %.2e", name, err);
      pass = pass && fin && h->s->nhist <= 2 && err <= 1e-10 && es <= 1e-10;
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%s: it %zu beta %.4e lambda %.10g err %.2e sep err %.2e\n",
                name, h->s->nhist, beta, h->s->lambda[0], err, es);
    }
  hard_row (h, "lambda", err, pass);
  hard_free (h);
}

static void
pushed (const char *name, lac_elem_type t, double frac, double beta_min)
{
  int dim = lac_refelem_get (t)->dim;
  size_t lo[3] = { 4, 4, 4 }, up[3] = { 3, 3, 3 };
  hard_spec sp;
  hard_taylor (&sp, name, t, lo, t, up, 0);
  double g0 = frac * 50.0 / (dim == 2 ? 4 : 3);
  sp.up.shift[dim - 1] -= g0;
  hard h;
  hard_run (&sp, &h);
  finish (&h, -HARD_P, dim == 2 ? "lo.ymax" : "lo.zmax",
          dim == 2 ? "up.ymin" : "up.zmin", g0, beta_min);
}

static void
squeezed (const char *name, lac_elem_type t, double frac, double beta_min)
{
  int dim = lac_refelem_get (t)->dim;
  size_t lo[3] = { 4, 4, 4 }, up[3] = { 3, 3, 3 };
  hard_spec sp;
  hard_taylor (&sp, name, t, lo, t, up, 0);
  double g0 = frac * 50.0 / (dim == 2 ? 4 : 3);
  sp.up.shift[dim - 1] -= g0;
  sp.load = NULL;
  sp.fix[sp.nfix++] = (hard_fix) { dim == 2 ? "up.ymax" : "up.zmax",
                                   dim - 1, 0 };
  double E = 2000, nu = 0.3, Ep = dim == 2 ? E / (1 - nu * nu) : E;
  hard h;
  hard_run (&sp, &h);
  finish (&h, -Ep * g0 / 100, NULL, NULL, 0, beta_min);
}

static void
obstacle (const char *name, lac_elem_type t, double frac, double beta_min)
{
  int dim = lac_refelem_get (t)->dim;
  hard_spec sp;
  memset (&sp, 0, sizeof sp);
  sp.name = name;
  sp.model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  sp.nbodies = 1;
  sp.up = (hard_body) { t, { 4, 4, 4 }, { 50, 50, 50 }, { 0, 0, 0 }, 2000,
                        0.3, NULL, NULL };
  sp.up.shift[dim - 1] = 50;
  double g0 = frac * 12.5;
  sp.slave = dim == 2 ? "ymin" : "zmin";
  sp.ob = (lac_obstacle) { dim, 50.0 + g0, { 0, 0 }, { 0, 0 }, 0 };
  sp.load = dim == 2 ? "ymax" : "zmax";
  sp.p = HARD_P;
  sp.fix[sp.nfix++] = (hard_fix) { "xmin", 0, 0 };
  if (dim == 3)
    sp.fix[sp.nfix++] = (hard_fix) { "ymin", 1, 0 };
  hard h;
  hard_run (&sp, &h);
  finish (&h, -HARD_P, NULL, sp.slave, g0, beta_min);
}

int
main (void)
{
  lac_init ();
  pushed ("penetration 1e-3 h, floating, quad4", LAC_QUAD4, 1e-3, 0.4);
  pushed ("penetration 0.1 h, floating, quad4", LAC_QUAD4, 0.1, 0.4);
  pushed ("penetration 0.1 h, floating, tri6", LAC_TRI6, 0.1, 0.4);
  pushed ("penetration 0.1 h, floating, hex8", LAC_HEX8, 0.1, 0.1);
  squeezed ("penetration 1e-3 h, both held, quad4", LAC_QUAD4, 1e-3, 0.4);
  squeezed ("penetration 0.1 h, both held, quad8", LAC_QUAD8, 0.1, 0.4);
  squeezed ("penetration 0.1 h, both held, tet4", LAC_TET4, 0.1, 0.1);
  obstacle ("penetration 0.1 h, rigid flat, quad4", LAC_QUAD4, 0.1, 0.4);
  obstacle ("penetration 0.1 h, rigid flat, hex8", LAC_HEX8, 0.1, 0.1);
  lac_finalize ();
  return check_summary ();
}
