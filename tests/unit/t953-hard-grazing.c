/* t953: hard case -- grazing contact: the contact zone ends inside a facet
 *                                    [LAC (18), Alg. 1; issue 6 item 3]
 *
 * A flat block [0,50] x [50,100] (x [0,50]) pressed with p = 25 onto a
 * convex rigid bump, the graph y = 50 - kappa x^2 (z = 50 - kappa (x^2 +
 * y^2) in 3D) touching the block at the symmetry axis x = 0 only: the
 * initial gap kappa x^2 grows from zero, the contact zone [0, a] opens
 * around the apex and its end a falls inside a facet (a Hertz-like
 * problem; kappa = 0.002 gives a ~ 20 mm).  Then the same with two
 * deformable bodies: an upper quad8 block whose bottom is the parabola
 * y = 50 + kappa x^2 (mapped nodes: the quadratic edges represent it
 * exactly; slave, 16 cells) on a flat lower quad4 block (master, 4 cells).
 * The block is held vertically by the contact alone, so the active set
 * starts from all-active (lac_newton.h: restart).
 *
 * No closed-form solution.  Asserted: the active set converges in at most
 * 15 iterations; U and lambda finite; complementarity [LAC (18)] lambda <= 0,
 * d >= 0, lambda d = 0 (1e-8); the vertical contact force sum (C lambda)
 * balances the load on the block (1e-10, the "error" of the table; on
 * the curved slave it is the integral of lambda n_y, not of lambda); the active set is a non-empty proper
 * subset of the multipliers, contiguous from the apex (every active
 * macro-element is nearer the axis than every inactive one); beta_h >= 0.3
 * (2D) and 0.1 (3D): every macro-element is fully covered, the bound is
 * the conforming one.
 */
#include "t95-hard.h"

#define KAPPA 0.002

/* the upper block's bottom bent to y = 50 + kappa x^2, the top kept flat */
static void
bend (double *x, const void *ctx)
{
  (void) ctx;
  x[1] += KAPPA * x[0] * x[0] * (100 - x[1]) / 50;
}

/* distance to the axis of the centroid of the nodes of macro-element m */
static double
macro_r (const hard *h, size_t m)
{
  double c[3] = { 0, 0, 0 };
  int cnt = 0, nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  for (size_t j = h->M->ptr[m]; j < h->M->ptr[m + 1]; j++)
    {
      int nn = lac_mesh_facet_nodes (h->m, h->M->cell[j], h->M->face[j],
                                     nodes, &ft);
      for (int a = 0; a < nn; a++, cnt++)
        for (int i = 0; i < h->dim; i++)
          c[i] += h->m->x[(size_t) nodes[a] * (size_t) h->dim + (size_t) i];
    }
  return h->dim == 2 ? c[0] / cnt : hypot (c[0], c[1]) / cnt;
}

static void
grazing (const hard_spec *sp, double beta_min)
{
  hard h;
  int st = hard_run (sp, &h);
  double beta = hard_beta (&h), err = -1;
  const char *name = sp->name;
  check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", name,
                h.stage ? h.stage : "-");
  check_true (beta >= beta_min, "%s: beta_h %.4e >= %.2g", name, beta,
              beta_min);
  int pass = !st && beta >= beta_min;
  if (!st)
    {
      int fin = hard_finite (&h), cp = hard_complementarity (&h, 1e-8);
      err = hard_err_balance (&h, sp->nbodies == 1 ? "body" : "up.body",
                              h.dim - 1);
      size_t na = lac_newton_nactive (h.s);
      double ramax = 0, rimin = INFINITY;
      for (size_t i = 0; i < h.c->k; i++)
        {
          double r = macro_r (&h, h.c->macro[i]);
          if (h.s->active[i])
            ramax = fmax (ramax, r);
          else
            rimin = fmin (rimin, r);
        }
      check_true (fin, "%s: finite", name);
      check_true (h.s->nhist <= 15, "%s: %zu iterations", name, h.s->nhist);
      check_true (cp, "%s: complementarity", name);
      check_true (err <= 1e-10, "%s: force balance %.2e", name, err);
      check_true (na > 0 && na < h.c->k, "%s: %zu of %zu active", name, na,
                  h.c->k);
      check_true (ramax < rimin, "%s: active zone contiguous (%g < %g)", name,
                  ramax, rimin);
      pass = pass && fin && h.s->nhist <= 15 && cp && err <= 1e-10 && na > 0
        && na < h.c->k && ramax < rimin;
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%s: k %zu active %zu (zone ends between %.2f and %.2f) it "
                "%zu beta %.4e force err %.2e\n", name, h.c->k, na, ramax,
                rimin, h.s->nhist, beta, err);
    }
  hard_row (&h, "force", err, pass);
  hard_free (&h);
}

static void
obstacle (const char *name, lac_elem_type t, size_t n, double beta_min)
{
  int dim = lac_refelem_get (t)->dim;
  hard_spec sp;
  memset (&sp, 0, sizeof sp);
  sp.name = name;
  sp.model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  sp.nbodies = 1;
  sp.up = (hard_body) { t, { n, n, n / 2 }, { 50, 50, 50 }, { 0, 0, 0 },
                        2000, 0.3, NULL, NULL };
  sp.up.shift[dim - 1] = 50;
  sp.slave = dim == 2 ? "ymin" : "zmin";
  sp.ob = (lac_obstacle) { dim, 50.0, { -KAPPA, dim == 3 ? -KAPPA : 0 },
                           { 0, 0 }, 0 };
  sp.load = dim == 2 ? "ymax" : "zmax";
  sp.p = HARD_P;
  sp.fix[sp.nfix++] = (hard_fix) { "xmin", 0, 0 };
  if (dim == 3)
    sp.fix[sp.nfix++] = (hard_fix) { "ymin", 1, 0 };
  sp.maxit = 15;
  grazing (&sp, beta_min);
}

int
main (void)
{
  lac_init ();
  obstacle ("grazing bump, quad4", LAC_QUAD4, 10, 0.3);
  obstacle ("grazing bump, quad4 40 cells", LAC_QUAD4, 40, 0.3);
  obstacle ("grazing bump, quad8", LAC_QUAD8, 10, 0.3);
  obstacle ("grazing bump, tri3", LAC_TRI3, 10, 0.3);
  obstacle ("grazing bump, hex8", LAC_HEX8, 6, 0.1);
  /* two deformable bodies, curved quad8 slave on a flat coarse master */
  hard_spec sp;
  size_t nlo[3] = { 4, 4, 4 }, nup[3] = { 16, 8, 8 };
  hard_taylor (&sp, "grazing parabola on block, quad8/quad4", LAC_QUAD4, nlo,
               LAC_QUAD8, nup, 0);
  sp.up.map = bend;
  sp.maxit = 15;
  grazing (&sp, 0.3);
  lac_finalize ();
  return check_summary ();
}
