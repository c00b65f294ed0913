/* t434: the small-strain limit of the nonlinear loop is the linear LAC
 *       solution                                  [LAC §4.5, Alg. 1; (18)]
 *
 * A unit square (cube) on the rigid paraboloid v <= c |w|^2 (apex at the
 * origin, symmetry on x = 0 (and y = 0)), its top pushed down by
 * delta = 1e-5 with c = -1e-5: the contact zone covers part of the bottom.
 * Solved twice: by the linear chain (K, pairing on the reference
 * configuration, lac_newton's active set, as t450) and by lac_nonlinear
 * (neo-Hookean, one load step, re-pairing every iteration).  The two
 * agree to O(delta): the same active set, displacements and multipliers
 * within 1e-4 of their maxima (measured: 2e-6 to 5e-6).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "solve/lac_loadstep.h"
#include "solve/lac_nonlinear.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

#define DELTA 1e-5
#define CURV (-1e-5)

static void
fix (lac_dirichlet *d, lac_mesh *m, const char *g, int comp, double v)
{
  const lac_group *G = lac_mesh_group (m, g);
  check_true (G != NULL, "group %s", g);
  if (G)
    lac_dirichlet_add_group (d, m, G, comp, v);
}

static void
limit (lac_elem_type type)
{
  const lac_refelem *re = lac_refelem_get (type);
  int dim = re->dim, v = dim - 1;
  size_t n[3] = { 6, 3, 3 };
  if (dim == 3)
    n[0] = n[1] = 4;
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  lac_mesh_box (type, n, L, 0.0, &m);
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, dim == 2 ? "ymin" : "zmin", NULL, &M),
                LAC_SUCCESS, "%s macro", re->name);
  size_t ndof = (size_t) dim * m->nnodes;
  lac_model model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells * sizeof *nu);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = 300, nu[c] = 0.3;
  lac_dirichlet *D = lac_dirichlet_alloc ();
  fix (D, m, "xmin", 0, 0);
  if (dim == 3)
    fix (D, m, "ymin", 1, 0);
  fix (D, m, dim == 2 ? "ymax" : "zmax", v, -DELTA);
  lac_obstacle ob = { dim, 0.0, { CURV, dim == 3 ? CURV : 0 }, { 0, 0 }, 0 };
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };

  /* 1. the linear chain */
  lac_elastic el = { model, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_assembly_stiffness (m, &el, T);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  double *F = calloc (ndof, sizeof *F);
  lac_dirichlet_apply (D, K, F);
  lac_pairing *P = NULL;
  lac_contact *c = NULL;
  check_status (lac_obstacle_pairing (&S, &ob, 0, &P), LAC_SUCCESS, "pairing");
  check_status (lac_contact_build (m, model, M, P, NULL, LAC_EPSILON_DEFAULT, &c),
                LAC_SUCCESS, "contact");
  lac_contact_apply_dirichlet (c, D->n, D->dof, D->val);
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_newton *lin = NULL;
  check_status (lac_newton_solve_system (LAC_STRATEGY_SADDLE, &sys, 30, 1e-10, &lin), LAC_SUCCESS, "linear");

  /* 2. the nonlinear loop */
  lac_hyper h = { model, E, nu, NULL, 0 };
  lac_nl_problem prob = { m, &h, NULL, D, NULL, M, NULL, &ob, 0, 0, NULL, NULL,
                          NULL };
  lac_nl *s = lac_nl_alloc (&prob, NULL);
  lac_loadstep *ls = s ? lac_loadstep_alloc (s, NULL) : NULL;
  check_status (lac_loadstep_to (ls, 1.0), LAC_SUCCESS, "%s nonlinear", re->name);

  /* 3. compare */
  double eu = 0, umax = 0, el_ = 0, lmax = 0;
  size_t same = 0, nact = 0;
  for (size_t j = 0; j < ndof; j++)
    {
      eu = fmax (eu, fabs (ls->loop->U[j] - lin->U[j]));
      umax = fmax (umax, fabs (lin->U[j]));
    }
  for (size_t mm = 0; mm < M->n; mm++)
    {
      long i = c->mult[mm];
      double ll = i >= 0 ? lin->lambda[i] : 0.0;
      char al = i >= 0 ? lin->active[i] : 0;
      el_ = fmax (el_, fabs (ls->loop->lambda[mm] - ll));
      lmax = fmax (lmax, fabs (ll));
      same += al == ls->loop->active[mm];
      nact += al != 0;
    }
  check_int ((long) same, (long) M->n, "%s: same statuses", re->name);
  check_true (nact > 0 && nact < M->n, "%s: partial contact (%zu of %zu)",
              re->name, nact, M->n);
  check_true (eu <= 1e-4 * umax, "%s: |U - U_lin| = %.2e of %.2e", re->name, eu, umax);
  check_true (el_ <= 1e-4 * lmax, "%s: |lambda - lambda_lin| = %.2e of %.2e",
              re->name, el_, lmax);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%-6s active %zu/%zu  du/u = %.2e  dl/l = %.2e  its = %d\n",
            re->name, nact, M->n, eu / umax, el_ / lmax, ls->steps[0].iters);
  lac_loadstep_free (ls);
  lac_nl_free (s);
  lac_newton_free (lin);
  lac_contact_free (c);
  lac_pairing_free (P);
  free (F);
  lac_csc_free (K);
  lac_dirichlet_free (D);
  free (E);
  free (nu);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  limit (LAC_QUAD4);
  limit (LAC_QUAD8);
  limit (LAC_HEX8);
  limit (LAC_HEX20);
  lac_finalize ();
  return check_summary ();
}
