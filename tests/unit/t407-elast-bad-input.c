/* t407: the elasticity assembly refuses bad input with a clear message
 *       (groups of the wrong dimension, components out of range, sizes)
 */
#include <stdio.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

static void
one (const double *x, void *ctx, double *out)
{
  (void) x;
  (void) ctx;
  out[0] = out[1] = out[2] = 1.0;
}

int
main (void)
{
  lac_init ();
  lac_mesh *m = NULL;
  size_t n[2] = { 2, 2 };
  double L[2] = { 1, 1 };
  check_status (lac_mesh_box (LAC_TRI3, n, L, 0.0, &m), LAC_SUCCESS, "box");
  if (!m)
    return check_summary ();
  size_t ndof = 2 * m->nnodes;
  double E[8], nu[8], F[64] = { 0 };
  for (int c = 0; c < 8; c++)
    {
      E[c] = 1.0;
      nu[c] = 0.25;
    }
  lac_elastic mat = { LAC_PLANE_STRAIN, E, nu };
  const lac_group *body = lac_mesh_group (m, "body");
  const lac_group *xmin = lac_mesh_group (m, "xmin");
  lac_dirichlet *d = lac_dirichlet_alloc ();

  /* Surface loads need facet groups, volume forces cell groups. */
  check_status (lac_assembly_traction (m, LAC_PLANE_STRAIN, body, one, NULL,
                                       F), LAC_EINVAL, "traction on cells");
  check_message ("'body' has dimension 2", "names the group and dimension");
  check_status (lac_assembly_pressure (m, LAC_PLANE_STRAIN, NULL, 1.0, F),
                LAC_EINVAL, "pressure on NULL group");
  check_status (lac_assembly_volume_force (m, LAC_PLANE_STRAIN, xmin, one,
                                           NULL, F), LAC_EINVAL,
                "volume force on facets");
  check_message ("'xmin' has dimension 1", "names the group and dimension");
  /* The model must match the mesh. */
  check_status (lac_assembly_pressure (m, LAC_SOLID3D, xmin, 1.0, F),
                LAC_EINVAL, "3D model on a 2D mesh");
  check_message ("needs a 3D mesh", "says what is wrong");

  /* Dirichlet: component range, missing group, dof range. */
  check_status (lac_dirichlet_add_group (d, m, xmin, 2, 0.0), LAC_EINVAL,
                "component 2 in 2D");
  check_message ("component 2 out of range 0..1", "names the component");
  check_status (lac_dirichlet_add_group (d, m, xmin, -1, 0.0), LAC_EINVAL,
                "component -1");
  check_status (lac_dirichlet_add_group (d, m, lac_mesh_group (m, "nope"), 0,
                                         0.0), LAC_EINVAL, "unknown group");
  check_status (lac_dirichlet_add_group (d, m, xmin, 0, 0.0), LAC_SUCCESS,
                "good Dirichlet group");
  check_int ((long) d->n, (long) xmin->nnodes, "one entry per node");

  /* Sizes: a K of the wrong size is refused. */
  lac_triplet *T = lac_triplet_alloc (ndof - 1, ndof - 1, 0);
  check_status (lac_assembly_stiffness (m, &mat, T), LAC_EBADLEN,
                "K of the wrong size");
  lac_triplet_free (T);
  lac_csc *K = lac_csc_alloc (3, 3, 0);
  check_status (lac_dirichlet_apply (d, K, F), LAC_EBADLEN,
                "fixed dof beyond K");
  lac_csc_free (K);

  /* Axisymmetric mesh crossing the axis. */
  for (size_t a = 0; a < m->nnodes; a++)
    m->x[2 * a] -= 0.5;
  lac_elastic axi = { LAC_AXISYMMETRIC, E, nu };
  double Ke[36];
  check_status (lac_assembly_cell_stiffness (m, &axi, 0, Ke), LAC_EINVAL,
                "axisymmetric cell with r < 0");
  check_message ("r >= 0", "says why");
  check_status (lac_assembly_cell_stiffness (m, &mat, 99, Ke), LAC_EINVAL,
                "cell out of range");

  /* Errors without a gradient cannot give H1 norms. */
  double u[64] = { 0 }, l2, h1;
  check_status (lac_post_errors (m, LAC_PLANE_STRAIN, u, one, NULL, NULL, &l2,
                                 &h1, NULL, NULL), LAC_EINVAL,
                "H1 error without gradient");
  check_status (lac_post_errors (m, LAC_PLANE_STRAIN, u, one, NULL, NULL, &l2,
                                 NULL, NULL, NULL), LAC_SUCCESS,
                "L2 error without gradient");
  check_rel (l2, 1.4142135623730951, 1e-12, "||(1,1)||_0 on the unit square");

  lac_dirichlet_free (d);
  lac_mesh_free (m);
  lac_finalize ();
  return check_summary ();
}
