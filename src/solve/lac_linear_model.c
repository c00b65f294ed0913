/* lac_linear_model.c -- the contact model of a small-strain scene
 *                       (see lac_linear_model.h)  [LAC (8), (16)-(18)]
 */
#include "solve/lac_linear_model.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* r = F - K U and ||(|K| |U|)||^2 (the size of the terms that K U adds
 * up, whatever cancels), from K's entries. */
static void
residual_entries (lac_linear_model *lm, const double *U, double *nku)
{
  const lac_csc *K = lm->sys.K;
  size_t n = K->ncol;
  double *ku = lm->x;                               /* |K| |U|, scratch */
  memset (ku, 0, n * sizeof *ku);
  for (size_t j = 0; j < n; j++)
    lm->r[j] = lm->sys.F[j];
  for (size_t j = 0; j < n; j++)
    for (int q = K->p[j]; q < K->p[j + 1]; q++)
      {
        lm->r[K->i[q]] -= K->x[q] * U[j];           /* r = F - K U */
        ku[K->i[q]] += fabs (K->x[q] * U[j]);
      }
  for (size_t j = 0; j < n; j++)
    *nku += ku[j] * ku[j];
}

/* The same from Kop (no entries): K U by its product, and the bound
 * ||(|K| |U|)|| <= ||K||_inf ||U||_2 (|K| symmetric). */
static int
residual_op (lac_linear_model *lm, const double *U, double *nku)
{
  const lac_stiffness_op *op = lm->sys.Kop;
  double nu = 0, norm = 0;
  int status = lac_system_k_mult (&lm->sys, U, lm->x);   /* K U */
  if (status)
    return status;
  for (size_t j = 0; j < op->n; j++)
    {
      lm->r[j] = lm->sys.F[j] - lm->x[j];
      nu += U[j] * U[j];
    }
  if (nu > 0 && (status = lac_system_norm_k (&lm->sys, &norm)))
    return status;                /* at U = 0 (before the first set) none */
  *nku = norm * norm * nu;
  return LAC_SUCCESS;
}

/* r = F - K U, d = G - C^T U; the force scale: |F| and |K| |U|. */
static int
evaluate (void *self, const double *U, int tangent, lac_model_point *p)
{
  lac_linear_model *lm = self;
  const lac_contact_system *sys = &lm->sys;
  size_t n = lac_system_n (sys), k = sys->C ? sys->C->ncol : 0;
  double nf = 0, nku = 0;
  int status = LAC_SUCCESS;
  (void) tangent;
  if (sys->K)
    residual_entries (lm, U, &nku);
  else if ((status = residual_op (lm, U, &nku)))
    return status;
  for (size_t j = 0; j < n; j++)
    nf += sys->F[j] * sys->F[j];
  if (k > 0)
    lac_system_gaps (sys, U, lm->d);                /* d = G - C^T U */
  const lac_contact *c = lm->data ? lm->data->all : NULL;
  *p = (lac_model_point) { .k = k, .C = sys->C, .d = lm->d,
                           .area = lm->area, .size = lm->size,
                           .slot = lm->slot, .lost = c ? c->lost : NULL,
                           .rho = sys->rho, .r = lm->r,
                           .fscale = fmax (sqrt (nf), sqrt (nku)) };
  if (c && c->Ct)                            /* friction: Ct^T U + sfix */
    {
      for (size_t j = 0; j < c->Ct->ncol; j++)
        {
          lm->slip[j] = c->sfix[j];
          for (int q = c->Ct->p[j]; q < c->Ct->p[j + 1]; q++)
            lm->slip[j] += c->Ct->x[q] * U[c->Ct->i[q]];
        }
      p->Ct = c->Ct;
      p->slip = lm->slip;
      p->sfix = c->sfix;
      p->mu = c->mu;
    }
  return LAC_SUCCESS;
}

static int
linearize (void *self, const double *U, const lac_contact_system **sys,
           int *news)
{
  lac_linear_model *lm = self;
  (void) U;
  *sys = lm->Call ? &lm->sys_rows : &lm->sys;
  *news = lm->news;
  lm->news = LAC_MODEL_SAME;
  return LAC_SUCCESS;
}

static int
uncovered (void *self, const double *U, double tol, lac_contact_uncovered *u)
{
  lac_linear_model *lm = self;
  memset (u, 0, sizeof *u);
  if (!lm->set)
    return LAC_SUCCESS;
  const lac_mesh *m = lm->set->pair[0].mesh;
  size_t n = (size_t) m->dim * m->nnodes;
  double umax = 0;
  memcpy (lm->x, U, n * sizeof *lm->x);
  lac_frames_to_global (lm->dir ? lm->dir->frames : NULL, lm->x);  /* T U */
  for (size_t j = 0; j < n; j++)
    {
      umax = fmax (umax, fabs (lm->x[j]));
      lm->x[j] += m->x[j];                          /* x = X + U */
    }
  int status = lac_contact_set_uncovered (lm->set, lm->x, lm->data,
                                          2 * umax, tol, u);
  lm->miss = *u;
  return status;
}

/* Node-to-segment, a slave node inside the master that no reach gives a
 * multiplier: its projection along its normal misses the master facets
 * in the reference shape (the loop's message speaks of macro-elements
 * and epsilon, which this method has not). */
static int
nts_missed (const lac_linear_model *lm)
{
  const lac_contact_uncovered *u = &lm->miss;
  const lac_contact *c = lm->data->all;
  size_t node = c && u->macro < c->nmacro ? c->inode[u->macro] : 0;
  const lac_mesh *m = lm->set->pair[0].mesh;
  LAC_ERROR (LAC_EADMISS, "slave node %zu at (%.6g, %.6g, %.6g) has no "
             "node-to-segment multiplier (its projection along its normal "
             "misses the master surface in the reference shape) and passes "
             "%.3g into the master: node-to-segment cannot hold it; use "
             "method = lac, or a master surface that extends under it",
             m->node_tag[node], u->x[0], u->x[1], u->x[2], u->depth);
}

/* [c_n c_t] of every column side by side: column i (1 + ntan) is C's
 * column i, the next ntan those of Ct. */
static lac_csc *
columns_side_by_side (const lac_contact *c)
{
  const lac_csc *C = c->C, *T = c->Ct;
  size_t nt = (size_t) c->ntan, q = 1 + nt, e = 0;
  lac_csc *A = lac_csc_alloc (C->nrow, c->k * q, (size_t) (C->p[c->k]
                                                      + T->p[T->ncol]) + 1);
  if (!A)
    return NULL;
  A->p[0] = 0;
  for (size_t i = 0; i < c->k; i++)
    for (size_t b = 0; b < q; b++)
      {
        const lac_csc *S = b == 0 ? C : T;
        size_t col = b == 0 ? i : i * nt + b - 1;
        for (int p = S->p[col]; p < S->p[col + 1]; p++, e++)
          {
            A->i[e] = S->i[p];
            A->x[e] = S->x[p];
          }
        A->p[i * q + b + 1] = (int) e;
      }
  return A;
}

/* The friction of the contact data: the columns side by side, the system
 * that carries them. */
static int
take_friction (lac_linear_model *lm, const lac_contact *c)
{
  size_t q = 1 + (size_t) c->ntan;
  lac_csc_free (lm->Call);
  lac_free (lm->Gall);
  lac_free (lm->slip);
  lm->Call = columns_side_by_side (c);
  lm->Gall = lac_calloc (c->k * q + 1, sizeof *lm->Gall);
  lm->slip = lac_calloc (c->k * (q - 1) + 1, sizeof *lm->slip);
  if (!lm->Call || !lm->Gall || !lm->slip)
    LAC_ERROR (LAC_ENOMEM, "the frictional columns of %zu multipliers", c->k);
  lm->sys_rows = lm->sys;
  lm->sys_rows.C = lm->Call;
  lm->sys_rows.G = lm->Gall;
  lm->sys_rows.rho = NULL;
  return LAC_SUCCESS;
}

/* The system's C and G, and the maps, from the contact data. */
static int
take_contact (lac_linear_model *lm)
{
  const lac_contact *c = lm->data->all;
  lm->sys.C = c->C;
  lm->sys.G = c->G;
  lm->slot = c->macro;
  lm->area = c->area;
  lm->size = c->size;
  return c->Ct ? take_friction (lm, c) : LAC_SUCCESS;
}

/* ---- load steps: the Dirichlet part of G ------------------------------ */

void
lac_linear_lift_clear (lac_linear_lift *l)
{
  lac_free (l->G0);
  lac_free (l->e);
  lac_free (l->et);
  memset (l, 0, sizeof *l);
}

/* G0 = G of `all` and C_D, its entries in the rows of the Dirichlet dofs,
 * into *l (before lac_contact_apply_dirichlet zeroes them). */
static int
lift_keep (const lac_dirichlet *dir, const lac_contact *all,
           lac_linear_lift *l)
{
  const lac_csc *C = all->C;
  char *fixed = lac_calloc (C->nrow + 1, 1);
  int status = LAC_SUCCESS;
  memset (l, 0, sizeof *l);
  if (!fixed || !(l->G0 = lac_malloc ((all->k + 1) * sizeof *l->G0)))
    status = LAC_ERRMSG (LAC_ENOMEM, "mean gaps of %zu multipliers",
                         all->k);
  for (size_t t = 0; !status && t < dir->n; t++)
    if (dir->dof[t] < C->nrow)
      fixed[dir->dof[t]] = 1;
  for (size_t i = 0; !status && i < C->ncol; i++)
    for (int p = C->p[i]; !status && p < C->p[i + 1]; p++)
      if (fixed[C->i[p]])
        {
          if (lac_grow (&l->e, l->n + 1, &l->cap, sizeof *l->e, 64))
            status = LAC_ERRMSG (LAC_ENOMEM, "Dirichlet rows of C");
          else
            l->e[l->n++] = (lac_linear_lift_entry) { i, (size_t) C->i[p],
                                                     C->x[p] };
        }
  const lac_csc *T = all->Ct;                      /* friction: Ct_D */
  for (size_t i = 0; !status && T && i < T->ncol; i++)
    for (int p = T->p[i]; !status && p < T->p[i + 1]; p++)
      if (fixed[T->i[p]])
        {
          if (lac_grow (&l->et, l->nt + 1, &l->capt, sizeof *l->et, 64))
            status = LAC_ERRMSG (LAC_ENOMEM, "Dirichlet rows of Ct");
          else
            l->et[l->nt++] = (lac_linear_lift_entry) { i, (size_t) T->i[p],
                                                       T->x[p] };
        }
  if (!status)
    memcpy (l->G0, all->G, all->k * sizeof *l->G0);
  else
    lac_linear_lift_clear (l);
  lac_free (fixed);
  return status;
}

int
lac_linear_lift_record (const lac_dirichlet *dir, lac_contact *all,
                        lac_linear_lift *l)
{
  int status = lift_keep (dir, all, l);
  return status ? status : lac_contact_apply_dirichlet (all, dir->n,
                                                        dir->dof, dir->val);
}

void
lac_linear_model_keep_lift (lac_linear_model *lm, lac_linear_lift *l)
{
  lac_linear_lift_clear (&lm->lift);
  lm->lift = *l;
  memset (l, 0, sizeof *l);
  lac_linear_model_dirichlet (lm);
}

void
lac_linear_model_dirichlet (lac_linear_model *lm)
{
  const lac_linear_lift *l = &lm->lift;
  const lac_dirichlet *dir = lm->dir;
  double *g = lm->x, *G;                /* the values, by dof (scratch) */
  if (!l->G0 || !lm->data || !lm->data->all)
    return;
  G = lm->data->all->G;
  for (size_t t = 0; t < dir->n; t++)
    g[dir->dof[t]] = dir->val[t];       /* later entries win */
  memcpy (G, l->G0, lm->data->all->k * sizeof *G);
  for (size_t j = 0; j < l->n; j++)     /* G_i -= C(dof, i) g_dof */
    G[l->e[j].col] -= l->e[j].x * g[l->e[j].dof];
  double *sfix = lm->data->all->sfix;   /* friction: sfix = Ct_D^T g */
  if (sfix)
    memset (sfix, 0, lm->data->all->Ct->ncol * sizeof *sfix);
  for (size_t j = 0; sfix && j < l->nt; j++)
    sfix[l->et[j].col] += l->et[j].x * g[l->et[j].dof];
}

/* A new concatenation of the contact data of every pair, as the caller's
 * was made: C turned to the nodal frames of rollers (T^T C, fem/lac_frames.h),
 * then the Dirichlet values moved into G (with load steps, G0 and C_D
 * kept first, in *l). */
static int
new_contact (const lac_linear_model *lm, lac_contact *all,
             lac_linear_lift *l)
{
  int status = lac_contact_to_frames (all, lm->dir->frames);
  if (!status && lm->lift.G0)
    return lac_linear_lift_record (lm->dir, all, l);
  return status ? status : lac_contact_apply_dirichlet (all, lm->dir->n,
                                                        lm->dir->dof,
                                                        lm->dir->val);
}

/* The widened reach of every pair of s: w. */
static void
set_widened (lac_contact_set *s, double w)
{
  for (size_t p = 0; p < s->n; p++)
    s->pair[p].widened = w;
}

/* The pairs made again on the reference shape with `reach` more than
 * their own: the largest reach asked, not the sum (2 max |U| + depth is
 * measured from the reference shape, each time). */
static int
widen (void *self, const double *U, double reach, size_t *more)
{
  lac_linear_model *lm = self;
  lac_contact_set_data nd = { 0 };
  lac_linear_lift l = { 0 };
  int status;
  (void) U;
  *more = 0;
  if (!lm->set)
    return LAC_SUCCESS;
  size_t k0 = lm->data->all->k;
  double w0 = lm->set->pair[0].widened;
  set_widened (lm->set, fmax (w0, reach));
  if ((status = lac_contact_set_build (lm->set, NULL, &nd))
      || (nd.all && (status = new_contact (lm, nd.all, &l))))
    {
      lac_linear_lift_clear (&l);
      lac_contact_set_data_clear (&nd);
      set_widened (lm->set, w0);
      return status;
    }
  if (!nd.all || nd.all->k <= k0)
    {
      lac_linear_lift_clear (&l);
      lac_contact_set_data_clear (&nd);             /* nothing gained */
      set_widened (lm->set, w0);
      return lm->set->pair[0].nts ? nts_missed (lm) : LAC_SUCCESS;
    }
  *more = nd.all->k - k0;
  lac_contact_set_data_clear (lm->data);
  *lm->data = nd;
  if (l.G0)
    {
      lac_linear_lift_clear (&lm->lift);
      lm->lift = l;
    }
  lm->news = LAC_MODEL_NEW_C;
  return take_contact (lm);
}

static const lac_contact_model_type linear_type =
  { "linear", 0, evaluate, linearize, NULL, uncovered, widen };

/* The model of sys with room for nslot columns (one per macro-element at
 * most). */
static int
init (lac_linear_model *lm, const lac_contact_system *sys, double E,
      size_t nslot, lac_contact_model *m)
{
  size_t n = lac_system_n (sys);
  memset (lm, 0, sizeof *lm);
  lm->sys = *sys;
  lm->news = LAC_MODEL_NEW_K;
  lm->d = lac_malloc ((nslot ? nslot : 1) * sizeof *lm->d);
  lm->r = lac_malloc ((n ? n : 1) * sizeof *lm->r);
  lm->x = lac_malloc ((n ? n : 1) * sizeof *lm->x);
  if (!lm->d || !lm->r || !lm->x)
    {
      lac_linear_model_clear (lm);
      LAC_ERROR (LAC_ENOMEM, "linear model of %zu dofs", n);
    }
  *m = (lac_contact_model) { &linear_type, lm, n, nslot, E > 0 ? E : 1.0,
                             2, 0 };
  return LAC_SUCCESS;
}

int
lac_linear_model_init (lac_linear_model *lm, const lac_contact_system *sys,
                       double E, lac_contact_model *m)
{
  return init (lm, sys, E, sys->C ? sys->C->ncol : 0, m);
}

int
lac_linear_model_init_set (lac_linear_model *lm,
                           const lac_contact_system *sys,
                           lac_contact_set *set, lac_contact_set_data *data,
                           const lac_dirichlet *dir, double E,
                           lac_contact_model *m)
{
  int status = init (lm, sys, E, data->all->nmacro, m);   /* nts: nodes */
  if (status)
    return status;
  lm->set = set;
  set_widened (set, 0);       /* a new loop: from the pairs' own reach */
  lm->data = data;
  lm->dir = dir;
  m->dim = set->pair[0].mesh->dim;
  m->ntan = data->all->ntan;
  return take_contact (lm);
}

void
lac_linear_model_clear (lac_linear_model *lm)
{
  lac_linear_lift_clear (&lm->lift);
  lac_free (lm->d);
  lac_free (lm->r);
  lac_free (lm->x);
  lac_csc_free (lm->Call);
  lac_free (lm->Gall);
  lac_free (lm->slip);
  memset (lm, 0, sizeof *lm);
}
