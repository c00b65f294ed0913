/* t450: the Taylor patch test through the whole contact chain, every
 *       element type, slave and master swapped           [LAC §5.1, Tables 1-2]
 *
 * Two 50 mm squares (cubes) stacked, meshed independently with a mesh-size
 * ratio of 4:3 (2D) or 3:2 (3D), so the interface meshes do not match and
 * their nodes do not align; E = 2000, nu = 0.3; symmetry on x = 0 (and
 * y = 0 in 3D) for both bodies, the lower body on its bottom; pressure
 * p = 25 on the top.  The exact solution is uniform: sigma_yy (sigma_zz
 * in 3D) = -25 and lambda = -25 on every macro-element.  The chain:
 * macro-mesh (refinement) -> pairing -> admissibility -> C, G -> active set.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "solve/lac_newton.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

#define P 25.0

static void
fix (lac_dirichlet *d, lac_mesh *m, const char *g, int comp)
{
  const lac_group *G = lac_mesh_group (m, g);
  check_true (G != NULL, "group %s", g);
  if (G)
    lac_dirichlet_add_group (d, m, G, comp, 0.0);
}

static void
taylor (lac_elem_type type, int swap)
{
  const lac_refelem *re = lac_refelem_get (type);
  int dim = re->dim;
  const char *tn = re->name;
  size_t nlo[3] = { 4, 4, 3 }, nup[3] = { 3, 3, 2 };
  if (dim == 3)
    nlo[0] = nlo[1] = 3, nup[0] = nup[1] = 2;
  double L[3] = { 50, 50, 50 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  lac_mesh_box (type, nlo, L, 0.0, &lo);
  lac_mesh_box (type, nup, L, 0.0, &up);
  for (size_t i = 0; i < up->nnodes; i++)
    up->x[i * dim + dim - 1] += 50.0;                   /* stack on top */
  check_status (lac_mesh_merge (lo, "lo.", up, "up.", &m), LAC_SUCCESS, "%s merge", tn);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  const char *top = dim == 2 ? "lo.ymax" : "lo.zmax";
  const char *bot = dim == 2 ? "up.ymin" : "up.zmin";
  const char *slave = swap ? top : bot, *master = swap ? bot : top;

  /* 1. macro-mesh of the slave surface (refines 3D cells) */
  lac_macro *M = NULL;
  int st = lac_macromesh_build (&m, slave, NULL, &M);
  check_status (st, LAC_SUCCESS, "%s/%d macromesh", tn, swap);
  if (st)
    {
      lac_mesh_free (m);
      return;
    }
  /* 2. pairing */
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (m, lac_mesh_group (m, master));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *Pr = NULL;
  st = lac_pairing_build (&S, &Mf, &po, &Pr);
  check_status (st, LAC_SUCCESS, "%s/%d pairing", tn, swap);
  /* 3. stiffness, load, Dirichlet */
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells * sizeof *nu);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = 2000, nu[c] = 0.3;
  lac_elastic mat = { dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D, E, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_assembly_stiffness (m, &mat, T);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  double *F = calloc (ndof, sizeof *F);
  lac_assembly_pressure (m, mat.model, lac_mesh_group (m, dim == 2 ? "up.ymax" : "up.zmax"), P, F);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  fix (D, m, "lo.xmin", 0);
  fix (D, m, "up.xmin", 0);
  if (dim == 3)
    {
      fix (D, m, "lo.ymin", 1);
      fix (D, m, "up.ymin", 1);
    }
  fix (D, m, dim == 2 ? "lo.ymin" : "lo.zmin", dim - 1);
  lac_dirichlet_apply (D, K, F);
  /* 4. admissibility and the LAC terms */
  lac_contact *c = NULL;
  if (!st)
    st = lac_contact_build (m, mat.model, M, Pr, &Mf, LAC_EPSILON_DEFAULT, &c);
  check_status (st, LAC_SUCCESS, "%s/%d contact", tn, swap);
  if (!st)
    {
      lac_contact_apply_dirichlet (c, D->n, D->dof, D->val);
      check_int ((long) c->k, (long) M->n, "%s/%d: every macro-element admissible", tn, swap);
      /* 5. the active set */
      lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
      lac_newton *s = NULL;
      st = lac_newton_solve_system (LAC_STRATEGY_SADDLE, &sys, 10, 1e-10, &s);
      check_status (st, LAC_SUCCESS, "%s/%d newton", tn, swap);
      check_true (s->nhist <= 3, "%s/%d: %zu active-set iterations", tn, swap, s->nhist);
      double el = 0, es = 0;
      for (size_t i = 0; i < c->k; i++)
        el = fmax (el, fabs (s->lambda[i] + P) / P);
      double xi[3] = { 0.2, 0.2, 0.2 }, sig[6];
      for (size_t cc = 0; cc < m->ncells; cc++)
        {
          if (m->type[cc] == LAC_PYR5)
            xi[0] = xi[1] = 0.1;
          lac_post_stress_at (m, &mat, s->U, cc, xi, sig);
          es = fmax (es, fabs (sig[dim - 1] + P) / P);
        }
      check_true (el <= 1e-12, "%s/%d: max rel err lambda %.2e", tn, swap, el);
      check_true (es <= 1e-12, "%s/%d: max rel err sigma %.2e", tn, swap, es);
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%-6s swap=%d k=%zu it=%zu err_lambda=%.2e err_sigma=%.2e\n",
                tn, swap, c->k, s->nhist, el, es);
      lac_newton_free (s);
    }
  lac_contact_free (c);
  lac_dirichlet_free (D);
  free (F);
  free (E);
  free (nu);
  lac_csc_free (K);
  lac_pairing_free (Pr);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  const lac_elem_type types[] = { LAC_TRI3, LAC_QUAD4, LAC_TRI6, LAC_QUAD8,
                                  LAC_QUAD9, LAC_TET4, LAC_HEX8, LAC_TET10,
                                  LAC_HEX20, LAC_HEX27 };
  for (size_t t = 0; t < sizeof types / sizeof *types; t++)
    for (int swap = 0; swap < 2; swap++)
      taylor (types[t], swap);
  lac_finalize ();
  return check_summary ();
}
