/* t433: large homogeneous compression through contact -- one generalized
 *       Newton loop for contact, neo-Hookean material and large
 *       displacements, re-pairing at every iteration    [LAC §4.5, Alg. 1]
 *
 * 1. Obstacle.  A unit square (cube) lies on the rigid plane y = 0 (z = 0
 *    in 3D), symmetry on x = 0 (and y = 0 in 3D); its top is pushed down
 *    by delta = 0.2 (20 %) in 4 load steps.  The frictionless contact
 *    leaves it in homogeneous uniaxial compression: F = diag(t, l, 1) in
 *    plane strain, diag(t, t, l) in 3D, l = 1 - delta and t from the
 *    traction-free sides,
 *      mu (t^2 - 1) + lambda ln J = 0,   J = t l   (t^2 l in 3D),
 *    so every multiplier must equal the Cauchy stress
 *      sigma_N = P_N l / J,   P_N = mu (l - 1/l) + lambda ln J / l,
 *    and the displacement must be (F - I) X at every node.
 * 2. Two bodies.  The same with a second square of the same material on
 *    top (non-matching meshes, 4 and 3 cells per side; the lower body on
 *    y = 0 by symmetry): each is compressed by delta/2, and the interface
 *    stretches by t: the pairing must follow the current coordinates.
 *    (With different materials the lateral stretches differ, the smaller
 *    face no longer covers the larger one and the solution is not
 *    homogeneous.)
 * 3. 40 %.  The block of 1 pushed by 40 % in ONE load step
 *    (|lambda| / E = 0.6): at most 6 Newton iterations.
 * 4. Step control.  The block starts 0.1 above the plane and its top goes
 *    down by 0.5 (40 % once it lands) in one load step, with a budget of
 *    4 Newton iterations per sub-step, which the whole step cannot meet:
 *    the step is cut, the sub-steps after the landing converge fast and
 *    grow back (some are longer than the one before), and the record
 *    counts them (quad4, hex8).  (Tolerance 1e-12 at 40 % in one step,
 *    1e-10 otherwise.)
 * All are exact in the discrete space (homogeneous fields, flat
 * interfaces): lambda to 1e-8, U to 1e-8; and each step takes a few
 * Newton iterations (<= 8; measured: 3 solves and the final check).
 *
 * The tangent is the consistent one (lac_nonlinear.h); the frozen-geometry
 * tangent converges here too (at 20 %, |lambda| / E = 0.25) but diverges
 * for the quadratic elements at 40 % (|lambda| / E = 0.6).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "solve/lac_loadstep.h"
#include "solve/lac_nonlinear.h"
#include "base/lac_status.h"

#define DELTA 0.2
#define NSTEPS 4

/* One run: the compression, its load steps, the Newton budget. */
typedef struct run
{
  double delta;           /* the top pushed down by delta                 */
  int nsteps, maxit, two;
  double gap;             /* the plane that far below the block (one body) */
} run;

/* lateral stretch t and nominal stress P_N for axial stretch l */
static double
lateral (double l, double E, double nu, int dim, double *PN)
{
  double lam, mu, t = 1.0;
  lac_hyper_lame (E, nu, &lam, &mu);
  for (int it = 0; it < 60; it++)
    {
      double J = dim == 3 ? t * t * l : t * l;
      double g = mu * (t * t - 1) + lam * log (J);
      double dg = 2 * mu * t + lam * (dim == 3 ? 2 / t : 1 / t);
      t -= g / dg;
    }
  double J = dim == 3 ? t * t * l : t * l;
  *PN = mu * (l - 1 / l) + lam * log (J) / l;
  return t;
}

static void
fix (lac_dirichlet *d, lac_mesh *m, const char *g, int comp, double v)
{
  const lac_group *G = lac_mesh_group (m, g);
  check_true (G != NULL, "group %s", g);
  if (G)
    lac_dirichlet_add_group (d, m, G, comp, v);
}

/* One unit box (groups "xmin", ...) or two stacked ones ("lo.", "up."). */
static lac_mesh *
boxes (lac_elem_type type, int two)
{
  int dim = lac_refelem_get (type)->dim;
  size_t nlo[3] = { 4, 4, 3 }, nup[3] = { 3, 3, 2 };
  if (dim == 3)
    nlo[0] = nlo[1] = 3, nup[0] = nup[1] = 2;
  double L[3] = { 1, 1, 1 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  lac_mesh_box (type, nlo, L, 0.0, &lo);
  if (!two)
    return lo;
  lac_mesh_box (type, nup, L, 0.0, &up);
  for (size_t i = 0; i < up->nnodes; i++)
    up->x[i * dim + dim - 1] += 1.0;
  lac_mesh_merge (lo, "lo.", up, "up.", &m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  return m;
}

static void
compress (lac_elem_type type, run rn)
{
  int two = rn.two;
  const lac_refelem *re = lac_refelem_get (type);
  int dim = re->dim, v = dim - 1;          /* the vertical component */
  const char *tn = re->name;
  const char *vmin = dim == 2 ? "ymin" : "zmin", *vmax = dim == 2 ? "ymax" : "zmax";
  char g1[32], g2[32];
  const char *lo = two ? "lo." : "";
  lac_mesh *m = boxes (type, two);
  double E1 = 300, nu = 0.3;
  /* 1. macro-mesh of the slave surface */
  snprintf (g1, sizeof g1, "%s%s", two ? "up." : "", vmin);
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, g1, NULL, &M), LAC_SUCCESS, "%s macro", tn);
  /* 2. material */
  double *E = malloc (m->ncells * sizeof *E), *NU = malloc (m->ncells * sizeof *NU);
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = E1;
      NU[c] = nu;
    }
  lac_hyper mat = { dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D, E, NU, NULL, 0 };
  /* 3. Dirichlet: symmetry planes, the top pushed down */
  lac_dirichlet *D = lac_dirichlet_alloc ();
  snprintf (g2, sizeof g2, "%sxmin", lo);
  fix (D, m, g2, 0, 0);
  if (dim == 3)
    {
      snprintf (g2, sizeof g2, "%symin", lo);
      fix (D, m, g2, 1, 0);
    }
  if (two)
    {
      fix (D, m, "up.xmin", 0, 0);
      if (dim == 3)
        fix (D, m, "up.ymin", 1, 0);
      snprintf (g2, sizeof g2, "lo.%s", vmin);
      fix (D, m, g2, v, 0);
    }
  snprintf (g2, sizeof g2, "%s%s", two ? "up." : "", vmax);
  fix (D, m, g2, v, -rn.delta);
  /* 4. the problem */
  lac_obstacle ob = { dim, -rn.gap, { 0, 0 }, { 0, 0 }, 0 };
  lac_pairing_facets master = { 0 };
  if (two)
    {
      snprintf (g2, sizeof g2, "lo.%s", vmax);
      master = lac_pairing_facets_of (m, lac_mesh_group (m, g2));
    }
  lac_nl_problem prob = { m, &mat, NULL, D, NULL, M, two ? &master : NULL,
                          two ? NULL : &ob, 0, 0, NULL, NULL, NULL };
  lac_nl_opts opts;
  lac_nl_opts_init (&opts);
  opts.tol = rn.delta > DELTA && !rn.maxit ? 1e-12 : 1e-10;
  if (rn.maxit > 0)
    opts.maxit = rn.maxit;
  opts.popts.degree_nonaffine = 0;  /* the exact rule of lac_pairing (degree
                                       18 on the trapezoids of the hex20
                                       cut): exactness to 1e-10 needs it */
  lac_nl *s = lac_nl_alloc (&prob, &opts);
  lac_loadstep *ls = s ? lac_loadstep_alloc (s, &opts) : NULL;
  check_true (ls != NULL, "%s alloc: %s", tn, lac_error_message ());
  if (!ls)
    {
      lac_nl_free (s);
      goto done;
    }
  int maxits = 0, st = 0, cuts = 0;
  for (int k = 1; k <= rn.nsteps && !st; k++)
    {
      st = lac_loadstep_to (ls, (double) k / rn.nsteps);
      check_status (st, LAC_SUCCESS, "%s two=%d delta=%g step %d", tn, two,
                    rn.delta, k);
      maxits = ls->steps[ls->nsteps - 1].iters > maxits
               ? ls->steps[ls->nsteps - 1].iters : maxits;
      cuts += ls->steps[ls->nsteps - 1].cuts;
    }
  if (rn.maxit > 0 && !st)
    {
      const lac_nl_step *r = &ls->steps[ls->nsteps - 1];
      check_true (r->cuts >= 1 && r->substeps >= 2 && r->grown >= 1,
                  "%s delta=%g maxit=%d: %d cuts, %d sub-steps (the shortest "
                  "%g), %d grown back", tn, rn.delta, rn.maxit, r->cuts,
                  r->substeps, r->dt_min, r->grown);
    }
  else
    check_true (maxits <= (rn.delta > DELTA ? 6 : 8), "%s two=%d delta=%g: "
                "%d Newton iterations in a step", tn, two, rn.delta, maxits);
  /* 5. the exact solution */
  double l1 = two ? 1 - rn.delta / 2 : 1 - rn.delta + rn.gap, l2 = l1, P1,
    t1, t2;
  t1 = lateral (l1, E1, nu, dim, &P1);
  t2 = t1;
  double J1 = dim == 3 ? t1 * t1 * l1 : t1 * l1;
  double sigma = P1 * l1 / J1;
  double el = 0, eu = 0;
  for (size_t mm = 0; mm < M->n; mm++)
    el = fmax (el, fabs (ls->loop->lambda[mm] - sigma));
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *X = m->x + a * dim;
      int up = two && X[v] > 1 + 1e-12;
      for (int i = 0; i < dim; i++)
        {
          double ex;
          if (i < v)
            ex = ((two && up ? t2 : t1) - 1) * X[i];
          else if (!two || !up)
            ex = (l1 - 1) * X[v] - rn.gap;
          else
            ex = (l1 - 1) + (l2 - 1) * (X[v] - 1);
          if (two && fabs (X[v] - 1) < 1e-12)
            continue;                  /* nodes of both bodies sit there */
          eu = fmax (eu, fabs (ls->loop->U[a * dim + i] - ex));
        }
    }
  check_true (el <= 1e-8 * fabs (sigma), "%s two=%d delta=%g: lambda error "
              "%.2e (sigma_N = %.6g)", tn, two, rn.delta, el, sigma);
  check_true (eu <= 1e-8, "%s two=%d delta=%g: displacement error %.2e", tn,
              two, rn.delta, eu);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%-6s two=%d delta=%g maxit=%d sigma_N=%.6f err_lambda=%.2e "
            "err_u=%.2e its/step=%d cuts=%d pairings=%zu\n", tn, two,
            rn.delta, rn.maxit, sigma, el, eu, maxits, cuts, s->npairings);
  lac_loadstep_free (ls);
  lac_nl_free (s);
done:
  lac_dirichlet_free (D);
  free (E);
  free (NU);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  const lac_elem_type types[] = { LAC_QUAD4, LAC_QUAD8, LAC_TRI6, LAC_HEX8,
                                  LAC_HEX20, LAC_HEX27 };
  for (size_t i = 0; i < sizeof types / sizeof *types; i++)
    {
      compress (types[i], (run) { DELTA, NSTEPS, 0, 0, 0 });
      compress (types[i], (run) { DELTA, NSTEPS, 0, 1, 0 });
      compress (types[i], (run) { 0.4, 1, 0, 0, 0 });
    }
  compress (LAC_QUAD4, (run) { 0.5, 1, 4, 0, 0.1 });
  compress (LAC_HEX8, (run) { 0.5, 1, 4, 0, 0.1 });
  lac_finalize ();
  return check_summary ();
}
