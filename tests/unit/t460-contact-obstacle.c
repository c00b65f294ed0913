/* t460: a rigid analytic obstacle as the master          [LAC (18), §5.3]
 *
 * 1. Exact gaps: a flat slave y = 0 over a graph y <= -0.01 - 0.05 (x-1/2)^2
 *    (the paper's 2D foundation lowered by 0.01): at every point the gap
 *    is the distance to the graph (an independent golden-section search),
 *    the closest point is on the graph and nu = -n^O there; G_i = the
 *    integral of the distance over each macro-element.
 *    A curved slave above a flat: C pushes along the flat's normal.
 * 2. The patch test against a flat rigid foundation: a block pressed with
 *    p = 25 onto y <= 50 (z <= 50 in 3D), held by the contact alone:
 *    lambda = -25 and sigma = -25 exactly; with an initial gap g0 = 0.1
 *    the block first closes it (the iteration restarts from all active,
 *    lac_newton.h) and the bottom moves down by 0.1.
 */
#include <math.h>
#include <stdlib.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "solve/lac_newton.h"
#include "contact/lac_obstacle.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

/* h(t) of the lowered foundation, its slope, and the distance from (x, y)
 * to its graph by golden-section search on the squared distance (an
 * independent computation: no Newton, no normal). */
static double
foundation (double t)
{
  return -0.01 - 0.05 * (t - 0.5) * (t - 0.5);
}

static double
distance (double x, double y)
{
  double a = x - 0.2, b = x + 0.2, r = 0.5 * (sqrt (5.0) - 1);
  for (int it = 0; it < 200 && b - a > 1e-17; it++)
    {
      double t1 = b - r * (b - a), t2 = a + r * (b - a);
      double d1 = pow (x - t1, 2) + pow (y - foundation (t1), 2);
      double d2 = pow (x - t2, 2) + pow (y - foundation (t2), 2);
      if (d1 < d2)
        b = t2;
      else
        a = t1;
    }
  double t = 0.5 * (a + b);
  return sqrt (pow (x - t, 2) + pow (y - foundation (t), 2));
}

/* int_a^b distance((x, 0), graph) dx, composite Simpson on 2000 pieces. */
static double
distance_integral (double a, double b)
{
  int n = 2000;
  double h = (b - a) / n, s = distance (a, 0) + distance (b, 0);
  for (int k = 1; k < n; k++)
    s += (k % 2 ? 4 : 2) * distance (a + k * h, 0);
  return s * h / 3;
}

static void
exact_gaps (void)
{
  size_t n[3] = { 5, 1, 1 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  lac_mesh_box (LAC_QUAD8, n, L, 0.0, &m);
  lac_macro *M = NULL;
  lac_macromesh_build (&m, "ymin", NULL, &M);
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_obstacle ob = { 2, -0.01, { -0.05, 0 }, { 0.5, 0 }, 0 };
  lac_pairing *P = NULL;
  check_status (lac_obstacle_pairing (&S, &ob, 0, &P), LAC_SUCCESS, "obstacle pairing");
  double eg = 0, eon = 0, epar = 0, below = 0;
  for (size_t s = 0; P && s < P->nslave; s++)
    for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
      {
        int nodes[9];
        lac_map mp;
        lac_contact_facet_eval (m, M->cell[s], M->face[s], P->xs + p, nodes, &mp);
        double x = mp.x[0], *nu = P->normal + 2 * p, g = P->gap[p];
        /* the closest point x - g n^O = x + g nu is on the graph, nu is
         * the inward normal there, g the distance (< the vertical one) */
        double cx = x + g * nu[0], cy = g * nu[1];
        double slope = -0.1 * (cx - 0.5), len = sqrt (1 + slope * slope);
        eg = fmax (eg, fabs (g - distance (x, 0)));
        eon = fmax (eon, fabs (cy - foundation (cx)));
        epar = fmax (epar, fabs (nu[0] - slope / len) + fabs (nu[1] + 1 / len));
        below = fmax (below, g - (0 - foundation (x)));
      }
  check_abs (eg, 0, 1e-15, "gaps = distances to the graph");
  check_abs (eon, 0, 1e-16, "closest points on the graph");
  check_abs (epar, 0, 1e-15, "nu = -n^O at the closest points");
  check_true (below <= 0, "distance not above the vertical gap (%.2e)", below);
  lac_contact *c = NULL;
  check_status (lac_contact_build (m, LAC_PLANE_STRAIN, M, P, NULL, 1e-2, &c),
                LAC_SUCCESS, "contact against the obstacle");
  for (size_t i = 0; c && i < c->k; i++)
    {
      /* macro-element i is the segment [a, b] of the bottom side */
      size_t mm = c->macro[i];
      double a = 1, b = 0;
      for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
        {
          int nodes[9];
          lac_elem_type ft;
          int nn = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], nodes, &ft);
          for (int q = 0; q < nn; q++)
            a = fmin (a, m->x[2 * nodes[q]]), b = fmax (b, m->x[2 * nodes[q]]);
        }
      check_rel (c->G[i], distance_integral (a, b), 1e-9,
                 "G_%zu = int of the distance over [%g, %g]", i, a, b);
      check_rel (c->area[i], b - a, 1e-13, "area %zu", i);
    }
  lac_contact_free (c);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

/* A curved slave over a rigid flat: the bottom of a quad8 box bent to
 * y = 0.2 (x - 1/2)^2 + 0.1 above y <= 0.  The constraint acts along the
 * flat's normal: every column of C pushes straight down, sum_a C(a_x, i)
 * = 0 and sum_a C(a_y, i) = -|T^m| (the slave normal would tilt them by
 * up to 22 degrees), and the gaps are the heights: G_i = int y. */
static void
curved_on_flat (void)
{
  size_t n[3] = { 6, 2, 1 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  lac_mesh_box (LAC_QUAD8, n, L, 0.0, &m);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double x = m->x[2 * a], y = m->x[2 * a + 1];
      m->x[2 * a + 1] = y + (1 - y) * (0.2 * (x - 0.5) * (x - 0.5) + 0.1);
    }
  lac_macro *M = NULL;
  lac_macromesh_build (&m, "ymin", NULL, &M);
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_obstacle ob = { 2, 0.0, { 0, 0 }, { 0, 0 }, 0 };
  lac_pairing *P = NULL;
  lac_contact *c = NULL;
  check_status (lac_obstacle_pairing (&S, &ob, 0, &P), LAC_SUCCESS, "curved slave: pairing");
  check_status (lac_contact_build (m, LAC_PLANE_STRAIN, M, P, NULL, 1e-2, &c),
                LAC_SUCCESS, "curved slave: contact");
  double ex = 0, ey = 0, eG = 0, tilt = 0;
  for (size_t i = 0; c && i < c->k; i++)
    {
      double sx = 0, sy = 0, G = 0;
      for (int q = c->C->p[i]; q < c->C->p[i + 1]; q++)
        {
          if (c->C->i[q] % 2)
            sy += c->C->x[q];
          else
            sx += c->C->x[q];
        }
      size_t mm = c->macro[i];
      for (size_t j = M->ptr[mm]; j < M->ptr[mm + 1]; j++)
        for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
          {
            int nodes[9];
            lac_map mp;
            lac_contact_facet_eval (m, M->cell[j], M->face[j], P->xs + p, nodes, &mp);
            G += P->w[p] * mp.x[1];
            tilt = fmax (tilt, fabs (mp.normal[0]));
          }
      ex = fmax (ex, fabs (sx) / c->area[i]);
      ey = fmax (ey, fabs (sy + c->area[i]) / c->area[i]);
      eG = fmax (eG, fabs (c->G[i] - G) / fabs (G));
    }
  check_true (tilt > 0.1, "the slave normal is tilted (%.3f)", tilt);
  check_abs (ex, 0, 1e-14, "columns of C: no horizontal part");
  check_abs (ey, 0, 1e-14, "columns of C: -|T^m| vertically");
  check_abs (eG, 0, 1e-14, "G_i = int of the height");
  lac_contact_free (c);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

static void
rigid_patch (lac_elem_type type, double g0)
{
  const lac_refelem *re = lac_refelem_get (type);
  int dim = re->dim;
  size_t n[3] = { 3, 3, 2 };
  double L[3] = { 50, 50, 50 };
  lac_mesh *m = NULL;
  lac_mesh_box (type, n, L, 0.0, &m);
  for (size_t a = 0; a < m->nnodes; a++)
    m->x[a * dim + dim - 1] += 50.0;
  lac_macro *M = NULL;
  lac_macromesh_build (&m, dim == 2 ? "ymin" : "zmin", NULL, &M);
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_obstacle ob = { dim, 50.0 - g0, { 0, 0 }, { 0, 0 }, 0 };
  lac_pairing *P = NULL;
  lac_obstacle_pairing (&S, &ob, 0, &P);
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
  lac_assembly_pressure (m, mat.model, lac_mesh_group (m, dim == 2 ? "ymax" : "zmax"), 25.0, F);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  lac_dirichlet_add_group (D, m, lac_mesh_group (m, "xmin"), 0, 0.0);
  if (dim == 3)
    lac_dirichlet_add_group (D, m, lac_mesh_group (m, "ymin"), 1, 0.0);
  lac_dirichlet_apply (D, K, F);
  lac_contact *c = NULL;
  check_status (lac_contact_build (m, mat.model, M, P, NULL, 1e-2, &c), LAC_SUCCESS,
                "%s g0 = %g: contact", re->name, g0);
  lac_contact_apply_dirichlet (c, D->n, D->dof, D->val);
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  check_status (lac_newton_solve_system (LAC_STRATEGY_SADDLE, &sys, 10, 1e-10, &s), LAC_SUCCESS, "%s g0 = %g: newton", re->name, g0);
  check_int (s->restarted, g0 > 0, "%s g0 = %g: restart from all active", re->name, g0);
  double el = 0, es = 0, eu = 0, sig[6], xi[3] = { 0.2, 0.2, 0.2 };
  for (size_t i = 0; i < c->k; i++)
    el = fmax (el, fabs (s->lambda[i] + 25) / 25);
  for (size_t cc = 0; cc < m->ncells; cc++)
    {
      if (m->type[cc] == LAC_PYR5)
        xi[0] = xi[1] = 0.1;
      lac_post_stress_at (m, &mat, s->U, cc, xi, sig);
      es = fmax (es, fabs (sig[dim - 1] + 25) / 25);
    }
  const lac_group *bot = lac_mesh_group (m, dim == 2 ? "ymin" : "zmin");
  for (size_t k = 0; k < bot->nnodes; k++)
    eu = fmax (eu, fabs (s->U[bot->node[k] * dim + dim - 1] + g0));
  check_true (el <= 1e-12, "%s g0 = %g: lambda err %.2e", re->name, g0, el);
  check_true (es <= 1e-12, "%s g0 = %g: sigma err %.2e", re->name, g0, es);
  check_true (eu <= 1e-12, "%s g0 = %g: bottom moved by -g0 (err %.2e)", re->name, g0, eu);
  lac_newton_free (s);
  lac_contact_free (c);
  lac_dirichlet_free (D);
  free (F), free (E), free (nu);
  lac_csc_free (K);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  exact_gaps ();
  curved_on_flat ();
  const lac_elem_type types[] = { LAC_TRI3, LAC_QUAD4, LAC_TRI6, LAC_QUAD8,
                                  LAC_HEX8, LAC_TET10, LAC_HEX27 };
  for (size_t t = 0; t < sizeof types / sizeof *types; t++)
    {
      rigid_patch (types[t], 0.0);
      rigid_patch (types[t], 0.1);
    }
  lac_finalize ();
  return check_summary ();
}
