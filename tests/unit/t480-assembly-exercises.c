/* t480-assembly-exercises.c -- the answers of
 *                          chapters/06-assembly/exercises.md  [LAC (16)-(18)]
 *
 * Set-ups: two stacked blocks meshed independently (non-matching
 * interfaces), the upper one the slave, flat interface, n^S = -e_d.
 *
 * Exercise 1 (the example's table): C^M(node at x = 10, T^0 = [0,15]) =
 *   int_0^15 hat_10 = 8.75, C^S(slave node at 15, T^0) = -3.75,
 *   C^S(slave node at 7.5, T^0) = -7.5, area = 15, G = 7.5, to 1e-12.
 * Exercise 2 (partition of unity): for every multiplier i,
 *   sum over slave dofs of C(dof, i) n^S_c = |T^i cap Gamma_C| = area_i,
 *   sum over master dofs = -area_i, sum of area_i = |Gamma_C|, to 1e-12 --
 *   quad4, quad8, tri6 (2D), tet4, hex8, hex27 (3D), and axisymmetric quad8
 *   (area_i = pi (r1^2 - r0^2), 2 pi r weighted).
 * Exercise 3 (rigid motions): u = t n^S on the slave body gives C^T U =
 *   t area; on the master body -t area; on both 0; a tangential
 *   translation 0 (to 1e-12 |t| area).
 * Exercise 4 (mean gaps): a constant initial gap g0 gives G = g0 area; the
 *   example's slope b (g0(x) = 0.5 + b x) gives G_i = area_i (0.5 + b
 *   xbar_i) = 8.625 and 10.875 for b = 0.01, to 1e-12.
 * Exercise 5 (Dirichlet data on the master): a rigid foundation raised by w
 *   gives G_i - w area_i and zero master rows in C.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "base/lac_status.h"

#define PI 3.14159265358979323846

typedef struct setup
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_pairing *P;
  lac_contact *c;
  size_t nmaster;   /* nodes [0, nmaster) belong to the master body */
  int dim;
} setup;

/* Lower block [0,30] x [0,10] (x [0,30]) with nlo cells, upper block lifted
 * by g0, nup cells; slope b: top of the lower block at y = 10 - b x. */
static int
build (lac_elem_type type, const size_t *nlo, const size_t *nup,
       lac_model model, double g0, double slope, setup *s)
{
  int dim = lac_refelem_get (type)->dim;
  double L[3] = { 30, 10, 30 };
  if (dim == 3)
    L[1] = 30, L[2] = 10;
  lac_mesh *lo = NULL, *up = NULL;
  int st;
  s->mesh = NULL;
  s->M = NULL;
  s->P = NULL;
  s->c = NULL;
  s->dim = dim;
  if ((st = lac_mesh_box (type, nlo, L, 0.0, &lo))
      || (st = lac_mesh_box (type, nup, L, 0.0, &up)))
    {
      lac_mesh_free (lo);
      return st;
    }
  for (size_t a = 0; a < lo->nnodes; a++)
    lo->x[a * dim + dim - 1] -= lo->x[a * dim + dim - 1] / 10 * slope * lo->x[a * dim];
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[a * dim + dim - 1] += 10.0 + g0;
  s->nmaster = lo->nnodes;
  st = lac_mesh_merge (lo, "lo.", up, "up.", &s->mesh);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  if (st)
    return st;
  st = lac_macromesh_build (&s->mesh, dim == 2 ? "up.ymin" : "up.zmin", NULL,
                            &s->M);
  if (st)
    return st;
  lac_pairing_facets S = { s->mesh, s->M->ptr[s->M->n], s->M->cell, s->M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (s->mesh,
      lac_mesh_group (s->mesh, dim == 2 ? "lo.ymax" : "lo.zmax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  st = lac_pairing_build (&S, &Mf, &po, &s->P);
  if (!st)
    st = lac_contact_build (s->mesh, model, s->M, s->P, &Mf,
                            LAC_EPSILON_DEFAULT, &s->c);
  return st;
}

static void
release (setup *s)
{
  lac_contact_free (s->c);
  lac_pairing_free (s->P);
  lac_macromesh_free (s->M);
  lac_mesh_free (s->mesh);
}

/* The entry C(dof, i) (0 if not stored). */
static double
entry (const lac_csc *C, size_t dof, size_t i)
{
  double v = 0;
  for (int p = C->p[i]; p < C->p[i + 1]; p++)
    if ((size_t) C->i[p] == dof)
      v += C->x[p];
  return v;
}

/* (C^T U)_i for U = t on the chosen bodies (1 slave, 2 master, 3 both). */
static double
ctu (const setup *s, size_t i, const double *t, int which)
{
  const lac_csc *C = s->c->C;
  double v = 0;
  for (int p = C->p[i]; p < C->p[i + 1]; p++)
    {
      size_t a = (size_t) C->i[p] / s->dim;
      int comp = C->i[p] % s->dim;
      int master = a < s->nmaster;
      if ((master && (which & 2)) || (!master && (which & 1)))
        v += C->x[p] * t[comp];
    }
  return v;
}

static void
exercise1 (void)
{
  size_t nlo[2] = { 3, 1 }, nup[2] = { 4, 1 };
  setup s;
  int st = build (LAC_QUAD4, nlo, nup, LAC_PLANE_STRAIN, 0.5, 0.0, &s);
  check_status (st, LAC_SUCCESS, "ex1: set-up");
  if (!st)
    {
      check_int ((long) s.c->k, 2, "ex1: two multipliers");
      /* lower nodes 0-3 bottom, 4-7 top (x = 0, 10, 20, 30); upper 8-12
       * bottom (x = 0, 7.5, 15, 22.5, 30) */
      check_rel (entry (s.c->C, 2 * 5 + 1, 0), 8.75, 1e-12, "ex1: C^M(x=10, T^0)");
      check_rel (entry (s.c->C, 2 * 4 + 1, 0), 5.0, 1e-12, "ex1: C^M(x=0, T^0)");
      check_rel (entry (s.c->C, 2 * 6 + 1, 0), 1.25, 1e-12, "ex1: C^M(x=20, T^0)");
      check_rel (entry (s.c->C, 2 * 10 + 1, 0), -3.75, 1e-12, "ex1: C^S(x=15, T^0)");
      check_rel (entry (s.c->C, 2 * 9 + 1, 0), -7.5, 1e-12, "ex1: C^S(x=7.5, T^0)");
      check_abs (entry (s.c->C, 2 * 11 + 1, 0), 0.0, 1e-14, "ex1: C^S(x=22.5, T^0)");
      check_abs (entry (s.c->C, 2 * 5, 0), 0.0, 1e-14, "ex1: x rows vanish");
      for (size_t i = 0; i < 2; i++)
        {
          check_rel (s.c->area[i], 15.0, 1e-12, "ex1: area %zu", i);
          check_rel (s.c->G[i], 7.5, 1e-12, "ex1: G %zu", i);
        }
    }
  release (&s);
}

static void
exercise2 (void)
{
  static const struct
  {
    lac_elem_type type;
    lac_model model;
    size_t nlo[3], nup[3];
  } cases[] = {
    { LAC_QUAD4, LAC_PLANE_STRAIN, { 3, 1, 1 }, { 4, 1, 1 } },
    { LAC_QUAD8, LAC_PLANE_STRAIN, { 4, 2, 1 }, { 3, 2, 1 } },
    { LAC_TRI6, LAC_PLANE_STRAIN, { 5, 1, 1 }, { 3, 1, 1 } },
    { LAC_QUAD8, LAC_AXISYMMETRIC, { 4, 2, 1 }, { 3, 2, 1 } },
    { LAC_TET4, LAC_SOLID3D, { 3, 3, 1 }, { 2, 2, 1 } },
    { LAC_HEX8, LAC_SOLID3D, { 3, 3, 1 }, { 2, 2, 1 } },
    { LAC_HEX27, LAC_SOLID3D, { 3, 3, 1 }, { 2, 2, 1 } },
  };
  for (size_t t = 0; t < sizeof cases / sizeof *cases; t++)
    {
      const char *tn = lac_refelem_get (cases[t].type)->name;
      int axi = cases[t].model == LAC_AXISYMMETRIC;
      setup s;
      int st = build (cases[t].type, cases[t].nlo, cases[t].nup,
                      cases[t].model, 0.0, 0.0, &s);
      check_status (st, LAC_SUCCESS, "ex2 %s%s: set-up", tn, axi ? " axi" : "");
      if (st)
        {
          release (&s);
          continue;
        }
      int d = s.dim;
      double total = 0, nS[3] = { 0, 0, 0 };
      nS[d - 1] = -1;
      for (size_t i = 0; i < s.c->k; i++)
        {
          double a = s.c->area[i];
          check_rel (ctu (&s, i, nS, 1), a, 1e-12, "ex2 %s%s: slave sum %zu",
                     tn, axi ? " axi" : "", i);
          check_rel (ctu (&s, i, nS, 2), -a, 1e-12, "ex2 %s%s: master sum %zu",
                     tn, axi ? " axi" : "", i);
          if (axi)
            {
              double r0 = INFINITY, r1 = -INFINITY;
              int nodes[LAC_MAX_FACE_NODES];
              lac_elem_type ft;
              size_t m = s.c->macro[i];
              for (size_t j = s.M->ptr[m]; j < s.M->ptr[m + 1]; j++)
                {
                  int nn = lac_mesh_facet_nodes (s.mesh, s.M->cell[j],
                                                 s.M->face[j], nodes, &ft);
                  for (int b = 0; b < nn; b++)
                    {
                      r0 = fmin (r0, s.mesh->x[2 * (size_t) nodes[b]]);
                      r1 = fmax (r1, s.mesh->x[2 * (size_t) nodes[b]]);
                    }
                }
              check_rel (a, PI * (r1 * r1 - r0 * r0), 1e-12,
                         "ex2 axi: area %zu = pi (r1^2 - r0^2)", i);
            }
          total += a;
        }
      double gc = axi ? PI * 900 : d == 2 ? 30 : 900;
      check_rel (total, gc, 1e-12, "ex2 %s%s: |Gamma_C|", tn, axi ? " axi" : "");
      release (&s);
    }
}

static void
exercise3 (void)
{
  static const struct
  {
    lac_elem_type type;
    size_t nlo[3], nup[3];
  } cases[] = {
    { LAC_QUAD4, { 3, 1, 1 }, { 4, 1, 1 } },
    { LAC_QUAD8, { 4, 2, 1 }, { 3, 2, 1 } },
    { LAC_HEX8, { 3, 3, 1 }, { 2, 2, 1 } },
  };
  for (size_t t = 0; t < sizeof cases / sizeof *cases; t++)
    {
      const char *tn = lac_refelem_get (cases[t].type)->name;
      setup s;
      int st = build (cases[t].type, cases[t].nlo, cases[t].nup,
                      lac_refelem_get (cases[t].type)->dim == 2
                      ? LAC_PLANE_STRAIN : LAC_SOLID3D, 0.0, 0.0, &s);
      check_status (st, LAC_SUCCESS, "ex3 %s: set-up", tn);
      if (st)
        {
          release (&s);
          continue;
        }
      int d = s.dim;
      double tn_[3] = { 0, 0, 0 }, tt[3] = { 0.3, 0.2, 0 };
      tn_[d - 1] = -0.01;                                /* t n^S, t = 0.01 */
      tt[d - 1] = 0;                                     /* tangential */
      for (size_t i = 0; i < s.c->k; i++)
        {
          double a = s.c->area[i];
          check_rel (ctu (&s, i, tn_, 1), 0.01 * a, 1e-12, "ex3 %s: slave %zu", tn, i);
          check_rel (ctu (&s, i, tn_, 2), -0.01 * a, 1e-12, "ex3 %s: master %zu", tn, i);
          check_abs (ctu (&s, i, tn_, 3), 0, 1e-12 * 0.01 * a, "ex3 %s: both %zu", tn, i);
          check_abs (ctu (&s, i, tt, 3), 0, 1e-12 * a, "ex3 %s: tangential %zu", tn, i);
          check_abs (ctu (&s, i, tt, 1), 0, 1e-12 * a, "ex3 %s: tangential slave %zu", tn, i);
        }
      release (&s);
    }
}

static void
exercise4 (void)
{
  size_t nlo[3] = { 3, 1, 1 }, nup[3] = { 4, 1, 1 };
  size_t nlo8[3] = { 4, 2, 1 }, nup8[3] = { 3, 2, 1 };
  setup s;
  /* constant gap, quad4 and quad8 */
  for (int q = 0; q < 2; q++)
    {
      int st = build (q ? LAC_QUAD8 : LAC_QUAD4, q ? nlo8 : nlo, q ? nup8 : nup,
                      LAC_PLANE_STRAIN, 0.37, 0.0, &s);
      check_status (st, LAC_SUCCESS, "ex4 constant: set-up");
      for (size_t i = 0; !st && i < s.c->k; i++)
        check_rel (s.c->G[i], 0.37 * s.c->area[i], 1e-12, "ex4: G = g0 area (%d, %zu)", q, i);
      release (&s);
    }
  /* the example's slope */
  int st = build (LAC_QUAD4, nlo, nup, LAC_PLANE_STRAIN, 0.5, 0.01, &s);
  check_status (st, LAC_SUCCESS, "ex4 slope: set-up");
  if (!st)
    {
      check_rel (s.c->G[0], 15 * (0.5 + 0.01 * 7.5), 1e-12, "ex4: G_0 = 8.625");
      check_rel (s.c->G[1], 15 * (0.5 + 0.01 * 22.5), 1e-12, "ex4: G_1 = 10.875");
      check_rel (s.c->G[0], 8.625, 1e-12, "ex4: G_0 value");
      check_rel (s.c->G[1], 10.875, 1e-12, "ex4: G_1 value");
    }
  release (&s);
}

static void
exercise5 (void)
{
  size_t nlo[3] = { 3, 1, 1 }, nup[3] = { 4, 1, 1 };
  setup s;
  int st = build (LAC_QUAD4, nlo, nup, LAC_PLANE_STRAIN, 0.5, 0.0, &s);
  check_status (st, LAC_SUCCESS, "ex5: set-up");
  if (st)
    {
      release (&s);
      return;
    }
  double w = 0.8, G0[2] = { s.c->G[0], s.c->G[1] };
  lac_dirichlet *D = lac_dirichlet_alloc ();
  const lac_group *body = lac_mesh_group (s.mesh, "lo.body");
  check_true (body != NULL, "ex5: group lo.body");
  lac_dirichlet_add_group (D, s.mesh, body, 0, 0.0);
  lac_dirichlet_add_group (D, s.mesh, body, 1, w);
  check_status (lac_contact_apply_dirichlet (s.c, D->n, D->dof, D->val),
                LAC_SUCCESS, "ex5: apply");
  for (size_t i = 0; i < 2; i++)
    {
      check_rel (s.c->G[i], G0[i] - w * s.c->area[i], 1e-12, "ex5: G_%zu - w area", i);
      check_rel (s.c->G[i], -4.5, 1e-12, "ex5: G_%zu = -4.5", i);
      double nS[2] = { 0, -1 };
      check_abs (ctu (&s, i, nS, 2), 0, 0, "ex5: master rows zeroed (%zu)", i);
      check_rel (ctu (&s, i, nS, 1), s.c->area[i], 1e-12, "ex5: slave rows kept (%zu)", i);
    }
  lac_dirichlet_free (D);
  release (&s);
}

int
main (void)
{
  lac_init ();
  exercise1 ();
  exercise2 ();
  exercise3 ();
  exercise4 ();
  exercise5 ();
  lac_finalize ();
  return check_summary ();
}
