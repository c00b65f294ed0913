/* t402: convergence rates on a manufactured solution, plane strain,
 *       axisymmetric and 3D, every volume element type
 *       [LAC (1)] [LAC (8)] [LAC §3.2]
 *
 * Exact field (A = 0.01, wave vectors k_i and phases p_i below):
 *   u_i(x) = A sin(k_i . x + p_i),
 *   grad:  d_j u_i = A cos(k_i . x + p_i) k_ij,
 *   force: f = -div sigma = -[(lambda + mu) grad(div u) + mu Lap u], with
 *          d_i div u = -A sum_j sin(k_j . x + p_j) k_jj k_ji,
 *          Lap u_i   = -A |k_i|^2 sin(k_i . x + p_i).
 * Axisymmetric (x = r in [1, 2], y = z in [0, 1]), the same u and
 *   f_r = -(d_r s_rr + d_z s_rz + (s_rr - s_tt)/r),
 *   f_z = -(d_r s_rz + d_z s_zz + s_rz/r),  with e = d_r u_r + u_r/r + d_z u_z,
 *   s_rr = lam e + 2 mu d_r u_r, s_tt = lam e + 2 mu u_r/r,
 *   s_zz = lam e + 2 mu d_z u_z, s_rz = mu (d_z u_r + d_r u_z);
 *   errors in the norms of the solid of revolution (lac_post.c).
 * Dirichlet data u on the whole boundary of the unit square/cube,
 * undistorted structured meshes (distort = 0: the serendipity elements lose
 * an order on general quadrilaterals, which is not what this test is about).
 * The rates fitted by least squares on log(err) vs log(h) over >= 4 levels
 * must be within 0.15 of k+1 (L2) and k (H1 seminorm), k the element order.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

#define AMP 0.01
#define YOUNG 100.0
#define POISSON 0.3

typedef struct mms
{
  int dim;
  int axi;          /* axisymmetric model (dim 2) */
  double k[3][3];   /* k[i] the wave vector of component i */
  double p[3];      /* phases */
  double lam, mu;
} mms;

static double
phase (const mms *S, int i, const double *x)
{
  double t = S->p[i];
  for (int j = 0; j < S->dim; j++)
    t += S->k[i][j] * x[j];
  return t;
}

static void
exact_u (const double *x, void *ctx, double *out)
{
  const mms *S = ctx;
  for (int i = 0; i < S->dim; i++)
    out[i] = AMP * sin (phase (S, i, x));
}

static void
exact_grad (const double *x, void *ctx, double *out)
{
  const mms *S = ctx;
  for (int i = 0; i < S->dim; i++)
    for (int j = 0; j < S->dim; j++)
      out[i * S->dim + j] = AMP * cos (phase (S, i, x)) * S->k[i][j];
}

static void
force (const double *x, void *ctx, double *out)
{
  const mms *S = ctx;
  int dim = S->dim;
  for (int i = 0; i < dim; i++)
    {
      double gdiv = 0.0, k2 = 0.0;
      for (int j = 0; j < dim; j++)
        {
          gdiv += -AMP * sin (phase (S, j, x)) * S->k[j][j] * S->k[j][i];
          k2 += S->k[i][j] * S->k[i][j];
        }
      double lap = -AMP * k2 * sin (phase (S, i, x));
      out[i] = -((S->lam + S->mu) * gdiv + S->mu * lap);
    }
}

/* Derivatives of u_i = A sin(t_i): first d_j, second d_jl. */
static double
du (const mms *S, int i, int j, const double *x)
{
  return AMP * cos (phase (S, i, x)) * S->k[i][j];
}

static double
ddu (const mms *S, int i, int j, int l, const double *x)
{
  return -AMP * sin (phase (S, i, x)) * S->k[i][j] * S->k[i][l];
}

/* Axisymmetric body force (file header); x = (r, z). */
static void
force_axi (const double *x, void *ctx, double *out)
{
  const mms *S = ctx;
  double lam = S->lam, mu = S->mu, r = x[0];
  double ur = AMP * sin (phase (S, 0, x));
  double ur_r = du (S, 0, 0, x), ur_z = du (S, 0, 1, x);
  double uz_r = du (S, 1, 0, x);
  double ur_rr = ddu (S, 0, 0, 0, x), ur_rz = ddu (S, 0, 0, 1, x);
  double ur_zz = ddu (S, 0, 1, 1, x);
  double uz_rr = ddu (S, 1, 0, 0, x), uz_rz = ddu (S, 1, 0, 1, x);
  double uz_zz = ddu (S, 1, 1, 1, x);
  double e_r = ur_rr + ur_r / r - ur / (r * r) + uz_rz;   /* d_r e */
  double e_z = ur_rz + ur_z / r + uz_zz;                  /* d_z e */
  double srr_r = lam * e_r + 2 * mu * ur_rr;
  double srz_z = mu * (ur_zz + uz_rz);
  double srz_r = mu * (ur_rz + uz_rr);
  double szz_z = lam * e_z + 2 * mu * uz_zz;
  double srz = mu * (ur_z + uz_r);
  out[0] = -(srr_r + srz_z + 2 * mu * (ur_r - ur / r) / r);
  out[1] = -(srz_r + szz_z + srz / r);
}

/* Solve on an n^dim box, return the errors. */
static int
solve (lac_elem_type type, const mms *S, size_t n, double *l2, double *h1)
{
  int dim = S->dim;
  size_t nn[3] = { n, n, n };
  double L[3] = { 1.0, 1.0, 1.0 };
  lac_mesh *m = NULL;
  int status = lac_mesh_box (type, nn, L, 0.0, &m);
  if (status)
    return status;
  lac_model model = dim == 3 ? LAC_SOLID3D
                    : S->axi ? LAC_AXISYMMETRIC : LAC_PLANE_STRAIN;
  if (S->axi)
    for (size_t a = 0; a < m->nnodes; a++)
      m->x[2 * a] += 1.0;                         /* r in [1, 2] */
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_calloc (ndof, sizeof *F);
  double *u = lac_calloc (ndof, sizeof *u);
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = YOUNG;
      nu[c] = POISSON;
    }
  lac_elastic mat = { model, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 16 * ndof);
  lac_dirichlet *d = lac_dirichlet_alloc ();
  lac_solver *s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  lac_csc *K = NULL;
  status = lac_assembly_stiffness (m, &mat, T);
  if (!status)
    status = lac_assembly_volume_force (m, model, NULL,
                                        S->axi ? force_axi : force,
                                        (void *) S, F);
  const char *bnd[6] = { "xmin", "xmax", "ymin", "ymax", "zmin", "zmax" };
  for (int k = 0; k < 2 * dim && !status; k++)
    status = lac_dirichlet_add_field (d, m, lac_mesh_group (m, bnd[k]),
                                      exact_u, (void *) S);
  if (!status)
    {
      K = lac_csc_from_triplet (T);
      status = K ? lac_dirichlet_apply (d, K, F) : LAC_ENOMEM;
    }
  if (!status)
    status = lac_solver_factor (s, K);
  if (!status)
    status = lac_solver_solve (s, F, u);
  if (!status)
    status = lac_post_errors (m, model, u, exact_u, exact_grad, (void *) S,
                              l2, h1, NULL, NULL);
  lac_csc_free (K);
  lac_solver_free (s);
  lac_dirichlet_free (d);
  lac_triplet_free (T);
  lac_free (u);
  lac_free (F);
  lac_free (nu);
  lac_free (E);
  lac_mesh_free (m);
  return status;
}

/* Least-squares slope of log(e) against log(h). */
static double
slope (int n, const double *h, const double *e)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < n; k++)
    {
      double X = log (h[k]), Y = log (e[k]);
      sx += X; sy += Y; sxx += X * X; sxy += X * Y;
    }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

static void
run (lac_elem_type type, const mms *S, const size_t *levels, int nlev)
{
  const lac_refelem *re = lac_refelem_get (type);
  const char *tag = S->axi ? " (axisymmetric)" : "";
  double h[8], el2[8], eh1[8];
  for (int k = 0; k < nlev; k++)
    {
      int status = solve (type, S, levels[k], &el2[k], &eh1[k]);
      check_status (status, LAC_SUCCESS, "%s%s n = %zu", re->name, tag,
                    levels[k]);
      if (status)
        return;
      h[k] = 1.0 / (double) levels[k];
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("  %-5s%s n = %2zu  L2 = %.4e  H1 = %.4e\n", re->name, tag,
                levels[k], el2[k], eh1[k]);
    }
  double r0 = slope (nlev, h, el2), r1 = slope (nlev, h, eh1);
  int k = re->order;
  check_abs (r0, k + 1, 0.15, "%s%s: L2 rate %.3f (expected %d)", re->name,
             tag, r0, k + 1);
  check_abs (r1, k, 0.15, "%s%s: H1 rate %.3f (expected %d)", re->name, tag,
             r1, k);
}

int
main (void)
{
  lac_init ();
  double lam = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON));
  double mu = YOUNG / (2 * (1 + POISSON));
  mms S2 = { 2, 0, { { 1.3, 0.7 }, { -0.6, 1.1 } }, { 0.3, 0.5 }, lam, mu };
  mms SA = { 2, 1, { { 1.3, 0.7 }, { -0.6, 1.1 } }, { 0.3, 0.5 }, lam, mu };
  mms S3 = { 3, 0, { { 1.3, 0.7, -0.4 }, { -0.6, 1.1, 0.5 },
                     { 0.4, -0.8, 1.2 } }, { 0.3, 0.5, -0.2 }, lam, mu };
  const size_t lin2[] = { 4, 8, 16, 32 }, quad2[] = { 2, 4, 8, 16 };
  const size_t lin3[] = { 2, 4, 8, 16 }, quad3[] = { 2, 3, 4, 6 };

  run (LAC_TRI3, &S2, lin2, 4);
  run (LAC_QUAD4, &S2, lin2, 4);
  run (LAC_TRI6, &S2, quad2, 4);
  run (LAC_QUAD8, &S2, quad2, 4);
  run (LAC_QUAD9, &S2, quad2, 4);
  run (LAC_TRI3, &SA, lin2, 4);
  run (LAC_QUAD4, &SA, lin2, 4);
  run (LAC_TRI6, &SA, quad2, 4);
  run (LAC_QUAD8, &SA, quad2, 4);
  run (LAC_QUAD9, &SA, quad2, 4);
  run (LAC_TET4, &S3, lin3, 4);
  run (LAC_HEX8, &S3, lin3, 4);
  run (LAC_TET10, &S3, quad3, 4);
  run (LAC_HEX20, &S3, quad3, 4);
  run (LAC_HEX27, &S3, quad3, 4);
  lac_finalize ();
  return check_summary ();
}
