/* t401: patch test -- a linear field is reproduced on distorted meshes
 *       for every volume element type and model            [LAC (1)] [LAC (8)]
 *
 * The exact displacement is imposed on the whole boundary, there is no load;
 * the discrete solution must equal the exact one at every node (1e-10
 * relative) and the stress must be the constant D eps (1e-10 relative).
 *
 * Plane strain and 3D: any affine field u = u0 + G x (G not symmetric, so a
 * rotation part is included) has a constant stress, hence div sigma = 0.
 *
 * Axisymmetric (x = r, y = z): for u_r = a0 + a1 r + a2 z, u_z = b0 + b1 r
 * + b2 z the strains are eps_rr = a1, eps_zz = b2, gamma_rz = a2 + b1 and
 * eps_tt = u_r / r = a1 + (a0 + a2 z)/r.  Equilibrium without body force,
 *   d(s_rr)/dr + d(s_rz)/dz + (s_rr - s_tt)/r = 0,
 *   d(s_rz)/dr + d(s_zz)/dz + s_rz/r = 0,
 * with constant stresses asks s_rr = s_tt (eps_rr = eps_tt: a0 = a2 = 0)
 * and s_rz = 0 (b1 = 0).  The linear exact solutions are therefore
 *   u_r = a1 r,   u_z = b0 + b2 z,
 * and these are what the axisymmetric patch uses (on r in [1, 2]).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

typedef struct patch
{
  lac_model model;
  double u0[3], G[9];
} patch;

static void
linear_u (const double *x, void *ctx, double *out)
{
  const patch *P = ctx;
  int dim = lac_model_dim (P->model);
  for (int i = 0; i < dim; i++)
    {
      out[i] = P->u0[i];
      for (int k = 0; k < dim; k++)
        out[i] += P->G[i * dim + k] * x[k];
    }
}

/* Voigt strain of the linear field (engineering shears). */
static void
linear_eps (const patch *P, double *e)
{
  const double *G = P->G;
  if (P->model == LAC_SOLID3D)
    {
      e[0] = G[0]; e[1] = G[4]; e[2] = G[8];
      e[3] = G[1] + G[3]; e[4] = G[5] + G[7]; e[5] = G[6] + G[2];
    }
  else
    {
      e[0] = G[0]; e[1] = G[3];
      e[2] = P->model == LAC_AXISYMMETRIC ? G[0] : 0.0;  /* u_r/r = a1 */
      e[3] = G[1] + G[2];
    }
}

static void
run (lac_elem_type type, lac_model model)
{
  const lac_refelem *re = lac_refelem_get (type);
  const char *mname = lac_model_name (model);
  int dim = lac_model_dim (model), ns = lac_model_nstress (model);
  size_t n[3] = { 4, 3, 3 };
  double L[3] = { 1.0, 1.3, 0.9 };
  lac_mesh *m = NULL;
  int status = lac_mesh_box (type, n, L, 0.2, &m);
  check_status (status, LAC_SUCCESS, "%s %s: box mesh", re->name, mname);
  if (status)
    return;
  patch P = { model, { 1e-3, -2e-3, 0.5e-3 }, { 0 } };
  if (model == LAC_AXISYMMETRIC)
    {
      for (size_t a = 0; a < m->nnodes; a++)
        m->x[2 * a] += 1.0;                       /* r in [1, 2] */
      P.u0[0] = 0.0;                              /* u_r = a1 r */
      P.G[0] = 2e-3;                              /* a1 */
      P.G[3] = -1.5e-3;                           /* b2 (u_z = b0 + b2 z) */
    }
  else
    {
      const double G3[9] = { 1e-3, 2e-3, -1e-3, -3e-3, 0.5e-3, 1.5e-3,
                             0.7e-3, -0.4e-3, 2.5e-3 };
      const double G2[4] = { 1e-3, 2e-3, -3e-3, 0.5e-3 };
      memcpy (P.G, dim == 3 ? G3 : G2, (size_t) (dim * dim) * sizeof (double));
    }

  /* The mesh must really be distorted: det J at the centroids varies. */
  double jmin = INFINITY, jmax = 0.0, xe[LAC_MAX_NODES * 3], xc[3] = { 0 };
  lac_map mp;
  for (int b = 0; b < re->nvertices; b++)
    for (int k = 0; k < dim; k++)
      xc[k] += re->xi[b * dim + k] / re->nvertices;
  for (size_t c = 0; c < m->ncells; c++)
    {
      lac_mesh_cell_coords (m, c, xe);
      lac_map_cell (re, dim, xe, xc, &mp);
      jmin = fmin (jmin, mp.detJ);
      jmax = fmax (jmax, mp.detJ);
    }
  check_true (jmax > 1.05 * jmin, "%s %s: mesh distorted (det J in [%g, %g])",
              re->name, mname, jmin, jmax);

  size_t ndof = (size_t) dim * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_calloc (ndof, sizeof *F);
  double *u = lac_calloc (ndof, sizeof *u);
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = 210.0;
      nu[c] = 0.3;
    }
  lac_elastic mat = { model, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 16 * ndof);
  status = lac_assembly_stiffness (m, &mat, T);
  check_status (status, LAC_SUCCESS, "%s %s: stiffness", re->name, mname);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_dirichlet *d = lac_dirichlet_alloc ();
  const char *bnd[6] = { "xmin", "xmax", "ymin", "ymax", "zmin", "zmax" };
  for (int k = 0; k < 2 * dim; k++)
    {
      status = lac_dirichlet_add_field (d, m, lac_mesh_group (m, bnd[k]),
                                        linear_u, &P);
      check_status (status, LAC_SUCCESS, "%s %s: Dirichlet on %s", re->name,
                    mname, bnd[k]);
    }
  status = lac_dirichlet_apply (d, K, F);
  check_status (status, LAC_SUCCESS, "%s %s: apply", re->name, mname);
  lac_solver *s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  status = lac_solver_factor (s, K);
  check_status (status, LAC_SUCCESS, "%s %s: factor", re->name, mname);
  if (!status)
    status = lac_solver_solve (s, F, u);
  check_status (status, LAC_SUCCESS, "%s %s: solve", re->name, mname);

  /* Nodal values: max |u_h - u| <= 1e-10 max |u|. */
  double err = 0.0, umax = 0.0, ue[3];
  for (size_t a = 0; a < m->nnodes; a++)
    {
      linear_u (m->x + (size_t) dim * a, &P, ue);
      for (int i = 0; i < dim; i++)
        {
          err = fmax (err, fabs (u[(size_t) dim * a + (size_t) i] - ue[i]));
          umax = fmax (umax, fabs (ue[i]));
        }
    }
  check_true (err <= 1e-10 * umax, "%s %s: nodal error %.3e (max |u| %.3e)",
              re->name, mname, err, umax);

  /* Stresses at every node of every cell and at the cell centroid. */
  double D[36], eps[6], sig[6], sh[6], smax = 0.0, serr = 0.0;
  lac_material_D (model, 210.0, 0.3, D);
  linear_eps (&P, eps);
  for (int i = 0; i < ns; i++)
    {
      sig[i] = 0.0;
      for (int k = 0; k < ns; k++)
        sig[i] += D[i * ns + k] * eps[k];
      smax = fmax (smax, fabs (sig[i]));
    }
  for (size_t c = 0; c < m->ncells; c++)
    for (int a = 0; a <= re->nnodes; a++)
      {
        double xi[3] = { 0 };
        if (a < re->nnodes)
          memcpy (xi, re->xi + a * dim, (size_t) dim * sizeof *xi);
        else
          for (int b = 0; b < re->nvertices; b++)
            for (int k = 0; k < dim; k++)
              xi[k] += re->xi[b * dim + k] / re->nvertices;
        status = lac_post_stress_at (m, &mat, u, c, xi, sh);
        if (status)
          {
            check_status (status, LAC_SUCCESS, "%s %s: stress", re->name,
                          mname);
            break;
          }
        for (int i = 0; i < ns; i++)
          serr = fmax (serr, fabs (sh[i] - sig[i]));
      }
  check_true (serr <= 1e-10 * smax, "%s %s: stress error %.3e (max |sigma|"
              " %.3e)", re->name, mname, serr, smax);

  /* Nodal averages give the same constant. */
  double *sn = lac_malloc (m->nnodes * (size_t) ns * sizeof *sn);
  double *vm = lac_malloc (m->nnodes * sizeof *vm);
  status = lac_post_stress_nodal (m, &mat, u, NULL, sn, vm);
  check_status (status, LAC_SUCCESS, "%s %s: nodal stress", re->name, mname);
  serr = 0.0;
  double vmerr = 0.0, vmx = lac_von_mises (model, sig);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      for (int i = 0; i < ns; i++)
        serr = fmax (serr, fabs (sn[a * (size_t) ns + (size_t) i] - sig[i]));
      vmerr = fmax (vmerr, fabs (vm[a] - vmx));
    }
  check_true (serr <= 1e-10 * smax && vmerr <= 1e-10 * vmx,
              "%s %s: nodal stress error %.3e, von Mises error %.3e",
              re->name, mname, serr, vmerr);

  lac_free (vm);
  lac_free (sn);
  lac_solver_free (s);
  lac_dirichlet_free (d);
  lac_csc_free (K);
  lac_triplet_free (T);
  lac_free (u);
  lac_free (F);
  lac_free (nu);
  lac_free (E);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  const lac_elem_type t2[] = { LAC_TRI3, LAC_TRI6, LAC_QUAD4, LAC_QUAD8,
                               LAC_QUAD9 };
  const lac_elem_type t3[] = { LAC_TET4, LAC_TET10, LAC_HEX8, LAC_HEX20,
                               LAC_HEX27 };
  for (int k = 0; k < 5; k++)
    {
      run (t2[k], LAC_PLANE_STRAIN);
      run (t2[k], LAC_AXISYMMETRIC);
      run (t3[k], LAC_SOLID3D);
    }
  lac_finalize ();
  return check_summary ();
}
