/* lac_exact.c -- the analytic solutions (see lac_exact.h)          [LAC §5]
 *
 * Solutions known to the code (the [exact] section of a scene):
 *   thick_sphere    hollow sphere a <= R <= b under inner pressure p, outer
 *                   surface free (Lame; Timoshenko & Goodier, Theory of
 *                   Elasticity, 3rd ed., §137):
 *                     u_R = p a^3 / (E (b^3 - a^3))
 *                           ((1 - 2 nu) R + (1 + nu) b^3 / (2 R^2))
 *   thick_cylinder  hollow cylinder a <= r <= b in plane strain (ibid.,
 *                   §28):
 *                     u_r = (1 + nu) p a^2 / (E (b^2 - a^2))
 *                           ((1 - 2 nu) r + b^2 / r)
 * Both are u = g(R) x with g = C1 + C2 / R^k (k = 3, 2), so their
 * gradient is g I + g'(R) x x^T / R.
 *   taylor          the Taylor patch test [LAC §5.1]: a uniform stress,
 *                   sigma = -p on the vertical axis (y in 2D, z in 3D),
 *                   every other component zero but the plane-strain
 *                   sigma_zz = -nu p; u_i = c_i x_i vanishes on the
 *                   symmetry planes x_i = 0.  The contact pressure is
 *                   lambda = -p on every horizontal interface.
 *   taylor_shear    the frictional patch test: taylor's stress plus the
 *                   shear sigma_xv = tau (v the vertical axis, y in 2D, z
 *                   in 3D), u = diag(c) x + (tau / G) x_v e_x (the
 *                   rotation that keeps u_v free of x): the contact
 *                   tractions are lambda_n = -p and tau along the
 *                   interface on every horizontal one.
 *   biaxial         a uniform stress sigma_xx = sigma_yy = -p, every other
 *                   component zero but the plane-strain sigma_zz =
 *                   -2 nu p (plane strain, 3D); u_i = c_i x_i as above.
 *                   The contact pressure is lambda = -p on every interface
 *                   normal to x or y: a body pressed into an inner corner.
 *   manufactured2d  the paper's 2D manufactured solution [LAC §5.3]:
 *                     u_x = -0.2 y^3 (x - 1/2),
 *                     u_y = -0.05 (x - 1/2)^2 (1 + y) - 0.01 y,
 *                   which closes the gap to y <= -0.05 (x-1/2)^2 on y = 0
 *   manufactured3d  u_x = u_y = 0.2 x y z^2,
 *                   u_z = -0.2 (1 + x^2 + y^2)(1 + 0.01 z) - 0.01 z - 0.3,
 *                   which closes the gap to z <= -0.2 (1+x^2+y^2) - 0.3
 * The manufactured ones carry their second derivatives, from which the
 * body force f = -div sigma = -[(l+m) grad div u + m lap u] follows for
 * any E, nu (Lame l, m; the paper takes E = 1, nu = 0).
 *
 * Adding a solution: a setup (coefficients from the parameters), u and
 * grad u (or reuse the radial ones), and one line in lac_exact_table.
 */
#include "fem/lac_exact.h"

#include <math.h>
#include <string.h>

/* ---- radial solutions u = g(R) x -------------------------------------- */

double
lac_exact_radius (const lac_exact *e, const double *x)
{
  double R2 = 0;
  for (int i = 0; i < e->nr; i++)
    R2 += x[i] * x[i];
  return sqrt (R2);
}

static void
radial_u (const lac_exact *e, const double *x, double *out)
{
  double R = lac_exact_radius (e, x), g = e->C1 + e->C2 / pow (R, e->k);
  for (int i = 0; i < e->dim; i++)
    out[i] = i < e->nr ? g * x[i] : 0.0;              /* u = g(R) x */
}

static void
radial_grad (const lac_exact *e, const double *x, double *out)
{
  double R = lac_exact_radius (e, x), g = e->C1 + e->C2 / pow (R, e->k);
  double gp = -e->k * e->C2 / pow (R, e->k + 1);      /* g'(R) */
  for (int i = 0; i < e->dim; i++)
    for (int j = 0; j < e->dim; j++)
      out[i * e->dim + j] = (i < e->nr && j < e->nr)
        ? (i == j ? g : 0.0) + gp * x[i] * x[j] / R : 0.0;
}

static void
sphere_setup (lac_exact *e)
{
  double a = e->par.a, b = e->par.b, p = e->par.p, E = e->par.E;
  double nu = e->par.nu, c = p * a * a * a / (E * (b * b * b - a * a * a));
  e->nr = e->dim;
  e->k = 3;
  e->C1 = c * (1 - 2 * nu);
  e->C2 = c * (1 + nu) * b * b * b / 2;
}

static void
cylinder_setup (lac_exact *e)
{
  double a = e->par.a, b = e->par.b, p = e->par.p, E = e->par.E;
  double nu = e->par.nu, c = (1 + nu) * p * a * a / (E * (b * b - a * a));
  e->nr = 2;
  e->k = 2;
  e->C1 = c * (1 - 2 * nu);
  e->C2 = c * b * b;
}

/* ---- linear solutions u_i = c_i x_i ----------------------------------- */

static void
linear_u (const lac_exact *e, const double *x, double *out)
{
  for (int i = 0; i < e->dim; i++)
    out[i] = e->c[i] * x[i];                          /* u = diag(c) x */
}

static void
linear_grad (const lac_exact *e, const double *x, double *out)
{
  (void) x;
  for (int i = 0; i < e->dim; i++)
    for (int j = 0; j < e->dim; j++)
      out[i * e->dim + j] = i == j ? e->c[i] : 0.0;
}

/* Strains of sigma = -p e_v e_v^T (v the last axis), Hooke's law. */
static void
taylor_setup (lac_exact *e)
{
  double p = e->par.p, E = e->par.E, nu = e->par.nu;
  if (e->model == LAC_PLANE_STRAIN)           /* eps_zz = 0 */
    {
      e->c[0] = nu * (1 + nu) * p / E;
      e->c[1] = -(1 - nu * nu) * p / E;
    }
  else                                        /* axisymmetric: (r, z); 3D */
    {
      for (int i = 0; i < e->dim - 1; i++)
        e->c[i] = nu * p / E;
      e->c[e->dim - 1] = -p / E;
    }
}

/* taylor's strains and the shear strain gamma = tau / G. */
static void
shear_setup (lac_exact *e)
{
  taylor_setup (e);
  e->gamma = e->par.tau * 2 * (1 + e->par.nu) / e->par.E;
}

static void
shear_u (const lac_exact *e, const double *x, double *out)
{
  linear_u (e, x, out);
  out[0] += e->gamma * x[e->dim - 1];                /* gamma x_v e_x */
}

static void
shear_grad (const lac_exact *e, const double *x, double *out)
{
  linear_grad (e, x, out);
  out[e->dim - 1] += e->gamma;                       /* du_x / dx_v */
}

/* Strains of sigma = -p (e_x e_x^T + e_y e_y^T), Hooke's law. */
static void
biaxial_setup (lac_exact *e)
{
  double p = e->par.p, E = e->par.E, nu = e->par.nu;
  if (e->model == LAC_PLANE_STRAIN)           /* eps_zz = 0 */
    e->c[0] = e->c[1] = -(1 + nu) * (1 - 2 * nu) * p / E;
  else                                        /* 3D: sigma_zz = 0 */
    {
      e->c[0] = e->c[1] = -(1 - nu) * p / E;
      e->c[2] = 2 * nu * p / E;
    }
}

/* ---- manufactured solutions [LAC §5.3] -------------------------------- */

static void
mfd2_u (const lac_exact *e, const double *x, double *u)
{
  (void) e;
  double a = x[0] - 0.5, y = x[1];
  u[0] = -0.2 * y * y * y * a;
  u[1] = -0.05 * a * a * (1 + y) - 0.01 * y;
}

static void
mfd2_grad (const lac_exact *e, const double *x, double *g)
{
  (void) e;
  double a = x[0] - 0.5, y = x[1];
  g[0] = -0.2 * y * y * y;               /* du_x/dx */
  g[1] = -0.6 * y * y * a;               /* du_x/dy */
  g[2] = -0.1 * a * (1 + y);             /* du_y/dx */
  g[3] = -0.05 * a * a - 0.01;           /* du_y/dy */
}

static void
mfd2_hess (const lac_exact *e, const double *x, double *h)
{
  (void) e;
  double a = x[0] - 0.5, y = x[1];
  h[0] = 0;                h[1] = -0.6 * y * y;       /* u_x: xx xy */
  h[2] = -0.6 * y * y;     h[3] = -1.2 * y * a;       /*      yx yy */
  h[4] = -0.1 * (1 + y);   h[5] = -0.1 * a;           /* u_y: xx xy */
  h[6] = -0.1 * a;         h[7] = 0;                  /*      yx yy */
}

static void
mfd3_u (const lac_exact *e, const double *x, double *u)
{
  (void) e;
  double X = x[0], Y = x[1], Z = x[2];
  u[0] = u[1] = 0.2 * X * Y * Z * Z;
  u[2] = -0.2 * (1 + X * X + Y * Y) * (1 + 0.01 * Z) - 0.01 * Z - 0.3;
}

static void
mfd3_grad (const lac_exact *e, const double *x, double *g)
{
  (void) e;
  double X = x[0], Y = x[1], Z = x[2];
  for (int i = 0; i < 2; i++)            /* u_x and u_y are equal */
    {
      g[3 * i + 0] = 0.2 * Y * Z * Z;
      g[3 * i + 1] = 0.2 * X * Z * Z;
      g[3 * i + 2] = 0.4 * X * Y * Z;
    }
  g[6] = -0.4 * X * (1 + 0.01 * Z);
  g[7] = -0.4 * Y * (1 + 0.01 * Z);
  g[8] = -0.002 * (1 + X * X + Y * Y) - 0.01;
}

static void
mfd3_hess (const lac_exact *e, const double *x, double *h)
{
  (void) e;
  double X = x[0], Y = x[1], Z = x[2];
  for (int i = 0; i < 2; i++)
    {
      double *q = h + 9 * i;             /* d2 u_i / dx_j dx_k */
      q[0] = 0;            q[1] = 0.2 * Z * Z;  q[2] = 0.4 * Y * Z;
      q[3] = 0.2 * Z * Z;  q[4] = 0;            q[5] = 0.4 * X * Z;
      q[6] = 0.4 * Y * Z;  q[7] = 0.4 * X * Z;  q[8] = 0.4 * X * Y;
    }
  double *q = h + 18;
  q[0] = -0.4 * (1 + 0.01 * Z);  q[1] = 0;                      q[2] = -0.004 * X;
  q[3] = 0;                      q[4] = -0.4 * (1 + 0.01 * Z);  q[5] = -0.004 * Y;
  q[6] = -0.004 * X;             q[7] = -0.004 * Y;             q[8] = 0;
}

static void
no_setup (lac_exact *e)
{
  (void) e;
}

/* ---- the table -------------------------------------------------------- */

#define M_PS (1u << LAC_PLANE_STRAIN)
#define M_AXI (1u << LAC_AXISYMMETRIC)
#define M_3D (1u << LAC_SOLID3D)

const lac_exact_solution lac_exact_table[] = {    /* lac_exact_kind order */
  { "thick_sphere", M_AXI | M_3D, "a b p E nu", sphere_setup, radial_u,
    radial_grad, NULL },
  { "thick_cylinder", M_PS | M_3D, "a b p E nu", cylinder_setup, radial_u,
    radial_grad, NULL },
  { "taylor", M_PS | M_AXI | M_3D, "p E nu", taylor_setup, linear_u,
    linear_grad, NULL },
  { "manufactured2d", M_PS, "E nu", no_setup, mfd2_u, mfd2_grad,
    mfd2_hess },
  { "manufactured3d", M_3D, "E nu", no_setup, mfd3_u, mfd3_grad,
    mfd3_hess },
  { "biaxial", M_PS | M_3D, "p E nu", biaxial_setup, linear_u, linear_grad,
    NULL },
  { "taylor_shear", M_PS | M_3D, "p tau E nu", shear_setup, shear_u,
    shear_grad, NULL },
  { NULL, 0, NULL, NULL, NULL, NULL, NULL }
};

int
lac_exact_count (void)
{
  int n = 0;
  while (lac_exact_table[n].name)
    n++;
  return n;
}

int
lac_exact_find (const char *name)
{
  for (int k = 0; lac_exact_table[k].name; k++)
    if (strcmp (lac_exact_table[k].name, name) == 0)
      return k;
  return LAC_EXACT_NONE;
}

const char *
lac_exact_name (int kind)
{
  return kind >= 0 && kind < lac_exact_count () ? lac_exact_table[kind].name
                                                : "none";
}

int
lac_exact_applies (int kind, lac_model model)
{
  return kind >= 0 && kind < lac_exact_count ()
         && (lac_exact_table[kind].models & (1u << model)) != 0;
}

void
lac_exact_init (lac_exact *e, int kind, lac_model model,
                const lac_exact_params *p)
{
  memset (e, 0, sizeof *e);
  e->kind = kind >= 0 && kind < lac_exact_count () ? kind : LAC_EXACT_NONE;
  e->model = model;
  e->dim = lac_model_dim (model);
  if (p)
    e->par = *p;
  if (e->kind != LAC_EXACT_NONE)
    lac_exact_table[e->kind].setup (e);
}

/* ---- evaluation ------------------------------------------------------- */

void
lac_exact_u (const double *x, void *ctx, double *u)
{
  const lac_exact *e = ctx;
  if (e->kind == LAC_EXACT_NONE)
    memset (u, 0, (size_t) e->dim * sizeof *u);
  else
    lac_exact_table[e->kind].u (e, x, u);
}

void
lac_exact_grad (const double *x, void *ctx, double *g)
{
  const lac_exact *e = ctx;
  if (e->kind == LAC_EXACT_NONE)
    memset (g, 0, (size_t) (e->dim * e->dim) * sizeof *g);
  else
    lac_exact_table[e->kind].grad (e, x, g);
}

/* sigma = D eps(u) with the Voigt strains of lac_material.h (engineering
 * shears; axisymmetric hoop strain u_r / r, its limit d u_r / d r on the
 * axis).  Zero if E, nu are not a valid material. */
void
lac_exact_sigma (const double *x, void *ctx, double *s)
{
  const lac_exact *e = ctx;
  double u[3], g[9], eps[6] = { 0 }, D[36];
  int d = e->dim, ns = lac_model_nstress (e->model);
  lac_exact_u (x, ctx, u);
  lac_exact_grad (x, ctx, g);
  eps[0] = g[0];
  eps[1] = g[d + 1];
  if (e->model == LAC_SOLID3D)
    {
      eps[2] = g[8];
      eps[3] = g[1] + g[3];
      eps[4] = g[5] + g[7];
      eps[5] = g[6] + g[2];
    }
  else
    {
      if (e->model == LAC_AXISYMMETRIC)     /* on the axis: d u_r / d r */
        eps[2] = x[0] > 0 ? u[0] / x[0] : g[0];
      eps[3] = g[1] + g[2];
    }
  for (int i = 0; i < ns; i++)
    s[i] = 0;
  if (lac_material_D (e->model, e->par.E, e->par.nu, D))
    return;
  for (int i = 0; i < ns; i++)
    for (int j = 0; j < ns; j++)
      s[i] += D[i * ns + j] * eps[j];
}

/* f = -div sigma = -[(l + m) grad(div u) + m lap u]  [LAC (1)], with the
 * Lame constants of the solution's material (plane strain: the same). */
void
lac_exact_force (const double *x, void *ctx, double *f)
{
  const lac_exact *e = ctx;
  int d = e->dim;
  double h[27];
  for (int i = 0; i < d; i++)
    f[i] = 0;
  if (e->kind == LAC_EXACT_NONE || !lac_exact_table[e->kind].hess)
    return;
  lac_exact_table[e->kind].hess (e, x, h);
  double E = e->par.E, nu = e->par.nu;
  double mu = E / (2 * (1 + nu)), la = E * nu / ((1 + nu) * (1 - 2 * nu));
  for (int i = 0; i < d; i++)
    {
      double graddiv = 0, lap = 0;
      for (int k = 0; k < d; k++)
        {
          graddiv += h[(k * d + k) * d + i];   /* d/dx_i (du_k/dx_k) */
          lap += h[(i * d + k) * d + k];       /* d2 u_i / dx_k^2 */
        }
      f[i] = -((la + mu) * graddiv + mu * lap);
    }
}

/* sigma n from the Voigt stress of the model. */
static void
sigma_times_n (int dim, const double *s, const double *n, double *t)
{
  if (dim == 2)
    {
      t[0] = s[0] * n[0] + s[3] * n[1];
      t[1] = s[3] * n[0] + s[1] * n[1];
      return;
    }
  t[0] = s[0] * n[0] + s[3] * n[1] + s[5] * n[2];
  t[1] = s[3] * n[0] + s[1] * n[1] + s[4] * n[2];
  t[2] = s[5] * n[0] + s[4] * n[1] + s[2] * n[2];
}

void
lac_exact_traction (const double *x, const double *n, void *ctx, double *t)
{
  const lac_exact *e = ctx;
  double s[6];
  lac_exact_sigma (x, ctx, s);
  sigma_times_n (e->dim, s, n, t);                         /* t = sigma n */
}

void
lac_exact_traction_tangential (const double *x, const double *n, void *ctx,
                               double *t)
{
  const lac_exact *e = ctx;
  double tn = 0;
  lac_exact_traction (x, n, ctx, t);
  for (int i = 0; i < e->dim; i++)
    tn += t[i] * n[i];
  for (int i = 0; i < e->dim; i++)
    t[i] -= tn * n[i];                          /* t - (n.t) n */
}

double
lac_exact_normal_stress (const lac_exact *e, const double *x, const double *n)
{
  double t[3], tn = 0;
  lac_exact_traction (x, n, (void *) e, t);
  for (int i = 0; i < e->dim; i++)
    tn += t[i] * n[i];
  return tn;
}
