/* t405: dense, UMFPACK and CHOLMOD give the same elasticity solution
 *       (1e-10 relative) on small 2D and 3D problems              [LAC (8)]
 *
 * A block clamped on xmin, pressed on xmax, with a volume force: plane
 * strain (quad8), axisymmetric (tri6, away from the axis) and 3D (hex8).
 */
#include <math.h>
#include <stdio.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

static void
gravity (const double *x, void *ctx, double *out)
{
  int dim = *(const int *) ctx;
  (void) x;
  for (int i = 0; i < dim; i++)
    out[i] = 0.0;
  out[dim - 1] = -0.5;                  /* f = -0.5 e_y (e_z in 3D) */
}

static void
run (lac_elem_type type, lac_model model, const size_t *n)
{
  const lac_refelem *re = lac_refelem_get (type);
  const char *name = re->name;
  int dim = lac_model_dim (model);
  double L[3] = { 2.0, 1.0, 1.0 };
  lac_mesh *m = NULL;
  int status = lac_mesh_box (type, n, L, 0.1, &m);
  check_status (status, LAC_SUCCESS, "%s: box", name);
  if (status)
    return;
  if (model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      m->x[2 * a] += 1.0;                 /* r in [1, 3] */
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_calloc (ndof, sizeof *F);
  double *u[3];
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = 1000.0;
      nu[c] = 0.3;
    }
  lac_elastic mat = { model, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_dirichlet *d = lac_dirichlet_alloc ();
  check_status (lac_assembly_stiffness (m, &mat, T), LAC_SUCCESS,
                "%s: stiffness", name);
  check_status (lac_assembly_pressure (m, model, lac_mesh_group (m, "xmax"),
                                       10.0, F), LAC_SUCCESS, "%s: pressure",
                name);
  check_status (lac_assembly_volume_force (m, model, NULL, gravity, &dim, F),
                LAC_SUCCESS, "%s: volume force", name);
  for (int i = 0; i < dim; i++)
    check_status (lac_dirichlet_add_group (d, m, lac_mesh_group (m, "xmin"),
                                           i, 0.0), LAC_SUCCESS,
                  "%s: clamp", name);
  lac_csc *K = lac_csc_from_triplet (T);
  check_status (lac_dirichlet_apply (d, K, F), LAC_SUCCESS, "%s: apply", name);

  const lac_solver_kind kinds[3] = { LAC_SOLVER_DENSE, LAC_SOLVER_UMFPACK,
                                     LAC_SOLVER_CHOLMOD };
  for (int k = 0; k < 3; k++)
    {
      u[k] = lac_calloc (ndof, sizeof *u[k]);
      lac_solver *s = lac_solver_alloc (kinds[k]);
      status = lac_solver_factor (s, K);
      if (!status)
        status = lac_solver_solve (s, F, u[k]);
      check_status (status, LAC_SUCCESS, "%s: solve with %s", name,
                    lac_solver_kind_name (kinds[k]));
      lac_solver_free (s);
    }
  double umax = 0.0, d1 = 0.0, d2 = 0.0;
  for (size_t i = 0; i < ndof; i++)
    {
      umax = fmax (umax, fabs (u[0][i]));
      d1 = fmax (d1, fabs (u[1][i] - u[0][i]));
      d2 = fmax (d2, fabs (u[2][i] - u[0][i]));
    }
  check_true (umax > 1e-3, "%s: non-trivial solution (max |u| = %g)", name,
              umax);
  check_true (d1 <= 1e-10 * umax, "%s: umfpack - dense = %.3e (max |u| %.3e)",
              name, d1, umax);
  check_true (d2 <= 1e-10 * umax, "%s: cholmod - dense = %.3e (max |u| %.3e)",
              name, d2, umax);
  for (int k = 0; k < 3; k++)
    lac_free (u[k]);
  lac_csc_free (K);
  lac_dirichlet_free (d);
  lac_triplet_free (T);
  lac_free (F);
  lac_free (nu);
  lac_free (E);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  const size_t n2[2] = { 6, 3 }, n3[3] = { 4, 2, 2 };
  run (LAC_QUAD8, LAC_PLANE_STRAIN, n2);
  run (LAC_TRI6, LAC_AXISYMMETRIC, n2);
  run (LAC_HEX8, LAC_SOLID3D, n3);
  lac_finalize ();
  return check_summary ();
}
