/* lac_contact_tangent.c -- derivatives of C(U) lambda and of the mean gaps
 *                          (see lac_contact_tangent.h)
 *                                          [LAC (16)-(18), §4.5, Alg. 1]
 *
 * Sub-facet by sub-facet of the admissible macro-elements: the local
 * nodes (the sub-facet's, then those of its master facets), then point by
 * point the geometry (point_eval), the derivatives of nu, g, eta and rho
 * along every dof of the point (point_derivs), and their products into
 * the sub-facet's block of H and its part of column i of B (point_add).
 */
#include "contact/lac_contact_tangent.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_spaces.h"

#define NQ (2 * LAC_MAX_FACE_NODES * 3)   /* dofs of one point: slave + master */
#define TWO_PI 6.283185307179586476925286766559

/* The geometry of one integration point. */
typedef struct point
{
  int dim, ns, nm;            /* slave and master nodes (nm = 0: obstacle)   */
  int snode[LAC_MAX_FACE_NODES], mnode[LAC_MAX_FACE_NODES];
  double phi[LAC_MAX_FACE_NODES], dphi[LAC_MAX_FACE_NODES * 2];
  double psi[LAC_MAX_FACE_NODES], dpsi[LAC_MAX_FACE_NODES * 2];
  double xs[3], nu[3], n[3], J, g, w, rho;
  double cv[3];               /* C's vector: nu, or -J n^O (obstacle)        */
  double Minv[9];             /* [t_1 .. -n]^-1 (deformable master)         */
  double nO[3], dnO[9];       /* obstacle: n^O and dn^O/dx_s (row-major)     */
  int slave_dir;              /* obstacle along n^S (lac_obstacle.h)        */
  double grad[3];             /* ... then grad F at x_m, F = v - h(w)       */
} point;

/* The derivatives of one point along its dofs q (slave node a, component
 * c at q = a dim + c; master node b at (ns + b) dim + c). */
typedef struct derivs
{
  double nu[3][NQ], cv[3][NQ], eta[2][NQ], g[NQ], rho[NQ];
} derivs;

/* One sub-facet's block under construction. */
typedef struct block
{
  size_t nn, cap;             /* local nodes                                 */
  int *node;
  double *H, *b;              /* (nn dim)^2 row-major, nn dim                */
  size_t hcap;
  double off;                 /* the interference of the gaps (c->offset)    */
} block;

void
lac_contact_tangent_free (lac_contact_tangent *t)
{
  if (!t)
    return;
  lac_csc_free (t->B);
  lac_free (t->bptr);
  lac_free (t->dof);
  lac_free (t->vptr);
  lac_free (t->val);
  lac_free (t);
}

/* ---- one point ---------------------------------------------------------- */

/* Nodes, shape functions and coordinates of facet (cell, face) at xi. */
static int
facet_eval (const lac_mesh *mesh, size_t cell, int face, const double *xi,
            int *nodes, double *N, double *dN, double *x, double t[2][3])
{
  lac_elem_type ft;
  int dim = mesh->dim, nn = lac_mesh_facet_nodes (mesh, cell, face, nodes,
                                                  &ft);
  const lac_refelem *re = nn > 0 ? lac_refelem_get (ft) : NULL;
  if (!re)
    LAC_ERROR (LAC_EINVAL, "cell %zu has no face %d", cell, face);
  lac_refelem_eval (re, xi, N, dN);
  memset (x, 0, 3 * sizeof *x);
  memset (t, 0, 6 * sizeof **t);
  for (int a = 0; a < nn; a++)
    for (int c = 0; c < dim; c++)
      {
        double xa = mesh->x[(size_t) nodes[a] * dim + c];
        x[c] += N[a] * xa;
        for (int k = 0; k < dim - 1; k++)
          t[k][c] += dN[a * (dim - 1) + k] * xa;       /* dx/dxi_k */
      }
  return nn;
}

/* Inverse of the dim x dim matrix A (row-major); 0 if singular. */
static int
invert (int dim, const double *A, double *Ai)
{
  if (dim == 2)
    {
      double det = A[0] * A[3] - A[1] * A[2];
      if (!(fabs (det) > 0))
        return 0;
      Ai[0] = A[3] / det, Ai[1] = -A[1] / det;
      Ai[2] = -A[2] / det, Ai[3] = A[0] / det;
      return 1;
    }
  double det = A[0] * (A[4] * A[8] - A[5] * A[7])
               - A[1] * (A[3] * A[8] - A[5] * A[6])
               + A[2] * (A[3] * A[7] - A[4] * A[6]);
  if (!(fabs (det) > 0))
    return 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      {
        int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3,
            c1 = (i + 2) % 3;                          /* cofactor (j, i) */
        Ai[i * 3 + j] = (A[r0 * 3 + c0] * A[r1 * 3 + c1]
                         - A[r0 * 3 + c1] * A[r1 * 3 + c0]) / det;
      }
  return 1;
}

/* The master side of point pt: master facet f at eta, or the obstacle. */
static int
master_eval (const lac_mesh *mesh, const lac_pairing_facets *master,
             const lac_obstacle *ob, size_t f, const double *eta, point *pt)
{
  int dim = pt->dim;
  double xm[3], tm[2][3], A[9];
  for (int c = 0; c < 3; c++)
    pt->cv[c] = pt->nu[c];
  if (!master || f >= master->n)                     /* rigid obstacle */
    {
      if (!ob)
        LAC_ERROR (LAC_EINVAL, "a point without master facet and no obstacle");
      pt->nm = 0;
      if ((pt->slave_dir = ob->slave_normal))       /* the paper's n^S */
        {
          for (int c = 0; c < dim; c++)
            xm[c] = pt->xs[c] + pt->g * pt->n[c];
          for (int k = 0; k < dim - 1; k++)
            pt->grad[k] = -2 * ob->curv[k] * (xm[k] - ob->center[k]);
          pt->grad[dim - 1] = 1;
          return LAC_SUCCESS;
        }
      int st = lac_obstacle_project (ob, pt->xs, &pt->g, pt->nO, pt->dnO);
      for (int c = 0; c < dim; c++)                 /* nu = -n^O, times J */
        pt->cv[c] = -pt->J * pt->nO[c];
      return st;
    }
  pt->nm = facet_eval (mesh, master->cell[f], master->face[f], eta,
                       pt->mnode, pt->psi, pt->dpsi, xm, tm);
  if (pt->nm < 0)
    return -pt->nm;
  for (int r = 0; r < dim; r++)                      /* A = [t_k .. -n] */
    {
      for (int k = 0; k < dim - 1; k++)
        A[r * dim + k] = tm[k][r];
      A[r * dim + dim - 1] = -pt->n[r];
    }
  if (!invert (dim, A, pt->Minv))
    LAC_ERROR (LAC_ESING, "master facet %zu is parallel to the slave normal "
               "at a contact point", f);
  return LAC_SUCCESS;
}

/* Geometry of point p of slave sub-facet j. */
static int
point_eval (const lac_mesh *mesh, lac_model model, const lac_macro *M,
            const lac_pairing *P, const lac_pairing_facets *master,
            const lac_obstacle *ob, size_t j, size_t p, point *pt)
{
  int dim = mesh->dim, dimf = dim - 1;
  double a[2][3];
  pt->dim = dim;
  pt->ns = facet_eval (mesh, M->cell[j], M->face[j], P->xs + p * dimf,
                       pt->snode, pt->phi, pt->dphi, pt->xs, a);
  if (pt->ns < 0)
    return -pt->ns;
  if (dim == 2)
    pt->nu[0] = a[0][1], pt->nu[1] = -a[0][0], pt->nu[2] = 0;
  else
    {
      pt->nu[0] = a[0][1] * a[1][2] - a[0][2] * a[1][1];   /* a_1 x a_2 */
      pt->nu[1] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
      pt->nu[2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    }
  pt->J = sqrt (pt->nu[0] * pt->nu[0] + pt->nu[1] * pt->nu[1]
                + pt->nu[2] * pt->nu[2]);
  if (!(pt->J > 0))
    LAC_ERROR (LAC_ESING, "slave sub-facet %zu is degenerate", j);
  for (int c = 0; c < 3; c++)
    pt->n[c] = pt->nu[c] / pt->J;
  pt->g = P->gap[p];
  pt->w = P->w[p] / pt->J;                            /* w^ = w / J */
  pt->rho = lac_model_weight (model, pt->xs);
  return master_eval (mesh, master, ob, P->master[p], P->xm + p * dimf, pt);
}

/* d.nu along dof q = (slave node a, component c): 3D dphi_a1 e_c x a_2 +
 * dphi_a2 a_1 x e_c, 2D dphi_a (e_c rotated). */
static void
dnu_slave (const point *pt, const double a[2][3], int q, double *dnu)
{
  int dim = pt->dim, an = q / dim, c = q % dim;
  double e[3] = { 0, 0, 0 };
  e[c] = 1;
  if (dim == 2)
    {
      dnu[0] = pt->dphi[an] * e[1];
      dnu[1] = -pt->dphi[an] * e[0];
      return;
    }
  double d1 = pt->dphi[an * 2], d2 = pt->dphi[an * 2 + 1];
  const double *a1 = a[0], *a2 = a[1];
  dnu[0] = d1 * (e[1] * a2[2] - e[2] * a2[1]) + d2 * (a1[1] * e[2] - a1[2] * e[1]);
  dnu[1] = d1 * (e[2] * a2[0] - e[0] * a2[2]) + d2 * (a1[2] * e[0] - a1[0] * e[2]);
  dnu[2] = d1 * (e[0] * a2[1] - e[1] * a2[0]) + d2 * (a1[0] * e[1] - a1[1] * e[0]);
}

/* The slave tangents again (point keeps only nu). */
static void
slave_tangents (const lac_mesh *mesh, const point *pt, double a[2][3])
{
  int dim = pt->dim;
  memset (a, 0, 6 * sizeof **a);
  for (int an = 0; an < pt->ns; an++)
    for (int c = 0; c < dim; c++)
      for (int k = 0; k < dim - 1; k++)
        a[k][c] += pt->dphi[an * (dim - 1) + k]
                   * mesh->x[(size_t) pt->snode[an] * dim + c];
}

/* The derivatives of nu, g, eta, rho along every dof of the point. */
static void
point_derivs (const lac_mesh *mesh, lac_model model, const point *pt,
              derivs *d)
{
  int dim = pt->dim, nq = (pt->ns + pt->nm) * dim, nsq = pt->ns * dim;
  double a[2][3];
  slave_tangents (mesh, pt, a);
  for (int q = 0; q < nq; q++)
    {
      double dnu[3] = { 0, 0, 0 }, rhs[3] = { 0, 0, 0 }, z[3] = { 0, 0, 0 };
      int slave = q < nsq, node = slave ? q / dim : q / dim - pt->ns;
      int c = q % dim;
      if (slave)
        dnu_slave (pt, a, q, dnu);
      double ndnu = 0;
      for (int r = 0; r < dim; r++)
        ndnu += pt->n[r] * dnu[r];
      for (int r = 0; r < dim; r++)          /* d.x_s + g d.n - d.y_psi */
        rhs[r] = pt->g * (dnu[r] - pt->n[r] * ndnu) / pt->J;
      rhs[c] += slave ? pt->phi[node] : -pt->psi[node];
      if (pt->nm > 0)
        for (int r = 0; r < dim; r++)
          for (int s = 0; s < dim; s++)
            z[r] += pt->Minv[r * dim + s] * rhs[s];
      else if (pt->slave_dir)    /* d.g = -grad F.(..) / grad F.n */
        {
          double gr = 0, gn = 0;
          for (int r = 0; r < dim; r++)
            {
              gr += pt->grad[r] * rhs[r];
              gn += pt->grad[r] * pt->n[r];
            }
          z[dim - 1] = -gr / gn;
        }
      else                       /* obstacle: d.g = n^O . d.x_s */
        z[dim - 1] = pt->nO[c] * pt->phi[node];
      int own = pt->nm == 0 && !pt->slave_dir;     /* cv = -J n^O */
      for (int r = 0; r < 3; r++)
        {
          d->nu[r][q] = dnu[r];
          d->cv[r][q] = !own || r >= dim ? dnu[r]
                        : -ndnu * pt->nO[r]
                          - pt->J * pt->dnO[r * dim + c] * pt->phi[node];
        }
      for (int k = 0; k < dim - 1; k++)
        d->eta[k][q] = z[k];
      d->g[q] = z[dim - 1];
      d->rho[q] = model == LAC_AXISYMMETRIC && slave && c == 0
                  ? TWO_PI * pt->phi[node] : 0.0;
    }
}

/* ---- one sub-facet's block ---------------------------------------------- */

/* Local index of global node v in the block, appended if new; -1: ENOMEM. */
static long
local_node (block *bk, int v)
{
  for (size_t l = 0; l < bk->nn; l++)
    if (bk->node[l] == v)
      return (long) l;
  if (lac_grow (&bk->node, bk->nn + 1, &bk->cap, sizeof *bk->node, 32))
    return -1;
  bk->node[bk->nn] = v;
  return (long) bk->nn++;
}

/* The local index of every dof q of the point (slave nodes, then master). */
static int
point_dofs (block *bk, const point *pt, size_t *loc)
{
  int dim = pt->dim;
  for (int a = 0; a < pt->ns + pt->nm; a++)
    {
      long l = local_node (bk, a < pt->ns ? pt->snode[a]
                                          : pt->mnode[a - pt->ns]);
      if (l < 0)
        LAC_ERROR (LAC_ENOMEM, "local nodes of a contact block");
      for (int c = 0; c < dim; c++)
        loc[a * dim + c] = (size_t) l * (size_t) dim + (size_t) c;
    }
  return LAC_SUCCESS;
}

/* The point's terms: B part b[loc] and, if lambda != 0, H[loc, loc]. */
static void
point_add (const point *pt, const derivs *d, const size_t *loc, double lam,
           size_t nl, block *bk)
{
  int dim = pt->dim, nq = (pt->ns + pt->nm) * dim;
  double e[3][NQ], f[LAC_MAX_FACE_NODES][NQ];
  double gm = pt->g - bk->off;        /* the gap of the mean gaps: g0 - delta */
  for (int q = 0; q < nq; q++)
    {
      double dJ = 0;
      for (int r = 0; r < dim; r++)
        {
          dJ += pt->n[r] * d->nu[r][q];
          e[r][q] = d->rho[q] * pt->cv[r] + pt->rho * d->cv[r][q];
        }
      bk->b[loc[q]] -= pt->w * (d->rho[q] * gm * pt->J          /* B */
                                + pt->rho * (d->g[q] * pt->J + gm * dJ));
      for (int b = 0; b < pt->nm; b++)
        {
          f[b][q] = 0;
          for (int k = 0; k < dim - 1; k++)
            f[b][q] += pt->dpsi[b * (dim - 1) + k] * d->eta[k][q];
        }
    }
  if (lam == 0)
    return;
  double s = lam * pt->w;
  for (int row = 0; row < nq; row++)                   /* H */
    {
      int node = row / dim, c = row % dim, slave = node < pt->ns;
      double *Hr = bk->H + loc[row] * nl;
      if (slave)
        for (int q = 0; q < nq; q++)
          Hr[loc[q]] += s * pt->phi[node] * e[c][q];
      else
        {
          int b = node - pt->ns;
          double sp = -s * pt->psi[b], sn = -s * pt->rho * pt->nu[c];
          for (int q = 0; q < nq; q++)
            Hr[loc[q]] += sp * e[c][q] + sn * f[b][q];
        }
    }
}

/* The local nodes of sub-facet j: its own, then its masters'. */
static int
block_nodes (const lac_mesh *mesh, const lac_pairing *P,
             const lac_pairing_facets *master, const lac_macro *M, size_t j,
             block *bk)
{
  int nodes[LAC_MAX_FACE_NODES], nn;
  lac_elem_type ft;
  bk->nn = 0;
  nn = lac_mesh_facet_nodes (mesh, M->cell[j], M->face[j], nodes, &ft);
  for (int a = 0; a < nn; a++)
    if (local_node (bk, nodes[a]) < 0)
      return LAC_ENOMEM;
  for (size_t p = P->ptr[j]; master && p < P->ptr[j + 1]; p++)
    {
      size_t f = P->master[p];
      if (f >= master->n || (p > P->ptr[j] && P->master[p - 1] == f))
        continue;
      nn = lac_mesh_facet_nodes (mesh, master->cell[f], master->face[f],
                                 nodes, &ft);
      for (int a = 0; a < nn; a++)
        if (local_node (bk, nodes[a]) < 0)
          return LAC_ENOMEM;
    }
  return LAC_SUCCESS;
}

/* Zeroed H and b for the block's nl = nn dim dofs. */
static int
block_clear (block *bk, size_t nl)
{
  if (nl * nl + nl > bk->hcap)
    {
      lac_free (bk->H);
      bk->hcap = nl * nl + nl;
      if (!(bk->H = lac_malloc (bk->hcap * sizeof *bk->H)))
        {
          bk->hcap = 0;
          LAC_ERROR (LAC_ENOMEM, "contact block of %zu dofs", nl);
        }
    }
  bk->b = bk->H + nl * nl;
  memset (bk->H, 0, (nl * nl + nl) * sizeof *bk->H);
  return LAC_SUCCESS;
}

/* ---- the result --------------------------------------------------------- */

typedef struct growth
{
  size_t ndof, cdof, nval, cval, cblock;
} growth;

/* Append block bk (nl dofs) to H. */
static int
append_block (lac_contact_tangent *t, growth *gr, const block *bk, int dim,
              size_t nl)
{
  size_t cap = gr->cblock;               /* bptr and vptr share it */
  if (lac_grow (&t->bptr, t->nblock + 2, &cap, sizeof *t->bptr, 16)
      || lac_grow (&t->vptr, t->nblock + 2, &gr->cblock, sizeof *t->vptr, 16)
      || lac_grow (&t->dof, gr->ndof + nl, &gr->cdof, sizeof *t->dof, 64)
      || lac_grow (&t->val, gr->nval + nl * nl, &gr->cval, sizeof *t->val,
                   256))
    LAC_ERROR (LAC_ENOMEM, "contact blocks, %zu values", gr->nval + nl * nl);
  for (size_t l = 0; l < nl; l++)
    t->dof[gr->ndof + l] = (size_t) bk->node[l / (size_t) dim] * (size_t) dim
                           + l % (size_t) dim;
  memcpy (t->val + gr->nval, bk->H, nl * nl * sizeof *t->val);
  gr->ndof += nl;
  gr->nval += nl * nl;
  t->nblock++;
  t->bptr[t->nblock] = gr->ndof;
  t->vptr[t->nblock] = gr->nval;
  return LAC_SUCCESS;
}

/* Sub-facet j of multiplier i: its block and its part of B(:, i). */
static int
subfacet (const lac_mesh *mesh, lac_model model, const lac_macro *M,
          const lac_pairing *P, const lac_pairing_facets *master,
          const lac_obstacle *ob, size_t j, size_t i, double lam,
          int wantB, lac_contact_tangent *t, growth *gr, block *bk,
          lac_triplet *TB)
{
  int dim = mesh->dim, status;
  size_t loc[NQ];
  point pt;
  derivs d;
  if ((status = block_nodes (mesh, P, master, M, j, bk)))
    return status;
  size_t nl = bk->nn * (size_t) dim;
  if ((status = block_clear (bk, nl)))
    return status;
  for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
    {
      if ((status = point_eval (mesh, model, M, P, master, ob, j, p, &pt))
          || (status = point_dofs (bk, &pt, loc)))
        return status;
      point_derivs (mesh, model, &pt, &d);
      point_add (&pt, &d, loc, lam, nl, bk);
    }
  for (size_t l = 0; wantB && l < nl && !status; l++)
    if (bk->b[l] != 0)
      status = lac_triplet_add (TB, (size_t) bk->node[l / (size_t) dim]
                                * (size_t) dim + l % (size_t) dim, i,
                                bk->b[l]);
  if (!status && lam != 0 && P->ptr[j + 1] > P->ptr[j])
    status = append_block (t, gr, bk, dim, nl);
  return status;
}

/* Column i is made if its B is wanted or it adds to H (lambda_i != 0). */
static int
column_made (const double *lambda, const char *want, size_t i)
{
  return !want || want[i] || lambda[i] != 0;
}

int
lac_contact_tangent_build_cols (const lac_mesh *mesh, lac_model model,
                                const lac_macro *M, const lac_pairing *P,
                                const lac_pairing_facets *master,
                                const lac_obstacle *obstacle,
                                const lac_contact *c, const double *lambda,
                                const char *want, size_t i0, size_t i1,
                                lac_contact_tangent **out)
{
  size_t ndof = (size_t) mesh->dim * mesh->nnodes, k = i1 - i0;
  int status = LAC_SUCCESS;
  *out = NULL;
  if (!M || !P || !c || (c->k > 0 && !lambda))
    LAC_ERROR (LAC_EINVAL, "NULL macro-mesh, pairing, contact data or "
               "multipliers");
  if (i0 > i1 || i1 > c->k)
    LAC_ERROR (LAC_EINVAL, "columns %zu..%zu of a contact with %zu", i0, i1,
               c->k);
  lac_contact_tangent *t = lac_calloc (1, sizeof *t);
  lac_triplet *TB = lac_triplet_alloc (ndof, k ? k : 1, 0);
  block bk = { 0, 0, NULL, NULL, NULL, 0, c->offset };
  growth gr = { 0, 0, 0, 0, 0 };
  if (!t || !TB)
    status = LAC_ERRMSG (LAC_ENOMEM, "contact tangent");
  if (t)
    {
      t->ndof = ndof, t->k = k;
      t->bptr = lac_calloc (16, sizeof *t->bptr);      /* bptr[0] = 0 */
      t->vptr = lac_calloc (16, sizeof *t->vptr);
      gr.cblock = 16;
      if (!status && (!t->bptr || !t->vptr))
        status = LAC_ERRMSG (LAC_ENOMEM, "contact tangent");
    }
  for (size_t i = i0; !status && i < i1; i++)      /* column i - i0 of B */
    for (size_t j = M->ptr[c->macro[i]]; !status && j < M->ptr[c->macro[i]
                                                                 + 1]; j++)
      if (column_made (lambda, want, i))
        status = subfacet (mesh, model, M, P, master, obstacle, j, i - i0,
                           lambda[i], !want || want[i], t, &gr, &bk, TB);
  if (!status)
    {
      TB->ncol = k;
      if (!(t->B = lac_csc_from_triplet (TB)))
        status = LAC_ENOMEM;
    }
  lac_triplet_free (TB);
  lac_free (bk.node);
  lac_free (bk.H);
  if (status)
    {
      lac_contact_tangent_free (t);
      return status;
    }
  *out = t;
  return LAC_SUCCESS;
}

int
lac_contact_tangent_build (const lac_mesh *mesh, lac_model model,
                           const lac_macro *M, const lac_pairing *P,
                           const lac_pairing_facets *master,
                           const lac_obstacle *obstacle,
                           const lac_contact *c, const double *lambda,
                           const char *want, lac_contact_tangent **out)
{
  return lac_contact_tangent_build_cols (mesh, model, M, P, master, obstacle,
                                         c, lambda, want, 0, c ? c->k : 0,
                                         out);
}

/* The points of the pairing that column i's derivatives go through: the
 * work of its part of the build. */
size_t
lac_contact_tangent_work (const lac_macro *M, const lac_pairing *P,
                          const lac_contact *c, const double *lambda,
                          const char *want, size_t i)
{
  size_t w = 0;
  if (!column_made (lambda, want, i))
    return 0;
  for (size_t j = M->ptr[c->macro[i]]; j < M->ptr[c->macro[i] + 1]; j++)
    w += P->ptr[j + 1] - P->ptr[j];
  return w;
}

void
lac_contact_tangent_apply (const lac_contact_tangent *t, const double *x,
                           double *y)
{
  for (size_t b = 0; b < t->nblock; b++)
    {
      const size_t *dof = t->dof + t->bptr[b];
      size_t nl = t->bptr[b + 1] - t->bptr[b];
      const double *H = t->val + t->vptr[b];
      for (size_t r = 0; r < nl; r++)
        {
          double s = 0;
          for (size_t q = 0; q < nl; q++)
            s += H[r * nl + q] * x[dof[q]];
          y[dof[r]] += s;                            /* y += H x */
        }
    }
}

/* The positions pos[0 .. dim-1] in dof[0 .. nl-1] of the components of
 * node a; 0 if one is missing. */
static int
node_positions (const size_t *dof, size_t nl, int dim, size_t a, size_t *pos)
{
  int found = 0;
  for (size_t q = 0; q < nl; q++)
    if (dof[q] / (size_t) dim == a)
      pos[dof[q] % (size_t) dim] = q, found++;
  return found == dim;
}

/* H <- R~^T H R~ on the rows and columns pos of a block of nl dofs (R the
 * node's frame, row-major 3 x 3). */
static void
rotate_block (double *H, size_t nl, int dim, const size_t *pos,
              const double *R)
{
  double h[3];
  for (size_t j = 0; j < nl; j++)                         /* rows: R^T H */
    {
      for (int i = 0; i < dim; i++)
        {
          h[i] = 0;
          for (int k = 0; k < dim; k++)
            h[i] += R[3 * k + i] * H[pos[k] * nl + j];
        }
      for (int i = 0; i < dim; i++)
        H[pos[i] * nl + j] = h[i];
    }
  for (size_t r = 0; r < nl; r++)                       /* columns: H R */
    {
      for (int i = 0; i < dim; i++)
        {
          h[i] = 0;
          for (int k = 0; k < dim; k++)
            h[i] += H[r * nl + pos[k]] * R[3 * k + i];
        }
      for (int i = 0; i < dim; i++)
        H[r * nl + pos[i]] = h[i];
    }
}

int
lac_contact_tangent_rotate (lac_contact_tangent *t, const lac_frames *f)
{
  if (!f)
    return LAC_SUCCESS;
  int status = lac_frames_rotate_rows (f, &t->B), dim = f->dim;
  for (size_t b = 0; !status && b < t->nblock; b++)
    {
      const size_t *dof = t->dof + t->bptr[b];
      size_t nl = t->bptr[b + 1] - t->bptr[b], pos[3];
      for (size_t q = 0; q < nl && !status; q++)
        {
          size_t a = dof[q] / (size_t) dim;
          const double *R = lac_frames_of (f, a);
          if (!R || dof[q] % (size_t) dim != 0)     /* once per node */
            continue;
          if (!node_positions (dof, nl, dim, a, pos))
            status = LAC_ERRMSG (LAC_ESANITY, "contact tangent: node %zu "
                                 "has a frame but not all its components "
                                 "in block %zu", a + 1, b);
          else
            rotate_block (t->val + t->vptr[b], nl, dim, pos, R);
        }
    }
  return status;
}

/* The sizes of the n tangents side by side. */
static void
cat_sizes (lac_contact_tangent *const *t, size_t n, size_t *k, size_t *nnz,
           size_t *nb, size_t *nd, size_t *nv)
{
  *k = *nnz = *nb = *nd = *nv = 0;
  for (size_t p = 0; p < n; p++)
    {
      *k += t[p]->k;
      *nnz += (size_t) t[p]->B->p[t[p]->k];
      *nb += t[p]->nblock;
      *nd += t[p]->bptr[t[p]->nblock];
      *nv += t[p]->vptr[t[p]->nblock];
    }
}

/* Tangent p appended to out (its sizes so far: out->k columns, out->nblock
 * blocks). */
static void
cat_one (const lac_contact_tangent *t, lac_contact_tangent *out)
{
  size_t k0 = out->k, b0 = out->nblock;
  size_t z0 = (size_t) out->B->p[k0], d0 = out->bptr[b0], v0 = out->vptr[b0];
  size_t nz = (size_t) t->B->p[t->k], nd = t->bptr[t->nblock],
         nv = t->vptr[t->nblock];
  for (size_t i = 0; i < t->k; i++)
    out->B->p[k0 + i + 1] = (int) z0 + t->B->p[i + 1];
  for (size_t b = 0; b < t->nblock; b++)
    {
      out->bptr[b0 + b + 1] = d0 + t->bptr[b + 1];
      out->vptr[b0 + b + 1] = v0 + t->vptr[b + 1];
    }
  if (nz)                          /* an empty tangent may hold NULL arrays */
    {
      memcpy (out->B->i + z0, t->B->i, nz * sizeof (int));
      memcpy (out->B->x + z0, t->B->x, nz * sizeof (double));
    }
  if (nd)
    memcpy (out->dof + d0, t->dof, nd * sizeof *t->dof);
  if (nv)
    memcpy (out->val + v0, t->val, nv * sizeof *t->val);
  out->k += t->k;
  out->nblock += t->nblock;
}

int
lac_contact_tangent_cat (lac_contact_tangent *const *t, size_t n,
                         lac_contact_tangent **out)
{
  size_t k, nnz, nb, nd, nv;
  *out = NULL;
  if (n == 0)
    LAC_ERROR (LAC_EINVAL, "no tangent to put side by side");
  cat_sizes (t, n, &k, &nnz, &nb, &nd, &nv);
  lac_contact_tangent *c = lac_calloc (1, sizeof *c);
  if (c)
    {
      c->B = lac_csc_alloc (t[0]->ndof, k, nnz ? nnz : 1);
      c->bptr = lac_calloc (nb + 1, sizeof *c->bptr);
      c->vptr = lac_calloc (nb + 1, sizeof *c->vptr);
      c->dof = lac_malloc ((nd + 1) * sizeof *c->dof);
      c->val = lac_malloc ((nv + 1) * sizeof *c->val);
    }
  if (!c || !c->B || !c->bptr || !c->vptr || !c->dof || !c->val)
    {
      lac_contact_tangent_free (c);
      LAC_ERROR (LAC_ENOMEM, "derivatives of %zu contact columns", k);
    }
  c->ndof = t[0]->ndof;
  c->B->p[0] = 0;
  for (size_t p = 0; p < n; p++)
    cat_one (t[p], c);
  *out = c;
  return LAC_SUCCESS;
}
