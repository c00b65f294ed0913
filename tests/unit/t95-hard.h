/* t95-hard.h -- the whole contact chain for the hard-case tests t95x, t96x
 *                                     [LAC §4, Alg. 1, (10); issue 6 item 3]
 *
 * One hard case is one `hard_spec`: one or two bodies built in code
 * (lac_mesh_box, then shifted and optionally mapped node by node, so that
 * quadratic cells can be curved), a slave facet group, a master facet group
 * or a rigid obstacle, Dirichlet data, one pressure load, epsilon.
 * hard_run goes through the chain of t450/t460/t470
 *
 *   mesh boxes -> lac_mesh_merge -> macro-mesh -> pairing (or obstacle)
 *   -> stiffness, pressure, Dirichlet -> contact (admissibility, C, G)
 *   -> active set (lac_newton_solve) -> beta_h (lac_infsup, dense path,
 *      H1 Gram matrix, M = diag(h_i |T^m_i cap Gamma_C|))
 *
 * and keeps every intermediate object, so that a test can check the
 * solution against an exact one.  A stage that fails stores its status and
 * the library's one-line message (hard.stage, hard.msg); the later stages
 * are skipped.
 *
 * With LAC_HARD_TABLE=1 in the environment, hard_row prints one line
 * "row | case | k | iterations | beta_h | error | status" per case
 * (chapters/11-infsup/hard-cases.sh collects them into the table).
 *
 * Header-only (static inline: a test uses what it needs); every t95x/t96x
 * includes it.
 */
#ifndef T95_HARD_H
#define T95_HARD_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "contact/lac_infsup.h"
#include "solve/lac_newton.h"
#include "contact/lac_obstacle.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

typedef struct hard_body
{
  lac_elem_type type;
  size_t n[3];            /* cells per direction                          */
  double L[3];            /* box [0,L0] x [0,L1] (x [0,L2])               */
  double shift[3];        /* added to every node                          */
  double E, nu;
  /* optional: x <- map(x) for every node (after the shift); curved cells */
  void (*map) (double *x, const void *ctx);
  const void *ctx;
} hard_body;

typedef struct hard_fix
{
  const char *group;      /* any group of the merged mesh                 */
  int comp;               /* component                                    */
  double val;
} hard_fix;

#define HARD_MAXFIX 12

typedef struct hard_spec
{
  const char *name;       /* the row label                                */
  lac_model model;        /* PLANE_STRAIN (0) by default                  */
  int nbodies;            /* 2: lo, up merged with prefixes "lo.", "up.";
                             1: only `up`, groups without prefix          */
  hard_body lo, up;
  const char *slave;      /* facet group carrying the multipliers         */
  const char *master;     /* facet group, or NULL for the obstacle `ob`   */
  lac_obstacle ob;
  double eps;             /* 0: LAC_EPSILON_DEFAULT                       */
  const char *load;       /* pressure p on this facet group (NULL: none)  */
  double p;
  hard_fix fix[HARD_MAXFIX];
  int nfix;
  int maxit;              /* active-set iterations allowed (0: 10)        */
  int robust;             /* pairing option                               */
  int allow_empty;        /* pairing option                               */
  const char *solver;     /* a strategy: "dense" | "schur" | "augmented" |
                             "saddle" (NULL: saddle) */
  int show_rcond;         /* the table's status says "ok, rcond R"         */
} hard_spec;

typedef struct hard
{
  const hard_spec *sp;
  int dim;
  size_t ndof;
  lac_mesh *m;
  lac_macro *M;
  lac_pairing *P;
  lac_pairing_facets Mf;
  double *E, *nu;
  lac_elastic mat;
  lac_csc *K;
  double *F;
  lac_dirichlet *D;
  lac_contact *c;
  lac_newton *s;
  lac_infsup *inf;
  double rcond;           /* of the last saddle factorization (0: n/a)    */
  int status;             /* LAC_SUCCESS, or the status of `stage`        */
  const char *stage;      /* "mesh", "macromesh", "pairing", "contact",
                             "newton", "infsup", or NULL                  */
  char msg[512];
  double seconds;
} hard;

static inline double
hard_now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

static inline int
hard_fail (hard *h, const char *stage, int st)
{
  h->status = st;
  h->stage = stage;
  snprintf (h->msg, sizeof h->msg, "%s", lac_error_message ());
  return st;
}

static inline int
hard_box (const hard_body *b, lac_mesh **out)
{
  int st = lac_mesh_box (b->type, b->n, b->L, 0.0, out);
  if (st)
    return st;
  lac_mesh *m = *out;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double *x = m->x + a * (size_t) m->dim;
      for (int i = 0; i < m->dim; i++)
        x[i] += b->shift[i];
      if (b->map)
        b->map (x, b->ctx);
    }
  return LAC_SUCCESS;
}

/* Build and solve; returns h->status.  *h is zeroed first, hard_free is
 * always safe afterwards. */
static inline int
hard_run (const hard_spec *sp, hard *h)
{
  int st;
  double t0 = hard_now ();
  memset (h, 0, sizeof *h);
  h->sp = sp;
  /* 1. meshes */
  lac_mesh *lo = NULL, *up = NULL;
  if ((st = hard_box (&sp->up, &up)))
    return hard_fail (h, "mesh", st);
  if (sp->nbodies == 2)
    {
      if ((st = hard_box (&sp->lo, &lo))
          || (st = lac_mesh_merge (lo, "lo.", up, "up.", &h->m)))
        {
          lac_mesh_free (lo);
          lac_mesh_free (up);
          return hard_fail (h, "mesh", st);
        }
      lac_mesh_free (lo);
      lac_mesh_free (up);
    }
  else
    h->m = up;
  h->dim = h->m->dim;
  /* 2. macro-mesh of the slave surface (3D: refines the first layer) */
  if ((st = lac_macromesh_build (&h->m, sp->slave, NULL, &h->M)))
    return hard_fail (h, "macromesh", st);
  /* 3. pairing, or the obstacle's exact gaps */
  lac_pairing_facets S = { h->m, h->M->ptr[h->M->n], h->M->cell, h->M->face };
  if (sp->master)
    {
      const lac_group *g = lac_mesh_group (h->m, sp->master);
      if (!g)
        {
          snprintf (h->msg, sizeof h->msg, "no group %s", sp->master);
          h->status = LAC_EINVAL, h->stage = "pairing";
          return h->status;
        }
      h->Mf = lac_pairing_facets_of (h->m, g);
      lac_pairing_opts po;
      lac_pairing_opts_init (&po);
      po.robust = sp->robust;
      po.allow_empty = sp->allow_empty;
      st = lac_pairing_build (&S, &h->Mf, &po, &h->P);
    }
  else
    st = lac_obstacle_pairing (&S, &sp->ob, 0, &h->P);
  if (st)
    return hard_fail (h, "pairing", st);
  /* 4. stiffness, load, Dirichlet */
  lac_mesh *m = h->m;
  h->ndof = (size_t) h->dim * m->nnodes;
  h->E = malloc (m->ncells * sizeof *h->E);
  h->nu = malloc (m->ncells * sizeof *h->nu);
  h->F = calloc (h->ndof, sizeof *h->F);
  h->D = lac_dirichlet_alloc ();
  if (!h->E || !h->nu || !h->F || !h->D)
    return hard_fail (h, "mesh", LAC_ENOMEM);
  const lac_group *ub = lac_mesh_group (m, "up.body");
  char *isup = calloc (m->ncells ? m->ncells : 1, 1);
  if (!isup)
    return hard_fail (h, "mesh", LAC_ENOMEM);
  if (ub)
    for (size_t q = 0; q < ub->n; q++)
      isup[ub->cell[q]] = 1;
  for (size_t c = 0; c < m->ncells; c++)
    {
      const hard_body *b = (sp->nbodies == 1 || isup[c]) ? &sp->up : &sp->lo;
      h->E[c] = b->E, h->nu[c] = b->nu;
    }
  free (isup);
  h->mat.model = sp->model;
  h->mat.E = h->E;
  h->mat.nu = h->nu;
  lac_triplet *T = lac_triplet_alloc (h->ndof, h->ndof, 0);
  if ((st = lac_assembly_stiffness (m, &h->mat, T)))
    {
      lac_triplet_free (T);
      return hard_fail (h, "mesh", st);
    }
  h->K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  if (sp->load)
    {
      const lac_group *g = lac_mesh_group (m, sp->load);
      if (!g || (st = lac_assembly_pressure (m, sp->model, g, sp->p, h->F)))
        return hard_fail (h, "mesh", g ? st : LAC_EINVAL);
    }
  for (int k = 0; k < sp->nfix; k++)
    {
      const lac_group *g = lac_mesh_group (m, sp->fix[k].group);
      if (!g)
        {
          snprintf (h->msg, sizeof h->msg, "no group %s", sp->fix[k].group);
          h->status = LAC_EINVAL, h->stage = "mesh";
          return h->status;
        }
      lac_dirichlet_add_group (h->D, m, g, sp->fix[k].comp, sp->fix[k].val);
    }
  lac_dirichlet_apply (h->D, h->K, h->F);
  /* 5. admissibility, C, G */
  double eps = sp->eps > 0 ? sp->eps : LAC_EPSILON_DEFAULT;
  if ((st = lac_contact_build (m, sp->model, h->M, h->P,
                               sp->master ? &h->Mf : NULL, eps, &h->c)))
    return hard_fail (h, "contact", st);
  if ((st = lac_contact_apply_dirichlet (h->c, h->D->n, h->D->dof,
                                         h->D->val)))
    return hard_fail (h, "contact", st);
  /* 6. the active set */
  lac_contact_system sys = { h->K, h->F, h->c->C, h->c->G, NULL, 0, NULL, NULL, NULL };
  lac_strategy_kind kind = LAC_STRATEGY_SADDLE;
  if (sp->solver)
    kind = (lac_strategy_kind) lac_strategy_from_name (sp->solver);
  h->s = NULL;
  st = lac_newton_solve_system (kind, &sys, sp->maxit > 0 ? sp->maxit : 10, 1e-10, &h->s);
  if (st)
    return hard_fail (h, "newton", st);
  lac_strategy_counts counts;
  lac_strategy_get_counts (h->s->strategy, &counts);
  h->rcond = counts.rcond;
  h->seconds = hard_now () - t0;
  return LAC_SUCCESS;
}

/* beta_h of the case's multipliers (dense path, H1 norm); -1 on failure
 * (stage "infsup", message kept).  Call after a successful hard_run (also
 * allowed after a failed "newton" stage: C is built). */
static inline double
hard_beta (hard *h)
{
  if (!h->c)
    return -1;
  char *fixed = calloc (h->ndof, 1);
  lac_csc *A = NULL, *Mn = NULL;
  lac_infsup_opts o;
  lac_infsup_opts_init (&o);
  o.path = LAC_INFSUP_DENSE;
  int st;
  if (!fixed)
    return -1;
  for (size_t q = 0; q < h->D->n; q++)
    fixed[h->D->dof[q]] = 1;
  if ((st = lac_infsup_gram_h1 (h->m, h->sp->model, fixed, 0.0, &A))
      || (st = lac_infsup_norm_lac (h->m, h->M, h->c, NULL, &Mn))
      || (st = lac_infsup_estimate (A, h->c->C, Mn, &o, &h->inf)))
    {
      int keep = h->status;
      hard_fail (h, "infsup", st);
      if (keep)
        h->status = keep;
    }
  free (fixed);
  lac_csc_free (A);
  lac_csc_free (Mn);
  return h->inf ? h->inf->beta : -1;
}

/* U and lambda are finite. */
static inline int
hard_finite (const hard *h)
{
  if (!h->s)
    return 0;
  for (size_t j = 0; j < h->ndof; j++)
    if (!isfinite (h->s->U[j]))
      return 0;
  for (size_t i = 0; i < h->c->k; i++)
    if (!isfinite (h->s->lambda[i]) || !isfinite (h->s->d[i]))
      return 0;
  return 1;
}

/* max_i |lambda_i - want| / |want| */
static inline double
hard_err_lambda (const hard *h, double want)
{
  double e = 0;
  for (size_t i = 0; i < h->c->k; i++)
    e = fmax (e, fabs (h->s->lambda[i] - want) / fabs (want));
  return e;
}

/* max over the cells of |sigma_comp - want| / |want| at one interior point */
static inline double
hard_err_sigma (const hard *h, int comp, double want)
{
  double e = 0, sig[6], xi[3];
  for (size_t c = 0; c < h->m->ncells; c++)
    {
      xi[0] = xi[1] = xi[2] = h->m->type[c] == LAC_PYR5 ? 0.1 : 0.2;
      if (lac_post_stress_at (h->m, &h->mat, h->s->U, c, xi, sig))
        return INFINITY;
      e = fmax (e, fabs (sig[comp] - want) / fabs (want));
    }
  return e;
}

/* The total contact force sum_i lambda_i |T^m_i cap Gamma_C| against
 * `want` (relative error). */
static inline double
hard_err_force (const hard *h, double want)
{
  double f = 0;
  for (size_t i = 0; i < h->c->k; i++)
    f += h->s->lambda[i] * h->c->area[i];
  return fabs (f - want) / fabs (want);
}

/* Equilibrium of one body in one direction, for a body that is free to
 * translate along component `comp` (no Dirichlet data on it): then the
 * translation t is in the kernel of K and t^T (K U - C lambda - F) = 0
 * gives sum_{j in t} (C lambda)_j = -sum_{j in t} F_j, the contact force
 * (the integral of lambda n, also on a curved interface) against the
 * load.  Returns the relative error; group: the body's cell group. */
static inline double
hard_err_balance (const hard *h, const char *group, int comp)
{
  const lac_group *g = lac_mesh_group (h->m, group);
  const lac_csc *C = h->c->C;
  double *f = calloc (h->ndof, sizeof *f), a = 0, b = 0;
  if (!g || !f)
    {
      free (f);
      return INFINITY;
    }
  for (size_t i = 0; i < h->c->k; i++)
    for (int q = C->p[i]; q < C->p[i + 1]; q++)
      f[C->i[q]] += C->x[q] * h->s->lambda[i];
  for (size_t q = 0; q < g->nnodes; q++)
    {
      size_t j = g->node[q] * (size_t) h->dim + (size_t) comp;
      a += f[j];
      b += h->F[j];
    }
  free (f);
  return fabs (a + b) / fabs (b);
}

/* Complementarity of the discrete solution [LAC (18)], scaled:
 * lambda <= 0, d >= 0, lambda d = 0 up to tol (lambda relative to
 * max|lambda|, d relative to |C(:,i)|_1 max|U|). */
static inline int
hard_complementarity (const hard *h, double tol)
{
  double lmax = 0, umax = 0;
  for (size_t i = 0; i < h->c->k; i++)
    lmax = fmax (lmax, fabs (h->s->lambda[i]));
  for (size_t j = 0; j < h->ndof; j++)
    umax = fmax (umax, fabs (h->s->U[j]));
  const lac_csc *C = h->c->C;
  for (size_t i = 0; i < h->c->k; i++)
    {
      double cn = 0;
      for (int q = C->p[i]; q < C->p[i + 1]; q++)
        cn += fabs (C->x[q]);
      double ds = cn * fmax (umax, 1e-300), l = h->s->lambda[i], d = h->s->d[i];
      if (l > tol * lmax || d < -tol * ds - 1e-300
          || fabs (l * d) > tol * lmax * ds)
        return 0;
    }
  return 1;
}

static inline const char *
hard_stname (int st)
{
  switch (st)
    {
    case LAC_SUCCESS: return "ok";
    case LAC_EINVAL: return "EINVAL";
    case LAC_ESING: return "ESING";
    case LAC_EMAXITER: return "EMAXITER";
    case LAC_EADMISS: return "EADMISS";
    default: return "error";
    }
}

/* One row of the table (LAC_HARD_TABLE=1): case, k, iterations, beta_h,
 * the error (what, value; what NULL or err < 0: "-"), status: "ok" or
 * "FAILS" (the test's assertions on the case), followed for a case that
 * stops by "stops:", its stage, status and message. */
static inline void
hard_row_raw (const char *name, long k, long iters, double beta,
              const char *what, double err, const char *status)
{
  if (!getenv ("LAC_HARD_TABLE"))
    return;
  char b[32], e[48];
  if (beta >= 0)
    snprintf (b, sizeof b, "%.4e", beta);
  else
    snprintf (b, sizeof b, "-");
  if (what)
    snprintf (e, sizeof e, "%s %.2e", what, err);
  else
    snprintf (e, sizeof e, "-");
  printf ("row|%s|%ld|%ld|%s|%s|%s\n", name, k, iters, b, e, status);
  fflush (stdout);
}

static inline void
hard_row (const hard *h, const char *what, double err, int pass)
{
  char status[600];
  if (h->status && h->stage)
    snprintf (status, sizeof status, "%s, stops: %s %s: %s",
              pass ? "ok" : "FAILS", h->stage, hard_stname (h->status),
              h->msg);
  else if (h->sp->show_rcond)
    snprintf (status, sizeof status, "%s, rcond %.1e", pass ? "ok" : "FAILS",
              h->rcond);
  else
    snprintf (status, sizeof status, "%s", pass ? "ok" : "FAILS");
  hard_row_raw (h->sp->name, h->c ? (long) h->c->k : -1,
                h->s ? (long) h->s->nhist : -1,
                h->inf ? h->inf->beta : -1, err >= 0 ? what : NULL, err,
                status);
}

static inline void
hard_free (hard *h)
{
  lac_infsup_free (h->inf);
  lac_newton_free (h->s);
  lac_contact_free (h->c);
  lac_dirichlet_free (h->D);
  free (h->F);
  lac_csc_free (h->K);
  free (h->E);
  free (h->nu);
  lac_pairing_free (h->P);
  lac_macromesh_free (h->M);
  lac_mesh_free (h->m);
  memset (h, 0, sizeof *h);
}

/* ---- ready-made set-ups ------------------------------------------------ */

/* The Taylor patch test of chapter 08 [LAC §5.1]: lower block `lo` (n_lo
 * cells per side) under the upper block `up` (n_up), both 50 wide, the
 * upper one stacked on top and pressed with p = 25; symmetry on x = 0 (and
 * y = 0 in 3D) for both, the lower block held on its bottom.  swap = 0:
 * slave = the upper block's bottom; 1: the lower block's top.  Exact:
 * sigma_vv = lambda = -25 everywhere. */
#define HARD_P 25.0

static inline void
hard_taylor (hard_spec *sp, const char *name, lac_elem_type tlo,
             const size_t *nlo, lac_elem_type tup, const size_t *nup,
             int swap)
{
  int dim = lac_refelem_get (tlo)->dim;
  memset (sp, 0, sizeof *sp);
  sp->name = name;
  sp->model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  sp->nbodies = 2;
  hard_body lo = { tlo, { nlo[0], nlo[1], nlo[2] }, { 50, 50, 50 },
                   { 0, 0, 0 }, 2000, 0.3, NULL, NULL };
  hard_body up = lo;
  up.type = tup;
  memcpy (up.n, nup, sizeof up.n);
  up.shift[dim - 1] = 50;
  sp->lo = lo, sp->up = up;
  const char *top = dim == 2 ? "lo.ymax" : "lo.zmax";
  const char *bot = dim == 2 ? "up.ymin" : "up.zmin";
  sp->slave = swap ? top : bot;
  sp->master = swap ? bot : top;
  sp->load = dim == 2 ? "up.ymax" : "up.zmax";
  sp->p = HARD_P;
  int f = 0;
  sp->fix[f++] = (hard_fix) { "lo.xmin", 0, 0 };
  sp->fix[f++] = (hard_fix) { "up.xmin", 0, 0 };
  if (dim == 3)
    {
      sp->fix[f++] = (hard_fix) { "lo.ymin", 1, 0 };
      sp->fix[f++] = (hard_fix) { "up.ymin", 1, 0 };
    }
  sp->fix[f++] = (hard_fix) { dim == 2 ? "lo.ymin" : "lo.zmin", dim - 1, 0 };
  sp->nfix = f;
}

/* Run a Taylor-type case and check: it converges, U and lambda finite,
 * at most maxit active-set iterations, lambda and sigma_vv = -25 to tol
 * (tol < 0: not checked), beta_h >= beta_min.  Prints the row. */
static inline void
hard_check_taylor (const hard_spec *sp, size_t maxit, double tol,
                   double beta_min)
{
  hard h;
  int st = hard_run (sp, &h);
  check_status (st, LAC_SUCCESS, "%s: solved (stage %s)", sp->name,
                h.stage ? h.stage : "-");
  double beta = hard_beta (&h), el = -1, es = -1;
  int pass = !st && beta >= beta_min;
  check_true (beta >= beta_min, "%s: beta_h = %.4e >= %.2g", sp->name, beta,
              beta_min);
  if (!st)
    {
      int fin = hard_finite (&h);
      check_true (fin, "%s: U, lambda finite", sp->name);
      check_true (h.s->nhist <= maxit, "%s: %zu active-set iterations <= %zu",
                  sp->name, h.s->nhist, maxit);
      el = hard_err_lambda (&h, -HARD_P);
      es = hard_err_sigma (&h, h.dim - 1, -HARD_P);
      if (tol >= 0)
        {
          check_true (el <= tol, "%s: lambda err %.2e <= %.0e", sp->name, el,
                      tol);
          check_true (es <= tol, "%s: sigma err %.2e <= %.0e", sp->name, es,
                      tol);
        }
      pass = pass && fin && h.s->nhist <= maxit
        && (tol < 0 || (el <= tol && es <= tol));
    }
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: k = %zu it = %zu beta = %.4e lambda err %.2e sigma err "
            "%.2e rcond %.2e (%.2f s)\n", sp->name, h.c ? h.c->k : 0,
            h.s ? h.s->nhist : 0, beta, el, es, h.rcond, h.seconds);
  hard_row (&h, "lambda", el, pass);
  hard_free (&h);
}

/* The non-conforming set-up of t470 [LAC Def. 1, Thm. 2]: the slave is the
 * top of a rigid base [0,50]^d (every dof of "lo.body" fixed, nbase cells
 * per side, 2 layers), the master the bottom of a block [0,Lm] x [0,50]
 * (x [0,50]) stacked on it (nblock cells per side), pressed with p = 25,
 * symmetric on x = 0 (and y = 0).  Gamma_C = [0, Lm] ends inside slave
 * cells.  While every covered macro-element is admissible the uniform
 * state is the discrete solution: lambda = -25 exactly; a dropped one
 * leaves the total force -25 Lm (x 50) on the others. */
static inline void
hard_narrow (hard_spec *sp, const char *name, lac_elem_type t, size_t nbase,
             size_t nblock, double Lm, double eps)
{
  int dim = lac_refelem_get (t)->dim;
  memset (sp, 0, sizeof *sp);
  sp->name = name;
  sp->model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  sp->nbodies = 2;
  hard_body lo = { t, { nbase, nbase, 2 }, { 50, 50, 50 }, { 0, 0, 0 },
                   2000, 0.3, NULL, NULL };
  if (dim == 2)
    lo.n[1] = 2;
  hard_body up = { t, { nblock, nblock, nblock }, { Lm, 50, 50 }, { 0, 0, 0 },
                   2000, 0.3, NULL, NULL };
  up.shift[dim - 1] = 50;
  sp->lo = lo, sp->up = up;
  sp->slave = dim == 2 ? "lo.ymax" : "lo.zmax";
  sp->master = dim == 2 ? "up.ymin" : "up.zmin";
  sp->load = dim == 2 ? "up.ymax" : "up.zmax";
  sp->p = HARD_P;
  sp->eps = eps;
  int f = 0;
  for (int c = 0; c < dim; c++)
    sp->fix[f++] = (hard_fix) { "lo.body", c, 0 };
  sp->fix[f++] = (hard_fix) { "up.xmin", 0, 0 };
  if (dim == 3)
    sp->fix[f++] = (hard_fix) { "up.ymin", 1, 0 };
  sp->nfix = f;
}

#endif /* T95_HARD_H */
