/* t406: a body that is not fixed against rigid motions is reported as
 *       singular (LAC_ESING) by every solver; invalid materials are refused
 *       with a message naming the value                     [LAC (2)] [LAC (4)]
 */
#include <math.h>
#include <stdio.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* Assemble a box, fix the listed (group, component) pairs, try each solver:
 * every one must answer `want`. */
static void
run (lac_elem_type type, lac_model model, int nfix, const char **grp,
     const int *comp, int want, const char *what)
{
  int dim = lac_model_dim (model);
  size_t n[3] = { 3, 2, 2 };
  double L[3] = { 2.0, 1.0, 1.0 };
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (type, n, L, 0.0, &m), LAC_SUCCESS, "box");
  if (!m)
    return;
  if (model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      m->x[2 * a] += 1.0;
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_calloc (ndof, sizeof *F);
  double *u = lac_calloc (ndof, sizeof *u);
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = 2000.0;
      nu[c] = 0.3;
    }
  lac_elastic mat = { model, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_dirichlet *d = lac_dirichlet_alloc ();
  lac_assembly_stiffness (m, &mat, T);
  lac_assembly_pressure (m, model, lac_mesh_group (m, "xmax"), 1.0, F);
  for (int k = 0; k < nfix; k++)
    lac_dirichlet_add_group (d, m, lac_mesh_group (m, grp[k]), comp[k], 0.0);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_dirichlet_apply (d, K, F);
  const lac_solver_kind kinds[3] = { LAC_SOLVER_DENSE, LAC_SOLVER_UMFPACK,
                                     LAC_SOLVER_CHOLMOD };
  for (int k = 0; k < 3; k++)
    {
      lac_solver *s = lac_solver_alloc (kinds[k]);
      lac_error_clear ();
      int status = lac_solver_factor (s, K);
      if (!status)
        status = lac_solver_solve (s, F, u);
      check_status (status, want, "%s: %s with %s",
                    lac_refelem_get (type)->name, what,
                    lac_solver_kind_name (kinds[k]));
      if (want == LAC_ESING)
        check_true (lac_error_message ()[0] != '\0', "%s: a message is set"
                    " (%s)", what, lac_solver_kind_name (kinds[k]));
      lac_solver_free (s);
    }
  lac_csc_free (K);
  lac_dirichlet_free (d);
  lac_triplet_free (T);
  lac_free (u);
  lac_free (F);
  lac_free (nu);
  lac_free (E);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  const char *xmin[3] = { "xmin", "xmin", "xmin" };
  const int c012[3] = { 0, 1, 2 };
  const char *roller[3] = { "xmin", "ymin", "zmin" };

  /* 1. Free-floating bodies and bodies missing one direction: singular. */
  run (LAC_QUAD4, LAC_PLANE_STRAIN, 0, NULL, NULL, LAC_ESING, "free body");
  run (LAC_QUAD4, LAC_PLANE_STRAIN, 1, xmin, c012, LAC_ESING,
       "u_x fixed only (slides in y)");
  run (LAC_HEX8, LAC_SOLID3D, 2, xmin, c012, LAC_ESING,
       "u_x, u_y fixed only (slides in z)");
  /* Axisymmetric: only u_z is free (u_r is resisted by the hoop strain). */
  run (LAC_TRI6, LAC_AXISYMMETRIC, 0, NULL, NULL, LAC_ESING, "free ring");
  /* 2. The same bodies correctly supported: regular. */
  run (LAC_QUAD4, LAC_PLANE_STRAIN, 2, xmin, c012, LAC_SUCCESS, "clamped");
  run (LAC_HEX8, LAC_SOLID3D, 3, roller, c012, LAC_SUCCESS,
       "three symmetry planes");
  const char *zfix[1] = { "ymin" };
  const int c1[1] = { 1 };
  run (LAC_TRI6, LAC_AXISYMMETRIC, 1, zfix, c1, LAC_SUCCESS,
       "ring with u_z fixed on one side");

  /* 3. Invalid materials. */
  check_status (lac_material_check (-5.0, 0.3), LAC_EINVAL, "E < 0");
  check_message ("E = -5", "message names E");
  check_status (lac_material_check (0.0, 0.3), LAC_EINVAL, "E = 0");
  check_status (lac_material_check (100.0, 0.5), LAC_EINVAL, "nu = 1/2");
  check_message ("nu = 0.5", "message names nu");
  check_status (lac_material_check (100.0, 0.7), LAC_EINVAL, "nu = 0.7");
  check_status (lac_material_check (100.0, -1.0), LAC_EINVAL, "nu = -1");
  check_status (lac_material_check (100.0, NAN), LAC_EINVAL, "nu = NaN");
  check_status (lac_material_check (100.0, 0.49), LAC_SUCCESS, "nu = 0.49");
  double D[36];
  check_status (lac_material_D (LAC_SOLID3D, 100.0, 0.5, D), LAC_EINVAL,
                "D refuses nu = 1/2");

  /* An invalid material in one cell stops the assembly with its index. */
  lac_mesh *m = NULL;
  size_t n[2] = { 2, 2 };
  double L[2] = { 1, 1 };
  lac_mesh_box (LAC_QUAD4, n, L, 0.0, &m);
  double E[4] = { 1, 1, 1, 1 }, nu[4] = { 0.3, 0.3, 0.5, 0.3 };
  lac_elastic mat = { LAC_PLANE_STRAIN, E, nu };
  lac_triplet *T = lac_triplet_alloc (2 * m->nnodes, 2 * m->nnodes, 0);
  check_status (lac_assembly_stiffness (m, &mat, T), LAC_EINVAL,
                "assembly with nu = 0.5 in cell 2");
  check_message ("cell 2", "message names the cell");
  check_message ("nu = 0.5", "message names nu");
  lac_triplet_free (T);
  lac_mesh_free (m);
  lac_finalize ();
  return check_summary ();
}
