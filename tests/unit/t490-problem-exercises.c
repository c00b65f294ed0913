/* t490: the answers of chapters/01-problem/exercises.md, computed by the
 *       code and checked against closed forms                  [LAC §2]
 *
 * Exercise 1: thick sphere, u_r(30) = 0.103968... (axisymmetric tri6 vs the
 *   Lame formula, 1e-3), and the hoop stress at the inner surface
 *   sigma_tt(20) = 125/7 = 17.857 (nodal average, 2%).
 * Exercise 2: plane strain block under uniaxial stress sigma_yy = -p:
 *   sigma_xx = 0, sigma_zz = nu sigma_yy, eps_xx = -nu (1+nu) sigma_yy / E,
 *   eps_yy = (1 - nu^2) sigma_yy / E (exact to 1e-10: a linear field).
 * Exercise 3: degrees of freedom of structured meshes: 3x3 quad8 -> 40
 *   nodes, 80 dofs; quad9 -> 49, 98; tri6 -> 49, 98; 2x2x2 hex20 -> 81, 243.
 * Exercise 4: axisymmetric patch: u_r = c r is reproduced exactly, u_r = c
 *   is not (it is not a solution without body force).
 * Exercise 5: the kernel of the unconstrained stiffness: 3 rigid modes in
 *   plane strain, 6 in 3D, 1 in the axisymmetric model.
 */
#include <math.h>
#include <stdio.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "io/lac_mesh_gmsh.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

/* Solve K u = F with Dirichlet data on a box or a read mesh (helper). */
typedef struct problem
{
  lac_mesh *m;
  lac_model model;
  double *E, *nu, *F, *u;
  lac_triplet *T;
  lac_dirichlet *d;
} problem;

static int
problem_init (problem *P, lac_mesh *m, lac_model model, double E, double nu)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  P->m = m;
  P->model = model;
  P->E = lac_malloc (m->ncells * sizeof *P->E);
  P->nu = lac_malloc (m->ncells * sizeof *P->nu);
  P->F = lac_calloc (ndof, sizeof *P->F);
  P->u = lac_calloc (ndof, sizeof *P->u);
  P->T = lac_triplet_alloc (ndof, ndof, 0);
  P->d = lac_dirichlet_alloc ();
  for (size_t c = 0; c < m->ncells; c++)
    {
      P->E[c] = E;
      P->nu[c] = nu;
    }
  lac_elastic mat = { model, P->E, P->nu };
  return lac_assembly_stiffness (m, &mat, P->T);
}

static int
problem_solve (problem *P)
{
  lac_csc *K = lac_csc_from_triplet (P->T);
  lac_solver *s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  int status = lac_dirichlet_apply (P->d, K, P->F);
  if (!status)
    status = lac_solver_factor (s, K);
  if (!status)
    status = lac_solver_solve (s, P->F, P->u);
  lac_solver_free (s);
  lac_csc_free (K);
  return status;
}

static void
problem_free (problem *P)
{
  lac_dirichlet_free (P->d);
  lac_triplet_free (P->T);
  lac_free (P->u);
  lac_free (P->F);
  lac_free (P->nu);
  lac_free (P->E);
  lac_mesh_free (P->m);
}

/* Exercise 1: u_r(30) of the thick sphere. */
static void
exercise1 (void)
{
  const double a = 20, b = 40, p = 25, E = 2000, nu = 0.3;
  double k = p * a * a * a / (E * (b * b * b - a * a * a));
  double ur30 = k * ((1 - 2 * nu) * 30 + (1 + nu) * b * b * b / (2 * 900.0));
  /* hoop stress sigma_tt(R) = p a^3 / (b^3 - a^3) (b^3 / (2 R^3) + 1) */
  double stt = p * a * a * a / (b * b * b - a * a * a)
               * (b * b * b / (2 * a * a * a) + 1);
  check_rel (ur30, 0.10396825396825397, 1e-14, "ex1: formula u_r(30)");
  check_rel (stt, 125.0 / 7.0, 1e-14, "ex1: formula sigma_tt(20)");

  lac_mesh_opts o = { 0 };
  o.order = 2;
  o.level = 2;
  lac_mesh *m = NULL;
  problem P;
  int status = lac_mesh_read ("chapters/01-problem/sphere-axi.geo", &o, &m);
  check_status (status, LAC_SUCCESS, "ex1: read sphere-axi.geo");
  if (status)
    return;
  status = problem_init (&P, m, LAC_AXISYMMETRIC, E, nu);
  if (!status)
    status = lac_assembly_pressure (m, LAC_AXISYMMETRIC,
                                    lac_mesh_group (m, "inner"), p, P.F);
  if (!status)
    status = lac_dirichlet_add_group (P.d, m, lac_mesh_group (m, "axis"), 0,
                                      0.0);
  if (!status)
    status = lac_dirichlet_add_group (P.d, m, lac_mesh_group (m, "equator"),
                                      1, 0.0);
  if (!status)
    status = problem_solve (&P);
  check_status (status, LAC_SUCCESS, "ex1: solve");
  /* Mean radial displacement over the nodes on R = 30. */
  double sum = 0.0;
  int cnt = 0;
  for (size_t i = 0; i < m->nnodes && !status; i++)
    {
      const double *x = m->x + 2 * i, *ui = P.u + 2 * i;
      double R = hypot (x[0], x[1]);
      if (fabs (R - 30.0) < 1e-6)
        {
          sum += (ui[0] * x[0] + ui[1] * x[1]) / R;
          cnt++;
        }
    }
  check_true (cnt > 0, "ex1: nodes on R = 30 (%d)", cnt);
  if (cnt > 0)
    check_rel (sum / cnt, ur30, 1e-3, "ex1: computed u_r(30) = %.6f",
               sum / cnt);
  /* Hoop stress at the inner equator node (20, 0): s[2] = sigma_tt. */
  double *sig = lac_malloc (m->nnodes * 4 * sizeof *sig);
  lac_elastic mat = { LAC_AXISYMMETRIC, P.E, P.nu };
  status = lac_post_stress_nodal (m, &mat, P.u, NULL, sig, NULL);
  for (size_t i = 0; i < m->nnodes && !status; i++)
    if (fabs (m->x[2 * i] - a) < 1e-9 && fabs (m->x[2 * i + 1]) < 1e-9)
      check_rel (sig[4 * i + 2], stt, 0.02, "ex1: sigma_tt(20) = %.4f",
                 sig[4 * i + 2]);
  lac_free (sig);
  problem_free (&P);
}

/* Exercise 2: plane strain, uniaxial stress. */
static void
exercise2 (void)
{
  const double E = 1000, nu = 0.3, p = 2.0;
  size_t n[2] = { 2, 2 };
  double L[2] = { 1, 1 };
  lac_mesh *m = NULL;
  problem P;
  lac_mesh_box (LAC_QUAD4, n, L, 0.0, &m);
  int status = problem_init (&P, m, LAC_PLANE_STRAIN, E, nu);
  if (!status)
    status = lac_assembly_pressure (m, LAC_PLANE_STRAIN,
                                    lac_mesh_group (m, "ymax"), p, P.F);
  if (!status)        /* rollers: u_x = 0 on xmin, u_y = 0 on ymin */
    status = lac_dirichlet_add_group (P.d, m, lac_mesh_group (m, "xmin"), 0,
                                      0.0);
  if (!status)
    status = lac_dirichlet_add_group (P.d, m, lac_mesh_group (m, "ymin"), 1,
                                      0.0);
  if (!status)
    status = problem_solve (&P);
  check_status (status, LAC_SUCCESS, "ex2: solve");
  double s[4], xi[2] = { 0, 0 };
  lac_elastic mat = { LAC_PLANE_STRAIN, P.E, P.nu };
  lac_post_stress_at (m, &mat, P.u, 3, xi, s);
  check_abs (s[0], 0.0, 1e-10 * p, "ex2: sigma_xx = 0");
  check_rel (s[1], -p, 1e-10, "ex2: sigma_yy = -p");
  check_rel (s[2], -nu * p, 1e-10, "ex2: sigma_zz = nu sigma_yy");
  /* strains from the displacement of the corner (1, 1) */
  size_t c = m->nnodes - 1;
  check_rel (P.u[2 * c], nu * (1 + nu) * p / E, 1e-10,
             "ex2: eps_xx = -nu (1+nu) sigma_yy / E");
  check_rel (P.u[2 * c + 1], -(1 - nu * nu) * p / E, 1e-10,
             "ex2: eps_yy = (1-nu^2) sigma_yy / E");
  problem_free (&P);
}

/* Exercise 3: counting nodes and dofs. */
static void
exercise3 (void)
{
  struct { lac_elem_type t; size_t n; long nodes; } c[] = {
    { LAC_QUAD4, 3, 16 }, { LAC_QUAD8, 3, 40 }, { LAC_QUAD9, 3, 49 },
    { LAC_TRI6, 3, 49 }, { LAC_HEX20, 2, 81 }, { LAC_HEX27, 2, 125 }
  };
  for (int k = 0; k < 6; k++)
    {
      size_t n[3] = { c[k].n, c[k].n, c[k].n };
      double L[3] = { 1, 1, 1 };
      lac_mesh *m = NULL;
      check_status (lac_mesh_box (c[k].t, n, L, 0.0, &m), LAC_SUCCESS, "box");
      if (!m)
        continue;
      const char *name = lac_refelem_get (c[k].t)->name;
      check_int ((long) m->nnodes, c[k].nodes, "ex3: %s nodes", name);
      check_int ((long) (m->nnodes * (size_t) m->dim), c[k].nodes * m->dim,
                 "ex3: %s dofs", name);
      lac_mesh_free (m);
    }
  /* the closed form for n x n quad8: (n+1)^2 + 2 n (n+1) */
  check_int ((3 + 1) * (3 + 1) + 2 * 3 * (3 + 1), 40, "ex3: formula");
}

/* Exercise 4: axisymmetric patch with u_r = c r (exact) and u_r = c. */
typedef struct { double c; int constant; } axifield;

static void
axi_u (const double *x, void *ctx, double *out)
{
  const axifield *f = ctx;
  out[0] = f->constant ? f->c : f->c * x[0];
  out[1] = 0.0;
}

static double
axi_patch (int constant)
{
  size_t n[2] = { 4, 4 };
  double L[2] = { 1, 1 };
  lac_mesh *m = NULL;
  problem P;
  axifield f = { 1e-3, constant };
  lac_mesh_box (LAC_QUAD8, n, L, 0.0, &m);
  for (size_t a = 0; a < m->nnodes; a++)
    m->x[2 * a] += 1.0;                      /* r in [1, 2] */
  int status = problem_init (&P, m, LAC_AXISYMMETRIC, 100.0, 0.3);
  const char *bnd[4] = { "xmin", "xmax", "ymin", "ymax" };
  for (int k = 0; k < 4 && !status; k++)
    status = lac_dirichlet_add_field (P.d, m, lac_mesh_group (m, bnd[k]),
                                      axi_u, &f);
  if (!status)
    status = problem_solve (&P);
  check_status (status, LAC_SUCCESS, "ex4: solve");
  double err = 0.0, ue[2];
  for (size_t a = 0; a < m->nnodes; a++)
    {
      axi_u (m->x + 2 * a, &f, ue);
      err = fmax (err, hypot (P.u[2 * a] - ue[0], P.u[2 * a + 1] - ue[1]));
    }
  problem_free (&P);
  return err / f.c;
}

static void
exercise4 (void)
{
  double e_lin = axi_patch (0), e_const = axi_patch (1);
  check_true (e_lin < 1e-10, "ex4: u_r = c r reproduced (%.2e)", e_lin);
  check_true (e_const > 1e-4, "ex4: u_r = c not reproduced (%.2e)", e_const);
}

/* Exercise 5: dimension of the kernel of the unconstrained K. */
static int
kernel_dim (lac_elem_type type, lac_model model)
{
  size_t n[3] = { 2, 2, 1 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  problem P;
  lac_mesh_box (type, n, L, 0.1, &m);
  if (model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      m->x[2 * a] += 1.0;
  problem_init (&P, m, model, 100.0, 0.3);
  size_t N = (size_t) m->dim * m->nnodes;
  gsl_matrix *A = gsl_matrix_calloc (N, N);
  gsl_vector *ev = gsl_vector_alloc (N);
  gsl_eigen_symm_workspace *w = gsl_eigen_symm_alloc (N);
  for (size_t k = 0; k < P.T->nz; k++)
    *gsl_matrix_ptr (A, (size_t) P.T->i[k], (size_t) P.T->j[k]) += P.T->x[k];
  gsl_eigen_symm (A, ev, w);
  double lmax = gsl_vector_max (ev);
  int zeros = 0;
  for (size_t k = 0; k < N; k++)
    if (fabs (gsl_vector_get (ev, k)) < 1e-10 * lmax)
      zeros++;
  gsl_eigen_symm_free (w);
  gsl_vector_free (ev);
  gsl_matrix_free (A);
  problem_free (&P);
  return zeros;
}

static void
exercise5 (void)
{
  check_int (kernel_dim (LAC_QUAD4, LAC_PLANE_STRAIN), 3,
             "ex5: rigid modes in plane strain");
  check_int (kernel_dim (LAC_HEX8, LAC_SOLID3D), 6, "ex5: rigid modes in 3D");
  check_int (kernel_dim (LAC_TRI6, LAC_AXISYMMETRIC), 1,
             "ex5: rigid modes in the axisymmetric model");
}

int
main (void)
{
  lac_init ();
  exercise1 ();
  exercise2 ();
  exercise3 ();
  exercise4 ();
  exercise5 ();
  lac_finalize ();
  return check_summary ();
}
