/* lac_quadrature.c -- quadrature rules on the reference elements  [LAC §3.1]
 *
 * Every integral of the method (stiffness, loads, the macro-element
 * averages of [LAC §3.1]) is computed by a rule
 *     int_K f  ~=  sum_q w_q f(xi_q),
 * exact for all polynomials of total degree <= `degree`.
 *
 *   line, quad, hex   tensor products of n-point Gauss-Legendre rules
 *                     (GSL's tables), n = floor(degree/2) + 1, exact for
 *                     Q_{2n-1} and so of total degree 2n-1.
 *   tri  (degree<=8)  fully symmetric rules with positive weights and
 *                     interior points: centroid (1), Strang-Fix (3),
 *                     Dunavant 4 (6), Radon/Hammer 5 (7), Dunavant 6 (12),
 *                     Dunavant 8 (16); digits polished by Gauss-Newton on
 *                     the monomial moments.
 *   tet  (degree<=5)  centroid (1), the 4-point degree-2 rule, an 8-point
 *                     degree-3 rule with equal weights (two vertex orbits,
 *                     derived below) and the classical 14-point
 *                     degree-5 rule (e.g. Walkington 2000).
 *   above             collapsed (Stroud conical product, Duffy) rules: the
 *                     simplex is the image of a cube by
 *                       tri: x = u,  y = v (1-u),                 J = 1-u
 *                       tet: x = u,  y = v (1-u),  z = w (1-u)(1-v),
 *                            J = (1-u)^2 (1-v)
 *                     with Gauss-Jacobi rules for the weights (1-u)^a and
 *                     Gauss-Legendre in the last variable; n points per
 *                     direction are exact for total degree 2n-1.
 *   pyramid           collapsed: x = xi (1-w), y = eta (1-w), z = w on
 *                     [-1,1]^2 x [0,1], J = (1-w)^2 taken exactly by a
 *                     Gauss-Jacobi rule in w; exact for total degree 2n-1
 *                     and for the products of the rational pyr5 basis and
 *                     of its gradients (polynomials in (xi, eta, w)).
 *
 * The 8-point degree-3 tetrahedron rule: with barycentric orbits
 * (a,a,a,1-3a), t = 1-4a, equal weights 1/8 and the moments of the unit
 * tetrahedron, exactness up to degree 3 reduces to
 *     t1^2 + t2^2 = 2/5,   t1^3 + t2^3 = 2/15,
 * so s = t1 + t2 solves s^3 - 6/5 s + 4/15 = 0 (root s = 0.2327...).
 *
 * References: Strang & Fix (1973); Dunavant, IJNME 21 (1985) 1129-1148;
 * Keast, CMAME 55 (1986) 339-348; Walkington, "Quadrature on simplices of
 * arbitrary dimension" (2000); Stroud, Approximate Calculation of Multiple
 * Integrals (1971); Karniadakis & Sherwin (2005) for the collapsed maps.
 */
#include "fem/lac_quadrature.h"

#include <string.h>

#include <gsl/gsl_integration.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

#define MAXDEG_TENSOR 41
#define MAXDEG_COLLAPSED 31

/* ---- symmetric simplex rules (weights as fractions of the measure) ----- */

typedef enum { S3, S21, S111, S4, S31, S22 } orbit_kind;

typedef struct
{
  orbit_kind kind;
  double a, b;   /* barycentric parameters        */
  double w;      /* weight of each point of orbit */
} orbit;

typedef struct
{
  int degree, npts, norb;
  orbit orb[5];
} sym_rule;

static const sym_rule tri_rules[] = {
  { 1, 1, 1, { { S3, 0, 0, 1 } } },
  { 2, 3, 1, { { S21, 1.0 / 6, 0, 1.0 / 3 } } },
  { 4, 6, 2, { { S21, 0.44594849091596489, 0, 0.22338158967801153 },
               { S21, 0.091576213509770674, 0, 0.10995174365532177 } } },
  { 5, 7, 3, { { S3, 0, 0, 0.225 },
               { S21, 0.10128650732345633880, 0, 0.12593918054482715260 },
               { S21, 0.47014206410511508977, 0, 0.13239415278850618074 } } },
  { 6, 12, 3, { { S21, 0.24928674517093685, 0, 0.1167862757263339 },
                { S21, 0.063089014491496453, 0, 0.050844906370198721 },
                { S111, 0.053145049844836187, 0.3103524510337638,
                  0.082851075618400341 } } },
  { 8, 16, 5, { { S3, 0, 0, 0.14431560767780519 },
                { S21, 0.459292588292737, 0, 0.095091634267272226 },
                { S21, 0.17056930775177506, 0, 0.10321737053471933 },
                { S21, 0.05054722831703086, 0, 0.032458497623196657 },
                { S111, 0.0083947774099735854, 0.2631128296345952,
                  0.027230314174438355 } } },
};

static const sym_rule tet_rules[] = {
  { 1, 1, 1, { { S4, 0, 0, 1 } } },
  { 2, 4, 1, { { S31, 0.13819660112501051518, 0, 0.25 } } },
  { 3, 8, 2, { { S31, 0.11295679451251102870, 0, 0.125 },
               { S31, 0.32886164993020291040, 0, 0.125 } } },
  { 5, 14, 3, { { S31, 0.092735250310890999, 0, 0.073493043116361526 },
                { S31, 0.31088591926330061, 0, 0.11268792571801467 },
                { S22, 0.45449629587434898, 0, 0.042546020777082541 } } },
};

#define NTRI_RULES ((int) (sizeof tri_rules / sizeof tri_rules[0]))
#define NTET_RULES ((int) (sizeof tet_rules / sizeof tet_rules[0]))

/* ---- allocation ----------------------------------------------------------- */

static lac_quad *
quad_new (lac_shape shape, int dim, int degree, int n)
{
  lac_quad *q = lac_malloc (sizeof *q);
  if (q == NULL)
    LAC_ERROR_NULL (LAC_ENOMEM, "no memory for a %d-point rule", n);
  q->shape = shape, q->dim = dim, q->degree = degree, q->n = n;
  q->xi = lac_malloc ((size_t) n * (size_t) dim * sizeof (double));
  q->w = lac_malloc ((size_t) n * sizeof (double));
  if (q->xi == NULL || q->w == NULL)
    {
      lac_quad_free (q);
      LAC_ERROR_NULL (LAC_ENOMEM, "no memory for a %d-point rule", n);
    }
  return q;
}

void
lac_quad_free (lac_quad *q)
{
  if (q == NULL)
    return;
  lac_free (q->xi);
  lac_free (q->w);
  lac_free (q);
}

double
lac_quad_ref_measure (lac_shape shape)
{
  switch (shape)
    {
    case LAC_SHAPE_LINE: return 2;
    case LAC_SHAPE_QUAD: return 4;
    case LAC_SHAPE_HEX: return 8;
    case LAC_SHAPE_TRI: return 0.5;
    case LAC_SHAPE_TET: return 1.0 / 6;
    case LAC_SHAPE_PYR: return 4.0 / 3;
    }
  return 0;
}

int
lac_quad_max_degree (lac_shape shape)
{
  switch (shape)
    {
    case LAC_SHAPE_LINE: case LAC_SHAPE_QUAD: case LAC_SHAPE_HEX:
      return MAXDEG_TENSOR;
    case LAC_SHAPE_TRI: case LAC_SHAPE_TET: case LAC_SHAPE_PYR:
      return MAXDEG_COLLAPSED;
    }
  return -1;
}

/* ---- 1D rules ------------------------------------------------------------- */

/* n-point Gauss-Legendre rule on [a, b]. */
static int
gauss_legendre (int n, double a, double b, double *x, double *w)
{
  gsl_integration_glfixed_table *t =
    gsl_integration_glfixed_table_alloc ((size_t) n);
  if (t == NULL)             /* n >= 1 here: GSL could not allocate it */
    LAC_ERROR (n > 0 ? LAC_ENOMEM : LAC_EDEP, "GSL's %d-point "
               "Gauss-Legendre table", n);
  for (int i = 0; i < n; i++)
    gsl_integration_glfixed_point (a, b, (size_t) i, &x[i], &w[i], t);
  gsl_integration_glfixed_table_free (t);
  return LAC_SUCCESS;
}

/* n-point Gauss-Jacobi rule for int_0^1 (1-u)^alpha f(u) du. */
static int
gauss_jacobi01 (int n, int alpha, double *x, double *w)
{
  gsl_integration_fixed_workspace *ws =
    gsl_integration_fixed_alloc (gsl_integration_fixed_jacobi, (size_t) n,
                                 0.0, 1.0, (double) alpha, 0.0);
  if (ws == NULL)            /* n >= 1 here: GSL could not allocate it */
    LAC_ERROR (n > 0 ? LAC_ENOMEM : LAC_EDEP, "GSL's %d-point Gauss-Jacobi "
               "rule", n);
  const double *gx = gsl_integration_fixed_nodes (ws);
  const double *gw = gsl_integration_fixed_weights (ws);
  for (int i = 0; i < n; i++)
    x[i] = gx[i], w[i] = gw[i];
  gsl_integration_fixed_free (ws);
  return LAC_SUCCESS;
}

/* ---- tensor-product and collapsed rules ------------------------------------ */

#define NMAX (MAXDEG_TENSOR / 2 + 1)

/* Gauss-Legendre^dim on [-1,1]^dim, n = degree/2 + 1 points a direction. */
static lac_quad *
rule_tensor (lac_shape shape, int dim, int degree)
{
  int n = degree / 2 + 1, np = n;
  double x[NMAX], w[NMAX];
  for (int k = 1; k < dim; k++)
    np *= n;
  if (gauss_legendre (n, -1, 1, x, w))
    return NULL;
  lac_quad *q = quad_new (shape, dim, 2 * n - 1, np);
  if (q == NULL)
    return NULL;
  for (int p = 0; p < np; p++)
    {
      int r = p;
      q->w[p] = 1;
      for (int k = 0; k < dim; k++, r /= n)   /* digit k of p in base n */
        {
          q->xi[p * dim + k] = x[r % n];
          q->w[p] *= w[r % n];
        }
    }
  return q;
}

/* The collapsed maps from the square or cube of u = (u, v, w) to the
 * element (file header). */
static void
map_tri (const double *u, double *xi)
{
  xi[0] = u[0];
  xi[1] = u[1] * (1 - u[0]);
}

static void
map_tet (const double *u, double *xi)
{
  xi[0] = u[0];
  xi[1] = u[1] * (1 - u[0]);
  xi[2] = u[2] * (1 - u[0]) * (1 - u[1]);
}

static void
map_pyr (const double *u, double *xi)
{
  double s = 1 - u[2];
  xi[0] = u[0] * s;
  xi[1] = u[1] * s;
  xi[2] = u[2];
}

/* The 1D rules a collapsed rule is the product of: Gauss-Legendre on
 * [0,1] or [-1,1], Gauss-Jacobi for the weight (1-u) or (1-u)^2 on [0,1]
 * (the Jacobian of the map). */
typedef enum { LEGENDRE_01, LEGENDRE_11, JACOBI_1, JACOBI_2 } rule1d_kind;

static const struct
{
  lac_shape shape;
  int dim;
  rule1d_kind rule[3];                   /* in u, v, w */
  void (*map) (const double *u, double *xi);
} collapsed_rules[] = {
  { LAC_SHAPE_TRI, 2, { JACOBI_1, LEGENDRE_01 }, map_tri },
  { LAC_SHAPE_TET, 3, { JACOBI_2, JACOBI_1, LEGENDRE_01 }, map_tet },
  { LAC_SHAPE_PYR, 3, { LEGENDRE_11, LEGENDRE_11, JACOBI_2 }, map_pyr },
};

static int
rule1d (rule1d_kind kind, int n, double *x, double *w)
{
  switch (kind)
    {
    case LEGENDRE_01: return gauss_legendre (n, 0, 1, x, w);
    case LEGENDRE_11: return gauss_legendre (n, -1, 1, x, w);
    case JACOBI_1: return gauss_jacobi01 (n, 1, x, w);
    case JACOBI_2: return gauss_jacobi01 (n, 2, x, w);
    }
  LAC_ERROR (LAC_ESANITY, "1D rule kind %d", (int) kind);
}

/* The collapsed rule of a triangle, tetrahedron or pyramid: the product
 * of n-point 1D rules (the last coordinate running fastest), mapped to
 * the element; exact for total degree 2n - 1. */
static lac_quad *
rule_collapsed (lac_shape shape, int degree)
{
  int k = 0, n = degree / 2 + 1;
  double x[3][NMAX], w[3][NMAX];
  while (collapsed_rules[k].shape != shape)
    k++;
  int dim = collapsed_rules[k].dim, np = dim == 2 ? n * n : n * n * n;
  for (int d = 0; d < dim; d++)
    if (rule1d (collapsed_rules[k].rule[d], n, x[d], w[d]))
      return NULL;
  lac_quad *q = quad_new (shape, dim, 2 * n - 1, np);
  if (q == NULL)
    return NULL;
  for (int p = 0; p < np; p++)
    {
      int i[3], rest = p;
      double u[3];
      for (int d = dim - 1; d >= 0; d--, rest /= n)
        i[d] = rest % n;                 /* digits of p in base n: (i, j, k) */
      q->w[p] = w[0][i[0]];
      for (int d = 0; d < dim; d++)
        u[d] = x[d][i[d]];
      for (int d = 1; d < dim; d++)
        q->w[p] *= w[d][i[d]];
      collapsed_rules[k].map (u, q->xi + p * dim);
    }
  return q;
}

/* ---- symmetric rules --------------------------------------------------------- */

/* The points of one orbit, as barycentric coordinates (lambda_0..d). */
static int
orbit_points (const orbit *o, double lam[24][4])
{
  double a = o->a, b = o->b, c;
  switch (o->kind)
    {
    case S3:
      lam[0][0] = lam[0][1] = lam[0][2] = 1.0 / 3;
      return 1;
    case S21:
      for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
          lam[i][k] = (k == i) ? 1 - 2 * a : a;
      return 3;
    case S111:
      c = 1 - a - b;
      {
        static const int perm[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 },
                                        { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
        double v[3] = { a, b, c };
        for (int i = 0; i < 6; i++)
          for (int k = 0; k < 3; k++)
            lam[i][k] = v[perm[i][k]];
      }
      return 6;
    case S4:
      lam[0][0] = lam[0][1] = lam[0][2] = lam[0][3] = 0.25;
      return 1;
    case S31:
      for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
          lam[i][k] = (k == i) ? 1 - 3 * a : a;
      return 4;
    case S22:
      {
        static const int pair[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 },
                                        { 1, 2 }, { 1, 3 }, { 2, 3 } };
        for (int i = 0; i < 6; i++)
          for (int k = 0; k < 4; k++)
            lam[i][k] = (k == pair[i][0] || k == pair[i][1]) ? a : 0.5 - a;
      }
      return 6;
    }
  return 0;
}

/* Expand a symmetric rule: xi_k = lambda_{k+1}, w = measure * weight. */
static lac_quad *
rule_symmetric (lac_shape shape, int dim, const sym_rule *s)
{
  lac_quad *q = quad_new (shape, dim, s->degree, s->npts);
  double meas = lac_quad_ref_measure (shape), lam[24][4] = { { 0 } };
  int p = 0;
  if (q == NULL)
    return NULL;
  for (int o = 0; o < s->norb; o++)
    {
      int m = orbit_points (&s->orb[o], lam);
      for (int i = 0; i < m; i++, p++)
        {
          for (int k = 0; k < dim; k++)
            q->xi[p * dim + k] = lam[i][k + 1];
          q->w[p] = meas * s->orb[o].w;
        }
    }
  if (p != s->npts)
    {
      lac_quad_free (q);
      LAC_ERROR_NULL (LAC_ESANITY, "rule of degree %d: %d points, not %d",
                      s->degree, p, s->npts);
    }
  return q;
}

/* lac_quad_alloc: the cheapest rule known here exact to `degree`. */
lac_quad *
lac_quad_alloc (lac_shape shape, int degree)
{
  int maxdeg = lac_quad_max_degree (shape);
  if (maxdeg < 0)
    LAC_ERROR_NULL (LAC_EINVAL, "unknown shape %d", (int) shape);
  if (degree < 0 || degree > maxdeg)
    LAC_ERROR_NULL (LAC_EINVAL, "degree %d out of range 0..%d", degree,
                    maxdeg);
  switch (shape)
    {
    case LAC_SHAPE_LINE: return rule_tensor (shape, 1, degree);
    case LAC_SHAPE_QUAD: return rule_tensor (shape, 2, degree);
    case LAC_SHAPE_HEX: return rule_tensor (shape, 3, degree);
    case LAC_SHAPE_TRI:
      for (int i = 0; i < NTRI_RULES; i++)
        if (tri_rules[i].degree >= degree)
          return rule_symmetric (shape, 2, &tri_rules[i]);
      return rule_collapsed (shape, degree);
    case LAC_SHAPE_TET:
      for (int i = 0; i < NTET_RULES; i++)
        if (tet_rules[i].degree >= degree)
          return rule_symmetric (shape, 3, &tet_rules[i]);
      return rule_collapsed (shape, degree);
    case LAC_SHAPE_PYR:
      return rule_collapsed (shape, degree);
    }
  return NULL;
}

/* ---- a cache of rules -------------------------------------------------- */

/* The slot of the cache for a degree asked on shape. */
static int
cache_degree (lac_shape shape, int degree)
{
  int maxdeg = lac_quad_max_degree (shape);
  if (maxdeg >= 0 && degree > maxdeg)
    degree = maxdeg;                    /* the best rule there is */
  if (degree > LAC_QUAD_CACHE_MAXDEG)
    degree = LAC_QUAD_CACHE_MAXDEG;
  return degree < 0 ? 0 : degree;
}

const lac_quad *
lac_quad_cache_get (lac_quad_cache *qc, lac_shape shape, int degree)
{
  degree = cache_degree (shape, degree);
  if (!qc->q[shape][degree])
    qc->q[shape][degree] = lac_quad_alloc (shape, degree);  /* message set */
  return qc->q[shape][degree];
}

static void
table_free (lac_quad_table *t)
{
  if (!t)
    return;
  lac_free (t->N);
  lac_free (t->dN);
  lac_free (t);
}

static lac_quad_table *
table_make (const lac_refelem *re, const lac_quad *q)
{
  size_t nen = (size_t) re->nnodes, d = (size_t) re->dim, n = (size_t) q->n;
  lac_quad_table *t = lac_calloc (1, sizeof *t);
  if (t)
    {
      t->q = q;
      t->N = lac_malloc (n * nen * sizeof *t->N);
      t->dN = lac_malloc (n * nen * d * sizeof *t->dN);
    }
  if (!t || !t->N || !t->dN)
    {
      table_free (t);
      LAC_ERROR_NULL (LAC_ENOMEM, "shape functions of %s at %zu points",
                      re->name, n);
    }
  for (size_t p = 0; p < n; p++)
    lac_refelem_eval (re, q->xi + p * d, t->N + p * nen, t->dN + p * nen * d);
  return t;
}

const lac_quad_table *
lac_quad_cache_table (lac_quad_cache *qc, const lac_refelem *re, int degree)
{
  const lac_quad *q = lac_quad_cache_get (qc, re->shape, degree);
  if (!q)
    return NULL;
  lac_quad_table **t = &qc->t[re->type][cache_degree (re->shape, degree)];
  if (!*t)
    *t = table_make (re, q);       /* message set */
  return *t;
}

void
lac_quad_cache_free (lac_quad_cache *qc)
{
  for (int s = 0; s <= LAC_SHAPE_PYR; s++)
    for (int d = 0; d <= LAC_QUAD_CACHE_MAXDEG; d++)
      lac_quad_free (qc->q[s][d]);
  for (int e = 0; e < LAC_NELEM_TYPES; e++)
    for (int d = 0; d <= LAC_QUAD_CACHE_MAXDEG; d++)
      table_free (qc->t[e][d]);
  memset (qc, 0, sizeof *qc);
}
