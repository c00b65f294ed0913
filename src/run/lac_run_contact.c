/* lac_run_contact.c -- the contact part of a run       [LAC §3.1, §4.3-4.6]
 *
 * For a scene with a [contact] section:
 *   stage contact   the macro-mesh of the slave group (refining the first
 *                   layer of cells where Hypothesis 1 needs it) and the
 *                   pairing of its sub-facets with the master group;
 *   assemble        admissibility [LAC Def. 1], C and the mean gaps
 *                   [LAC (16)-(18)], the Dirichlet values moved into G;
 *   solve           the active-set method [LAC Alg. 1] (lac_newton.c);
 *   post            the multipliers, their errors against the [exact]
 *                   contact pressure n.sigma.n, the summary;
 *   output          contact.csv, one line per macro-element.
 * A scene without [contact] runs none of this (no search, no Newton loop).
 */
#include "run/lac_run_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "contact/lac_obstacle.h"
#include "base/lac_status.h"

#define NEWTON_TOL 1e-10

/* Mark the nodes of the slave and master groups (the rigid-motion check
 * leaves bodies with a contact surface to the contact constraints). */
static int
mark_contact_nodes (lac_run *r, const lac_group *s, const lac_group *m)
{
  lac_free (r->on_contact);
  r->on_contact = lac_calloc (r->mesh->nnodes, 1);
  if (!r->on_contact)
    LAC_ERROR (LAC_ENOMEM, "contact node marks");
  for (size_t k = 0; k < s->nnodes; k++)
    r->on_contact[s->node[k]] = 1;
  for (size_t k = 0; m && k < m->nnodes; k++)
    r->on_contact[m->node[k]] = 1;
  return LAC_SUCCESS;
}

/* The facet group named by `key` of the [contact] section, checked. */
const lac_group *
lac_run_contact_group (lac_run *r, const char *key, const char *name)
{
  const lac_scene_contact *c = &r->scene->contact[0];
  const lac_group *g = lac_mesh_group (r->mesh, name);
  if (!g)
    {
      lac_scene_error (r->scene, &c->sec, key, LAC_EINVAL, "no physical "
                       "group of that name in mesh '%s'",
                       r->scene->mesh.file);
      return NULL;
    }
  if (g->dim != r->dim - 1 || g->n == 0)
    {
      lac_scene_error (r->scene, &c->sec, key, LAC_EINVAL, "%s",
                       g->n == 0 ? "the group has no facets"
                       : "not a group of boundary facets (dimension "
                         "must be the mesh's minus one)");
      return NULL;
    }
  return g;
}

/* Stage 2: macro-mesh and pairing. */
int
lac_run_stage_contact (lac_run *r)
{
  const lac_scene *sc = r->scene;
  const lac_scene_contact *c;
  lac_pairing_opts po;
  int status;
  double t0;
  if (sc->ncontact == 0)
    {
      snprintf (r->progress, sizeof r->progress, "no [contact]: skipped");
      return LAC_SUCCESS;
    }
  c = &sc->contact[0];
  if (!lac_run_contact_group (r, "slave", c->slave)
      || (c->master && !lac_run_contact_group (r, "master", c->master)))
    return LAC_EINVAL;
  t0 = lac_run_now ();
  status = c->method == 0                        /* lac: Hypothesis 1 */
           ? lac_macromesh_build (&r->mesh, c->slave, NULL, &r->macro)
           : lac_macromesh_trace (r->mesh, c->slave, &r->macro);
  if (status)
    return lac_scene_error (sc, &c->sec, "slave", status, "%s",
                            lac_error_message ());
  r->time_refine = lac_run_now () - t0;
  r->ndof = (size_t) r->dim * r->mesh->nnodes;
  const lac_group *gm = c->master ? lac_mesh_group (r->mesh, c->master) : NULL;
  const lac_group *gs = lac_mesh_group (r->mesh, c->slave);
  lac_pairing_facets S = { r->mesh, r->macro->ptr[r->macro->n],
                           r->macro->cell, r->macro->face };
  lac_pairing_opts_init (&po);
  t0 = lac_run_now ();
  if (gm)
    {
      r->master = lac_pairing_facets_of (r->mesh, gm);
      status = lac_pairing_build (&S, &r->master, &po, &r->pairing);
    }
  else
    {
      lac_obstacle ob = { r->dim, c->height, { c->curvature[0],
                          c->curvature[1] }, { c->center[0], c->center[1] } };
      memset (&r->master, 0, sizeof r->master);          /* no master mesh */
      status = lac_obstacle_pairing (&S, &ob, 0, &r->pairing);
    }
  r->time_pairing = lac_run_now () - t0;
  if (status)
    return lac_scene_error (sc, &c->sec, NULL, status, "%s",
                            lac_error_message ());
  if ((status = mark_contact_nodes (r, gs, gm)))
    return status;
  snprintf (r->progress, sizeof r->progress, "%zu macro-elements on '%s' "
            "(%zu cells cut, %zu nodes added), %zu pairs with %s%s%s",
            r->macro->n, c->slave, r->macro->ncut, r->macro->nnew,
            r->pairing->npairs, gm ? "'" : "the rigid obstacle",
            gm ? c->master : "", gm ? "'" : "");
  if (r->pairing->nfail)                   /* projections that failed */
    snprintf (r->progress + strlen (r->progress),
              sizeof r->progress - strlen (r->progress),
              "; %zu pairs dropped (projection failed)", r->pairing->nfail);
  return LAC_SUCCESS;
}

/* Assemble stage: admissibility, C, G; d holds the Dirichlet data. */
int
lac_run_contact_assemble (lac_run *r, const lac_dirichlet *d)
{
  const lac_scene_contact *c;
  int status;
  if (r->scene->ncontact == 0)
    return LAC_SUCCESS;
  c = &r->scene->contact[0];
  if (c->method == 2)                            /* node-to-segment */
    status = lac_contact_build_nts (r->mesh, r->model, r->macro, r->pairing,
                                    &r->master, &r->contact);
  else
    status = lac_contact_build (r->mesh, r->model, r->macro, r->pairing,
                                r->master.n ? &r->master : NULL,
                                c->epsilon > 0 ? c->epsilon
                                : LAC_EPSILON_DEFAULT,
                                &r->contact);
  if (status)
    return lac_scene_error (r->scene, &c->sec, status == LAC_EADMISS
                            ? "epsilon" : NULL, status, "%s",
                            lac_error_message ());
  return lac_contact_apply_dirichlet (r->contact, d->n, d->dof, d->val);
}

/* Solve stage: the active set [LAC Alg. 1], (*) solved by the strategy
 * chosen from the problem (solve/lac_strategy.h). */
int
lac_run_contact_solve (lac_run *r)
{
  lac_contact_system sys = { r->K, r->b, r->contact->C, r->contact->G, NULL,
                             0, NULL, NULL };
  const lac_scene_contact *sc = &r->scene->contact[0];
  lac_strategy_kind want = (lac_strategy_kind) (r->opts.strategy
                                                ? r->opts.strategy
                                                : sc->strategy);
  lac_strategy_kind kind = lac_strategy_choose (want, r->ndof, r->contact->k,
                                                sys.nfree);
  int status;
  if (kind == LAC_NSTRATEGIES)
    return lac_scene_error (r->scene, &sc->sec, "strategy", LAC_EINVAL, "%s",
                            lac_error_message ());
  r->newton = lac_newton_alloc (kind, r->ndof, r->contact->k);
  if (!r->newton)
    return LAC_ENOMEM;
  status = lac_newton_solve (r->newton, &sys, sc->max_iterations,
                             NEWTON_TOL);
  if (status)
    return status;
  r->fallback = lac_strategy_fallback (r->newton->strategy);
  if (!(r->u = lac_malloc (r->ndof * sizeof *r->u)))
    LAC_ERROR (LAC_ENOMEM, "displacement of %zu dofs", r->ndof);
  memcpy (r->u, r->newton->U, r->ndof * sizeof *r->u);
  snprintf (r->progress, sizeof r->progress, "%s, active set: %zu "
            "iteration%s, %zu of %zu multipliers active",
            lac_strategy_name (lac_strategy_kind_of (r->newton->strategy)),
            r->newton->nhist, r->newton->nhist > 1 ? "s" : "",
            lac_newton_nactive (r->newton), r->contact->k);
  return LAC_SUCCESS;
}

static int multiplier_means (lac_run *r, const lac_exact *e);

/* n^T sigma n for a Voigt stress of the model (lac_material.h order). */
static double
normal_stress (int dim, const double *s, const double *n)
{
  if (dim == 2)
    return n[0] * n[0] * s[0] + n[1] * n[1] * s[1] + 2 * n[0] * n[1] * s[3];
  return n[0] * n[0] * s[0] + n[1] * n[1] * s[1] + n[2] * n[2] * s[2]
         + 2 * (n[0] * n[1] * s[3] + n[1] * n[2] * s[4] + n[2] * n[0] * s[5]);
}

/* Per multiplier: the centroid of T^m cap Gamma_C and, with an exact
 * solution, the mean of its contact pressure n.sigma.n there; *l2 =
 * ||lambda - lambda_h||_{0, Gamma_C} over the covered parts of every
 * macro-element (lambda_h = 0 on the non-admissible ones, Gamma_C^eps).
 * Axisymmetric measures carry 2 pi r. */
static int
multiplier_geometry (lac_run *r, const lac_exact *e, double *l2)
{
  const lac_contact *c = r->contact;
  int dim = r->dim, nodes[LAC_MAX_FACE_NODES];
  const lac_macro *M = r->macro;
  const lac_pairing *P = r->pairing;
  lac_map mp;
  *l2 = 0;
  if (c->xpt)                                    /* collocation points */
    {
      for (size_t i = 0; i < c->k; i++)
        {
          memcpy (r->lam_x + 3 * i, c->xpt + 3 * i, 3 * sizeof (double));
          if (e->kind == LAC_EXACT_NONE)
            continue;
          r->lam_exact[i] = lac_exact_normal_stress (e, c->xpt + 3 * i,
                                                     c->npt + 3 * i);
          double d = r->lam_exact[i] - r->newton->lambda[i];
          *l2 += c->area[i] * d * d;             /* nodal quadrature */
        }
      *l2 = sqrt (*l2);
      return LAC_SUCCESS;
    }
  for (size_t mm = 0; e->kind != LAC_EXACT_NONE && mm < M->n; mm++)
    {
      long i = c->mult[mm];
      double lh = i >= 0 ? r->newton->lambda[i] : 0.0, s[6];
      for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
        for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
          {
            int nn = lac_contact_facet_eval (r->mesh, M->cell[j], M->face[j],
                                             P->xs + p * (dim - 1), nodes, &mp);
            if (nn < 0)
              return -nn;
            double w = P->w[p] * lac_model_weight (r->model, mp.x);
            lac_exact_sigma (mp.x, (void *) e, s);
            double d = normal_stress (dim, s, mp.normal) - lh;
            *l2 += w * d * d;                    /* int (lambda - lambda_h)^2 */
          }
    }
  *l2 = sqrt (*l2);
  return multiplier_means (r, e);
}

static int
multiplier_means (lac_run *r, const lac_exact *e)
{
  const lac_macro *M = r->macro;
  const lac_pairing *P = r->pairing;
  const lac_contact *c = r->contact;
  int dim = r->dim, nodes[LAC_MAX_FACE_NODES];
  lac_map mp;
  for (size_t i = 0; i < c->k; i++)
    {
      size_t m = c->macro[i];
      double wsum = 0, s[6], *xc = r->lam_x + i * 3;
      xc[0] = xc[1] = xc[2] = r->lam_exact[i] = 0;
      for (size_t j = M->ptr[m]; j < M->ptr[m + 1]; j++)
        for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
          {
            int nn = lac_contact_facet_eval (r->mesh, M->cell[j], M->face[j],
                                             P->xs + p * (dim - 1), nodes, &mp);
            if (nn < 0)
              return -nn;
            double w = P->w[p] * lac_model_weight (r->model, mp.x);
            wsum += w;                          /* as the LAC terms: 2 pi r */
            for (int k = 0; k < dim; k++)
              xc[k] += w * mp.x[k];
            if (e->kind != LAC_EXACT_NONE)
              {
                lac_exact_sigma (mp.x, (void *) e, s);
                r->lam_exact[i] += w * normal_stress (dim, s, mp.normal);
              }
          }
      for (int k = 0; k < dim && wsum > 0; k++)
        xc[k] /= wsum;
      if (wsum > 0)
        r->lam_exact[i] /= wsum;
    }
  return LAC_SUCCESS;
}

/* max over nodes and components |sigma_h - sigma| / max |sigma|. */
static double
sigma_error (const lac_run *r, const lac_exact *e)
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
sigma_rr_error (const lac_run *r, const lac_exact *e, int b)
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

/* Post stage: multipliers, their errors, the summary lines. */
int
lac_run_contact_post (lac_run *r, const lac_exact *e)
{
  const lac_newton *s = r->newton;
  size_t k = r->contact->k;
  double lmin = HUGE_VAL, lmax = -HUGE_VAL, elam = 0, lref = 0, l2lam;
  int status;
  r->lam_x = lac_calloc (3 * k, sizeof *r->lam_x);
  r->lam_exact = lac_calloc (k, sizeof *r->lam_exact);
  if (!r->lam_x || !r->lam_exact)
    LAC_ERROR (LAC_ENOMEM, "multiplier data");
  if ((status = multiplier_geometry (r, e, &l2lam)))
    return status;
  for (size_t i = 0; i < k; i++)
    {
      lmin = fmin (lmin, s->lambda[i]);
      lmax = fmax (lmax, s->lambda[i]);
      elam = fmax (elam, fabs (s->lambda[i] - r->lam_exact[i]));
      lref = fmax (lref, fabs (r->lam_exact[i]));
    }
  if (r->pairing->nfail
      && (status = lac_run_summary_add (r, "pairs_dropped", "%zu",
                                        r->pairing->nfail)))
    return status;
  if ((status = lac_run_summary_add (r, "macro_elements", "%zu", r->macro->n))
      || (status = lac_run_summary_add (r, "multipliers", "%zu", k))
      || (status = lac_run_summary_add (r, "active", "%zu",
                                        lac_newton_nactive (s)))
      || (status = lac_run_summary_add (r, "newton_iterations", "%zu",
                                        s->nhist))
      || (status = lac_run_summary_add (r, "lambda_min", "%.10e", lmin))
      || (status = lac_run_summary_add (r, "lambda_max", "%.10e", lmax)))
    return status;
  if (e->kind == LAC_EXACT_NONE)
    return LAC_SUCCESS;
  if ((status = lac_run_summary_add (r, "max_rel_err_lambda", "%.3e",
                                     lref > 0 ? elam / lref : elam))
      || (status = lac_run_summary_add (r, "l2_err_lambda", "%.10e", l2lam)))
    return status;
  if ((status = lac_run_summary_add (r, "max_rel_err_sigma", "%.3e",
                                     sigma_error (r, e))))
    return status;
  if (e->nr == 0)
    return LAC_SUCCESS;
  int bs = r->mesh->body[r->macro->cell[0]];           /* slave body  */
  if ((status = lac_run_summary_add (r, "max_rel_err_sigma_rr_slave", "%.3e",
                                     sigma_rr_error (r, e, bs)))
      || r->master.n == 0)                             /* rigid master */
    return status;
  int bm = r->mesh->body[r->master.cell[0]];           /* master body */
  return lac_run_summary_add (r, "max_rel_err_sigma_rr_master", "%.3e",
                              sigma_rr_error (r, e, bm));
}

/* Output stage: contact.csv, one line per macro-element. */
int
lac_run_contact_csv (const lac_run *r, const char *path)
{
  const lac_contact *c = r->contact;
  FILE *f = fopen (path, "w");
  if (!f)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  fprintf (f, "macro,x,y,z,measure,covered,criterion,admissible,"
           "multiplier,lambda,lambda_exact,mean_gap,active\n");
  for (size_t m = 0; m < c->nmacro; m++)
    {
      long i = c->mult[m];
      const double *x = i >= 0 ? r->lam_x + 3 * i : NULL;
      fprintf (f, "%zu,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%d,%ld,%.10e,"
               "%.10e,%.10e,%d\n", m, x ? x[0] : 0.0, x ? x[1] : 0.0,
               x ? x[2] : 0.0, c->meas[m], c->covered[m], c->crit[m],
               c->admissible[m], i, i >= 0 ? r->newton->lambda[i] : 0.0,
               i >= 0 ? r->lam_exact[i] : 0.0,
               i >= 0 && c->area[i] > 0 ? r->newton->d[i] / c->area[i] : 0.0,
               i >= 0 ? r->newton->active[i] : 0);
    }
  if (fclose (f) != 0)
    LAC_ERROR (LAC_EIO, "cannot write '%s'", path);
  return LAC_SUCCESS;
}
