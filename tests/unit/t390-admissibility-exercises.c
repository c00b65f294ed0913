/* t390-admissibility-exercises.c -- the answers of
 *                         chapters/05-admissibility/exercises.md  [LAC Def. 1]
 *
 * The library's numbers (lac_contact fields meas, covered, phiint, crit,
 * admissible, k) are compared with closed forms derived by hand.  The
 * geometry is that of the chapter's example: a slave block [0,50] x
 * [50,100] on a master block [0,Lm] x [0,50], so that the master edge x = Lm
 * cuts one slave macro-element T^m of length L, covered on a fraction
 * delta from its left end.
 *
 * Exercise 1 (seg3, quad8 slave, 5 cells, L = 10, Lm = 30 + 10 delta):
 *   int_{T^m cap Gamma_C} phi = L (2 delta^2 - 4 delta^3 / 3),
 *   phibar = 2 delta - 4 delta^2 / 3,
 *   crit   = 2 delta^{3/2} (1 - 2 delta / 3),
 *   for delta in {0.05, 0.15, 0.3, 0.5, 0.7, 0.9, 0.95}, to 1e-12 (the
 *   maximum is at delta = 0.9, 0.68305 > 2/3); at epsilon =
 *   0.1 the macro-element is lost below delta* = 0.1452567..., the root of
 *   crit(delta) = 0.1 (library crit at delta* = 0.1 to 1e-12, admissible
 *   at delta* + 1e-6, not at delta* - 1e-6).
 * Exercise 2 (two gathered seg2, quad4 slave, 4 cells, L = 25,
 *   Lm = 25 + 25 delta):  phibar = delta, crit = delta^{3/2} for delta <=
 *   1/2;  int phi = (L/2)(1 - 2 (1 - delta)^2), crit = (1 - 2 (1 -
 *   delta)^2) / (2 sqrt(delta)) above; threshold at epsilon = 0.1:
 *   delta* = 0.1^{2/3} = 0.215443...
 * Exercise 3 (the example, quad8, Lm = 37): crit = 2/3 for macro-elements
 *   0-2, 2 0.7^{3/2} (1 - 1.4/3) = 0.6247062... for 3, 0 for 4; k = 4 at
 *   epsilon = 0.62, 3 at 0.63 and 0.66, LAC_EADMISS at 0.67; |Gamma_C^ad|
 *   + |Gamma_C^eps| = 37.  Pressed by p = 25 (step 4 of the example):
 *   sum_i lambda_i |T^i cap Gamma_C| = -1250 (1e-10) for epsilon = 1e-2 and
 *   0.63; the mean gap of T^3 is 0 (active) at 1e-2 and -0.610 (1e-3,
 *   penetration) at 0.63, when T^3 has no multiplier.
 * Exercise 4 (fully covered macro-elements, the remark after Def. 1):
 *   crit = phibar = 2/3 (seg3), 1/2 (seg2 pair), 1/3 (tet4 and hex8 fans of
 *   tri3), 4/9 (hex27 face) -- all above the default epsilon = 1e-2.
 * Exercise 5 (hex27 slave, a strip covered: the seg3 answer times 2/3):
 *   crit = (4/3) delta^{3/2} (1 - 2 delta / 3) at delta = 0.7.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

/* The example's set-up: slave block of width 50 (nup cells across) on top
 * of a master block [0, Lm] (x [0, 50]); returns the status of
 * lac_contact_build; *c, *M, *mesh must be freed by the caller. */
static int
setup (lac_elem_type type, size_t nup, double Lm, double eps, lac_mesh **mesh,
       lac_macro **M, lac_contact **c)
{
  int dim = lac_refelem_get (type)->dim;
  size_t nlo[3] = { 4, 4, 1 }, nu[3] = { nup, nup, 1 };     /* 2D: as the example */
  if (dim == 3)
    nlo[1] = nu[1] = 1;
  double Llo[3] = { Lm, 50, 50 }, Lup[3] = { 50, 50, 50 };
  lac_mesh *lo = NULL, *up = NULL;
  int st;
  *mesh = NULL;
  *M = NULL;
  *c = NULL;
  if ((st = lac_mesh_box (type, nlo, Llo, 0.0, &lo))
      || (st = lac_mesh_box (type, nu, Lup, 0.0, &up)))
    {
      lac_mesh_free (lo);
      return st;
    }
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[a * dim + dim - 1] += 50.0;
  st = lac_mesh_merge (lo, "lo.", up, "up.", mesh);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  if (st)
    return st;
  st = lac_macromesh_build (mesh, dim == 2 ? "up.ymin" : "up.zmin", NULL, M);
  if (st)
    return st;
  lac_pairing_facets S = { *mesh, (*M)->ptr[(*M)->n], (*M)->cell, (*M)->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (*mesh,
      lac_mesh_group (*mesh, dim == 2 ? "lo.ymax" : "lo.zmax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P = NULL;
  st = lac_pairing_build (&S, &Mf, &po, &P);
  if (!st)
    st = lac_contact_build (*mesh, dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D,
                            *M, P, &Mf, eps, c);
  lac_pairing_free (P);
  return st;
}

static void
release (lac_mesh *mesh, lac_macro *M, lac_contact *c)
{
  lac_contact_free (c);
  lac_macromesh_free (M);
  lac_mesh_free (mesh);
}

/* Closed forms. */
static double
seg3_phiint (double L, double d)
{
  return L * (2 * d * d - 4 * d * d * d / 3);
}

static double
seg3_crit (double d)
{
  return 2 * pow (d, 1.5) * (1 - 2 * d / 3);
}

static double
seg2_phiint (double L, double d)
{
  return d <= 0.5 ? L * d * d : 0.5 * L * (1 - 2 * (1 - d) * (1 - d));
}

static double
seg2_crit (double d)
{
  return d <= 0.5 ? pow (d, 1.5) : (1 - 2 * (1 - d) * (1 - d)) / (2 * sqrt (d));
}

/* The root of f(d) = eps on (0, 1/2] by bisection (f increasing there). */
static double
threshold (double (*f) (double), double eps)
{
  double a = 0, b = 0.5;
  for (int it = 0; it < 200; it++)
    {
      double c = 0.5 * (a + b);
      if (f (c) < eps)
        a = c;
      else
        b = c;
    }
  return 0.5 * (a + b);
}

/* One partly covered macro-element m of length L: check the fields. */
static void
check_partial (const char *what, lac_elem_type type, size_t nup, double L,
               size_t m, double x0, double delta, double crit,
               double phiint)
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_contact *c;
  int st = setup (type, nup, x0 + L * delta, LAC_EPSILON_DEFAULT, &mesh, &M, &c);
  check_status (st, LAC_SUCCESS, "%s delta = %g: set-up", what, delta);
  if (!st)
    {
      check_rel (c->meas[m], L, 1e-12, "%s delta = %g: |T^m|", what, delta);
      check_rel (c->covered[m], L * delta, 1e-12, "%s delta = %g: covered",
                 what, delta);
      check_rel (c->phiint[m], phiint, 1e-12, "%s delta = %g: int phi", what,
                 delta);
      check_rel (c->crit[m], crit, 1e-12, "%s delta = %g: crit", what, delta);
      check_rel (c->phiint[m] / c->covered[m], phiint / (L * delta), 1e-12,
                 "%s delta = %g: phibar", what, delta);
    }
  release (mesh, M, c);
}

/* Is macro-element m admissible at epsilon when covered on delta? */
static int
admissible_at (lac_elem_type type, size_t nup, double L, size_t m, double x0,
               double delta, double eps, double *crit)
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_contact *c;
  int st = setup (type, nup, x0 + L * delta, eps, &mesh, &M, &c);
  check_status (st, LAC_SUCCESS, "set-up at delta = %.9f", delta);
  int ad = !st && c->admissible[m];
  if (!st && crit)
    *crit = c->crit[m];
  release (mesh, M, c);
  return ad;
}

static void
exercise1 (void)
{
  static const double deltas[] = { 0.05, 0.15, 0.3, 0.5, 0.7, 0.9, 0.95 };
  for (size_t i = 0; i < sizeof deltas / sizeof *deltas; i++)
    {
      double d = deltas[i];
      check_partial ("ex1 seg3", LAC_QUAD8, 5, 10.0, 3, 30.0, d, seg3_crit (d),
                     seg3_phiint (10.0, d));
    }
  check_rel (seg3_crit (0.9), 0.68305197459637, 1e-13, "ex1: max at 0.9");
  double ds = threshold (seg3_crit, 0.1), crit = 0;
  check_abs (ds, 0.1452567, 1e-7, "ex1: delta* (%.9f)", ds);
  admissible_at (LAC_QUAD8, 5, 10.0, 3, 30.0, ds, 0.1, &crit);
  check_rel (crit, 0.1, 1e-12, "ex1: crit(delta*) = epsilon");
  check_true (admissible_at (LAC_QUAD8, 5, 10.0, 3, 30.0, ds + 1e-6, 0.1, NULL),
              "ex1: admissible just above delta*");
  check_true (!admissible_at (LAC_QUAD8, 5, 10.0, 3, 30.0, ds - 1e-6, 0.1, NULL),
              "ex1: not admissible just below delta*");
}

static void
exercise2 (void)
{
  static const double deltas[] = { 0.1, 0.3, 0.48, 0.5, 0.6, 0.9 };
  for (size_t i = 0; i < sizeof deltas / sizeof *deltas; i++)
    {
      double d = deltas[i];
      check_partial ("ex2 seg2 pair", LAC_QUAD4, 4, 25.0, 1, 25.0, d,
                     seg2_crit (d), seg2_phiint (25.0, d));
    }
  double ds = pow (0.1, 2.0 / 3.0), crit = 0;
  check_rel (threshold (seg2_crit, 0.1), ds, 1e-12, "ex2: delta* = 0.1^(2/3)");
  admissible_at (LAC_QUAD4, 4, 25.0, 1, 25.0, ds, 0.1, &crit);
  check_rel (crit, 0.1, 1e-12, "ex2: crit(delta*) = epsilon");
  check_true (admissible_at (LAC_QUAD4, 4, 25.0, 1, 25.0, ds + 1e-6, 0.1, NULL),
              "ex2: admissible just above delta*");
  check_true (!admissible_at (LAC_QUAD4, 4, 25.0, 1, 25.0, ds - 1e-6, 0.1, NULL),
              "ex2: not admissible just below delta*");
}

static void
exercise3 (void)
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_contact *c;
  int st = setup (LAC_QUAD8, 5, 37.0, LAC_EPSILON_DEFAULT, &mesh, &M, &c);
  check_status (st, LAC_SUCCESS, "ex3: set-up");
  if (st)
    return;
  double want[5] = { 2.0 / 3, 2.0 / 3, 2.0 / 3, seg3_crit (0.7), 0 };
  check_rel (want[3], 0.6247062, 1e-7, "ex3: crit of the cut macro-element");
  for (int m = 0; m < 5; m++)
    check_abs (c->crit[m], want[m], 1e-12, "ex3: crit[%d]", m);
  double ad = 0;
  for (int m = 0; m < 5; m++)
    ad += c->covered[m];
  check_rel (ad, 37.0, 1e-12, "ex3: |Gamma_C| = 37");
  check_int ((long) c->k, 4, "ex3: k at the default epsilon");
  check_int (c->mult[4], -1, "ex3: the uncovered one has no multiplier");
  release (mesh, M, c);
  static const double eps[] = { 0.62, 0.63, 0.66 };
  static const long k[] = { 4, 3, 3 };
  for (int e = 0; e < 3; e++)
    {
      st = setup (LAC_QUAD8, 5, 37.0, eps[e], &mesh, &M, &c);
      check_status (st, LAC_SUCCESS, "ex3: epsilon = %g", eps[e]);
      if (!st)
        {
          check_int ((long) c->k, k[e], "ex3: k at epsilon = %g", eps[e]);
          double rest = 0;
          for (int m = 0; m < 5; m++)
            if (!c->admissible[m])
              rest += c->covered[m];
          check_abs (rest, k[e] == 4 ? 0.0 : 7.0, 1e-11,
                     "ex3: |Gamma_C^eps| at epsilon = %g", eps[e]);
        }
      release (mesh, M, c);
    }
  st = setup (LAC_QUAD8, 5, 37.0, 0.67, &mesh, &M, &c);
  check_status (st, LAC_EADMISS, "ex3: epsilon = 0.67");
  check_message ("no admissible macro-element", "ex3: message");
  release (mesh, M, c);
}

/* Exercise 3, step 4 of the example: press the upper block (p = 25) and
 * return sum_i lambda_i |T^i cap Gamma_C| and the mean gap of macro 3
 * measured with the columns of the default-epsilon contact data. */
static void
press (double eps, double *force, double *gap3)
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_contact *c, *all;
  *force = *gap3 = NAN;
  int st = setup (LAC_QUAD8, 5, 37.0, LAC_EPSILON_DEFAULT, &mesh, &M, &all);
  check_status (st, LAC_SUCCESS, "ex3 press: set-up");
  if (st)
    return;
  lac_macromesh_free (M);
  lac_mesh_free (mesh);
  st = setup (LAC_QUAD8, 5, 37.0, eps, &mesh, &M, &c);
  check_status (st, LAC_SUCCESS, "ex3 press: set-up");
  if (st)
    {
      lac_contact_free (all);
      release (mesh, M, c);
      return;
    }
  size_t ndof = 2 * mesh->nnodes;
  double *E = malloc (mesh->ncells * sizeof *E);
  double *nu = malloc (mesh->ncells * sizeof *nu);
  for (size_t k = 0; k < mesh->ncells; k++)
    E[k] = 2000, nu[k] = 0.3;
  lac_elastic mat = { LAC_PLANE_STRAIN, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_assembly_stiffness (mesh, &mat, T);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  double *F = calloc (ndof, sizeof *F);
  lac_assembly_pressure (mesh, mat.model, lac_mesh_group (mesh, "up.ymax"),
                         25.0, F);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  lac_dirichlet_add_group (D, mesh, lac_mesh_group (mesh, "lo.ymin"), 0, 0.0);
  lac_dirichlet_add_group (D, mesh, lac_mesh_group (mesh, "lo.ymin"), 1, 0.0);
  lac_dirichlet_add_group (D, mesh, lac_mesh_group (mesh, "lo.xmin"), 0, 0.0);
  lac_dirichlet_add_group (D, mesh, lac_mesh_group (mesh, "up.xmin"), 0, 0.0);
  lac_dirichlet_apply (D, K, F);
  lac_contact_apply_dirichlet (c, D->n, D->dof, D->val);
  lac_contact_apply_dirichlet (all, D->n, D->dof, D->val);
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  st = lac_newton_solve_system (LAC_STRATEGY_SADDLE, &sys, 20, 1e-10, &s);
  check_status (st, LAC_SUCCESS, "ex3 press: newton at epsilon = %g", eps);
  if (!st)
    {
      *force = 0;
      for (size_t i = 0; i < c->k; i++)
        *force += s->lambda[i] * c->area[i];
      long i = all->mult[3];
      double d = all->G[i];
      for (int p = all->C->p[i]; p < all->C->p[i + 1]; p++)
        d -= all->C->x[p] * s->U[all->C->i[p]];
      *gap3 = d / all->area[i];
    }
  lac_newton_free (s);
  lac_dirichlet_free (D);
  free (F);
  free (E);
  free (nu);
  lac_csc_free (K);
  lac_contact_free (all);
  release (mesh, M, c);
}

static void
exercise3_press (void)
{
  double f, g;
  press (LAC_EPSILON_DEFAULT, &f, &g);
  check_rel (f, -1250, 1e-10, "ex3: sum lambda area (default epsilon)");
  check_abs (g, 0, 1e-12, "ex3: T^3 closed (default epsilon)");
  press (0.63, &f, &g);
  check_rel (f, -1250, 1e-10, "ex3: sum lambda area (epsilon = 0.63)");
  check_rel (g, -0.610, 1e-3, "ex3: T^3 sinks (epsilon = 0.63): %.6f", g);
}

static void
exercise4 (void)
{
  static const struct
  {
    lac_elem_type type;
    size_t nup;
    double mean;
  } cases[] = {
    { LAC_QUAD8, 5, 2.0 / 3 }, { LAC_QUAD9, 5, 2.0 / 3 },
    { LAC_QUAD4, 4, 0.5 }, { LAC_TRI3, 4, 0.5 }, { LAC_TET4, 2, 1.0 / 3 },
    { LAC_HEX8, 2, 1.0 / 3 }, { LAC_HEX27, 2, 4.0 / 9 },
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++)
    {
      lac_mesh *mesh;
      lac_macro *M;
      lac_contact *c;
      const char *tn = lac_refelem_get (cases[i].type)->name;
      int st = setup (cases[i].type, cases[i].nup, 50.0, LAC_EPSILON_DEFAULT,
                      &mesh, &M, &c);
      check_status (st, LAC_SUCCESS, "ex4 %s: set-up", tn);
      if (!st)
        {
          check_int ((long) c->k, (long) M->n, "ex4 %s: all admissible", tn);
          for (size_t m = 0; m < M->n; m++)
            {
              check_rel (c->covered[m], c->meas[m], 1e-12,
                         "ex4 %s: delta = 1 on %zu", tn, m);
              check_rel (c->crit[m], cases[i].mean, 1e-12,
                         "ex4 %s: crit = phibar on %zu", tn, m);
            }
        }
      release (mesh, M, c);
    }
}

static void
exercise5 (void)
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_contact *c;
  int st = setup (LAC_HEX27, 5, 37.0, LAC_EPSILON_DEFAULT, &mesh, &M, &c);
  check_status (st, LAC_SUCCESS, "ex5: set-up");
  if (!st)
    {
      check_rel (c->covered[3], 0.7 * c->meas[3], 1e-12, "ex5: delta");
      check_rel (c->crit[3], 2.0 / 3 * seg3_crit (0.7), 1e-12, "ex5: crit");
      check_rel (c->crit[0], 4.0 / 9, 1e-12, "ex5: crit full");
    }
  release (mesh, M, c);
}

int
main (void)
{
  lac_init ();
  exercise1 ();
  exercise2 ();
  exercise3 ();
  exercise3_press ();
  exercise4 ();
  exercise5 ();
  lac_finalize ();
  return check_summary ();
}
