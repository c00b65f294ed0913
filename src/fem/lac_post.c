/* lac_post.c -- post-processing: stresses and errors        [LAC (2)] [LAC §5]
 *
 * Stresses sigma = A eps(u_h)  [LAC (2)] evaluated from the gradient of the
 * discrete displacement inside a cell, their nodal averages and the von
 * Mises stress; the L2 error and the H1-seminorm error of u_h against an
 * exact solution, the quantities of the convergence studies [LAC §3.2]
 * [LAC §5].
 *
 * Axisymmetric model (x = r, y = z): the hoop strain is u_r / r; on the
 * axis (r = 0, where u_r = 0 for a regular field) it is replaced by its
 * limit du_r/dr.  Norms are the norms of the solid of revolution, i.e. the
 * integrals carry the weight 2 pi r:
 *   ||v||_0^2 = int |v|^2 2 pi r dr dz,
 *   |v|_1^2   = int (|grad_(r,z) v|^2 + (v_r / r)^2) 2 pi r dr dz,
 * the second being the 3D H1 seminorm of the revolved vector field (the
 * hoop term (v_r/r)^2 is the only non-zero part of the gradient the (r,z)
 * gradient does not show).  Plane strain: norms over the section (per
 * unit thickness).
 *
 * Error quadrature: degree 2*order + 2 of the cell (+1 in the axisymmetric
 * model for the weight r), exact for the polynomial part of |u - u_h|^2 on
 * affine cells; on curved cells and for non-polynomial exact fields it is an
 * approximation, far below the discretization error.
 */
#include "fem/lac_post.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "fem/lac_nodal.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"


/* Largest extent of the bounding box of a cell (for relative tolerances). */
static double
cell_diameter (int nen, int dim, const double *xe)
{
  double diam = 0.0;
  for (int k = 0; k < dim; k++)
    {
      double lo = xe[k], hi = xe[k];
      for (int a = 1; a < nen; a++)
        {
          lo = fmin (lo, xe[a * dim + k]);
          hi = fmax (hi, xe[a * dim + k]);
        }
      diam = fmax (diam, hi - lo);
    }
  return diam;
}

/* The displacements of the nodes of cell c: ue[a*dim + i] = u_{a,i}. */
static void
cell_values (const lac_mesh *m, size_t c, int nen, const double *u,
             double *ue)
{
  const int *conn = m->conn + m->ptr[c];
  for (int a = 0; a < nen; a++)
    memcpy (ue + a * m->dim, u + (size_t) m->dim * (size_t) conn[a],
            (size_t) m->dim * sizeof *ue);
}

/* Displacement and its gradient at a mapped point of a cell, from its
 * nodal values ue (cell_values):
 *   uh[i] = sum_a N_a u_{a,i},  gh[i*dim + k] = sum_a u_{a,i} dN_a/dx_k. */
static void
interp (int dim, int nen, const lac_map *mp, const double *ue, double *uh,
        double *gh)
{
  memset (uh, 0, (size_t) dim * sizeof *uh);
  memset (gh, 0, (size_t) (dim * dim) * sizeof *gh);
  for (int a = 0; a < nen; a++)
    {
      const double *ua = ue + a * dim;
      for (int i = 0; i < dim; i++)
        {
          uh[i] += mp->N[a] * ua[i];                          /* u_h */
          for (int k = 0; k < dim; k++)
            gh[i * dim + k] += ua[i] * mp->dNdx[a * dim + k]; /* grad u_h */
        }
    }
}

/* Voigt strain (engineering shears) from the displacement and its gradient.
 * hoop: the axisymmetric eps_tt (ignored otherwise). */
static void
strain (lac_model model, const double *g, double hoop, double *e)
{
  if (model == LAC_SOLID3D)
    {
      e[0] = g[0];               /* eps_xx */
      e[1] = g[4];               /* eps_yy */
      e[2] = g[8];               /* eps_zz */
      e[3] = g[1] + g[3];        /* gamma_xy */
      e[4] = g[5] + g[7];        /* gamma_yz */
      e[5] = g[6] + g[2];        /* gamma_zx */
    }
  else
    {
      e[0] = g[0];               /* eps_xx (rr) */
      e[1] = g[3];               /* eps_yy (zz) */
      e[2] = model == LAC_AXISYMMETRIC ? hoop : 0.0;  /* eps_tt or eps_zz = 0 */
      e[3] = g[1] + g[2];        /* gamma_xy (rz) */
    }
}

/* Stress at reference point xi of cell c (no argument checks): the
 * lac_cell_stress of the linear law, law = a lac_elastic. */
static int
stress_at (const lac_mesh *m, const void *law, const double *u, size_t c,
           const double *xi, double *s)
{
  const lac_elastic *mat = law;
  int dim = m->dim, ns = lac_model_nstress (mat->model);
  double xe[LAC_MAX_NODES * 3], ue[LAC_MAX_NODES * 3], D[36], uh[3], gh[9],
         e[6];
  lac_map mp;
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  if (!re || re->dim != dim)
    LAC_ERROR (LAC_EINVAL, "cell %zu is not a %dD cell", c, dim);
  int status = lac_material_D (mat->model, mat->E[c], mat->nu[c], D);
  if (status)
    LAC_ERROR (status, "cell %zu: E = %g, nu = %g is not a valid material",
               c, mat->E[c], mat->nu[c]);
  lac_mesh_cell_coords (m, c, xe);
  status = lac_map_cell (re, dim, xe, xi, &mp);
  if (status)
    LAC_ERROR (status, "cell %zu (%s): det J = %g <= 0 at the point", c,
               re->name, mp.detJ);
  cell_values (m, c, re->nnodes, u, ue);
  interp (dim, re->nnodes, &mp, ue, uh, gh);
  double hoop = 0.0;
  if (mat->model == LAC_AXISYMMETRIC)
    {
      double r = mp.x[0];
      if (fabs (r) <= 1e-12 * cell_diameter (re->nnodes, dim, xe))
        hoop = gh[0];                 /* on the axis: u_r/r -> du_r/dr */
      else
        hoop = uh[0] / r;             /* eps_tt = u_r / r */
    }
  strain (mat->model, gh, hoop, e);
  for (int i = 0; i < ns; i++)        /* s = D eps  [LAC (2)] */
    {
      s[i] = 0.0;
      for (int k = 0; k < ns; k++)
        s[i] += D[i * ns + k] * e[k];
    }
  return LAC_SUCCESS;
}

/* Common checks of the stress routines. */
static int
check_args (const lac_mesh *m, const lac_elastic *mat, const double *u)
{
  if (!m || !mat || !u || !mat->E || !mat->nu)
    LAC_ERROR (LAC_EINVAL, "mesh, material or displacement is NULL");
  if (lac_model_dim (mat->model) != m->dim)
    LAC_ERROR (LAC_EINVAL, "model %s needs a %dD mesh, the mesh is %dD",
               lac_model_name (mat->model), lac_model_dim (mat->model), m->dim);
  return LAC_SUCCESS;
}

/* lac_post_stress_at: s = D eps(u_h)(x(xi)) in cell c  [LAC (2)].
 *   [in]  m, mat, u (dim*nnodes), c, xi (reference coordinates)
 *   [out] s   lac_model_nstress values (plane strain: s[2] = sigma_zz)
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ESING (det J <= 0) */
int
lac_post_stress_at (const lac_mesh *m, const lac_elastic *mat,
                    const double *u, size_t c, const double *xi, double *s)
{
  int status = check_args (m, mat, u);
  return status ? status : lac_nodal_point (m, stress_at, mat, u, c, xi, s);
}

/* lac_post_stress_nodal: sigma at every node, the unweighted mean of the
 * values of the cells (with E[c] > 0, and cells[c] != 0 if cells is given)
 * that contain the node; vm = von Mises of the mean (may be NULL).
 *   [out] sigma  nnodes*ns, vm  nnodes
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ESING, LAC_ENOMEM */
int
lac_post_stress_nodal (const lac_mesh *m, const lac_elastic *mat,
                       const double *u, const char *cells, double *sigma,
                       double *vm)
{
  int status = check_args (m, mat, u);
  return status ? status : lac_nodal_average (m, mat->model, mat->E, cells,
                                              stress_at, mat, u, sigma, vm);
}

/* lac_post_stress_sum: lac_post_stress_nodal's sums (lac_nodal_sum). */
int
lac_post_stress_sum (const lac_mesh *m, const lac_elastic *mat,
                     const double *u, const char *cells, double *sigma,
                     double *count)
{
  int status = check_args (m, mat, u);
  return status ? status : lac_nodal_sum (m, mat->model, mat->E, cells,
                                          stress_at, mat, u, sigma, count);
}

/* lac_post_error_sums: the squares of lac_post_errors' four numbers,
 * summed over the cells with cells[c] != 0 (cells NULL: all):
 * sq = { ||u - u_h||_0^2, |u - u_h|_1^2, ||u||_0^2, |u|_1^2 } (the last
 * two 0 and the H1 terms 0 when grad is NULL).
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ESING, LAC_ENOMEM */
int
lac_post_error_sums (const lac_mesh *m, lac_model model, const double *u,
                     const char *cells, lac_field *exact,
                     lac_field_grad *grad, void *ctx, double sq[4])
{
  if (!m || !u || !exact)
    LAC_ERROR (LAC_EINVAL, "mesh, displacement or exact field is NULL");
  if (lac_model_dim (model) != m->dim)
    LAC_ERROR (LAC_EINVAL, "model %s needs a %dD mesh, the mesh is %dD",
               lac_model_name (model), lac_model_dim (model), m->dim);
  int dim = m->dim, status = LAC_SUCCESS, axi = model == LAC_AXISYMMETRIC;
  double el2 = 0, eh1 = 0, nl2 = 0, nh1 = 0;
  double xe[LAC_MAX_NODES * 3], uc[LAC_MAX_NODES * 3], uh[3], gh[9], ue[3],
         ge[9];
  lac_quad_cache qc;            /* a rule per cell type, its shape */
  lac_map mp;                   /* functions evaluated once (lac_map_cell_at) */
  memset (&qc, 0, sizeof qc);
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      if (cells && !cells[c])
        continue;
      if (!re || re->dim != dim)
        {
          status = LAC_ERRMSG (LAC_EINVAL, "cell %zu is not a %dD cell", c,
                               dim);
          break;
        }
      const lac_quad_table *t = lac_quad_cache_table (&qc, re, 2 * re->order
                                                      + 2 + axi);
      if (!t && (status = LAC_ENOMEM))          /* message set */
        break;
      const lac_quad *q = t->q;
      int nen = re->nnodes;
      lac_mesh_cell_coords (m, c, xe);
      cell_values (m, c, nen, u, uc);
      for (int p = 0; p < q->n; p++)
        {
          status = lac_map_cell_at (re, dim, xe, q->xi + p * dim,
                                    t->N + p * nen, t->dN + p * nen * dim,
                                    &mp);
          if (status)
            break;
          double w = q->w[p] * mp.detJ * lac_model_weight (model, mp.x);
          interp (dim, nen, &mp, uc, uh, gh);
          exact (mp.x, ctx, ue);
          for (int i = 0; i < dim; i++)
            {
              el2 += w * (ue[i] - uh[i]) * (ue[i] - uh[i]);  /* |u - u_h|^2 */
              nl2 += w * ue[i] * ue[i];                      /* |u|^2 */
            }
          if (!grad)
            continue;
          grad (mp.x, ctx, ge);
          for (int k = 0; k < dim * dim; k++)
            {
              eh1 += w * (ge[k] - gh[k]) * (ge[k] - gh[k]); /* |grad e|^2 */
              nh1 += w * ge[k] * ge[k];
            }
          if (axi)
            {
              double r = mp.x[0];
              double d = (ue[0] - uh[0]) / r;                /* hoop term */
              eh1 += w * d * d;
              nh1 += w * (ue[0] / r) * (ue[0] / r);
            }
        }
      if (status)
        {
          status = LAC_ERRMSG (status, "cell %zu (%s): det J <= 0", c,
                               re->name);
          break;
        }
    }
  lac_quad_cache_free (&qc);
  sq[0] = el2, sq[1] = eh1, sq[2] = nl2, sq[3] = nh1;
  return status;
}

/* lac_post_errors: l2 = ||u - u_h||_0 and h1 = |u - u_h|_1 over all cells,
 * with l2_exact = ||u||_0, h1_exact = |u|_1 (norms as in the file header:
 * weight 2 pi r and the hoop term in the axisymmetric model).
 *   [in]  m, model, u (dim*nnodes), exact(x, ctx, out[dim]), grad(x, ctx,
 *         out[dim*dim]) (grad may be NULL if h1 and h1_exact are NULL)
 *   [out] l2, h1, l2_exact, h1_exact (each may be NULL)
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ESING, LAC_ENOMEM */
int
lac_post_errors (const lac_mesh *m, lac_model model, const double *u,
                 lac_field *exact, lac_field_grad *grad, void *ctx,
                 double *l2, double *h1, double *l2_exact, double *h1_exact)
{
  double sq[4];
  if (!grad && (h1 || h1_exact))
    LAC_ERROR (LAC_EINVAL, "H1 errors asked for but the gradient is NULL");
  int status = lac_post_error_sums (m, model, u, NULL, exact, grad, ctx, sq);
  if (status)
    return status;
  lac_post_error_roots (sq, l2, h1, l2_exact, h1_exact);
  return LAC_SUCCESS;
}

void
lac_post_error_roots (const double sq[4], double *l2, double *h1,
                      double *l2_exact, double *h1_exact)
{
  if (l2)
    *l2 = sqrt (sq[0]);
  if (h1)
    *h1 = sqrt (sq[1]);
  if (l2_exact)
    *l2_exact = sqrt (sq[2]);
  if (h1_exact)
    *h1_exact = sqrt (sq[3]);
}
