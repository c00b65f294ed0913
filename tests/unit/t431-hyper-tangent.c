/* t431: hyperelastic cells -- the tangent is the derivative of the internal
 *       force, rigid rotations are stress free, and the small-strain limit
 *       is linear elasticity                                [LAC §4.5, §5.4]
 *
 * For both laws (neo-Hookean, Saint Venant-Kirchhoff) and every cell type:
 *   1. A = dP/dF of the law against central differences of P (1e-6 rel);
 *   2. K_T(u) of a cell against central differences of its internal force
 *      at a random displacement of 10 % of the cell size (1e-6 rel);
 *   3. objectivity: u = (R - I) X with R a 40 degree rotation gives
 *      F_int = 0 (1e-11 of the force scale E h^2);
 *   4. K_T(0) equals lac_assembly_cell_stiffness (1e-10 rel) on distorted
 *      straight-sided cells (the same quadrature), 3D, plane strain and
 *      axisymmetric.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "fem/lac_hyper.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

#define E0 300.0
#define NU0 0.3

static double
frand (unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 65535.0 - 0.5;       /* in [-1/2, 1/2] */
}

/* 1. the law's tangent against differences of P */
static void
law_fd (lac_law law)
{
  unsigned seed = 7;
  double F[9], P[9], A[81], Pp[9], Pm[9], h = 1e-6, err = 0, amax = 0;
  for (int i = 0; i < 9; i++)
    F[i] = (i % 4 == 0) + 0.4 * frand (&seed);
  check_status (lac_hyper_stress (law, E0, NU0, F, P, A), LAC_SUCCESS, "law");
  for (int kL = 0; kL < 9; kL++)
    {
      double Fp[9], Fm[9];
      memcpy (Fp, F, sizeof F);
      memcpy (Fm, F, sizeof F);
      Fp[kL] += h;
      Fm[kL] -= h;
      lac_hyper_stress (law, E0, NU0, Fp, Pp, NULL);
      lac_hyper_stress (law, E0, NU0, Fm, Pm, NULL);
      for (int iJ = 0; iJ < 9; iJ++)
        {
          double fd = (Pp[iJ] - Pm[iJ]) / (2 * h);
          err = fmax (err, fabs (fd - A[iJ * 9 + kL]));
          amax = fmax (amax, fabs (A[iJ * 9 + kL]));
        }
    }
  check_true (err <= 1e-6 * amax, "%s: |A - dP/dF| = %.2e of %.2e",
              lac_law_name (law), err, amax);
  double Fbad[9] = { -1, 0, 0, 0, 1, 0, 0, 0, 1 };
  check_status (lac_hyper_stress (law, E0, NU0, Fbad, P, A), LAC_ESING,
                "%s: det F < 0", lac_law_name (law));
}

/* A one-pyramid mesh (lac_mesh_box has none). */
static lac_mesh *
pyramid (void)
{
  static const double x[15] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                0.5, 0.5, 0.8 };
  lac_mesh *m = lac_mesh_alloc (3, 5, 1, 5);
  memcpy (m->x, x, sizeof x);
  for (int a = 0; a < 5; a++)
    {
      m->conn[a] = a;
      m->node_tag[a] = (size_t) a + 1;
    }
  m->type[0] = LAC_PYR5;
  m->ptr[1] = 5;
  m->cell_tag[0] = 1;
  m->body[0] = 0;
  return m;
}

static lac_mesh *
small_mesh (lac_elem_type t, double distort)
{
  if (t == LAC_PYR5)
    return pyramid ();
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 2, 2, 2 };
  double L[3] = { 2, 1.5, 1 };
  lac_mesh *m = NULL;
  lac_mesh_box (t, n, L, distort, &m);
  if (m && re->dim == 2)
    for (size_t a = 0; a < m->nnodes; a++)
      m->x[2 * a] += 1.0;                   /* r in [1, 3] (axisymmetric) */
  return m;
}

/* 2. and 3. for cell 0 of a small mesh */
static void
cell_fd (lac_elem_type t, lac_model model, lac_law law)
{
  const char *tn = lac_refelem_get (t)->name;
  lac_mesh *m = small_mesh (t, 0.15);
  check_true (m != NULL, "%s mesh", tn);
  if (!m)
    return;
  int dim = m->dim, nen = (int) (m->ptr[1] - m->ptr[0]), nc = nen * dim;
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells * sizeof *nu);
  char *lw = malloc (m->ncells);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = E0, nu[c] = NU0, lw[c] = (char) law;
  lac_hyper h = { model, E, nu, lw, 0 };
  double *u = calloc (ndof, sizeof *u), *Ke = malloc ((size_t) (nc * nc) * sizeof *Ke);
  double fp[LAC_MAX_NODES * 3], fm[LAC_MAX_NODES * 3], fe[LAC_MAX_NODES * 3];
  unsigned seed = 11;
  for (size_t j = 0; j < ndof; j++)
    u[j] = 0.1 * frand (&seed);
  check_status (lac_hyper_cell (m, &h, 0, u, NULL, Ke), LAC_SUCCESS, "%s Ke", tn);
  double err = 0, kmax = 0, step = 1e-6;
  const int *conn = m->conn + m->ptr[0];
  for (int b = 0; b < nen; b++)
    for (int k = 0; k < dim; k++)
      {
        size_t g = (size_t) dim * (size_t) conn[b] + (size_t) k;
        double u0 = u[g];
        memset (fp, 0, sizeof fp);
        memset (fm, 0, sizeof fm);
        u[g] = u0 + step;
        lac_hyper_cell (m, &h, 0, u, fp, NULL);
        u[g] = u0 - step;
        lac_hyper_cell (m, &h, 0, u, fm, NULL);
        u[g] = u0;
        for (int r = 0; r < nc; r++)
          {
            double fd = (fp[r] - fm[r]) / (2 * step);
            err = fmax (err, fabs (fd - Ke[r * nc + b * dim + k]));
            kmax = fmax (kmax, fabs (Ke[r * nc + b * dim + k]));
          }
      }
  check_true (err <= 1e-6 * kmax, "%s %s %s: |K_T - dF/du| = %.2e of %.2e",
              tn, lac_model_name (model), lac_law_name (law), err, kmax);

  /* 3. a rigid rotation by 40 degrees about (1, 2, 3)/|.| (3D), or in the
   * plane; plane strain only (an axisymmetric rotation is not rigid) */
  if (model != LAC_AXISYMMETRIC)
    {
      double th = 40.0 * 3.14159265358979323846 / 180, R[9], n[3] = { 1, 2, 3 }, s = sqrt (14.0);
      for (int i = 0; i < 3; i++)
        n[i] /= s;
      if (dim == 2)
        n[0] = n[1] = 0, n[2] = 1;
      double c = cos (th), sn = sin (th);
      for (int i = 0; i < 3; i++)          /* Rodrigues */
        for (int j = 0; j < 3; j++)
          R[i * 3 + j] = (i == j) * c + (1 - c) * n[i] * n[j];
      R[1] -= sn * n[2]; R[2] += sn * n[1]; R[3] += sn * n[2];
      R[5] -= sn * n[0]; R[6] -= sn * n[1]; R[7] += sn * n[0];
      for (size_t a = 0; a < m->nnodes; a++)
        for (int i = 0; i < dim; i++)
          {
            double y = 0;
            for (int k = 0; k < dim; k++)
              y += R[i * 3 + k] * m->x[a * (size_t) dim + (size_t) k];
            u[a * (size_t) dim + (size_t) i] = y - m->x[a * (size_t) dim + (size_t) i];
          }
      memset (fe, 0, sizeof fe);
      check_status (lac_hyper_cell (m, &h, 0, u, fe, NULL), LAC_SUCCESS, "%s rot", tn);
      double fmax_ = 0;
      for (int r = 0; r < nc; r++)
        fmax_ = fmax (fmax_, fabs (fe[r]));
      check_true (fmax_ <= 1e-11 * E0, "%s %s: rigid rotation, |F_int| = %.2e",
                  tn, lac_law_name (law), fmax_);
    }
  free (u);
  free (Ke);
  free (E);
  free (nu);
  free (lw);
  lac_mesh_free (m);
}

/* 4. K_T(0) = the linear stiffness, on every cell of a distorted mesh */
static void
small_strain (lac_elem_type t, lac_model model)
{
  const char *tn = lac_refelem_get (t)->name;
  lac_mesh *m = small_mesh (t, 0.2);
  if (!m)
    return;
  int dim = m->dim;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells * sizeof *nu);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = E0 * (1 + 0.1 * (double) c), nu[c] = NU0;
  size_t ncmax = LAC_MAX_NODES * 3;
  double *K1 = malloc (ncmax * ncmax * sizeof *K1), *K2 = malloc (ncmax * ncmax * sizeof *K2);
  lac_elastic el = { model, E, nu };
  double err = 0, kmax = 0;
  for (int law = 0; law < 2; law++)
    {
      char *lw = malloc (m->ncells);
      memset (lw, law, m->ncells);
      lac_hyper h = { model, E, nu, lw, 0 };
      for (size_t c = 0; c < m->ncells; c++)
        {
          int nc = (int) (m->ptr[c + 1] - m->ptr[c]) * dim;
          check_status (lac_assembly_cell_stiffness (m, &el, c, K1), LAC_SUCCESS, "lin");
          check_status (lac_hyper_cell (m, &h, c, NULL, NULL, K2), LAC_SUCCESS, "hyp");
          for (int i = 0; i < nc * nc; i++)
            {
              err = fmax (err, fabs (K1[i] - K2[i]));
              kmax = fmax (kmax, fabs (K1[i]));
            }
        }
      free (lw);
    }
  check_true (err <= 1e-10 * kmax, "%s %s: |K_T(0) - K| = %.2e of %.2e", tn,
              lac_model_name (model), err, kmax);
  free (K1);
  free (K2);
  free (E);
  free (nu);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  law_fd (LAC_LAW_NEO_HOOKEAN);
  law_fd (LAC_LAW_LINEAR);
  const lac_elem_type t2[] = { LAC_TRI3, LAC_QUAD4, LAC_TRI6, LAC_QUAD8, LAC_QUAD9 };
  const lac_elem_type t3[] = { LAC_TET4, LAC_HEX8, LAC_TET10, LAC_HEX20,
                               LAC_HEX27, LAC_PYR5 };
  for (int law = 0; law < 2; law++)
    {
      for (size_t i = 0; i < sizeof t2 / sizeof *t2; i++)
        {
          cell_fd (t2[i], LAC_PLANE_STRAIN, (lac_law) law);
          cell_fd (t2[i], LAC_AXISYMMETRIC, (lac_law) law);
        }
      for (size_t i = 0; i < sizeof t3 / sizeof *t3; i++)
        cell_fd (t3[i], LAC_SOLID3D, (lac_law) law);
    }
  for (size_t i = 0; i < sizeof t2 / sizeof *t2; i++)
    {
      small_strain (t2[i], LAC_PLANE_STRAIN);
      small_strain (t2[i], LAC_AXISYMMETRIC);
    }
  for (size_t i = 0; i < sizeof t3 / sizeof *t3; i++)
    small_strain (t3[i], LAC_SOLID3D);
  lac_finalize ();
  return check_summary ();
}
