/* lac_run_multipliers.c -- the contact multipliers after the solve
 *                          (see lac_run_multipliers.h)
 *                                               [LAC (16)-(18); §5.1-5.2]
 */
#include "run/lac_run_multipliers.h"

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* What the computations below read. */
typedef struct ctx
{
  lac_model model;
  int dim, ns;
  const lac_mesh *mesh;
  const lac_run_setup *setup;
  const lac_contact *contact;
  const double *lambda;        /* of the active set's solution           */
  const double *sigma;         /* nodal stresses                         */
  lac_run_multipliers *mu;
} ctx;

static int multiplier_means (ctx *r, const lac_exact *e);

/* n^T sigma n for a Voigt stress of the model (lac_material.h order). */
static double
normal_stress (int dim, const double *s, const double *n)
{
  if (dim == 2)
    return n[0] * n[0] * s[0] + n[1] * n[1] * s[1] + 2 * n[0] * n[1] * s[3];
  return n[0] * n[0] * s[0] + n[1] * n[1] * s[1] + n[2] * n[2] * s[2]
         + 2 * (n[0] * n[1] * s[3] + n[1] * n[2] * s[4] + n[2] * n[0] * s[5]);
}

/* The quadrature of the pairing over the covered part of macro-element m,
 * with the weights of the LAC terms (2 pi r in the axisymmetric model):
 * sum = int 1, int x (3), int n.sigma.n (with an exact solution, else 0);
 * l2 (if not NULL) += int (n.sigma.n - lh)^2. */
static int
macro_quadrature (const ctx *r, const lac_exact *e, size_t slot, double lh,
                  double sum[5], double *l2)
{
  const lac_run_setup *st = r->setup;
  size_t pr = lac_contact_set_pair_of (&st->set, slot);
  size_t m = slot - st->set.offset[pr];
  const lac_macro *M = st->macro[pr];
  const lac_pairing *P = st->data.P[pr];
  int dim = r->dim, nodes[LAC_MAX_FACE_NODES];
  double s[6];
  lac_map mp;
  memset (sum, 0, 5 * sizeof *sum);
  for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)
    for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
      {
        int nn = lac_contact_facet_eval (r->mesh, M->cell[j], M->face[j],
                                         P->xs + p * (dim - 1), nodes, &mp);
        if (nn < 0)
          return -nn;
        double w = P->w[p] * lac_model_weight (r->model, mp.x);
        sum[0] += w;
        for (int k = 0; k < dim; k++)
          sum[1 + k] += w * mp.x[k];
        if (e->kind == LAC_EXACT_NONE)
          continue;
        lac_exact_sigma (mp.x, (void *) e, s);
        double sn = normal_stress (dim, s, mp.normal);
        sum[4] += w * sn;
        if (l2)
          *l2 += w * (sn - lh) * (sn - lh);
      }
  return LAC_SUCCESS;
}

/* Per multiplier: the centroid of T^m cap Gamma_C and, with an exact
 * solution, the mean of its contact pressure n.sigma.n there; *l2 =
 * ||lambda - lambda_h||_{0, Gamma_C} over the covered parts of every
 * macro-element (lambda_h = 0 on the non-admissible ones, Gamma_C^eps).
 * Axisymmetric measures carry 2 pi r. */
static int
multiplier_geometry (ctx *r, const lac_exact *e, double *l2)
{
  const lac_contact *c = r->contact;
  *l2 = 0;
  if (c->xpt)                                    /* collocation points */
    {
      for (size_t i = 0; i < c->k; i++)
        {
          memcpy (r->mu->x + 3 * i, c->xpt + 3 * i, 3 * sizeof (double));
          if (e->kind == LAC_EXACT_NONE)
            continue;
          r->mu->exact[i] = lac_exact_normal_stress (e, c->xpt + 3 * i,
                                                     c->npt + 3 * i);
          double d = r->mu->exact[i] - r->lambda[i];
          *l2 += c->area[i] * d * d;             /* nodal quadrature */
        }
      *l2 = sqrt (*l2);
      return LAC_SUCCESS;
    }
  for (size_t m = 0; e->kind != LAC_EXACT_NONE && m < c->nmacro; m++)
    {
      long i = c->mult[m];
      double sum[5];
      int status = macro_quadrature (r, e, m, i >= 0 ? r->lambda[i] : 0.0,
                                     sum, l2);
      if (status)
        return status;
    }
  *l2 = sqrt (*l2);
  return multiplier_means (r, e);
}

/* Per multiplier: the centroid of T^m cap Gamma_C, and the mean of the
 * exact contact pressure n.sigma.n there. */
static int
multiplier_means (ctx *r, const lac_exact *e)
{
  const lac_contact *c = r->contact;
  for (size_t i = 0; i < c->k; i++)
    {
      double sum[5], *xc = r->mu->x + i * 3;
      int status = macro_quadrature (r, e, c->macro[i], 0.0, sum, NULL);
      if (status)
        return status;
      for (int k = 0; k < 3; k++)
        xc[k] = sum[0] > 0 ? sum[1 + k] / sum[0] : sum[1 + k];
      r->mu->exact[i] = sum[0] > 0 ? sum[4] / sum[0] : sum[4];
    }
  return LAC_SUCCESS;
}

/* max over nodes and components |sigma_h - sigma| / max |sigma|. */
static double
sigma_error (const ctx *r, const lac_exact *e)
{
  double emax = 0, smax = 0, s[6];
  for (size_t a = 0; a < r->mesh->nnodes; a++)
    {
      lac_exact_sigma (r->mesh->x + a * (size_t) r->dim, (void *) e, s);
      for (int k = 0; k < r->ns; k++)
        {
          emax = fmax (emax, fabs (r->sigma[a * (size_t) r->ns + k] - s[k]));
          smax = fmax (smax, fabs (s[k]));
        }
    }
  return smax > 0 ? emax / smax : emax;
}

/* Radial solutions: max over the nodes of body `b` of |sigma_rr^h -
 * sigma_rr| / max |sigma_rr| there, sigma_rr = n.sigma.n, n = x/|x| over
 * the radial coordinates (the normalization avoids dividing by the zero
 * of a free surface). */
static double
sigma_rr_error (const ctx *r, const lac_exact *e, int b)
{
  const lac_mesh *m = r->mesh;
  double emax = 0, smax = 0, s[6], n[3];
  char *in = lac_calloc (m->nnodes, 1);
  if (!in)
    return NAN;
  for (size_t c = 0; c < m->ncells; c++)
    if (m->body[c] == b)
      for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
        in[m->conn[p]] = 1;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *x = m->x + a * (size_t) r->dim;
      double R = lac_exact_radius (e, x);
      if (!in[a] || R <= 0)
        continue;
      for (int k = 0; k < r->dim; k++)
        n[k] = k < e->nr ? x[k] / R : 0.0;
      lac_exact_sigma (x, (void *) e, s);
      double se = normal_stress (r->dim, s, n);
      double sh = normal_stress (r->dim, r->sigma + a * (size_t) r->ns, n);
      emax = fmax (emax, fabs (sh - se));
      smax = fmax (smax, fabs (se));
    }
  lac_free (in);
  return smax > 0 ? emax / smax : emax;
}

/* The summary lines of the multipliers. */
static int
summary (const ctx *r, const lac_newton *s, const lac_exact *e, double l2lam,
         lac_summary *sum)
{
  size_t k = r->contact->k;
  double lmin = HUGE_VAL, lmax = -HUGE_VAL, elam = 0, lref = 0;
  int status;
  for (size_t i = 0; i < k; i++)
    {
      lmin = fmin (lmin, r->lambda[i]);
      lmax = fmax (lmax, r->lambda[i]);
      elam = fmax (elam, fabs (r->lambda[i] - r->mu->exact[i]));
      lref = fmax (lref, fabs (r->mu->exact[i]));
    }
  if ((status = lac_summary_add (sum, "macro_elements", "%zu",
                                 lac_contact_set_nslot (&r->setup->set)))
      || (status = lac_summary_add (sum, "multipliers", "%zu", k))
      || (status = lac_summary_add (sum, "active", "%zu",
                                    lac_newton_nactive (s)))
      || (status = lac_summary_add (sum, "newton_iterations", "%zu",
                                    s->nhist))
      || (status = lac_summary_add (sum, "lambda_min", LAC_SUMMARY_REAL, lmin))
      || (status = lac_summary_add (sum, "lambda_max", LAC_SUMMARY_REAL,
                                    lmax)))
    return status;
  if (e->kind == LAC_EXACT_NONE)
    return LAC_SUCCESS;
  if ((status = lac_summary_add (sum, "max_rel_err_lambda", LAC_SUMMARY_REAL,
                                 lref > 0 ? elam / lref : elam))
      || (status = lac_summary_add (sum, "l2_err_lambda", LAC_SUMMARY_REAL,
                                    l2lam)))
    return status;
  return lac_summary_add (sum, "max_rel_err_sigma", LAC_SUMMARY_REAL,
                          sigma_error (r, e));
}

/* sigma_rr of the slave and master bodies (radial solutions). */
static int
summary_radial (const ctx *r, const lac_exact *e, lac_summary *sum)
{
  const lac_run_setup *st = r->setup;
  int status;
  if (e->kind == LAC_EXACT_NONE || e->nr == 0)
    return LAC_SUCCESS;
  int bs = r->mesh->body[st->macro[0]->cell[0]];       /* slave body  */
  if ((status = lac_summary_add (sum, "max_rel_err_sigma_rr_slave",
                                 LAC_SUMMARY_REAL,
                                 sigma_rr_error (r, e, bs)))
      || st->master[0].n == 0)                          /* rigid master */
    return status;
  int bm = r->mesh->body[st->master[0].cell[0]];       /* master body */
  return lac_summary_add (sum, "max_rel_err_sigma_rr_master", LAC_SUMMARY_REAL,
                          sigma_rr_error (r, e, bm));
}

int
lac_run_multipliers_post (lac_model model, const lac_mesh *m,
                          const lac_run_setup *setup, const lac_contact *c,
                          const lac_newton *nw, const lac_exact *e,
                          const double *sigma, lac_run_multipliers *mu,
                          lac_summary *sum)
{
  double *lam = lac_malloc ((c->k + 1) * sizeof *lam), l2lam;
  ctx r = { model, lac_model_dim (model), lac_model_nstress (model), m,
            setup, c, lam, sigma, mu };
  int status;
  mu->x = lac_calloc (3 * c->k + 1, sizeof *mu->x);
  mu->exact = lac_calloc (c->k + 1, sizeof *mu->exact);
  if (!mu->x || !mu->exact || !lam)
    {
      lac_free (lam);
      LAC_ERROR (LAC_ENOMEM, "multiplier data");
    }
  for (size_t i = 0; i < c->k; i++)
    lam[i] = nw->lambda[c->macro[i]];          /* per column */
  if (!(status = multiplier_geometry (&r, e, &l2lam))
      && !(status = summary (&r, nw, e, l2lam, sum)))
    status = summary_radial (&r, e, sum);
  lac_free (lam);
  return status;
}

void
lac_run_multipliers_clear (lac_run_multipliers *mu)
{
  lac_free (mu->x);
  lac_free (mu->exact);
  mu->x = mu->exact = NULL;
}
