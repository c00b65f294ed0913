/* example.c -- chapter 01: one elastic body, the forms of (8)     [LAC §2]
 *
 * Build:        make build/chapters/01-problem   (plain `make` builds it
 *               too, with the library and every chapter's program);
 *               outside the tree, against lac installed by make install
 *               (README.md, "Using lac as a library"):
 *                 cc example.c $(pkg-config --cflags --libs lac)
 * Sample runs:  build/chapters/01-problem                 plane strain,
 *                                                        quad8, CHOLMOD
 *               build/chapters/01-problem --dim 3        3D, hex20
 *               build/chapters/01-problem --solver dense the same with
 *                                                        the dense LU
 * Description:
 *   A block 10 x 1 (x 1) clamped on its left end (Gamma_D, [LAC (4)]) and
 *   pressed on its top (Gamma_N, [LAC (3)]) by p = 0.01: a short cantilever
 *   under a uniform load.  The program assembles K and F of the weak form
 *   [LAC (8)] without contact, eliminates the Dirichlet conditions, solves,
 *   and prints the deflection of the free end and the bending stress at
 *   mid-span next to Euler-Bernoulli beam theory.  The output is short and
 *   deterministic (the same with every solver to the printed digits).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex01: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* The index of the mesh node nearest to the point p. */
static size_t
nearest_node (const lac_mesh *m, const double *p)
{
  size_t best = 0;
  double dbest = INFINITY;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double d = 0;
      for (int k = 0; k < m->dim; k++)
        d += pow (m->x[(size_t) m->dim * a + (size_t) k] - p[k], 2);
      if (d < dbest)
        {
          dbest = d;
          best = a;
        }
    }
  return best;
}

int
main (int argc, char **argv)
{
  int dim = 2;
  lac_solver_kind solver = LAC_SOLVER_CHOLMOD;
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--dim") && k + 1 < argc)
        dim = atoi (argv[++k]);
      else if (!strcmp (argv[k], "--solver") && k + 1 < argc
               && lac_solver_kind_from_name (argv[k + 1]) >= 0)
        solver = (lac_solver_kind) lac_solver_kind_from_name (argv[++k]);
      else
        {
          fprintf (stderr, "usage: ex01 [--dim 2|3] [--solver dense|umfpack"
                   "|cholmod]\n");
          return 2;
        }
    }
  if (dim != 2 && dim != 3)
    {
      fprintf (stderr, "ex01: --dim must be 2 or 3\n");
      return 2;
    }
  lac_init ();

  // @sect The mesh
  /* 1. A structured mesh of $[0,L] \times [0,h]\,(\times [0,h])$ with
   *    quadratic cells (quad8 in 2D, hex20 in 3D), built in code.  Its
   *    boundary groups are called "xmin", "xmax", "ymin", ... */
  const double Lx = 10.0, h = 1.0, E = 1000.0, nu = 0.3, p = 0.01;
  size_t n[3] = { 20, 2, 2 };
  double L[3] = { Lx, h, h };
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (dim == 2 ? LAC_QUAD8 : LAC_HEX20, n, L, 0.0, &m),
                "lac_mesh_box");
  lac_model model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  size_t ndof = (size_t) dim * m->nnodes;
  printf ("model %s, %zu cells of type %s, %zu nodes, %zu dofs\n",
          lac_model_name (model), m->ncells, lac_refelem_get (m->type[0])->name,
          m->nnodes, ndof);

  // @sect The material
  /* 2. Hooke's law $\sigma = \mathcal{A}\varepsilon$ [LAC (2)]: one Young's
   *    modulus and one Poisson ratio per cell.  lac_material_check refuses
   *    $E \le 0$ and $\nu \notin (-1, 1/2)$. */
  double *Ec = lac_malloc (m->ncells * sizeof *Ec);
  double *nuc = lac_malloc (m->ncells * sizeof *nuc);
  check_status (Ec && nuc ? lac_material_check (E, nu) : LAC_ENOMEM,
                "material");
  for (size_t c = 0; c < m->ncells; c++)
    {
      Ec[c] = E;
      nuc[c] = nu;
    }
  lac_elastic mat = { model, Ec, nuc };

  // @sect The stiffness matrix and the load
  /* 3. $K$ discretizes $a(u,v) = \int_\Omega \mathcal{A}\varepsilon(u) :
   *    \varepsilon(v)$ and $F$ discretizes $l(v) = \int_{\Gamma_N} F \cdot v$
   *    [LAC (8)]; here the surface load is a pressure $F = -p\,n$ on the
   *    top face "ymax" (n the outward normal, so it pushes down). */
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  double *F = lac_calloc (ndof, sizeof *F);
  double *u = lac_calloc (ndof, sizeof *u);
  check_status (T && F && u ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  check_status (lac_assembly_stiffness (m, &mat, T), "lac_assembly_stiffness");
  check_status (lac_assembly_pressure (m, model, lac_mesh_group (m, "ymax"),
                                       p, F), "lac_assembly_pressure");
  lac_csc *K = lac_csc_from_triplet (T);
  check_status (K ? LAC_SUCCESS : LAC_ENOMEM, "lac_csc_from_triplet");

  // @sect Dirichlet conditions
  /* 4. The clamp $u = 0$ on $\Gamma_D$ = "xmin" [LAC (4)], by symmetric
   *    elimination: K keeps its symmetry and, with the rigid motions
   *    removed, is positive definite, so CHOLMOD can factor it. */
  lac_dirichlet *D = lac_dirichlet_alloc ();
  check_status (D ? LAC_SUCCESS : LAC_ENOMEM, "lac_dirichlet_alloc");
  for (int i = 0; i < dim; i++)
    check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "xmin"), i,
                                           0.0), "lac_dirichlet_add_group");
  check_status (lac_dirichlet_apply (D, K, F), "lac_dirichlet_apply");

  // @sect Solving
  /* 5. $K u = F$ with the chosen back end (dense LU, UMFPACK or CHOLMOD). */
  lac_solver *S = lac_solver_alloc (solver);
  check_status (S ? LAC_SUCCESS : LAC_ENOMEM, "lac_solver_alloc");
  check_status (lac_solver_factor (S, K), "lac_solver_factor");
  check_status (lac_solver_solve (S, F, u), "lac_solver_solve");

  // @sect Results
  /* 6. The deflection of the free end (mean $u_y$ over "xmax") and the
   *    bending stress $\sigma_{xx}$ on the top fibre at mid-span, from the
   *    nodal averages of $\sigma = \mathcal{A}\varepsilon(u^h)$.  Beam theory
   *    for a cantilever under the load $q = p\,b$ per unit length (b the
   *    width, 1 in plane strain), $I = b h^3/12$:
   *    $w(L) = q L^4 / (8 E' I)$ with $E' = E/(1-\nu^2)$ in plane strain
   *    (the beam cannot contract sideways) and $E' = E$ in 3D, and
   *    $\sigma_{xx}(L/2, h) = M h / (2 I)$ with $M = q (L/2)^2 / 2$. */
  const lac_group *tip = lac_mesh_group (m, "xmax");
  double w = 0.0;
  for (size_t k = 0; k < tip->nnodes; k++)
    w += u[(size_t) dim * tip->node[k] + 1] / (double) tip->nnodes;
  int ns = lac_model_nstress (model);
  double *sig = lac_malloc (m->nnodes * (size_t) ns * sizeof *sig);
  double *vm = lac_malloc (m->nnodes * sizeof *vm);
  check_status (sig && vm ? lac_post_stress_nodal (m, &mat, u, NULL, sig, vm)
                : LAC_ENOMEM, "lac_post_stress_nodal");
  double mid[3] = { Lx / 2, h, h / 2 };
  size_t a = nearest_node (m, mid);
  double I = h * h * h / 12, q = p * (dim == 3 ? h : 1.0);
  double Eb = dim == 2 ? E / (1 - nu * nu) : E;
  double w_beam = q * pow (Lx, 4) / (8 * Eb * I);
  double s_beam = q * Lx * Lx / 8 * h / (2 * I);
  printf ("tip deflection   u_y(L)       = %.6e   (beam: %.6e)\n", w, -w_beam);
  printf ("mid-span stress  sigma_xx     = %.6e   (beam: %.6e)\n",
          sig[a * (size_t) ns], s_beam);
  printf ("                 von Mises    = %.6e\n", vm[a]);

  lac_free (vm);
  lac_free (sig);
  lac_solver_free (S);
  lac_dirichlet_free (D);
  lac_csc_free (K);
  lac_free (u);
  lac_free (F);
  lac_triplet_free (T);
  lac_free (nuc);
  lac_free (Ec);
  lac_mesh_free (m);
  lac_finalize ();
  return 0;
}
