/* t958: hard case -- a curved quadratic interface against a very coarse
 *       master                       [LAC §4.6, §5.2; issue 6 item 3]
 *
 * Two concentric quarter rings (plane strain: cylinders; axisymmetric:
 * spheres, the spheres-like case of chapter 09): an inner body
 * a = 50 < r < R = 75 and an outer body R < r < b = 100, same material
 * (E = 2000, nu = 0.3), pressure p = 25 on r = b, symmetry on both straight
 * sides.  Frictionless contact on r = R is then perfect bonding (no shear
 * in the exact solution), so the exact solution is Lame's for one thick
 * body under external pressure:
 *   cylinder  lambda = sigma_rr(R) = -p b^2/(b^2 - a^2) (1 - a^2/R^2) = -18.519
 *   sphere    lambda = sigma_rr(R) = -p b^3/(b^3 - a^3) (1 - a^3/R^3) = -20.106
 * The meshes are boxes mapped to (r, theta) node by node, so quadratic
 * cells have curved edges on the circles.  Slave: the outer body's inner
 * arc, tri6, 24 cells along the arc.  Master: the inner body's outer arc
 * with 1, 2 or 4 quad9 / quad8 cells along 90 degrees: its quadratic arc
 * (nodes on the circle) lies inside the circle, by up to 0.81 mm (1 cell),
 * 0.054 (2), 0.0035 (4), 1.4e-5 (16): 59 %, 4 %, 0.25 %, 1e-3 % of the
 * radial displacement at R (1.37 mm).  These are initial gaps of the
 * pairing, so lambda carries the geometric error of the coarse master.
 *
 * Asserted: the pairing covers the slave arc (every macro-element
 * admissible), the active set converges (at most 10 iterations), U and
 * lambda finite, complementarity, beta_h >= 0.2, and lambda against
 * Lame (max relative error over the multipliers): one master cell: not
 * bounded (measured 3.4: the arc touches near the nodes only, half the
 * multipliers are released); 2 cells <= 0.5 (measured 0.39), 4 cells
 * <= 0.05, 16 cells <= 1e-3 (measured 8e-5).  The error follows the
 * geometric error of the master, not the mesh ratio.
 */
#include "t95-hard.h"

#define RA 50.0
#define RC 75.0
#define RB 100.0

typedef struct ring { double r0, r1; } ring;

/* the box [0,1]^2 to the quarter ring r0 < r < r1, 0 < theta < pi/2 */
static void
to_ring (double *x, const void *ctx)
{
  const ring *g = ctx;
  double r = g->r0 + (g->r1 - g->r0) * x[0], t = 2 * atan (1.0) * x[1];
  x[0] = r * cos (t);
  x[1] = r * sin (t);
}

static void
rings (const char *name, lac_model model, lac_elem_type tm, size_t ntheta_m,
       size_t nr_m, double tol, double beta_min)
{
  static const ring inner = { RA, RC }, outer = { RC, RB };
  hard_spec sp;
  memset (&sp, 0, sizeof sp);
  sp.name = name;
  sp.model = model;
  sp.nbodies = 2;
  sp.lo = (hard_body) { tm, { nr_m, ntheta_m, 1 }, { 1, 1, 1 }, { 0, 0, 0 },
                        2000, 0.3, to_ring, &inner };
  sp.up = (hard_body) { LAC_TRI6, { 4, 24, 1 }, { 1, 1, 1 }, { 0, 0, 0 },
                        2000, 0.3, to_ring, &outer };
  sp.slave = "up.xmin";
  sp.master = "lo.xmax";
  sp.load = "up.xmax";
  sp.p = HARD_P;
  sp.fix[sp.nfix++] = (hard_fix) { "lo.ymin", 1, 0 };   /* theta = 0 */
  sp.fix[sp.nfix++] = (hard_fix) { "up.ymin", 1, 0 };
  sp.fix[sp.nfix++] = (hard_fix) { "lo.ymax", 0, 0 };   /* theta = 90 */
  sp.fix[sp.nfix++] = (hard_fix) { "up.ymax", 0, 0 };
  sp.maxit = 10;
  double want = model == LAC_AXISYMMETRIC
    ? -HARD_P * pow (RB, 3) / (pow (RB, 3) - pow (RA, 3))
      * (1 - pow (RA / RC, 3))
    : -HARD_P * RB * RB / (RB * RB - RA * RA) * (1 - RA * RA / (RC * RC));
  hard h;
  int st = hard_run (&sp, &h);
  double beta = hard_beta (&h), err = -1;
  check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", name,
                h.stage ? h.stage : "-");
  check_true (beta >= beta_min, "%s: beta_h %.4e >= %.2g", name, beta,
              beta_min);
  int pass = !st && beta >= beta_min;
  if (!st)
    {
      int fin = hard_finite (&h), cp = hard_complementarity (&h, 1e-8);
      err = hard_err_lambda (&h, want);
      check_int ((long) h.c->k, (long) h.c->nmacro, "%s: all admissible",
                 name);
      check_true (fin, "%s: finite", name);
      check_true (cp, "%s: complementarity", name);
      check_true (h.s->nhist <= 10, "%s: %zu iterations", name, h.s->nhist);
      check_true (err <= tol, "%s: lambda err %.3e <= %.2g", name, err, tol);
      pass = pass && fin && cp && h.s->nhist <= 10 && err <= tol
        && h.c->k == h.c->nmacro;
      if (getenv ("LAC_TEST_VERBOSE"))
        {
          double lmin = 0, lmax = -INFINITY;
          for (size_t i = 0; i < h.c->k; i++)
            lmin = fmin (lmin, h.s->lambda[i]),
              lmax = fmax (lmax, h.s->lambda[i]);
          printf ("%s: k %zu active %zu it %zu beta %.4e lambda in [%.4f, "
                  "%.4f], exact %.4f, err %.3e\n", name, h.c->k,
                  lac_newton_nactive (h.s), h.s->nhist, beta, lmin, lmax,
                  want, err);
        }
    }
  hard_row (&h, "lambda", err, pass);
  hard_free (&h);
}

int
main (void)
{
  lac_init ();
  rings ("curved tri6 on 1 quad9 master, cylinders", LAC_PLANE_STRAIN,
         LAC_QUAD9, 1, 1, INFINITY, 0.2);
  rings ("curved tri6 on 2 quad9 master, cylinders", LAC_PLANE_STRAIN,
         LAC_QUAD9, 2, 2, 0.5, 0.2);
  rings ("curved tri6 on 2 quad8 master, spheres", LAC_AXISYMMETRIC,
         LAC_QUAD8, 2, 2, 0.5, 0.2);
  rings ("curved tri6 on 4 quad8 master, spheres", LAC_AXISYMMETRIC,
         LAC_QUAD8, 4, 2, 0.05, 0.2);
  rings ("curved tri6 on 16 quad8 master, cylinders", LAC_PLANE_STRAIN,
         LAC_QUAD8, 16, 4, 1e-3, 0.2);
  lac_finalize ();
  return check_summary ();
}
