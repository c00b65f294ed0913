/* lac_hyper.c -- hyperelasticity in total Lagrangian form    [LAC §4.5, §5.4]
 *
 * See lac_hyper.h for the laws and the forms.  At each quadrature point of
 * a cell the kinematics are evaluated on the REFERENCE cell (the total
 * Lagrangian form: grad_X N_a never changes):
 *
 *   F_iJ = d_iJ + sum_a u_(a,i) dN_a/dX_J        (J < dim; F_33 = 1 in
 *                                                 plane strain,
 *   F_tt = 1 + sum_a u_(a,r) N_a / R              axisymmetric hoop)
 *
 * and the variation of F along dof (a,i) has at most three non-zero
 * entries: (i, J) -> dN_a/dX_J, and (t, t) -> N_a / R for i = r in the
 * axisymmetric model.  The tangent is assembled in two passes per point
 * (the cost is that of a linear B^T D B product):
 *
 *   T^(a,i)_kL = sum_(pQ) dF^(a,i)_pQ A_pQkL        (9 numbers per dof)
 *   K_(a,i),(b,k) += w sum_(kL) T^(a,i)_kL dF^(b,k)_kL.
 *
 * The assembly into a kept pattern is shared by the threads that come to
 * it (lac_hyper_job): each takes the runs of the pattern's slabs from a
 * queue (linalg/lac_queue.h) and adds their cells with a scratch of its
 * own (cell block, passes, shape tables).  The runs of a phase share no
 * node, so every entry receives its terms in the pattern's order (phase,
 * run, cell), whichever thread takes which run: the sums do not depend
 * on the timing.
 */
#include "fem/lac_hyper.h"

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "base/lac_mem.h"
#include "fem/lac_nodal.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"
#include "linalg/lac_tasks.h"


/* ---- laws --------------------------------------------------------------- */

int
lac_law_from_name (const char *name)
{
  if (!name)
    return -1;
  if (strcmp (name, "linear") == 0)
    return LAC_LAW_LINEAR;
  if (strcmp (name, "neo_hookean") == 0)
    return LAC_LAW_NEO_HOOKEAN;
  return -1;
}

const char *
lac_law_name (lac_law law)
{
  return law == LAC_LAW_NEO_HOOKEAN ? "neo_hookean" : "linear";
}

int
lac_hyper_lame (double E, double nu, double *lambda, double *mu)
{
  if (!(E > 0) || !(nu > -1 && nu < 0.5))
    LAC_ERROR (LAC_EINVAL, "E = %g, nu = %g is not a valid material (E > 0, "
               "-1 < nu < 1/2)", E, nu);
  *lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  *mu = E / (2 * (1 + nu));
  return LAC_SUCCESS;
}

/* Fi = F^-1 (3x3); returns det F. */
static double
inverse3 (const double *F, double *Fi)
{
  double c00 = F[4] * F[8] - F[5] * F[7];
  double c01 = F[5] * F[6] - F[3] * F[8];
  double c02 = F[3] * F[7] - F[4] * F[6];
  double J = F[0] * c00 + F[1] * c01 + F[2] * c02;
  if (J == 0)
    return 0;
  Fi[0] = c00 / J;
  Fi[1] = (F[2] * F[7] - F[1] * F[8]) / J;
  Fi[2] = (F[1] * F[5] - F[2] * F[4]) / J;
  Fi[3] = c01 / J;
  Fi[4] = (F[0] * F[8] - F[2] * F[6]) / J;
  Fi[5] = (F[2] * F[3] - F[0] * F[5]) / J;
  Fi[6] = c02 / J;
  Fi[7] = (F[1] * F[6] - F[0] * F[7]) / J;
  Fi[8] = (F[0] * F[4] - F[1] * F[3]) / J;
  return J;
}

/* Neo-Hookean P and A (lac_hyper.h), F^-T_iJ = Fi[J*3+i]. */
static void
neo_hookean (double lam, double mu, const double *F, const double *Fi,
             double J, double *P, double *A)
{
  double lnJ = log (J);
  for (int i = 0; i < 3; i++)
    for (int Jj = 0; Jj < 3; Jj++)                 /* P = mu (F - F^-T)   */
      P[i * 3 + Jj] = mu * F[i * 3 + Jj]           /*   + lam lnJ F^-T    */
                      + (lam * lnJ - mu) * Fi[Jj * 3 + i];
  if (!A)
    return;
  double c = mu - lam * lnJ;
  for (int i = 0; i < 3; i++)
    for (int Jj = 0; Jj < 3; Jj++)
      for (int k = 0; k < 3; k++)
        for (int L = 0; L < 3; L++)
          A[((i * 3 + Jj) * 3 + k) * 3 + L]
            = (i == k && Jj == L ? mu : 0.0)        /* mu d_ik d_JL        */
              + lam * Fi[Jj * 3 + i] * Fi[L * 3 + k] /* lam F^-1_Ji F^-1_Lk */
              + c * Fi[Jj * 3 + k] * Fi[L * 3 + i]; /* c F^-1_Jk F^-1_Li   */
}

/* Saint Venant-Kirchhoff P = F S and A (lac_hyper.h). */
static void
svk (double lam, double mu, const double *F, double *P, double *A)
{
  double E[9], S[9], trE = 0;
  for (int I = 0; I < 3; I++)
    for (int Jj = 0; Jj < 3; Jj++)
      {
        double s = 0;
        for (int k = 0; k < 3; k++)
          s += F[k * 3 + I] * F[k * 3 + Jj];        /* C = F^T F */
        E[I * 3 + Jj] = 0.5 * (s - (I == Jj));      /* E = (C - I)/2 */
      }
  trE = E[0] + E[4] + E[8];
  for (int I = 0; I < 9; I++)
    S[I] = 2 * mu * E[I] + (I % 4 == 0 ? lam * trE : 0.0);
                                         /* S = lam tr(E) I + 2 mu E */
  for (int i = 0; i < 3; i++)
    for (int Jj = 0; Jj < 3; Jj++)
      {
        double s = 0;
        for (int M = 0; M < 3; M++)
          s += F[i * 3 + M] * S[M * 3 + Jj];        /* P = F S */
        P[i * 3 + Jj] = s;
      }
  if (!A)
    return;
  for (int i = 0; i < 3; i++)
    for (int Jj = 0; Jj < 3; Jj++)
      for (int k = 0; k < 3; k++)
        for (int L = 0; L < 3; L++)
          {
            /* F_iM C_MJNL F_kN with C = lam d_MJ d_NL + mu (d_MN d_JL +
             * d_ML d_JN): lam F_iJ F_kL + mu ((F F^T)_ik d_JL + F_iL F_kJ) */
            double FFt = F[i * 3] * F[k * 3] + F[i * 3 + 1] * F[k * 3 + 1]
                         + F[i * 3 + 2] * F[k * 3 + 2];
            A[((i * 3 + Jj) * 3 + k) * 3 + L]
              = (i == k ? S[Jj * 3 + L] : 0.0)
                + lam * F[i * 3 + Jj] * F[k * 3 + L]
                + mu * ((Jj == L ? FFt : 0.0) + F[i * 3 + L] * F[k * 3 + Jj]);
          }
}

/* lac_hyper_stress: P(F) and A(F) of a law (lac_hyper.h).
 *   returns LAC_SUCCESS, LAC_EINVAL (material), LAC_ESING (det F <= 0) */
int
lac_hyper_stress (lac_law law, double E, double nu, const double *F,
                  double *P, double *A)
{
  double lam, mu, Fi[9];
  int status = lac_hyper_lame (E, nu, &lam, &mu);
  if (status)
    return status;
  double J = inverse3 (F, Fi);
  if (!(J > 0))
    LAC_ERROR (LAC_ESING, "det F = %g <= 0: the material is turned inside"
               " out", J);
  if (law == LAC_LAW_NEO_HOOKEAN)
    neo_hookean (lam, mu, F, Fi, J, P, A);
  else
    svk (lam, mu, F, P, A);
  return LAC_SUCCESS;
}

/* ---- kinematics at one point -------------------------------------------- */


static int
quad_degree (const lac_hyper *h, const lac_refelem *re)
{
  if (h->degree > 0)
    return h->degree;
  return 2 * re->order + (h->model == LAC_AXISYMMETRIC ? 2 : 0);
}

/* One point of a cell: the reference map, the weight w (dV, times 2 pi R
 * axisymmetric) and F.  ue: element displacements (nen*dim). */
typedef struct point
{
  lac_map mp;
  double w;
  double hoop;        /* 1 / R (axisymmetric), 0 otherwise                */
  double F[9];
} point;

static int
point_eval (const lac_hyper *h, const lac_refelem *re, int dim,
            const double *xe, const double *ue, const double *xi, double wq,
            const double *N, const double *dN, point *pt)
{
  int status = N ? lac_map_cell_at (re, dim, xe, xi, N, dN, &pt->mp)
                 : lac_map_cell (re, dim, xe, xi, &pt->mp);
  if (status)
    return status;
  pt->w = wq * pt->mp.detJ;
  pt->hoop = 0;
  memset (pt->F, 0, sizeof pt->F);
  pt->F[0] = pt->F[4] = pt->F[8] = 1.0;
  for (int a = 0; a < re->nnodes; a++)
    for (int i = 0; i < dim; i++)
      for (int J = 0; J < dim; J++)                   /* F = I + grad_X u */
        pt->F[i * 3 + J] += ue[a * dim + i] * pt->mp.dNdx[a * dim + J];
  if (h->model == LAC_AXISYMMETRIC)
    {
      double R = pt->mp.x[0];
      if (!(R > 0))
        LAC_ERROR (LAC_EINVAL, "R = %g <= 0 at a quadrature point; an "
                   "axisymmetric mesh must lie in r >= 0", R);
      pt->hoop = 1.0 / R;
      pt->w *= lac_model_weight (LAC_AXISYMMETRIC, pt->mp.x);   /* 2 pi R */
      for (int a = 0; a < re->nnodes; a++)            /* F_tt = 1 + u_r/R */
        pt->F[8] += ue[a * dim] * pt->mp.N[a] * pt->hoop;
    }
  return LAC_SUCCESS;
}

/* Non-zero entries of dF^(a,i): index pQ = p*3+Q and value; returns their
 * number (dim, or dim + 1 for the axisymmetric r component). */
static int
variation (const point *pt, int dim, int a, int i, int *idx, double *val)
{
  int n = 0;
  for (int Q = 0; Q < dim; Q++)
    {
      idx[n] = i * 3 + Q;
      val[n++] = pt->mp.dNdx[a * dim + Q];
    }
  if (pt->hoop > 0 && i == 0)
    {
      idx[n] = 8;
      val[n++] = pt->mp.N[a] * pt->hoop;
    }
  return n;
}

/* Ke += w dF : A : dF without the hoop term (3D, plane strain): dF^(a,i)
 * = e_i (x) grad N_a, so the block of nodes (a, b) is
 *   K_ab[i][k] = sum_JL dN_a,J A_iJkL dN_b,L,
 * first T_a[i][kL] = w sum_J dN_a,J A_iJkL (T row a D + i), then the
 * blocks a <= b (the lower part of a diagonal block is overwritten by the
 * mirror of cell_eval). */
static void
tangent_plain (const point *pt, int nen, int D, const double *A, double *Ke,
               double *T)
{
  int nc = nen * D;
  const double *dN = pt->mp.dNdx;
  for (int a = 0; a < nen; a++)
    for (int i = 0; i < D; i++)
      for (int k = 0; k < D; k++)
        for (int L = 0; L < D; L++)
          {
            double t = 0;
            for (int J = 0; J < D; J++)
              t += dN[a * D + J] * A[((i * 3 + J) * 3 + k) * 3 + L];
            T[(a * D + i) * 9 + k * 3 + L] = pt->w * t;
          }
  for (int b = 0; b < nen; b++)
    for (int r = 0; r < (b + 1) * D; r++)
      for (int k = 0; k < D; k++)
        {
          double t = 0;
          for (int L = 0; L < D; L++)
            t += T[r * 9 + k * 3 + L] * dN[b * D + L];
          Ke[r * nc + b * D + k] += t;
        }
}

/* The same in 3D with the loops over 3 written out (the assembly of a
 * large-deformation run spends most of its time here). */
static void
tangent_3d (const point *pt, int nen, const double *A, double *Ke, double *T)
{
  int nc = nen * 3;
  const double *dN = pt->mp.dNdx;
  for (int a = 0; a < nen; a++)
    {
      double d0 = pt->w * dN[a * 3], d1 = pt->w * dN[a * 3 + 1],
             d2 = pt->w * dN[a * 3 + 2];
      for (int i = 0; i < 3; i++)
        {
          const double *A0 = A + (i * 3) * 9, *A1 = A0 + 9, *A2 = A0 + 18;
          double *Tr = T + (a * 3 + i) * 9;
          for (int kL = 0; kL < 9; kL++)
            Tr[kL] = d0 * A0[kL] + d1 * A1[kL] + d2 * A2[kL];
        }
    }
  for (int b = 0; b < nen; b++)
    {
      double e0 = dN[b * 3], e1 = dN[b * 3 + 1], e2 = dN[b * 3 + 2];
      for (int r = 0; r < (b + 1) * 3; r++)
        {
          const double *Tr = T + r * 9;
          double *Kr = Ke + r * nc + b * 3;
          Kr[0] += Tr[0] * e0 + Tr[1] * e1 + Tr[2] * e2;
          Kr[1] += Tr[3] * e0 + Tr[4] * e1 + Tr[5] * e2;
          Kr[2] += Tr[6] * e0 + Tr[7] * e1 + Tr[8] * e2;
        }
    }
}

/* fe += w P : dF, Ke += w dF : A : dF at one point (two passes). */
static void
point_add (const point *pt, int nen, int dim, const double *P,
           const double *A, double *fe, double *Ke, double *T)
{
  if (Ke && pt->hoop == 0)
    {
      point_add (pt, nen, dim, P, A, fe, NULL, T);     /* fe only */
      if (dim == 3)
        tangent_3d (pt, nen, A, Ke, T);
      else
        tangent_plain (pt, nen, dim, A, Ke, T);
      return;
    }
  int nc = nen * dim, idx[4], n;
  double val[4];
  for (int a = 0; a < nen; a++)
    for (int i = 0; i < dim; i++)
      {
        int r = a * dim + i;
        n = variation (pt, dim, a, i, idx, val);
        double f = 0;
        for (int t = 0; t < n; t++)
          f += P[idx[t]] * val[t];
        if (fe)
          fe[r] += pt->w * f;                         /* fe += w P : dF */
        if (!Ke)
          continue;
        for (int kL = 0; kL < 9; kL++)                /* T = dF : A */
          {
            double s = 0;
            for (int t = 0; t < n; t++)
              s += val[t] * A[idx[t] * 9 + kL];
            T[r * 9 + kL] = s;
          }
      }
  if (!Ke)
    return;
  for (int b = 0; b < nen; b++)
    for (int k = 0; k < dim; k++)
      {
        int col = b * dim + k;
        n = variation (pt, dim, b, k, idx, val);
        for (int r = 0; r <= col; r++)                /* Ke += w T : dF */
          {
            double s = 0;
            for (int t = 0; t < n; t++)
              s += T[r * 9 + idx[t]] * val[t];
            Ke[r * nc + col] += pt->w * s;
          }
      }
}

/* ---- cells -------------------------------------------------------------- */

static int
check_hyper (const lac_mesh *m, const lac_hyper *h)
{
  if (!m || !h || !h->E || !h->nu)
    LAC_ERROR (LAC_EINVAL, "mesh or material is NULL");
  if (lac_model_dim (h->model) != m->dim)
    LAC_ERROR (LAC_EINVAL, "model %s needs a %dD mesh, the mesh is %dD",
               lac_model_name (h->model), lac_model_dim (h->model), m->dim);
  return LAC_SUCCESS;
}

/* Element displacements ue[a*dim+i] of cell c. */
static void
gather (const lac_mesh *m, size_t c, int nen, const double *u, double *ue)
{
  const int *conn = m->conn + m->ptr[c];
  for (int a = 0; a < nen; a++)
    for (int i = 0; i < m->dim; i++)
      ue[a * m->dim + i]
        = u ? u[(size_t) m->dim * (size_t) conn[a] + (size_t) i] : 0.0;
}

/* Cell c with a rule cache; fe, Ke accumulated (not zeroed); T scratch of
 * LAC_MAX_NODES*3*9 doubles. */
static int
cell_eval (const lac_mesh *m, const lac_hyper *h, size_t c, const double *u,
           lac_quad_cache *qc, double *fe, double *Ke, double *T)
{
  int dim = m->dim, status;
  double xe[LAC_MAX_NODES * 3], ue[LAC_MAX_NODES * 3], P[9], A[81];
  point pt;
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  if (!re || re->dim != dim)
    LAC_ERROR (LAC_EINVAL, "cell %zu (tag %zu) is not a %dD cell", c,
               m->cell_tag ? m->cell_tag[c] : c, dim);
  lac_law law = h->law ? (lac_law) h->law[c] : LAC_LAW_NEO_HOOKEAN;
  const lac_quad_table *t = lac_quad_cache_table (qc, re, quad_degree (h, re));
  if (!t)
    return LAC_ENOMEM;
  const lac_quad *q = t->q;
  int nen = re->nnodes, nc = nen * dim;
  lac_mesh_cell_coords (m, c, xe);
  gather (m, c, nen, u, ue);
  for (int p = 0; p < q->n; p++)
    {
      status = point_eval (h, re, dim, xe, ue, q->xi + p * dim, q->w[p],
                           t->N + p * nen, t->dN + p * nen * dim, &pt);
      if (status == LAC_ESING)
        LAC_ERROR (status, "cell %zu (tag %zu, %s): det J = %g <= 0 at "
                   "quadrature point %d of the reference cell", c,
                   m->cell_tag ? m->cell_tag[c] : c, re->name, pt.mp.detJ, p);
      if (status)
        return status;
      status = lac_hyper_stress (law, h->E[c], h->nu[c], pt.F, P,
                                 Ke ? A : NULL);
      if (status)
        LAC_ERROR (status, "cell %zu (tag %zu, %s), quadrature point %d: %s",
                   c, m->cell_tag ? m->cell_tag[c] : c, re->name, p,
                   lac_error_message ());
      point_add (&pt, nen, dim, P, A, fe, Ke, T);
    }
  if (Ke)
    for (int i = 0; i < nc; i++)                      /* symmetric lower part */
      for (int j = 0; j < i; j++)
        Ke[i * nc + j] = Ke[j * nc + i];
  return LAC_SUCCESS;
}

/* lac_hyper_cell: fe += F_int, Ke = K_T of cell c at u (lac_hyper.h).
 *   Ke is overwritten (its upper part accumulated, then mirrored). */
int
lac_hyper_cell (const lac_mesh *m, const lac_hyper *h, size_t c,
                const double *u, double *fe, double *Ke)
{
  lac_quad_cache qc;
  int status = check_hyper (m, h);
  if (status)
    return status;
  if (c >= m->ncells)
    LAC_ERROR (LAC_EINVAL, "cell %zu out of range (%zu cells)", c, m->ncells);
  double *T = lac_malloc (LAC_MAX_NODES * 3 * 9 * sizeof *T);
  if (!T)
    LAC_ERROR (LAC_ENOMEM, "tangent scratch");
  memset (&qc, 0, sizeof qc);
  if (Ke)
    {
      int nc = (int) (m->ptr[c + 1] - m->ptr[c]) * m->dim;
      memset (Ke, 0, (size_t) (nc * nc) * sizeof *Ke);
    }
  status = cell_eval (m, h, c, u, &qc, fe, Ke, T);
  lac_quad_cache_free (&qc);
  lac_free (T);
  return status;
}

/* ---- assembly ----------------------------------------------------------- */

/* The scratch of one thread that assembles: its own cell block, tangent
 * passes and shape tables.  scratch_free after scratch_alloc, whether it
 * failed or not. */
typedef struct scratch
{
  double *Ke, *T;
  lac_quad_cache qc;
} scratch;

static int
scratch_alloc (scratch *w)
{
  size_t ncmax = LAC_MAX_NODES * 3;
  memset (w, 0, sizeof *w);                 /* scratch_free may follow */
  w->Ke = lac_malloc (ncmax * ncmax * sizeof *w->Ke);
  w->T = lac_malloc (ncmax * 9 * sizeof *w->T);
  if (!w->Ke || !w->T)
    LAC_ERROR (LAC_ENOMEM, "element matrix of %zu^2 entries", ncmax);
  return LAC_SUCCESS;
}

static void
scratch_free (scratch *w)
{
  lac_quad_cache_free (&w->qc);
  lac_free (w->Ke);
  lac_free (w->T);
}

/* What the cells are added to: F_int, K into triplets (Tk) or into a
 * kept pattern (Kp, its scatter map: no search); any may be NULL. */
typedef struct sums
{
  double *Fint;
  lac_triplet *Tk;
  lac_pattern *Kp;
} sums;

/* The loop over cells shared by both assemblies: the cells cell[0..n)
 * (cell NULL: 0 .. n-1) with E > 0, in that order. */
static int
add_cells (const lac_mesh *m, const lac_hyper *h, const double *u,
           const size_t *cell, size_t n, const sums *out, scratch *w)
{
  int wantK = out->Tk || out->Kp, status = LAC_SUCCESS;
  double fe[LAC_MAX_NODES * 3];
  size_t dofs[LAC_MAX_NODES * 3];
  for (size_t q = 0; q < n && !status; q++)
    {
      size_t c = cell ? cell[q] : q;
      if (!(h->E[c] > 0.0))
        continue;
      int nc = lac_mesh_cell_dofs (m, c, dofs);
      memset (fe, 0, (size_t) nc * sizeof *fe);
      if (wantK)
        memset (w->Ke, 0, (size_t) (nc * nc) * sizeof *w->Ke);
      status = cell_eval (m, h, c, u, &w->qc, fe, wantK ? w->Ke : NULL,
                          w->T);
      if (status)
        break;
      if (out->Fint)
        for (int r = 0; r < nc; r++)
          out->Fint[dofs[r]] += fe[r];                /* Fint += fe */
      if (out->Tk)
        status = lac_triplet_add_block (out->Tk, (size_t) nc, dofs,
                                        (size_t) nc, dofs, w->Ke); /* K += Ke */
      if (out->Kp)
        lac_pattern_add (out->Kp, m, c, w->Ke);       /* K += Ke */
    }
  return status;
}

static int
check_K (const lac_mesh *m, const lac_triplet *Tk, const lac_csc *Kc)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  if ((Tk && (Tk->nrow != ndof || Tk->ncol != ndof))
      || (Kc && (Kc->nrow != ndof || Kc->ncol != ndof)))
    LAC_ERROR (LAC_EBADLEN, "K is not %zu x %zu (the mesh's dofs)", ndof, ndof);
  return LAC_SUCCESS;
}

/* Into triplets: the cells in order, one thread. */
int
lac_hyper_assemble (const lac_mesh *m, const lac_hyper *h, const double *u,
                    double *Fint, lac_triplet *K)
{
  sums out = { Fint, K, NULL };
  scratch w;
  int status = check_hyper (m, h);
  if (!status)
    status = check_K (m, K, NULL);
  if (status)
    return status;
  status = scratch_alloc (&w);
  if (!status)
    status = add_cells (m, h, u, NULL, m->ncells, &out, &w);
  scratch_free (&w);
  return status;
}

/* ---- into a kept pattern, shared by the threads (lac_hyper.h) ----------- */

int
lac_hyper_job_init (lac_hyper_job *j, const lac_mesh *m, const lac_hyper *h,
                    const double *u, double *Fint, lac_pattern *K,
                    int want_K)
{
  int status = check_hyper (m, h);
  if (status)
    return status;
  if (!K)
    LAC_ERROR (LAC_EINVAL, "K is NULL");
  if ((status = check_K (m, NULL, K->K)))
    return status;
  for (size_t c = 0; c < m->ncells; c++)
    if (h->E[c] > 0.0 && K->cptr[c + 1] == K->cptr[c])
      LAC_ERROR (LAC_EINVAL, "cell %zu is not in the pattern of K", c);
  *j = (lac_hyper_job) { m, h, u, Fint, K, want_K, { 0, 1 }, { 0 } };
  if (want_K)
    lac_pattern_zero (K);
  return K->order ? lac_queue_init (&j->q, 3, K->phase)
                  : lac_queue_init (&j->q, 1, j->all);
}

void
lac_hyper_job_clear (lac_hyper_job *j)
{
  lac_queue_destroy (&j->q);
}

/* One thread's share: the job and its scratch (NULL: none could be made,
 * every run it takes fails). */
typedef struct worker
{
  const lac_hyper_job *j;
  scratch *w;
} worker;

/* Run r: a run of the pattern's slabs, or every cell in order. */
static int
do_run (void *ctx, size_t r)
{
  const worker *k = ctx;
  const lac_hyper_job *j = k->j;
  const lac_pattern *p = j->K;
  sums out = { j->Fint, NULL, j->want_K ? j->K : NULL };
  if (!k->w)
    return LAC_ERRMSG (LAC_ENOMEM, "the scratch of an assembly's thread");
  if (!p->order)
    return add_cells (j->m, j->h, j->u, NULL, j->m->ncells, &out, k->w);
  return add_cells (j->m, j->h, j->u, p->order + p->run[r],
                    p->run[r + 1] - p->run[r], &out, k->w);
}

int
lac_hyper_job_work (lac_hyper_job *j, size_t most)
{
  scratch w;
  worker k = { j, scratch_alloc (&w) ? NULL : &w };
  int status = lac_queue_work (&j->q, do_run, &k, most);
  scratch_free (&w);
  return status;
}

static int
job_task (void *ctx)
{
  return lac_hyper_job_work (ctx, SIZE_MAX);
}

int
lac_hyper_assemble_pattern (const lac_mesh *m, const lac_hyper *h,
                            const double *u, double *Fint, lac_pattern *K)
{
  lac_hyper_job j;
  int status = lac_hyper_job_init (&j, m, h, u, Fint, K, 1);
  if (status)
    return status;
  status = lac_tasks_pair (job_task, &j, job_task, &j);
  lac_hyper_job_clear (&j);
  return status;
}

/* ---- Cauchy stress ------------------------------------------------------ */

/* sigma = P F^T / J in Voigt order (lac_material.h). */
static void
cauchy (lac_model model, const double *F, const double *P, double *s)
{
  double Fi[9], sg[9];
  double J = inverse3 (F, Fi);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      {
        double t = 0;
        for (int K = 0; K < 3; K++)
          t += P[i * 3 + K] * F[j * 3 + K];           /* P F^T */
        sg[i * 3 + j] = t / J;
      }
  s[0] = sg[0];
  s[1] = sg[4];
  s[2] = sg[8];
  s[3] = sg[1];
  if (model == LAC_SOLID3D)
    {
      s[4] = sg[5];
      s[5] = sg[2];
    }
}

/* The lac_cell_stress of the hyperelastic laws: law = a lac_hyper. */
static int
cauchy_at (const lac_mesh *m, const void *hyper, const double *u, size_t c,
           const double *xi, double *s)
{
  const lac_hyper *h = hyper;
  int dim = m->dim;
  double xe[LAC_MAX_NODES * 3], ue[LAC_MAX_NODES * 3], P[9];
  point pt;
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  if (!re || re->dim != dim)
    LAC_ERROR (LAC_EINVAL, "cell %zu is not a %dD cell", c, dim);
  lac_mesh_cell_coords (m, c, xe);
  gather (m, c, re->nnodes, u, ue);
  int status = point_eval (h, re, dim, xe, ue, xi, 1.0, NULL, NULL, &pt);
  if (status == LAC_EINVAL && h->model == LAC_AXISYMMETRIC)
    {
      /* on the axis: F_tt -> F_rr (the limit of u_r / R) */
      lac_error_clear ();
      pt.F[8] = pt.F[0];
      status = LAC_SUCCESS;
    }
  if (status)
    LAC_ERROR (status, "cell %zu (%s): det J = %g <= 0 at the point", c,
               re->name, pt.mp.detJ);
  lac_law law = h->law ? (lac_law) h->law[c] : LAC_LAW_NEO_HOOKEAN;
  status = lac_hyper_stress (law, h->E[c], h->nu[c], pt.F, P, NULL);
  if (status)
    LAC_ERROR (status, "cell %zu: %s", c, lac_error_message ());
  cauchy (h->model, pt.F, P, s);
  return LAC_SUCCESS;
}

int
lac_hyper_cauchy_at (const lac_mesh *m, const lac_hyper *h, const double *u,
                     size_t c, const double *xi, double *s)
{
  int status = check_hyper (m, h);
  return status ? status : lac_nodal_point (m, cauchy_at, h, u, c, xi, s);
}

int
lac_hyper_cauchy_nodal (const lac_mesh *m, const lac_hyper *h,
                        const double *u, const char *cells, double *sigma,
                        double *vm)
{
  int status = check_hyper (m, h);
  return status ? status : lac_nodal_average (m, h->model, h->E, cells,
                                              cauchy_at, h, u, sigma, vm);
}
