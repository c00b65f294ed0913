/* t432: homogeneous uniaxial stretch of a neo-Hookean bar against the
 *       closed form                                         [LAC §5.4]
 *
 * F = diag(l, t, t) (3D) or diag(l, t, 1) (plane strain), with the lateral
 * stretch t chosen so that the lateral faces are traction free:
 *   3D             P_22 = 0  <=>  mu (t^2 - 1) + lambda ln(l t^2) = 0,
 *   plane strain   P_22 = 0  <=>  mu (t^2 - 1) + lambda ln(l t) = 0,
 * (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, lac_hyper.h), and then
 *   P_11 = mu (l - 1/l) + lambda ln J / l,   sigma_11 = P_11 l / J,
 *   plane strain: sigma_33 = lambda ln J / J.
 * The field u = (F - I) X is imposed on a distorted box mesh; the nodal
 * internal forces must vanish at interior nodes, sum to P_11 |face| on the
 * face x = L and to zero on y = L; the Cauchy stress is the closed form
 * everywhere (1e-10 rel).  Also: for l = 1 + 1e-7, P_11 / (l - 1) = E.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "fem/lac_hyper.h"
#include "base/lac_status.h"

#define E0 1000.0
#define NU0 0.3

/* The lateral stretch t (Newton on the scalar equation above). */
static double
lateral (double l, double lam, double mu, int dim)
{
  double t = 1.0;
  for (int it = 0; it < 50; it++)
    {
      double J = dim == 3 ? l * t * t : l * t;
      double g = mu * (t * t - 1) + lam * log (J);
      double dg = 2 * mu * t + lam * (dim == 3 ? 2 / t : 1 / t);
      t -= g / dg;
    }
  return t;
}

static void
stretch (lac_elem_type type, double l)
{
  const lac_refelem *re = lac_refelem_get (type);
  int dim = re->dim;
  size_t n[3] = { 3, 2, 2 };
  double L[3] = { 3, 2, 2 }, lam, mu;
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (type, n, L, 0.2, &m), LAC_SUCCESS, "box");
  if (!m)
    return;
  lac_hyper_lame (E0, NU0, &lam, &mu);
  double t = lateral (l, lam, mu, dim);
  double J = dim == 3 ? l * t * t : l * t;
  double P11 = mu * (l - 1 / l) + lam * log (J) / l;
  double s11 = P11 * l / J, s33 = dim == 2 ? lam * log (J) / J : 0.0;
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells * sizeof *nu);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = E0, nu[c] = NU0;
  lac_hyper h = { dim == 3 ? LAC_SOLID3D : LAC_PLANE_STRAIN, E, nu, NULL, 0 };
  double *u = calloc (ndof, sizeof *u), *f = calloc (ndof, sizeof *f);
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; i < dim; i++)
      u[a * dim + i] = ((i == 0 ? l : t) - 1) * m->x[a * dim + i];
  check_status (lac_hyper_assemble (m, &h, u, f, NULL), LAC_SUCCESS, "assemble");
  /* forces on the faces x = L (sum), y = L (sum), interior (max) */
  char *bnd = calloc (m->nnodes, 1);
  double fx = 0, fy = 0, fin = 0;
  const lac_group *gx = lac_mesh_group (m, "xmax"), *gy = lac_mesh_group (m, "ymax");
  for (size_t g = 0; g < m->ngroups; g++)
    if (m->group[g].dim == dim - 1)
      for (size_t k = 0; k < m->group[g].nnodes; k++)
        bnd[m->group[g].node[k]] = 1;
  for (size_t k = 0; k < gx->nnodes; k++)
    fx += f[gx->node[k] * dim];
  for (size_t k = 0; k < gy->nnodes; k++)
    fy += f[gy->node[k] * dim + 1];
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; i < dim && !bnd[a]; i++)
      fin = fmax (fin, fabs (f[a * dim + i]));
  double A0 = dim == 3 ? L[1] * L[2] : L[1];
  check_rel (fx, P11 * A0, 1e-10, "%s l=%g: sum f_x on x = L", re->name, l);
  check_abs (fy, 0.0, 1e-10 * fabs (P11) * A0, "%s: sum f_y on y = L", re->name);
  check_abs (fin, 0.0, 1e-10 * fabs (P11) * A0, "%s: interior forces", re->name);
  /* Cauchy stress at a point of every cell */
  double xi[3] = { 0.1, 0.2, 0.15 }, s[6], err = 0;
  for (size_t c = 0; c < m->ncells; c++)
    {
      lac_hyper_cauchy_at (m, &h, u, c, xi, s);
      err = fmax (err, fabs (s[0] - s11));
      err = fmax (err, fabs (s[1]));
      err = fmax (err, fabs (s[2] - s33));
      err = fmax (err, fabs (s[3]));
    }
  check_true (err <= 1e-10 * fabs (s11), "%s l=%g: Cauchy stress error %.2e of"
              " sigma_11 = %g", re->name, l, err, s11);
  free (bnd);
  free (u);
  free (f);
  free (E);
  free (nu);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  const lac_elem_type types[] = { LAC_QUAD4, LAC_TRI6, LAC_QUAD8, LAC_HEX8,
                                  LAC_TET10, LAC_HEX20, LAC_HEX27 };
  for (size_t i = 0; i < sizeof types / sizeof *types; i++)
    {
      stretch (types[i], 1.6);       /* tension */
      stretch (types[i], 0.5);       /* compression */
    }
  /* the small-strain limit of the law: P_11 / (l - 1) -> E */
  double lam, mu, l = 1 + 1e-7;
  lac_hyper_lame (E0, NU0, &lam, &mu);
  double t = lateral (l, lam, mu, 3), Fm[9] = { l, 0, 0, 0, t, 0, 0, 0, t }, P[9];
  lac_hyper_stress (LAC_LAW_NEO_HOOKEAN, E0, NU0, Fm, P, NULL);
  check_rel (P[0] / (l - 1), E0, 1e-6, "small stretch: P_11 / (l - 1) = E");
  check_rel ((1 - t) / (l - 1), NU0, 1e-6, "small stretch: Poisson ratio");
  lac_finalize ();
  return check_summary ();
}
