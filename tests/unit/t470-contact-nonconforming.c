/* t470: geometric non-conformity: Gamma_C consistent with neither mesh
 *                                              [LAC Def. 1, §3.2.3, Thm. 2]
 *
 * The slave surface is the top of a clamped (rigid) base [0,50] (x [0,50])
 * cut into 5 cells per direction; the master is the bottom of a SHORTER
 * block [0,37] (x [0,50]) pressed with p = 25 on its top, symmetric on
 * x = 0 (and y = 0).  Gamma_C = [0,37] ends inside the slave cells
 * [30,40] (covered fraction delta = 0.7) and inside no master cell; the
 * cells [40,50] are not covered at all.
 *
 * Definition 1 by hand (criterion phibar sqrt(delta)):
 *   2D quad8, seg3 macro-element covered from one end on a fraction delta:
 *     int phi = L (2 delta^2 - 4 delta^3 / 3), crit = 2 delta^1.5 (1 - 2 delta/3)
 *     full: 2/3;  delta = 0.7: 0.62474...;  uncovered: 0.
 *   3D hex27, quad9 face (centre node phi = (1-s^2)(1-t^2)) covered on
 *     s in [s0, 1], s0 = 1 - 2 delta:  crit = I / (4 sqrt(delta)),
 *     I = (4/3) ((1 - s0) - (1 - s0^3)/3);  full: 4/9;  delta = 0.7: 0.41647...
 * So the admissible set shrinks exactly at these values as epsilon grows.
 * While the partly covered macro-elements are admissible the uniform
 * solution is the discrete one: lambda = -25 exactly (the base is rigid,
 * the block's bottom does not move); when they are dropped the solution
 * stays finite and the total contact force still balances the load.
 */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

#define LM 37.0

typedef struct problem
{
  lac_mesh *m;
  lac_macro *M;
  lac_pairing *P;
  lac_pairing_facets Mf;
  lac_elastic mat;
  double *E, *nu;
  int dim;
} problem;

static int
setup (problem *pb, lac_elem_type type)
{
  int dim = lac_refelem_get (type)->dim;
  size_t nlo[3] = { 5, 5, 1 }, nup[3] = { 4, 4, 4 };
  double Llo[3] = { 50, 50, 50 }, Lup[3] = { LM, 50, 50 };
  if (dim == 2)
    nlo[1] = 2;
  else
    nlo[2] = 1, nup[2] = 2;
  lac_mesh *lo = NULL, *up = NULL;
  lac_mesh_box (type, nlo, Llo, 0.0, &lo);
  lac_mesh_box (type, nup, Lup, 0.0, &up);
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[a * dim + dim - 1] += 50.0;
  pb->dim = dim;
  lac_mesh_merge (lo, "lo.", up, "up.", &pb->m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  int st = lac_macromesh_build (&pb->m, dim == 2 ? "lo.ymax" : "lo.zmax", NULL, &pb->M);
  lac_pairing_facets S = { pb->m, pb->M->ptr[pb->M->n], pb->M->cell, pb->M->face };
  pb->Mf = lac_pairing_facets_of (pb->m, lac_mesh_group (pb->m, dim == 2 ? "up.ymin" : "up.zmin"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  if (!st)
    st = lac_pairing_build (&S, &pb->Mf, &po, &pb->P);
  pb->E = malloc (pb->m->ncells * sizeof *pb->E);
  pb->nu = malloc (pb->m->ncells * sizeof *pb->nu);
  for (size_t c = 0; c < pb->m->ncells; c++)
    pb->E[c] = 2000, pb->nu[c] = 0.3;
  pb->mat.model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  pb->mat.E = pb->E;
  pb->mat.nu = pb->nu;
  return st;
}

static void
release (problem *pb)
{
  lac_pairing_free (pb->P);
  lac_macromesh_free (pb->M);
  lac_mesh_free (pb->m);
  free (pb->E);
  free (pb->nu);
}

/* Solve with epsilon; check lambda (exact while every covered macro is
 * admissible) and the balance of forces. */
static void
solve (problem *pb, double eps, int exact)
{
  int dim = pb->dim;
  lac_mesh *m = pb->m;
  size_t ndof = (size_t) dim * m->nnodes;
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_assembly_stiffness (m, &pb->mat, T);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  double *F = calloc (ndof, sizeof *F);
  lac_assembly_pressure (m, pb->mat.model, lac_mesh_group (m, dim == 2 ? "up.ymax" : "up.zmax"), 25.0, F);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  for (int c = 0; c < dim; c++)                       /* the rigid base */
    lac_dirichlet_add_group (D, m, lac_mesh_group (m, "lo.body"), c, 0.0);
  lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.xmin"), 0, 0.0);
  if (dim == 3)
    lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.ymin"), 1, 0.0);
  lac_dirichlet_apply (D, K, F);
  lac_contact *c = NULL;
  lac_contact_build (m, pb->mat.model, pb->M, pb->P, &pb->Mf, eps, &c);
  lac_contact_apply_dirichlet (c, D->n, D->dof, D->val);
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  check_status (lac_newton_solve_system (LAC_STRATEGY_SADDLE, &sys, 20, 1e-10, &s), LAC_SUCCESS, "%dD eps %g: newton", dim, eps);
  double el = 0, force = 0;
  int finite = 1;
  for (size_t i = 0; i < c->k; i++)
    {
      el = fmax (el, fabs (s->lambda[i] + 25) / 25);
      force += s->lambda[i] * c->area[i];
      finite &= isfinite (s->lambda[i]);
    }
  for (size_t j = 0; j < ndof; j++)
    finite &= isfinite (s->U[j]);
  double want = -25 * LM * (dim == 3 ? 50 : 1);
  check_true (finite, "%dD eps %g: finite solution", dim, eps);
  check_rel (force, want, 1e-10, "%dD eps %g: total contact force", dim, eps);
  if (exact)
    check_true (el <= 1e-12, "%dD eps %g: lambda exact (err %.2e)", dim, eps, el);
  lac_newton_free (s);
  lac_contact_free (c);
  lac_dirichlet_free (D);
  free (F);
  lac_csc_free (K);
}

/* Criterion of each macro-element vs the hand formula; admissible counts. */
static void
check_definition (problem *pb, double full, double part, size_t nfull,
                  size_t npart, size_t nnone)
{
  lac_contact *c = NULL;
  check_status (lac_contact_build (pb->m, pb->mat.model, pb->M, pb->P, &pb->Mf,
                                   1e-3, &c), LAC_SUCCESS, "%dD contact", pb->dim);
  size_t nf = 0, np = 0, nn = 0;
  for (size_t mm = 0; mm < c->nmacro; mm++)
    {
      double d = c->covered[mm] / c->meas[mm];
      if (fabs (d - 1) < 1e-12)
        nf++, check_rel (c->crit[mm], full, 1e-12, "%dD macro %zu full", pb->dim, mm);
      else if (fabs (d - 0.7) < 1e-12)
        np++, check_rel (c->crit[mm], part, 1e-12, "%dD macro %zu delta 0.7", pb->dim, mm);
      else
        nn++, check_abs (c->covered[mm], 0, 1e-12, "%dD macro %zu uncovered", pb->dim, mm);
    }
  check_int ((long) nf, (long) nfull, "%dD fully covered", pb->dim);
  check_int ((long) np, (long) npart, "%dD partly covered", pb->dim);
  check_int ((long) nn, (long) nnone, "%dD uncovered", pb->dim);
  lac_contact_free (c);
  /* the admissible set as epsilon grows, exactly at the hand values */
  const double eps[4] = { part * (1 - 1e-9), part * (1 + 1e-9),
                          full * (1 - 1e-9), full * (1 + 1e-9) };
  const long want[4] = { (long) (nfull + npart), (long) nfull, (long) nfull, 0 };
  for (int k = 0; k < 4; k++)
    {
      c = NULL;
      int st = lac_contact_build (pb->m, pb->mat.model, pb->M, pb->P, &pb->Mf,
                                  eps[k], &c);
      if (want[k] == 0)
        check_status (st, LAC_EADMISS, "%dD eps %.10g: nothing admissible", pb->dim, eps[k]);
      else
        check_int (c ? (long) c->k : -1, want[k], "%dD eps %.10g: admissible", pb->dim, eps[k]);
      lac_contact_free (c);
    }
}

int
main (void)
{
  lac_init ();
  problem pb = { 0 };
  /* 2D quad8 */
  double d = 0.7;
  double full2 = 2.0 / 3.0, part2 = 2 * pow (d, 1.5) * (1 - 2 * d / 3);
  check_status (setup (&pb, LAC_QUAD8), LAC_SUCCESS, "2D setup");
  check_definition (&pb, full2, part2, 3, 1, 1);
  solve (&pb, 0.5, 1);                    /* partial kept: exact */
  solve (&pb, 0.64, 0);                   /* partial dropped: finite */
  release (&pb);
  /* 3D hex27: 5 x 5 faces, columns x in [30,40] partly covered */
  double s0 = 1 - 2 * d;
  double I = 4.0 / 3.0 * ((1 - s0) - (1 - s0 * s0 * s0) / 3);
  double full3 = 4.0 / 9.0, part3 = I / (4 * sqrt (d));
  pb = (problem) { 0 };
  check_status (setup (&pb, LAC_HEX27), LAC_SUCCESS, "3D setup");
  check_definition (&pb, full3, part3, 15, 5, 5);
  solve (&pb, 0.4, 1);
  solve (&pb, 0.43, 0);
  release (&pb);
  lac_finalize ();
  return check_summary ();
}
