/* lac_assembly.c -- stiffness, loads, Dirichlet data  [LAC §2] [LAC §4.3]
 *
 * Discretizes the forms of the weak problem [LAC (8)]
 *   a(u,v) = int_Omega A eps(u) : eps(v) dOmega          (stiffness K)
 *   l(v)   = int_Omega f . v dOmega + int_Gamma_N F . v dGamma   (load F)
 * on the nodal Lagrange spaces of lac_spaces.h, dof = dim*node + component.
 *
 * Strain-displacement matrices B (eps = B u_e, Voigt order of
 * lac_material.h, engineering shears), for a node a with shape function N_a:
 *   plane strain   [ N_a,x 0 ; 0 N_a,y ; 0 0 ; N_a,y N_a,x ]  (eps_zz = 0)
 *   axisymmetric   [ N_a,r 0 ; 0 N_a,z ; N_a/r 0 ; N_a,z N_a,r ]
 *                  (the hoop strain eps_tt = u_r / r; x = r, y = z)
 *   3D             [ N_a,x 0 0 ; 0 N_a,y 0 ; 0 0 N_a,z ;
 *                    N_a,y N_a,x 0 ; 0 N_a,z N_a,y ; N_a,z 0 N_a,x ]
 * and Ke = int_e B^T D B w dx, with w = 1 (plane strain: per unit
 * thickness; 3D) or w = 2 pi r (axisymmetric: the integral over the solid
 * of revolution).  All volume and surface integrals here carry the same w.
 *
 * Quadrature degree (lac_quad_alloc gives a rule exact to at least it):
 *   2*order          for a straight-sided cell in plane strain or 3D: this
 *                    integrates B^T D B exactly on affine simplices and is
 *                    the usual "full" Gauss rule on quadrangles and
 *                    hexahedra (2x2(x2) for order 1, 3x3(x3) for order 2),
 *                    which also passes the patch test on distorted cells;
 *   + 2              if the cell is curved (a mid-node off the straight
 *                    position: the Jacobian is no longer constant), and
 *   + 2              in the axisymmetric model (the factor r in the weight
 *                    and the N_a/r of the hoop row).
 * Loads use 2*order + 2 (+1 axisymmetric): f and F are arbitrary smooth
 * functions, so these integrals are approximations in any case.
 *
 * Dirichlet conditions are imposed by symmetric elimination on the CSC
 * matrix, which keeps K symmetric positive definite so that CHOLMOD applies.
 */
#include "fem/lac_assembly.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "fem/lac_pattern.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"



/* is_curved: does the cell geometry differ from the (multi)linear map of
 * its vertices?  Checks every non-vertex node against the linear map
 * evaluated at that node's reference coordinates (relative tolerance 1e-10
 * of the vertex bounding box). */
static int
is_curved (const lac_refelem *re, int sdim, const double *xe)
{
  if (re->order < 2)
    return 0;
  const lac_refelem *rl = lac_refelem_get (lac_refelem_linear_type (re->type));
  if (!rl || rl == re)
    return 1;
  double lo[3] = { 0 }, hi[3] = { 0 }, diam = 0.0, N[LAC_MAX_NODES];
  for (int k = 0; k < sdim; k++)
    {
      lo[k] = hi[k] = xe[k];
      for (int a = 1; a < rl->nnodes; a++)
        {
          lo[k] = fmin (lo[k], xe[a * sdim + k]);
          hi[k] = fmax (hi[k], xe[a * sdim + k]);
        }
      diam = fmax (diam, hi[k] - lo[k]);
    }
  for (int a = rl->nnodes; a < re->nnodes; a++)
    {
      lac_refelem_eval (rl, re->xi + a * re->dim, N, NULL);
      for (int k = 0; k < sdim; k++)
        {
          double x = 0.0;
          for (int b = 0; b < rl->nnodes; b++)
            x += N[b] * xe[b * sdim + k];             /* linear map x(xi_a) */
          if (fabs (x - xe[a * sdim + k]) > 1e-10 * diam)
            return 1;
        }
    }
  return 0;
}

/* Quadrature degree for the stiffness of a cell (see the file header). */
static int
stiffness_degree (const lac_refelem *re, lac_model model, int curved)
{
  int deg = 2 * re->order;
  if (curved)
    deg += 2;
  if (model == LAC_AXISYMMETRIC)
    deg += 2;
  return deg;
}

/* Quadrature degree for load integrals (see the file header). */
static int
load_degree (const lac_refelem *re, lac_model model)
{
  return 2 * re->order + 2 + (model == LAC_AXISYMMETRIC ? 1 : 0);
}

/* fill_B: the strain-displacement matrix at one point (file header).
 *   [in]  model, nen, mp (N, dNdx and x of the cell map)
 *   [out] B   ns x (nen*dim), row-major, zeroed here */
static void
fill_B (lac_model model, int nen, const lac_map *mp, double *B)
{
  int dim = lac_model_dim (model), ns = lac_model_nstress (model);
  int nc = nen * dim;
  memset (B, 0, (size_t) (ns * nc) * sizeof *B);
  for (int a = 0; a < nen; a++)
    {
      const double *g = mp->dNdx + a * dim;       /* grad N_a */
      int c = a * dim;
      if (dim == 2)
        {
          B[0 * nc + c] = g[0];                   /* eps_xx = u_x,x */
          B[1 * nc + c + 1] = g[1];               /* eps_yy = u_y,y */
          if (model == LAC_AXISYMMETRIC)
            B[2 * nc + c] = mp->N[a] / mp->x[0];  /* eps_tt = u_r / r */
          B[3 * nc + c] = g[1];                   /* gamma_xy = u_x,y + u_y,x */
          B[3 * nc + c + 1] = g[0];
        }
      else
        {
          B[0 * nc + c] = g[0];                   /* eps_xx */
          B[1 * nc + c + 1] = g[1];               /* eps_yy */
          B[2 * nc + c + 2] = g[2];               /* eps_zz */
          B[3 * nc + c] = g[1];                   /* gamma_xy */
          B[3 * nc + c + 1] = g[0];
          B[4 * nc + c + 1] = g[2];               /* gamma_yz */
          B[4 * nc + c + 2] = g[1];
          B[5 * nc + c] = g[2];                   /* gamma_zx */
          B[5 * nc + c + 2] = g[0];
        }
    }
}

/* Check that a material description fits the mesh. */
static int
check_elastic (const lac_mesh *m, const lac_elastic *mat)
{
  if (!m || !mat)
    LAC_ERROR (LAC_EINVAL, "mesh or material is NULL");
  if (lac_model_dim (mat->model) == 0)
    LAC_ERROR (LAC_EINVAL, "unknown model %d", (int) mat->model);
  if (lac_model_dim (mat->model) != m->dim)
    LAC_ERROR (LAC_EINVAL, "model %s needs a %dD mesh, the mesh is %dD",
               lac_model_name (mat->model), lac_model_dim (mat->model), m->dim);
  if (!mat->E || !mat->nu)
    LAC_ERROR (LAC_EINVAL, "material arrays E or nu are NULL");
  return LAC_SUCCESS;
}

/* Element stiffness with a given quadrature cache (see the public one). */
static int
cell_stiffness (const lac_mesh *m, const lac_elastic *mat, size_t c,
                lac_quad_cache *qc, double *Ke)
{
  int dim = m->dim, ns = lac_model_nstress (mat->model);
  double D[36], xe[LAC_MAX_NODES * 3];
  double B[6 * LAC_MAX_NODES * 3], DB[6 * LAC_MAX_NODES * 3];
  lac_map mp;

  const lac_refelem *re = lac_refelem_get (m->type[c]);
  if (!re || re->dim != dim)
    LAC_ERROR (LAC_EINVAL, "cell %zu (tag %zu) has type %d, not a %dD cell",
               c, m->cell_tag ? m->cell_tag[c] : c, (int) m->type[c], dim);
  int status = lac_material_D (mat->model, mat->E[c], mat->nu[c], D);
  if (status)
    LAC_ERROR (status, "cell %zu (tag %zu): E = %g, nu = %g is not a valid"
               " material (E > 0, -1 < nu < 1/2)", c,
               m->cell_tag ? m->cell_tag[c] : c, mat->E[c], mat->nu[c]);
  int nen = re->nnodes, nc = nen * dim;
  lac_mesh_cell_coords (m, c, xe);
  const lac_quad *q = lac_quad_cache_get (qc, re->shape,
                                  stiffness_degree (re, mat->model,
                                                    is_curved (re, dim, xe)));
  if (!q)
    return LAC_ENOMEM;      /* message set by lac_quad_alloc */

  memset (Ke, 0, (size_t) (nc * nc) * sizeof *Ke);
  for (int p = 0; p < q->n; p++)
    {
      status = lac_map_cell (re, dim, xe, q->xi + p * dim, &mp);
      if (status)
        LAC_ERROR (status, "cell %zu (tag %zu, %s): det J = %g <= 0 at"
                   " quadrature point %d; inverted or degenerate cell", c,
                   m->cell_tag ? m->cell_tag[c] : c, re->name, mp.detJ, p);
      if (mat->model == LAC_AXISYMMETRIC && !(mp.x[0] > 0.0))
        LAC_ERROR (LAC_EINVAL, "cell %zu (tag %zu): r = %g <= 0 at a"
                   " quadrature point; an axisymmetric mesh must lie in r >= 0",
                   c, m->cell_tag ? m->cell_tag[c] : c, mp.x[0]);
      double w = q->w[p] * mp.detJ * lac_model_weight (mat->model, mp.x);
      fill_B (mat->model, nen, &mp, B);
      for (int i = 0; i < ns; i++)                  /* DB = D B */
        for (int j = 0; j < nc; j++)
          {
            double s = 0.0;
            for (int k = 0; k < ns; k++)
              s += D[i * ns + k] * B[k * nc + j];
            DB[i * nc + j] = s;
          }
      for (int i = 0; i < nc; i++)                  /* Ke += w B^T D B */
        for (int j = i; j < nc; j++)
          {
            double s = 0.0;
            for (int k = 0; k < ns; k++)
              s += B[k * nc + i] * DB[k * nc + j];
            Ke[i * nc + j] += w * s;
          }
    }
  for (int i = 0; i < nc; i++)                      /* symmetric lower part */
    for (int j = 0; j < i; j++)
      Ke[i * nc + j] = Ke[j * nc + i];
  return LAC_SUCCESS;
}

/* lac_assembly_cell_stiffness: Ke = int_e B^T D B w dx  [LAC (8)], the
 * contribution of cell c to a(u,v).
 *   [in]  m, mat, c   mesh, material (E[c], nu[c] checked), cell index
 *   [out] Ke          (nen*dim)^2 values, row-major, dof a*dim + i
 *   returns LAC_SUCCESS, LAC_EINVAL (bad material, model/mesh mismatch,
 *   axisymmetric cell with r <= 0), LAC_ESING (det J <= 0), LAC_ENOMEM */
int
lac_assembly_cell_stiffness (const lac_mesh *m, const lac_elastic *mat,
                             size_t c, double *Ke)
{
  lac_quad_cache qc;
  int status = check_elastic (m, mat);
  if (status)
    return status;
  if (c >= m->ncells)
    LAC_ERROR (LAC_EINVAL, "cell %zu out of range (%zu cells)", c, m->ncells);
  memset (&qc, 0, sizeof qc);
  status = cell_stiffness (m, mat, c, &qc, Ke);
  lac_quad_cache_free (&qc);
  return status;
}

int
lac_assembly_cell_stiffness_q (const lac_mesh *m, const lac_elastic *mat,
                               size_t c, lac_quad_cache *qc, double *Ke)
{
  return cell_stiffness (m, mat, c, qc, Ke);
}

/* lac_assembly_stiffness: K += sum_c Ke over the cells with E[c] > 0
 * (cells with E[c] <= 0 belong to no elastic body and are skipped).
 *   [in]     m, mat
 *   [in,out] K   triplets of size ndof x ndof, ndof = dim*nnodes
 *   returns LAC_SUCCESS, LAC_EBADLEN, LAC_EINVAL, LAC_ESING, LAC_ENOMEM */
int
lac_assembly_stiffness (const lac_mesh *m, const lac_elastic *mat,
                        lac_triplet *K)
{
  lac_quad_cache qc;
  int status = check_elastic (m, mat);
  if (status)
    return status;
  size_t ndof = (size_t) m->dim * m->nnodes;
  if (!K || K->nrow != ndof || K->ncol != ndof)
    LAC_ERROR (LAC_EBADLEN, "K is %zu x %zu, the mesh has %zu dofs",
               K ? K->nrow : 0, K ? K->ncol : 0, ndof);
  size_t nc_max = LAC_MAX_NODES * 3;
  double *Ke = lac_malloc (nc_max * nc_max * sizeof *Ke);
  size_t dofs[LAC_MAX_NODES * 3];
  if (!Ke)
    LAC_ERROR (LAC_ENOMEM, "element matrix of %zu^2 entries", nc_max);
  memset (&qc, 0, sizeof qc);
  for (size_t c = 0; c < m->ncells && !status; c++)
    {
      if (!(mat->E[c] > 0.0))
        continue;
      status = cell_stiffness (m, mat, c, &qc, Ke);
      if (status)
        break;
      size_t nc = (size_t) lac_mesh_cell_dofs (m, c, dofs);
      status = lac_triplet_add_block (K, nc, dofs, nc, dofs, Ke); /* K += Ke */
    }
  lac_quad_cache_free (&qc);
  lac_free (Ke);
  return status;
}

/* lac_assembly_stiffness_csc: K = sum_c Ke over the cells with E[c] > 0,
 * assembled into the pattern of those cells (lac_pattern.h).
 *   [in]  m, mat
 *   [out] K   ndof x ndof, new
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ESING, LAC_ENOMEM */
int
lac_assembly_stiffness_csc (const lac_mesh *m, const lac_elastic *mat,
                            lac_csc **K)
{
  lac_quad_cache qc;
  lac_pattern *P = NULL;
  int status = check_elastic (m, mat);
  *K = NULL;
  if (status)
    return status;
  char *cells = lac_malloc (m->ncells + 1);
  double *Ke = lac_malloc (LAC_MAX_NODES * 3 * LAC_MAX_NODES * 3
                           * sizeof *Ke);
  if (!cells || !Ke)
    {
      lac_free (cells);
      lac_free (Ke);
      LAC_ERROR (LAC_ENOMEM, "the stiffness of %zu cells", m->ncells);
    }
  for (size_t c = 0; c < m->ncells; c++)
    cells[c] = mat->E[c] > 0.0;            /* the cells of elastic bodies */
  if (!(P = lac_pattern_build (m, cells)))
    status = LAC_ENOMEM;        /* or too many entries: its message says */
  memset (&qc, 0, sizeof qc);
  for (size_t c = 0; c < m->ncells && !status; c++)
    if (cells[c] && !(status = cell_stiffness (m, mat, c, &qc, Ke)))
      lac_pattern_add (P, m, c, Ke);                          /* K += Ke */
  lac_quad_cache_free (&qc);
  lac_free (Ke);
  lac_free (cells);
  if (!status)
    {
      *K = P->K;                              /* the matrix is the caller's */
      P->K = NULL;
    }
  lac_pattern_free (P);
  return status;
}

/* Check a load vector target and a model against the mesh. */
static int
check_model (const lac_mesh *m, lac_model model)
{
  if (!m)
    LAC_ERROR (LAC_EINVAL, "mesh is NULL");
  if (lac_model_dim (model) != m->dim)
    LAC_ERROR (LAC_EINVAL, "model %s needs a %dD mesh, the mesh is %dD",
               lac_model_name (model), lac_model_dim (model), m->dim);
  return LAC_SUCCESS;
}

/* lac_assembly_volume_force: F += int f . v w dx over the cells of a cell
 * group g (all cells if g == NULL), the volume part of l(v)  [LAC (8)].
 *   [in]     m, model, g (dimension m->dim), f(x, ctx, out[dim])
 *   [in,out] F   length dim*nnodes
 *   returns LAC_SUCCESS, LAC_EINVAL (group of the wrong dimension),
 *   LAC_ESING (inverted cell), LAC_ENOMEM */
int
lac_assembly_volume_force (const lac_mesh *m, lac_model model,
                           const lac_group *g, lac_field *f, void *ctx,
                           double *F)
{
  lac_quad_cache qc;
  int status = check_model (m, model);
  if (status)
    return status;
  if (!f || !F)
    LAC_ERROR (LAC_EINVAL, "force field or load vector is NULL");
  if (g && (g->dim != m->dim || (g->n > 0 && g->face && g->face[0] >= 0)))
    LAC_ERROR (LAC_EINVAL, "group '%s' has dimension %d; a volume force needs"
               " a group of cells (dimension %d)", g->name ? g->name : "?",
               g->dim, m->dim);
  int dim = m->dim;
  size_t n = g ? g->n : m->ncells;
  double xe[LAC_MAX_NODES * 3], fx[3];
  lac_map mp;
  memset (&qc, 0, sizeof qc);
  for (size_t k = 0; k < n && !status; k++)
    {
      size_t c = g ? g->cell[k] : k;
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      if (!re || re->dim != dim)
        {
          status = LAC_ERRMSG (LAC_EINVAL, "cell %zu is not a %dD cell", c,
                               dim);
          break;
        }
      const lac_quad *q = lac_quad_cache_get (&qc, re->shape, load_degree (re, model));
      if (!q)
        {
          status = LAC_ENOMEM;
          break;
        }
      lac_mesh_cell_coords (m, c, xe);
      const int *conn = m->conn + m->ptr[c];
      for (int p = 0; p < q->n && !status; p++)
        {
          status = lac_map_cell (re, dim, xe, q->xi + p * dim, &mp);
          if (status)
            break;
          double w = q->w[p] * mp.detJ * lac_model_weight (model, mp.x);
          f (mp.x, ctx, fx);
          for (int a = 0; a < re->nnodes; a++)
            for (int i = 0; i < dim; i++)
              F[(size_t) dim * (size_t) conn[a] + (size_t) i]
                += w * fx[i] * mp.N[a];                     /* F += f.N_a w */
        }
    }
  lac_quad_cache_free (&qc);
  return status;
}

/* Surface loads: F += int_{facets of g} t(x) . v w ds, where t is a field
 * t(x) or t(x, n) (tn), or -p n (is_pressure).  Shared by the tractions
 * and the pressure. */
static int
surface_load (const lac_mesh *m, lac_model model, const lac_group *g,
              lac_field *t, lac_field_n *tn, void *ctx, int is_pressure,
              double p, double *F)
{
  lac_quad_cache qc;
  if (!is_pressure && !t && !tn)
    LAC_ERROR (LAC_EINVAL, "traction field is NULL");
  int status = check_model (m, model);
  if (status)
    return status;
  if (!g)
    LAC_ERROR (LAC_EINVAL, "no facet group given (NULL)");
  if (!F)
    LAC_ERROR (LAC_EINVAL, "load vector is NULL");
  if (g->dim != m->dim - 1)
    LAC_ERROR (LAC_EINVAL, "group '%s' has dimension %d; a surface load needs"
               " a group of boundary facets (dimension %d)",
               g->name ? g->name : "?", g->dim, m->dim - 1);
  int dim = m->dim;
  int fnodes[LAC_MAX_FACE_NODES];
  double xe[LAC_MAX_FACE_NODES * 3], tx[3];
  lac_elem_type ft;
  lac_map mp;
  memset (&qc, 0, sizeof qc);
  for (size_t k = 0; k < g->n && !status; k++)
    {
      int nf = lac_mesh_facet_nodes (m, g->cell[k], g->face[k], fnodes, &ft);
      const lac_refelem *rf = lac_refelem_get (ft);
      if (nf <= 0 || !rf || rf->dim != dim - 1)
        {
          status = LAC_ERRMSG (LAC_EINVAL, "group '%s': facet %zu (cell %zu,"
                               " face %d) is not a boundary facet",
                               g->name ? g->name : "?", k, g->cell[k],
                               g->face[k]);
          break;
        }
      for (int a = 0; a < nf; a++)
        for (int i = 0; i < dim; i++)
          xe[a * dim + i] = m->x[(size_t) dim * (size_t) fnodes[a]
                                 + (size_t) i];
      const lac_quad *q = lac_quad_cache_get (&qc, rf->shape, load_degree (rf, model));
      if (!q)
        {
          status = LAC_ENOMEM;
          break;
        }
      for (int ip = 0; ip < q->n && !status; ip++)
        {
          status = lac_map_face (rf, dim, xe, q->xi + ip * rf->dim, &mp);
          if (status)
            break;
          double w = q->w[ip] * mp.detJ * lac_model_weight (model, mp.x);
          if (is_pressure)
            for (int i = 0; i < dim; i++)
              tx[i] = -p * mp.normal[i];                   /* t = -p n */
          else if (tn)
            tn (mp.x, mp.normal, ctx, tx);                 /* t(x, n) */
          else
            t (mp.x, ctx, tx);
          for (int a = 0; a < nf; a++)
            for (int i = 0; i < dim; i++)
              F[(size_t) dim * (size_t) fnodes[a] + (size_t) i]
                += w * tx[i] * mp.N[a];                     /* F += t.N_a w */
        }
    }
  lac_quad_cache_free (&qc);
  return status;
}

/* lac_assembly_traction: F += int_{facets of g} t . v w ds, the Neumann part
 * of l(v) with sigma n = F on Gamma_N  [LAC (3)] [LAC (8)].
 *   [in]     m, model, g (dimension m->dim - 1), t(x, ctx, out[dim])
 *   [in,out] F   length dim*nnodes
 *   returns LAC_SUCCESS, LAC_EINVAL (wrong group), LAC_ESING, LAC_ENOMEM */
int
lac_assembly_traction (const lac_mesh *m, lac_model model,
                       const lac_group *g, lac_field *t, void *ctx,
                       double *F)
{
  return surface_load (m, model, g, t, NULL, ctx, 0, 0.0, F);
}

/* lac_assembly_traction_n: as lac_assembly_traction with a traction that
 * depends on the outward unit normal, t(x, n) (e.g. sigma(x) n of an exact
 * solution). */
int
lac_assembly_traction_n (const lac_mesh *m, lac_model model,
                         const lac_group *g, lac_field_n *t, void *ctx,
                         double *F)
{
  return surface_load (m, model, g, NULL, t, ctx, 0, 0.0, F);
}

/* lac_assembly_pressure: F += int_{facets of g} (-p n) . v w ds with n the
 * outward unit normal of the body  [LAC (3)]: p > 0 pushes on the surface.
 *   returns as lac_assembly_traction */
int
lac_assembly_pressure (const lac_mesh *m, lac_model model,
                       const lac_group *g, double p, double *F)
{
  return surface_load (m, model, g, NULL, NULL, NULL, 1, p, F);
}

/* ---- Dirichlet data [LAC (4)] ------------------------------------------ */

/* lac_dirichlet_alloc: an empty list of (dof, value) pairs. */
lac_dirichlet *
lac_dirichlet_alloc (void)
{
  lac_dirichlet *d = lac_calloc (1, sizeof *d);
  if (!d)
    LAC_ERROR_NULL (LAC_ENOMEM, "Dirichlet list");
  return d;
}

/* lac_dirichlet_free: frees the list (NULL allowed). */
void
lac_dirichlet_free (lac_dirichlet *d)
{
  if (!d)
    return;
  lac_free (d->dof);
  lac_free (d->val);
  lac_frames_free (d->frames);
  lac_free (d);
}

/* Append one pair, growing the arrays geometrically. */
static int
dirichlet_push (lac_dirichlet *d, size_t dof, double val)
{
  size_t cap = d->cap;                   /* dof and val share it */
  if (lac_grow (&d->dof, d->n + 1, &cap, sizeof *d->dof, 64)
      || lac_grow (&d->val, d->n + 1, &d->cap, sizeof *d->val, 64))
    LAC_ERROR (LAC_ENOMEM, "Dirichlet list of %zu entries", d->n + 1);
  d->dof[d->n] = dof;
  d->val[d->n] = val;
  d->n++;
  return LAC_SUCCESS;
}

int
lac_dirichlet_add (lac_dirichlet *d, size_t dof, double val)
{
  return dirichlet_push (d, dof, val);
}

/* lac_dirichlet_add_group: u_comp = value at every node of g  [LAC (4)].
 *   [in] g    a group of any dimension (its node list is used)
 *   [in] comp 0 .. dim-1
 *   returns LAC_SUCCESS, LAC_EINVAL (NULL group, comp out of range),
 *   LAC_ENOMEM */
int
lac_dirichlet_add_group (lac_dirichlet *d, const lac_mesh *m,
                         const lac_group *g, int comp, double value)
{
  if (!d || !m)
    LAC_ERROR (LAC_EINVAL, "Dirichlet list or mesh is NULL");
  if (!g)
    LAC_ERROR (LAC_EINVAL, "no group given (NULL): is the group name right?");
  if (comp < 0 || comp >= m->dim)
    LAC_ERROR (LAC_EINVAL, "group '%s': component %d out of range 0..%d",
               g->name ? g->name : "?", comp, m->dim - 1);
  for (size_t k = 0; k < g->nnodes; k++)
    {
      int status = dirichlet_push (d, (size_t) m->dim * g->node[k]
                                   + (size_t) comp, value);
      if (status)
        return status;
    }
  return LAC_SUCCESS;
}

/* lac_dirichlet_add_field: u = u_D(x) (all components) at the nodes of g.
 *   returns LAC_SUCCESS, LAC_EINVAL (NULL group or field), LAC_ENOMEM */
int
lac_dirichlet_add_field (lac_dirichlet *d, const lac_mesh *m,
                         const lac_group *g, lac_field *u, void *ctx)
{
  double val[3];
  if (!d || !m || !u)
    LAC_ERROR (LAC_EINVAL, "Dirichlet list, mesh or field is NULL");
  if (!g)
    LAC_ERROR (LAC_EINVAL, "no group given (NULL): is the group name right?");
  for (size_t k = 0; k < g->nnodes; k++)
    {
      size_t a = g->node[k];
      u (m->x + (size_t) m->dim * a, ctx, val);
      for (int i = 0; i < m->dim; i++)
        {
          int status = dirichlet_push (d, (size_t) m->dim * a + (size_t) i,
                                       val[i]);
          if (status)
            return status;
        }
    }
  return LAC_SUCCESS;
}

/* lac_dirichlet_dense: the pairs of d as two arrays of n dofs, fixed[k]
 * (0/1) and g[k] (later pairs for a dof win), new.
 *   returns LAC_SUCCESS, LAC_EBADLEN (a dof >= n), LAC_ENOMEM */
int
lac_dirichlet_dense (const lac_dirichlet *d, size_t n, char **fixed,
                     double **g)
{
  *fixed = lac_calloc (n ? n : 1, 1);
  *g = lac_calloc (n ? n : 1, sizeof **g);
  if (!*fixed || !*g)
    LAC_ERROR (LAC_ENOMEM, "work arrays for %zu dofs", n);
  for (size_t k = 0; k < d->n; k++)
    {
      if (d->dof[k] >= n)
        LAC_ERROR (LAC_EBADLEN, "fixed dof %zu out of range (K has %zu "
                   "dofs)", d->dof[k], n);
      (*fixed)[d->dof[k]] = 1;
      (*g)[d->dof[k]] = d->val[k];                 /* later entries win */
    }
  return LAC_SUCCESS;
}

/* lac_dirichlet_column: steps 1 and 2 of lac_dirichlet_apply for one
 * column, jl of K, dof j (row indices are dofs): F -= K(:,j) g_j if j is
 * fixed; then the entries in fixed rows or in a fixed column are zeroed
 * but the diagonal, which keeps d_j (1 if it was not positive), and g_j
 * becomes d_j g_j.  A column's lift reads only that column and g_j, and
 * its zeroing writes only that column, so the columns may be done one at
 * a time, in dof order, with the numbers of the whole matrix (the
 * digest of K, fem/lac_assembly_digest.c).
 *   returns LAC_SUCCESS, LAC_EINVAL (a fixed j with no diagonal entry) */
int
lac_dirichlet_column (lac_csc *K, size_t jl, size_t j, const char *fixed,
                      double *g, double *F)
{
  int diag = 0;
  if (fixed[j] && g[j] != 0.0)                            /* step 1 */
    for (int p = K->p[jl]; p < K->p[jl + 1]; p++)
      F[K->i[p]] -= K->x[p] * g[j];
  for (int p = K->p[jl]; p < K->p[jl + 1]; p++)          /* step 2 */
    {
      size_t i = (size_t) K->i[p];
      if (i == j)
        {
          diag = 1;
          if (fixed[j] && !(K->x[p] > 0.0))
            K->x[p] = 1.0;                                /* d_j = 1 */
          if (fixed[j])
            g[j] *= K->x[p];                              /* F(j) = d_j g_j */
        }
      else if (fixed[i] || fixed[j])
        K->x[p] = 0.0;
    }
  if (fixed[j] && !diag)
    LAC_ERROR (LAC_EINVAL, "fixed dof %zu has no diagonal entry in K: its "
               "node belongs to no assembled cell", j);
  return LAC_SUCCESS;
}

/* lac_dirichlet_apply: symmetric elimination of the fixed dofs.
 *   For every fixed dof k with value g_k:  F -= K(:,k) g_k, then row and
 *   column k of K are zeroed except the diagonal, and F(k) = d_k g_k, so
 *   that the row reads d_k u_k = d_k g_k.  The diagonal d_k keeps the value
 *   K(k,k) had (1 if it was not positive): a unit diagonal in a stiffness of
 *   size ~E h would spoil the pivot ratio the solvers test (lac_linalg.h,
 *   LAC_PIVOT_RTOL).  The free block of K is untouched, so K stays
 *   symmetric, and positive definite when the fixed dofs remove the rigid
 *   motions.
 *   [in]     d     Dirichlet pairs (later pairs for a dof win)
 *   [in,out] K, F  CSC matrix (square, ndof) and load vector (ndof)
 *   returns LAC_SUCCESS, LAC_EBADLEN (dof out of range), LAC_EINVAL (no
 *   diagonal entry stored for a fixed dof), LAC_ENOMEM */
int
lac_dirichlet_apply (const lac_dirichlet *d, lac_csc *K, double *F)
{
  int status = LAC_SUCCESS;
  if (!d || !K || !F)
    LAC_ERROR (LAC_EINVAL, "Dirichlet list, matrix or vector is NULL");
  if (K->nrow != K->ncol)
    LAC_ERROR (LAC_EBADLEN, "K is %zu x %zu, not square", K->nrow, K->ncol);
  size_t n = K->ncol;
  char *fixed = NULL;
  double *g = NULL;
  if ((status = lac_dirichlet_dense (d, n, &fixed, &g)))
    goto done;
  for (size_t j = 0; j < n && !status; j++)            /* steps 1 and 2 */
    status = lac_dirichlet_column (K, j, j, fixed, g, F);
  if (status)
    goto done;
  /* Step 3: F(k) = d_k g_k. */
  for (size_t k = 0; k < n; k++)
    if (fixed[k])
      F[k] = g[k];
done:
  lac_free (g);
  lac_free (fixed);
  return status;
}
