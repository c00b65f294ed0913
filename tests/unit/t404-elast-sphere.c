/* t404: thick sphere under internal pressure (Lame), one body, curved
 *       quadratic meshes read from the .geo files of chapter 01   [LAC §5.2]
 *
 * a = 20, b = 40, p = 25, E = 2000, nu = 0.3 and the exact radial
 * displacement (chapter 01, erratum 1: b is the outer radius)
 *   u_r(R) = p a^3 / (E (b^3 - a^3)) ((1 - 2 nu) R + (1 + nu) b^3 / (2 R^2)),
 * u_r(20) = 0.2, u_r(40) = 0.075, and the radial stress
 *   sigma_RR(R) = -p a^3 / (b^3 - a^3) (b^3 / R^3 - 1).
 * Axisymmetric model (quarter annulus, u_r = 0 on the axis, u_z = 0 on the
 * equator) with tri6 and quad8: every node within 0.1%.  3D octant with
 * three symmetry planes, tet10, hex20 and hex27: every node within 1%.
 * Meshes: sphere-axi.geo at level 2 (8 x 16 cells), sphere-octant.geo at
 * level 1 (3 blocks of 4 x 4 x 4 hexahedra, or 6 tetrahedra per
 * hexahedron).  The nodal error decreases like h^3 (measured: tri6 2.4e-2,
 * 4.1e-3, 6.3e-4, 8.6e-5 for levels 0-3; tet10 3.4e-2, 5.6e-3, 7.7e-4).  Also: the tangential displacement vanishes, and the radial
 * stress from the nodal averages at the inner surface is -p within 5%
 * (axisymmetric) or 15% (3D, coarser): nodal averages of the linear stress
 * of quadratic cells, converging like h^2, where the gradient is steepest.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "io/lac_mesh_gmsh.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

#define RA 20.0
#define RB 40.0
#define PRESS 25.0
#define YOUNG 2000.0
#define POISSON 0.3

static double
exact_ur (double R)
{
  double a3 = RA * RA * RA, b3 = RB * RB * RB;
  return PRESS * a3 / (YOUNG * (b3 - a3))
         * ((1 - 2 * POISSON) * R + (1 + POISSON) * b3 / (2 * R * R));
}

static void
run (const char *geo, lac_elem_type type, int level, double tol,
     double stol)
{
  const lac_refelem *re = lac_refelem_get (type);
  lac_mesh_opts o = { 0 };
  o.order = 2;
  o.level = level;
  o.recombine = (type == LAC_QUAD8 || type == LAC_HEX20 || type == LAC_HEX27);
  o.serendipity = (type == LAC_QUAD8 || type == LAC_HEX20);
  lac_mesh *m = NULL;
  int status = lac_mesh_read (geo, &o, &m);
  check_status (status, LAC_SUCCESS, "%s: read %s", re->name, geo);
  if (status)
    return;
  check_int (m->type[0], type, "%s: element type read from %s", re->name, geo);
  int dim = m->dim;
  lac_model model = dim == 3 ? LAC_SOLID3D : LAC_AXISYMMETRIC;
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_calloc (ndof, sizeof *F);
  double *u = lac_calloc (ndof, sizeof *u);
  int ns = lac_model_nstress (model);
  double *sig = lac_malloc (m->nnodes * (size_t) ns * sizeof *sig);
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = YOUNG;
      nu[c] = POISSON;
    }
  lac_elastic mat = { model, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_dirichlet *d = lac_dirichlet_alloc ();
  lac_solver *s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  lac_csc *K = NULL;
  status = lac_assembly_stiffness (m, &mat, T);
  if (!status)
    status = lac_assembly_pressure (m, model, lac_mesh_group (m, "inner"),
                                    PRESS, F);
  if (dim == 2)
    {
      if (!status)      /* u_r = 0 on the axis, u_z = 0 on the equator */
        status = lac_dirichlet_add_group (d, m, lac_mesh_group (m, "axis"),
                                          0, 0.0);
      if (!status)
        status = lac_dirichlet_add_group (d, m, lac_mesh_group (m, "equator"),
                                          1, 0.0);
    }
  else
    {
      const char *sym[3] = { "symx", "symy", "symz" };
      for (int k = 0; k < 3 && !status; k++)
        status = lac_dirichlet_add_group (d, m, lac_mesh_group (m, sym[k]), k,
                                          0.0);
    }
  if (!status)
    {
      K = lac_csc_from_triplet (T);
      status = K ? lac_dirichlet_apply (d, K, F) : LAC_ENOMEM;
    }
  if (!status)
    status = lac_solver_factor (s, K);
  if (!status)
    status = lac_solver_solve (s, F, u);
  if (!status)
    status = lac_post_stress_nodal (m, &mat, u, NULL, sig, NULL);
  check_status (status, LAC_SUCCESS, "%s: assemble and solve", re->name);

  /* Radial and tangential displacement at every node. */
  double err = 0.0, tang = 0.0, srr_err = 0.0;
  double ui = 0, uo = 0;
  for (size_t a = 0; a < m->nnodes && !status; a++)
    {
      const double *x = m->x + (size_t) dim * a, *ua = u + (size_t) dim * a;
      double R = 0.0, urh = 0.0, t2 = 0.0;
      for (int i = 0; i < dim; i++)
        R += x[i] * x[i];
      R = sqrt (R);
      for (int i = 0; i < dim; i++)
        urh += ua[i] * x[i] / R;                    /* u . e_R */
      for (int i = 0; i < dim; i++)
        t2 += pow (ua[i] - urh * x[i] / R, 2);      /* |u - (u.e_R) e_R|^2 */
      double ue = exact_ur (R);
      err = fmax (err, fabs (urh - ue) / ue);
      tang = fmax (tang, sqrt (t2) / ue);
      if (fabs (R - RA) < 1e-6)
        {
          ui = urh;
          /* sigma_RR = e_R . sigma e_R from the Voigt vector */
          const double *sa = sig + a * (size_t) ns;
          double srr;
          if (dim == 2)
            srr = (sa[0] * x[0] * x[0] + sa[1] * x[1] * x[1]
                   + 2 * sa[3] * x[0] * x[1]) / (R * R);
          else
            srr = (sa[0] * x[0] * x[0] + sa[1] * x[1] * x[1]
                   + sa[2] * x[2] * x[2] + 2 * sa[3] * x[0] * x[1]
                   + 2 * sa[4] * x[1] * x[2] + 2 * sa[5] * x[2] * x[0])
                  / (R * R);
          srr_err = fmax (srr_err, fabs (srr + PRESS) / PRESS);
        }
      if (fabs (R - RB) < 1e-6)
        uo = urh;
    }
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("  %-5s level %d: %zu nodes, u_r(20) = %.6f, u_r(40) = %.6f,"
            " max rel err %.2e, tangential %.2e, sigma_RR(20) err %.2e\n",
            re->name, level, m->nnodes, ui, uo, err, tang, srr_err);
  check_true (err <= tol, "%s: max relative error of u_r %.3e <= %.0e",
              re->name, err, tol);
  check_true (tang <= tol, "%s: tangential displacement %.3e <= %.0e",
              re->name, tang, tol);
  check_true (srr_err <= stol, "%s: sigma_RR(a) = -p within %.3e <= %g",
              re->name, srr_err, stol);
  check_rel (ui, 0.2, tol, "%s: u_r(20)", re->name);
  check_rel (uo, 0.075, tol, "%s: u_r(40)", re->name);

  lac_csc_free (K);
  lac_solver_free (s);
  lac_dirichlet_free (d);
  lac_triplet_free (T);
  lac_free (sig);
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
  check_rel (exact_ur (20.0), 0.2, 1e-14, "exact u_r(20)");
  check_rel (exact_ur (40.0), 0.075, 1e-14, "exact u_r(40)");
  const char *axi = "chapters/01-problem/sphere-axi.geo";
  const char *oct = "chapters/01-problem/sphere-octant.geo";
  run (axi, LAC_TRI6, 2, 1e-3, 0.05);
  run (axi, LAC_QUAD8, 2, 1e-3, 0.05);
  run (oct, LAC_TET10, 1, 1e-2, 0.15);
  run (oct, LAC_HEX20, 1, 1e-2, 0.15);
  run (oct, LAC_HEX27, 1, 1e-2, 0.15);
  lac_finalize ();
  return check_summary ();
}
