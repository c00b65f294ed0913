/* t510: the petsc strategy against the augmented one on the Taylor patch
 *       test, and plain elasticity                 [LAC (17), §5.1, ch. 13]
 *
 * The patch test of t450 (two blocks stacked, non-matching meshes,
 * pressure 25 on top, exact lambda = -25) in 2D (quad4) and 3D (hex8,
 * tet4): the active-set loop with the petsc strategy (projected CG, with
 * and without the nodal coordinates, and fieldsplit) gives the lambda
 * and U of the augmented strategy (CHOLMOD) to 1e-8 relative, and lambda
 * = -25 to 1e-8; the iterations and the true residual of the last solve
 * are reported.  After the loop, K U from the strategy's processes
 * (kappa K_W U - C W C^T U, what the root's residuals use once it freed
 * its K) equals K U to 1e-12 relative.  Without multipliers (k = 0) it
 * is the Cholesky solution
 * of K U = F.  A bad -lac_contact is refused with a message.  Built
 * without PETSc: the strategy fails with the apt-get line.  Runs on one
 * process; tests/cases-petsc.sh runs lac on two.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "solve/lac_linear_model.h"
#include "solve/lac_newton.h"
#include "solve/lac_petsc.h"
#include "base/lac_status.h"

#define P 25.0

typedef struct taylor
{
  lac_mesh *m;
  lac_macro *M;
  lac_pairing *Pr;
  lac_contact *c;
  lac_csc *K;
  double *F;
  size_t ndof;
} taylor;

static void
taylor_free (taylor *t)
{
  lac_contact_free (t->c);
  lac_pairing_free (t->Pr);
  lac_macromesh_free (t->M);
  lac_mesh_free (t->m);
  lac_csc_free (t->K);
  free (t->F);
}

static void
fix (lac_dirichlet *d, lac_mesh *m, const char *g, int comp)
{
  const lac_group *G = lac_mesh_group (m, g);
  if (G)
    lac_dirichlet_add_group (d, m, G, comp, 0.0);
}

/* The blocks of t450 (lower nlo cells a side, upper nup), pressure on
 * top, symmetry planes, the lower block on its bottom. */
static int
taylor_build (lac_elem_type type, size_t nlo, size_t nup, taylor *t)
{
  int dim = lac_refelem_get (type)->dim, st;
  size_t nl[3] = { nlo, nlo, nlo }, nu[3] = { nup, nup, nup };
  double L[3] = { 50, 50, 50 };
  lac_mesh *lo = NULL, *up = NULL;
  memset (t, 0, sizeof *t);
  lac_mesh_box (type, nl, L, 0.0, &lo);
  lac_mesh_box (type, nu, L, 0.0, &up);
  for (size_t i = 0; i < up->nnodes; i++)
    up->x[i * dim + dim - 1] += 50.0;
  st = lac_mesh_merge (lo, "lo.", up, "up.", &t->m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  if (st || (st = lac_macromesh_build (&t->m, dim == 2 ? "up.ymin"
                                       : "up.zmin", NULL, &t->M)))
    return st;
  lac_pairing_facets S = { t->m, t->M->ptr[t->M->n], t->M->cell,
                           t->M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (t->m, lac_mesh_group
                                                 (t->m, dim == 2 ? "lo.ymax"
                                                  : "lo.zmax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  if ((st = lac_pairing_build (&S, &Mf, &po, &t->Pr)))
    return st;
  t->ndof = (size_t) dim * t->m->nnodes;
  double *E = malloc (t->m->ncells * sizeof *E);
  double *nu_ = malloc (t->m->ncells * sizeof *nu_);
  for (size_t c = 0; c < t->m->ncells; c++)
    E[c] = 2000, nu_[c] = 0.3;
  lac_elastic mat = { dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D, E, nu_ };
  lac_triplet *T = lac_triplet_alloc (t->ndof, t->ndof, 0);
  lac_assembly_stiffness (t->m, &mat, T);
  t->K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  t->F = calloc (t->ndof, sizeof *t->F);
  lac_assembly_pressure (t->m, mat.model, lac_mesh_group
                         (t->m, dim == 2 ? "up.ymax" : "up.zmax"), P, t->F);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  fix (D, t->m, "lo.xmin", 0);
  fix (D, t->m, "up.xmin", 0);
  if (dim == 3)
    {
      fix (D, t->m, "lo.ymin", 1);
      fix (D, t->m, "up.ymin", 1);
    }
  fix (D, t->m, dim == 2 ? "lo.ymin" : "lo.zmin", dim - 1);
  lac_dirichlet_apply (D, t->K, t->F);
  st = lac_contact_build (t->m, mat.model, t->M, t->Pr, &Mf,
                          LAC_EPSILON_DEFAULT, &t->c);
  if (!st)
    lac_contact_apply_dirichlet (t->c, D->n, D->dof, D->val);
  lac_dirichlet_free (D);
  free (E);
  free (nu_);
  return st;
}

static double
reldiff (size_t n, const double *x, const double *y)
{
  double num = 0, den = 0;
  for (size_t i = 0; i < n; i++)
    {
      num = fmax (num, fabs (x[i] - y[i]));
      den = fmax (den, fabs (y[i]));
    }
  return den > 0 ? num / den : num;
}

/* The active-set loop with `kind`; U and lambda copied out. */
static int
newton (const taylor *t, lac_strategy_kind kind, int coords, double *U,
        double *lambda, lac_strategy_counts *cnt)
{
  lac_contact_system sys = { t->K, t->F, t->c->C, t->c->G, NULL, 0, NULL,
                             NULL, NULL };
  lac_linear_model lin;
  lac_contact_model m;
  lac_newton_opts o;
  int st = lac_linear_model_init (&lin, &sys, 0, &m);
  lac_newton_opts_init (&o);
  o.kind = kind;
  o.maxit = 10;
  lac_newton *s = st ? NULL : lac_newton_alloc (&m, &o);
  if (!s || !(s->strategy = lac_strategy_alloc (kind)))
    {
      lac_newton_free (s);
      lac_linear_model_clear (&lin);
      return lac_error_set (LAC_ENOMEM, __func__, "%s", lac_error_message ());
    }
  if (coords)
    lac_strategy_set_coordinates (s->strategy, t->m->dim, t->m->x);
  st = lac_newton_solve (s);
  if (!st && kind == LAC_STRATEGY_PETSC)        /* K U from the processes */
    {
      double *y0 = malloc (t->ndof * sizeof *y0);
      double *y1 = malloc (t->ndof * sizeof *y1);
      int sk = lac_strategy_kmul (s->strategy, t->ndof, s->U, y1);
      check_status (sk, LAC_SUCCESS, "kmul");
      check_true (!lac_strategy_own_k (s->strategy, t->ndof),
                  "no cells given: the strategy's K is the root's");
      lac_csc_matvec (t->K, s->U, y0);
      if (!sk)
        check_true (reldiff (t->ndof, y1, y0) <= 1e-12,
                    "kappa K_W U - C W C^T U against K U: %.2e",
                    reldiff (t->ndof, y1, y0));
      free (y0);
      free (y1);
    }
  if (!st)
    {
      memcpy (U, s->U, t->ndof * sizeof *U);
      memcpy (lambda, s->lambda, t->c->k * sizeof *lambda);
      lac_strategy_get_counts (s->strategy, cnt);
    }
  lac_newton_free (s);
  lac_linear_model_clear (&lin);
  return st;
}

static void
compare (lac_elem_type type, size_t nlo, size_t nup, int coords)
{
  const char *tn = lac_refelem_get (type)->name;
  taylor t;
  lac_strategy_counts c0, c1;
  int st = taylor_build (type, nlo, nup, &t);
  check_status (st, LAC_SUCCESS, "%s: the patch test", tn);
  if (st)
    {
      taylor_free (&t);
      return;
    }
  size_t n = t.ndof, k = t.c->k;
  double *U0 = malloc (n * sizeof *U0), *U1 = malloc (n * sizeof *U1);
  double *l0 = malloc (k * sizeof *l0), *l1 = malloc (k * sizeof *l1);
  check_status (newton (&t, LAC_STRATEGY_AUGMENTED, 0, U0, l0, &c0),
                LAC_SUCCESS, "%s augmented", tn);
  st = newton (&t, LAC_STRATEGY_PETSC, coords, U1, l1, &c1);
  check_status (st, LAC_SUCCESS, "%s petsc (coordinates %d)", tn, coords);
  if (!st)
    {
      double el = 0, dl = reldiff (k, l1, l0), du = reldiff (n, U1, U0);
      for (size_t i = 0; i < k; i++)
        el = fmax (el, fabs (l1[i] + P) / P);
      check_true (dl <= 1e-8, "%s: petsc vs augmented lambda %.2e", tn, dl);
      check_true (du <= 1e-8, "%s: petsc vs augmented U %.2e", tn, du);
      check_true (el <= 1e-8, "%s: lambda vs -25 %.2e", tn, el);
      check_true (c1.last_iterations > 0 && c1.last_residual <= 1e-9,
                  "%s: last solve %d iterations, residual %.2e", tn,
                  c1.last_iterations, c1.last_residual);
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%-5s n=%zu k=%zu coords=%d solves=%d iterations=%d "
                "(last %d, residual %.2e) backward error %.1e "
                "dlambda=%.1e dU=%.1e err_lambda=%.1e\n", tn, n, k, coords,
                c1.solves, c1.iterations, c1.last_iterations,
                c1.last_residual, c1.backward_error, dl, du, el);
    }
  free (U0);
  free (U1);
  free (l0);
  free (l1);
  taylor_free (&t);
}

/* k = 0: K U = F by conjugate gradients and GAMG against CHOLMOD, on the
 * lower block alone (held by its symmetry planes and bottom). */
static void
plain (void)
{
  taylor t;
  check_status (taylor_build (LAC_HEX8, 4, 3, &t), LAC_SUCCESS, "plain");
  lac_csc *C = lac_csc_alloc (t.ndof, 0, 0);
  /* the upper block is free without contact: hold it by its bottom */
  lac_dirichlet *D = lac_dirichlet_alloc ();
  for (int comp = 0; comp < 3; comp++)
    fix (D, t.m, "up.zmin", comp);
  lac_dirichlet_apply (D, t.K, t.F);
  lac_contact_system sys = { t.K, t.F, C, NULL, NULL, 0, NULL, NULL, NULL };
  lac_strategy *s = lac_strategy_alloc (LAC_STRATEGY_PETSC);
  lac_solver *chol = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  double *U = calloc (t.ndof, sizeof *U), *V = calloc (t.ndof, sizeof *V);
  double lam[1] = { 0 };
  const double G[1] = { 0 };
  sys.G = G;
  lac_strategy_set_coordinates (s, 3, t.m->x);
  check_status (lac_strategy_set (s, &sys), LAC_SUCCESS, "plain set");
  check_status (lac_strategy_solve (s, "", U, lam), LAC_SUCCESS,
                "plain solve");
  check_status (lac_solver_factor (chol, t.K), LAC_SUCCESS, "cholmod");
  check_status (lac_solver_solve (chol, t.F, V), LAC_SUCCESS, "cholmod");
  check_true (reldiff (t.ndof, U, V) <= 1e-8, "plain: petsc vs cholmod "
              "%.2e", reldiff (t.ndof, U, V));
  free (U);
  free (V);
  lac_solver_free (chol);
  lac_strategy_free (s);
  lac_dirichlet_free (D);
  lac_csc_free (C);
  taylor_free (&t);
}

int
main (void)
{
  lac_init ();
  if (!lac_petsc_available ())
    {
      check_true (lac_strategy_alloc (LAC_STRATEGY_PETSC) == NULL,
                  "no PETSc: no strategy");
      check_message ("apt-get install", "no PETSc: the install line");
      lac_finalize ();
      return check_summary ();
    }
  check_status (lac_petsc_initialize (NULL), LAC_SUCCESS, "initialize");
  compare (LAC_QUAD4, 8, 6, 1);
  compare (LAC_HEX8, 4, 3, 1);
  compare (LAC_HEX8, 4, 3, 0);
  compare (LAC_TET4, 3, 2, 1);
  plain ();
  check_status (lac_petsc_initialize ("-lac_contact fieldsplit"),
                LAC_SUCCESS, "fieldsplit");
  compare (LAC_HEX8, 4, 3, 1);
  compare (LAC_QUAD4, 8, 6, 1);
  check_status (lac_petsc_initialize ("-lac_contact nested"), LAC_SUCCESS,
                "options");
  check_true (lac_strategy_alloc (LAC_STRATEGY_PETSC) == NULL,
              "-lac_contact nested refused");
  check_message ("-lac_contact nested", "the message names the option");
  lac_petsc_finalize ();
  lac_finalize ();
  return check_summary ();
}
