/* lac_infsup_gram.c -- the norms of the inf-sup estimate     [LAC (10)]
 *
 * The matrices A (displacements) and M (multipliers) of lac_infsup.h:
 *   lac_infsup_gram_h1     A = sum_cells int (N_a N_b / ell^2 + grad N_a .
 *                          grad N_b)
 *                          per component (+ N_a N_b / r^2 on u_r in the
 *                          axisymmetric model, weight 2 pi r), the
 *                          Dirichlet dofs eliminated;
 *   lac_infsup_fixed_dofs  which dofs a stiffness had eliminated;
 *   lac_infsup_norm_lac    M = diag(h_i |T^m_i cap Gamma_C|).
 * Quadrature: degree 2*order + 2 (+ 2 axisymmetric), exact for the mass
 * term on affine cells and enough on curved ones (the norm only has to be
 * equivalent to the H1 norm, but it is computed accurately anyway).
 */
#include "contact/lac_infsup.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"


/* One rule per shape, allocated on first use. */
typedef struct gcache
{
  lac_quad *q[LAC_SHAPE_PYR + 1];   /* owned */
} gcache;

static const lac_quad *
gcache_get (gcache *gc, const lac_refelem *re, lac_model model)
{
  int deg = 2 * re->order + 2 + (model == LAC_AXISYMMETRIC ? 2 : 0);
  int maxdeg = lac_quad_max_degree (re->shape);
  if (maxdeg >= 0 && deg > maxdeg)
    deg = maxdeg;
  if (!gc->q[re->shape])
    gc->q[re->shape] = lac_quad_alloc (re->shape, deg);   /* message set */
  return gc->q[re->shape];
}

/* cell_gram: the scalar Gram block of cell c and its hoop part.
 *   Ge[a*nen + b] = int N_a N_b / ell^2 + grad N_a . grad N_b  (w dx)
 *   He[a*nen + b] = int N_a N_b / r^2  (w dx), axisymmetric only
 * with w = 2 pi r (axisymmetric) or 1. */
static int
cell_gram (const lac_mesh *m, lac_model model, size_t c, double ell,
           gcache *gc, double *Ge, double *He)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int dim = m->dim, nen, status;
  double xe[LAC_MAX_NODES * 3];
  lac_map mp;
  if (!re || re->dim != dim)
    LAC_ERROR (LAC_EINVAL, "cell %zu (tag %zu) is not a %dD cell", c,
               m->cell_tag[c], dim);
  const lac_quad *q = gcache_get (gc, re, model);
  if (!q)
    return LAC_ENOMEM;
  nen = re->nnodes;
  lac_mesh_cell_coords (m, c, xe);
  memset (Ge, 0, (size_t) (nen * nen) * sizeof *Ge);
  memset (He, 0, (size_t) (nen * nen) * sizeof *He);
  for (int p = 0; p < q->n; p++)
    {
      if ((status = lac_map_cell (re, dim, xe, q->xi + p * dim, &mp)))
        LAC_ERROR (status, "cell %zu (tag %zu, %s): det J = %g <= 0",
                   c, m->cell_tag[c], re->name, mp.detJ);
      double w = q->w[p] * mp.detJ;
      if (model == LAC_AXISYMMETRIC)
        {
          if (!(mp.x[0] > 0))
            LAC_ERROR (LAC_EINVAL, "cell %zu (tag %zu): r = %g <= 0 at a "
                       "quadrature point", c, m->cell_tag[c], mp.x[0]);
          w *= lac_model_weight (LAC_AXISYMMETRIC, mp.x);  /* 2 pi r dr dz */
        }
      for (int a = 0; a < nen; a++)
        for (int b = a; b < nen; b++)
          {
            double g = mp.N[a] * mp.N[b] / (ell * ell);   /* N_a N_b / ell^2 */
            for (int k = 0; k < dim; k++)             /* + grad . grad */
              g += mp.dNdx[a * dim + k] * mp.dNdx[b * dim + k];
            Ge[a * nen + b] += w * g;
            if (model == LAC_AXISYMMETRIC)            /* u_r^2 / r^2 */
              He[a * nen + b] += w * mp.N[a] * mp.N[b] / (mp.x[0] * mp.x[0]);
          }
    }
  for (int a = 0; a < nen; a++)                        /* mirror */
    for (int b = 0; b < a; b++)
      Ge[a * nen + b] = Ge[b * nen + a], He[a * nen + b] = He[b * nen + a];
  return LAC_SUCCESS;
}

/* Zero the rows and columns of the fixed dofs, keeping the diagonal. */
static void
eliminate (lac_csc *A, const char *fixed)
{
  for (size_t j = 0; j < A->ncol; j++)
    for (int p = A->p[j]; p < A->p[j + 1]; p++)
      if ((size_t) A->i[p] != j && (fixed[j] || fixed[A->i[p]]))
        A->x[p] = 0.0;
}

/* Diameter of the bounding box of the mesh nodes. */
static double
box_diameter (const lac_mesh *m)
{
  double d2 = 0;
  for (int k = 0; k < m->dim && m->nnodes; k++)
    {
      double lo = m->x[k], hi = m->x[k];
      for (size_t a = 1; a < m->nnodes; a++)
        {
          lo = fmin (lo, m->x[a * (size_t) m->dim + k]);
          hi = fmax (hi, m->x[a * (size_t) m->dim + k]);
        }
      d2 += (hi - lo) * (hi - lo);
    }
  return sqrt (d2);
}

int
lac_infsup_gram_h1 (const lac_mesh *mesh, lac_model model, const char *fixed,
                    double ell, lac_csc **A)
{
  gcache gc;
  lac_triplet *T = NULL;
  int status = LAC_SUCCESS, dim;
  size_t cap = 0, ndof;
  double Ge[LAC_MAX_NODES * LAC_MAX_NODES], He[LAC_MAX_NODES * LAC_MAX_NODES];
  size_t idx[LAC_MAX_NODES];
  if (!mesh || !A)
    LAC_ERROR (LAC_EINVAL, "mesh or output is NULL");
  *A = NULL;
  dim = mesh->dim;
  if (lac_model_dim (model) != dim)
    LAC_ERROR (LAC_EINVAL, "model %s needs a %dD mesh, the mesh is %dD",
               lac_model_name (model), lac_model_dim (model), dim);
  ndof = (size_t) dim * mesh->nnodes;
  if (!(ell > 0))
    ell = box_diameter (mesh);
  if (!(ell > 0))
    LAC_ERROR (LAC_EINVAL, "length scale ell = %g: the mesh has no extent",
               ell);
  for (size_t c = 0; c < mesh->ncells; c++)
    {
      size_t nen = mesh->ptr[c + 1] - mesh->ptr[c];
      cap += nen * nen * (size_t) dim;
    }
  memset (&gc, 0, sizeof gc);
  if (!(T = lac_triplet_alloc (ndof, ndof, cap)))
    LAC_ERROR (LAC_ENOMEM, "H1 Gram matrix of %zu dofs", ndof);
  for (size_t c = 0; c < mesh->ncells && !status; c++)
    {
      int nen = (int) (mesh->ptr[c + 1] - mesh->ptr[c]);
      if ((status = cell_gram (mesh, model, c, ell, &gc, Ge, He)))
        break;
      for (int k = 0; k < dim && !status; k++)
        {
          for (int a = 0; a < nen; a++)
            idx[a] = (size_t) dim * (size_t) mesh->conn[mesh->ptr[c] + a] + k;
          if (k == 0 && model == LAC_AXISYMMETRIC)
            for (int q = 0; q < nen * nen; q++)
              He[q] += Ge[q];                         /* u_r: + hoop term */
          status = lac_triplet_add_block (T, (size_t) nen, idx, (size_t) nen,
                                          idx, k == 0 && model
                                          == LAC_AXISYMMETRIC ? He : Ge);
        }
    }
  if (!status && !(*A = lac_csc_from_triplet (T)))
    status = LAC_ERRMSG (LAC_ENOMEM, "H1 Gram matrix of %zu dofs", ndof);
  if (!status && fixed)
    eliminate (*A, fixed);
  for (int s = 0; s <= LAC_SHAPE_PYR; s++)
    lac_quad_free (gc.q[s]);
  lac_triplet_free (T);
  return status;
}

size_t
lac_infsup_fixed_dofs (const lac_csc *K, char *fixed)
{
  size_t nfixed = 0;
  for (size_t j = 0; j < K->ncol; j++)
    {
      int diag = 0, off = 0;
      for (int p = K->p[j]; p < K->p[j + 1]; p++)
        if ((size_t) K->i[p] == j)
          diag = K->x[p] != 0.0;
        else if (K->x[p] != 0.0)
          off = 1;
      fixed[j] = (char) (diag && !off);
      nfixed += (size_t) fixed[j];
    }
  return nfixed;
}

double
lac_infsup_macro_diameter (const lac_mesh *mesh, const lac_macro *Mm,
                           size_t m)
{
  int nodes[LAC_MAX_FACE_NODES * 8];
  int n = 0, dim = mesh->dim;
  lac_elem_type ft;
  double d = 0;
  if (m >= Mm->n)
    return 0.0;
  for (size_t j = Mm->ptr[m]; j < Mm->ptr[m + 1]; j++)
    {
      int f[LAC_MAX_FACE_NODES];
      int nf = lac_mesh_facet_nodes (mesh, Mm->cell[j], Mm->face[j], f, &ft);
      for (int a = 0; a < nf; a++)
        {
          const double *xa = mesh->x + (size_t) f[a] * (size_t) dim;
          for (int b = 0; b < n; b++)               /* against those seen */
            {
              const double *xb = mesh->x + (size_t) nodes[b] * (size_t) dim;
              d = fmax (d, lac_vec_dist (dim, xa, xb));
            }
          if (n < (int) (sizeof nodes / sizeof *nodes))
            nodes[n++] = f[a];
        }
    }
  return d;
}

int
lac_infsup_norm_lac (const lac_mesh *mesh, const lac_macro *Mm,
                     const lac_contact *c, double *h, lac_csc **M)
{
  lac_csc *D;
  if (!mesh || !Mm || !c || !M)
    LAC_ERROR (LAC_EINVAL, "mesh, macro-mesh, contact data or output is NULL");
  *M = NULL;
  if (!c->xpt && c->nmacro != Mm->n)
    LAC_ERROR (LAC_EBADLEN, "contact data for %zu macro-elements, macro-mesh"
               " of %zu", c->nmacro, Mm->n);
  if (!(D = lac_csc_alloc (c->k, c->k, c->k)))
    LAC_ERROR (LAC_ENOMEM, "norm matrix of %zu multipliers", c->k);
  for (size_t i = 0; i < c->k; i++)
    {
      /* node-to-segment multipliers (c->xpt): the tributary measure w_i
       * of the node stands for |T^m cap Gamma_C|, and its size for h_i */
      double hi = c->xpt ? (mesh->dim == 2 ? c->area[i] : sqrt (c->area[i]))
                         : lac_infsup_macro_diameter (mesh, Mm, c->macro[i]);
      D->p[i] = (int) i;
      D->i[i] = (int) i;
      D->x[i] = hi * c->area[i];             /* h_i |T^m_i cap Gamma_C| */
      if (h)
        h[i] = hi;
      if (!(D->x[i] > 0))
        {
          lac_csc_free (D);
          LAC_ERROR (LAC_EINVAL, "multiplier %zu (macro-element %zu): h = %g,"
                     " |T^m cap Gamma_C| = %g: the norm needs both > 0", i,
                     c->macro[i], hi, c->area[i]);
        }
    }
  D->p[c->k] = (int) c->k;
  *M = D;
  return LAC_SUCCESS;
}
