/* t850: the inf-sup estimate on problems small enough to do by hand
 *                                                          [LAC (10)]
 *
 * beta_h^2 = min_mu mu^T C^T A^-1 C mu / mu^T M mu  (lac_infsup.h), both
 * paths (dense, sparse) on each case:
 *   1. one multiplier: beta^2 = c^T A^-1 c / m.  A = tridiag(-1, 2, -1) of
 *      order 3, c = e_1, m = 2: (A^-1)_11 = 3/4, beta^2 = 3/8;
 *   2. two multipliers, A = I_3, C = [1 0; 1 1; 0 1], M = I: S = C^T C =
 *      [2 1; 1 2], eigenvalues 1 and 3: beta = 1, mu = (1, -1)/sqrt 2;
 *   3. the H1 Gram matrix of the unit square, one quad4, ell = 1: the sum
 *      of the entries of a component block is |Omega| = 1 (constants have
 *      no gradient), and v = x gives v^T A v = int x^2 + 1 = 4/3;
 *   4. a one-body "contact": the same square with its bottom nodes fixed
 *      and the x-dofs of the top nodes fixed; the multiplier acts on the
 *      top side, c = int_top phi_a n_y = 1/2 on the y-dofs of the two top
 *      nodes.  The free block of A on those dofs is (mass + Laplacian of
 *      a bilinear square, adjacent nodes) [7/9 -1/9; -1/9 7/9], c is its
 *      eigenvector for 2/3, so c^T A^-1 c = (1/2)(3/2) = 3/4; M = h |side| =
 *      1: beta = sqrt(3)/2;  fixed dofs found again from a K after
 *      lac_dirichlet_apply (lac_infsup_fixed_dofs): 6 of 8;
 *   5. errors: sizes (LAC_EBADLEN), a singular A (LAC_ESING, the message
 *      points to the H1 norm), C with two equal columns (dense: beta = 0;
 *      sparse: LAC_ESING "dependent columns").
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_infsup.h"
#include "base/lac_status.h"

/* A CSC from a dense row-major matrix (zeros dropped). */
static lac_csc *
csc_dense (size_t nr, size_t nc, const double *a)
{
  lac_triplet *T = lac_triplet_alloc (nr, nc, nr * nc);
  for (size_t i = 0; i < nr; i++)
    for (size_t j = 0; j < nc; j++)
      if (a[i * nc + j] != 0)
        lac_triplet_add (T, i, j, a[i * nc + j]);
  lac_csc *A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

static lac_infsup *
est (const lac_csc *A, const lac_csc *C, const lac_csc *M, lac_infsup_path p,
     int want, const char *what)
{
  lac_infsup_opts o;
  lac_infsup *r = NULL;
  lac_infsup_opts_init (&o);
  o.path = p;
  int st = lac_infsup_estimate (A, C, M, &o, &r);
  check_status (st, want, "%s (%s)", what, lac_infsup_path_name (p));
  return r;
}

static void
case_one_multiplier (void)
{
  double a[9] = { 2, -1, 0, -1, 2, -1, 0, -1, 2 }, c[3] = { 1, 0, 0 }, m = 2;
  lac_csc *A = csc_dense (3, 3, a), *C = csc_dense (3, 1, c);
  lac_csc *M = csc_dense (1, 1, &m);
  for (int p = LAC_INFSUP_DENSE; p <= LAC_INFSUP_SPARSE; p++)
    {
      lac_infsup *r = est (A, C, M, (lac_infsup_path) p, LAC_SUCCESS, "case 1");
      if (!r)
        continue;
      check_rel (r->lambda_min, 3.0 / 8.0, 1e-14, "case 1: beta^2 = 3/8");
      check_rel (r->beta, sqrt (3.0 / 8.0), 1e-14, "case 1: beta");
      check_rel (r->mu[0], 1 / sqrt (2.0), 1e-14, "case 1: mu^T M mu = 1");
      check_int ((long) r->path, p, "case 1: path used");
      lac_infsup_free (r);
    }
  lac_csc_free (A);
  lac_csc_free (C);
  lac_csc_free (M);
}

static void
case_two_multipliers (void)
{
  double a[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, c[6] = { 1, 0, 1, 1, 0, 1 };
  double m[4] = { 1, 0, 0, 1 };
  lac_csc *A = csc_dense (3, 3, a), *C = csc_dense (3, 2, c);
  lac_csc *M = csc_dense (2, 2, m);
  for (int p = LAC_INFSUP_DENSE; p <= LAC_INFSUP_SPARSE; p++)
    {
      lac_infsup *r = est (A, C, M, (lac_infsup_path) p, LAC_SUCCESS, "case 2");
      if (!r)
        continue;
      check_rel (r->beta, 1.0, 1e-13, "case 2: beta = 1");
      check_rel (r->lambda_2, 3.0, 1e-13, "case 2: lambda_2 = 3");
      check_rel (fabs (r->mu[0]), 1 / sqrt (2.0), 1e-12, "case 2: |mu_0|");
      check_rel (r->mu[0] * r->mu[1], -0.5, 1e-12, "case 2: mu = (1,-1)/sqrt2");
      check_true (r->residual < 1e-12, "case 2: residual %g", r->residual);
      if (p == LAC_INFSUP_DENSE)
        check_rel (r->lambda_max, 3.0, 1e-13, "case 2: lambda_max");
      lac_infsup_free (r);
    }
  lac_csc_free (A);
  lac_csc_free (C);
  lac_csc_free (M);
}

/* v^T A v for the field v = x in component 0 (others 0). */
static double
energy_of_x (const lac_csc *A, const lac_mesh *m)
{
  size_t n = A->ncol;
  double *v = calloc (n, sizeof *v), *Av = calloc (n, sizeof *Av), s = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    v[2 * a] = m->x[2 * a];
  lac_csc_matvec (A, v, Av);
  for (size_t i = 0; i < n; i++)
    s += v[i] * Av[i];
  free (v);
  free (Av);
  return s;
}

static void
case_square (void)
{
  size_t nc[2] = { 1, 1 };
  double L[2] = { 1, 1 };
  lac_mesh *m = NULL;
  lac_csc *A = NULL, *Af = NULL;
  check_status (lac_mesh_box (LAC_QUAD4, nc, L, 0.0, &m), LAC_SUCCESS, "box");
  /* 3. the Gram matrix itself */
  check_status (lac_infsup_gram_h1 (m, LAC_PLANE_STRAIN, NULL, 1.0, &A),
                LAC_SUCCESS, "gram");
  double sum[2] = { 0, 0 };
  for (size_t j = 0; j < A->ncol; j++)
    for (int p = A->p[j]; p < A->p[j + 1]; p++)
      if ((size_t) A->i[p] % 2 == j % 2)
        sum[j % 2] += A->x[p];
  check_rel (sum[0], 1.0, 1e-14, "case 3: 1^T A_xx 1 = |Omega|");
  check_rel (sum[1], 1.0, 1e-14, "case 3: 1^T A_yy 1 = |Omega|");
  check_rel (energy_of_x (A, m), 4.0 / 3.0, 1e-14, "case 3: |x|_1^2 = 4/3");
  /* 4. fixed: bottom nodes, x of the top nodes; c on the top y-dofs */
  const lac_group *bot = lac_mesh_group (m, "ymin"), *top = lac_mesh_group (m, "ymax");
  lac_dirichlet *D = lac_dirichlet_alloc ();
  lac_dirichlet_add_group (D, m, bot, 0, 0.0);
  lac_dirichlet_add_group (D, m, bot, 1, 0.0);
  lac_dirichlet_add_group (D, m, top, 0, 0.0);
  char fixed[8] = { 0 }, fixed2[8];
  for (size_t k = 0; k < D->n; k++)
    fixed[D->dof[k]] = 1;
  double F[8] = { 0 };
  lac_csc *K = NULL;
  check_status (lac_infsup_gram_h1 (m, LAC_PLANE_STRAIN, NULL, 1.0, &K),
                LAC_SUCCESS, "gram as K");
  lac_dirichlet_apply (D, K, F);
  check_int ((long) lac_infsup_fixed_dofs (K, fixed2), 6, "case 4: fixed dofs");
  check_true (memcmp (fixed, fixed2, 8) == 0, "case 4: the same fixed dofs");
  check_status (lac_infsup_gram_h1 (m, LAC_PLANE_STRAIN, fixed, 1.0, &Af),
                LAC_SUCCESS, "gram, fixed");
  double c[8] = { 0 }, h = 1;
  for (size_t k = 0; k < top->nnodes; k++)
    c[2 * top->node[k] + 1] = 0.5;                  /* int_top phi_a n_y */
  lac_csc *C = csc_dense (8, 1, c), *M = csc_dense (1, 1, &h);
  for (int p = LAC_INFSUP_DENSE; p <= LAC_INFSUP_SPARSE; p++)
    {
      lac_infsup *r = est (Af, C, M, (lac_infsup_path) p, LAC_SUCCESS, "case 4");
      if (r)
        check_rel (r->beta, sqrt (3.0) / 2, 1e-13, "case 4: beta = sqrt(3)/2");
      lac_infsup_free (r);
    }
  lac_csc_free (C);
  lac_csc_free (M);
  lac_csc_free (K);
  lac_dirichlet_free (D);
  lac_csc_free (Af);
  lac_csc_free (A);
  lac_mesh_free (m);
}

static void
case_errors (void)
{
  double id[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, tiny[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1e-30 };
  double c[6] = { 1, 1, 0, 0, 1, 1 }, m[4] = { 1, 0, 0, 1 };
  lac_csc *I = csc_dense (3, 3, id);
  lac_csc *C = csc_dense (3, 2, c), *M = csc_dense (2, 2, m), *M1;
  lac_infsup *r = NULL;
  double one = 1;
  M1 = csc_dense (1, 1, &one);
  check_status (lac_infsup_estimate (I, C, M1, NULL, &r), LAC_EBADLEN, "M size");
  check_true (r == NULL, "no result on error");
  lac_csc *A0d = csc_dense (3, 3, tiny);       /* not positive definite */
  r = est (A0d, C, M, LAC_INFSUP_DENSE, LAC_ESING, "singular A");
  check_message ("H1 norm", "singular A: the message points to the H1 norm");
  lac_infsup_free (r);
  /* two equal columns: S singular */
  double c2[6] = { 1, 1, 1, 1, 0, 0 };
  lac_csc *C2 = csc_dense (3, 2, c2);
  r = est (I, C2, M, LAC_INFSUP_DENSE, LAC_SUCCESS, "dependent columns");
  if (r)
    check_true (r->beta < 1e-7, "dependent columns: beta = %g ~ 0", r->beta);
  lac_infsup_free (r);
  r = est (I, C2, M, LAC_INFSUP_SPARSE, LAC_ESING, "dependent columns");
  check_message ("dependent columns", "sparse path: dependent columns");
  lac_infsup_free (r);
  lac_csc_free (C2);
  lac_csc_free (A0d);
  lac_csc_free (M1);
  lac_csc_free (I);
  lac_csc_free (C);
  lac_csc_free (M);
}

int
main (void)
{
  lac_init ();
  case_one_multiplier ();
  case_two_multipliers ();
  case_square ();
  case_errors ();
  lac_finalize ();
  return check_summary ();
}
