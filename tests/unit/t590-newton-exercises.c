/* t590-newton-exercises.c -- the answers of chapters/07-newton/exercises.md
 *                                                [LAC §4.5, (18), Alg. 1]
 *
 * Two stacked plane-strain quad8 blocks [0,50] x [0,50] and [0,50] x
 * [50+g0, 100+g0], meshed independently (4 x 4 below, 3 x 3 above), E =
 * 2000, nu = 0.3, E' = E / (1 - nu^2); the upper bottom is the slave.
 *
 * Exercise 1 (Taylor patch test, upper block held by the contact alone,
 *   p = 25 on top): one iteration (nhist == 1), lambda = -25 to 1e-12;
 *   with CHOLMOD the Schur path refuses K: LAC_ESING, message "singular".
 * Exercise 2 (lifting: rollers u_x = 0 on the left sides, upper top u_y = 0,
 *   lower bottom u_y = -w, w = 0.01): nhist == 2, final active set empty,
 *   lambda = 0, d_i = w |T^i| to 1e-12; the first iteration (all active)
 *   had every status change (nchanged == k).
 * Exercise 3 (the same rollers, lower bottom pushed up by w = 0.1, initial
 *   gap g0): g0 = 0 -> 1 iteration, all active; g0 = 0.05 -> 2 iterations
 *   (all inactive, then all active); g0 = 0.2 -> 1 iteration, none active,
 *   d_i = (g0 - w) |T^i|.  Where active, lambda = -E' (w - g0) / 100 to
 *   1e-10, the same with dense, UMFPACK and CHOLMOD (K is SPD here).
 * Exercise 4 (the example's spring chain): nhist == 3, active set {1},
 *   lambda_1 = -47/6, u_3 = 0.095, u_9 = 0.25, u_12 = 0.31 (1e-12), every
 *   back end; with rho_i = 1e-3 or 1e3 the same 3 iterations and the same
 *   solution (1e-12).
 * Exercise 5 (the example's tilted block): 3 iterations, active set
 *   AAAAAAA... (contact on [0, 35]), sum_i lambda_i |T^i| = -625 (1e-10),
 *   lambda_i d_i = 0.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

#define E_ 2000.0
#define NU 0.3

typedef struct problem
{
  lac_mesh *m;
  lac_macro *M;
  lac_pairing *P;
  lac_contact *c;
  lac_csc *K;
  double *F;
  double *E, *nu;
} problem;

enum { TAYLOR, LIFT, PUSH, TILT };

/* Build one of the set-ups above; w: the prescribed displacement of the
 * lower bottom (LIFT: -w, PUSH: +w), g0: the initial gap. */
static int
build (int kind, double w, double g0, problem *pb)
{
  size_t nlo[2] = { 4, 4 }, nup[2] = { 3, 3 };
  double L[2] = { 50, 50 };
  lac_mesh *lo = NULL, *up = NULL;
  int st;
  memset (pb, 0, sizeof *pb);
  if (kind == TILT)
    nlo[0] = 8, nup[0] = 10, nup[1] = 4;
  if ((st = lac_mesh_box (LAC_QUAD8, nlo, L, 0.0, &lo))
      || (st = lac_mesh_box (LAC_QUAD8, nup, L, 0.0, &up)))
    {
      lac_mesh_free (lo);
      return st;
    }
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 50.0 + g0;
  st = lac_mesh_merge (lo, "lo.", up, "up.", &pb->m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  if (st)
    return st;
  lac_mesh *m = pb->m;
  if (kind == TILT)          /* the load on x < 25 and the corner node */
    {
      const lac_group *top = lac_mesh_group (m, "up.ymax");
      size_t fc[64], nf = 0, corner = 0;
      int ff[64];
      for (size_t j = 0; j < top->n && nf < 64; j++)
        {
          int nodes[LAC_MAX_FACE_NODES];
          lac_elem_type ft;
          int nn = lac_mesh_facet_nodes (m, top->cell[j], top->face[j], nodes, &ft);
          double xc = 0;
          for (int a = 0; a < nn; a++)
            xc += m->x[2 * (size_t) nodes[a]] / nn;
          if (xc < 25)
            fc[nf] = top->cell[j], ff[nf++] = top->face[j];
        }
      for (size_t k = 0; k < top->nnodes; k++)
        if (m->x[2 * top->node[k]] == 0.0)
          corner = top->node[k];
      if ((st = lac_mesh_add_group (m, "up.load", 1, 0, nf, fc, ff))
          || (st = lac_mesh_add_node_group (m, "up.corner", 0, 0, 1, &corner)))
        return st;
    }
  if ((st = lac_macromesh_build (&pb->m, "up.ymin", NULL, &pb->M)))
    return st;
  m = pb->m;
  lac_pairing_facets S = { m, pb->M->ptr[pb->M->n], pb->M->cell, pb->M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (m, lac_mesh_group (m, "lo.ymax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  if ((st = lac_pairing_build (&S, &Mf, &po, &pb->P))
      || (st = lac_contact_build (m, LAC_PLANE_STRAIN, pb->M, pb->P, &Mf,
                                  LAC_EPSILON_DEFAULT, &pb->c)))
    return st;
  size_t ndof = 2 * m->nnodes;
  pb->E = malloc (m->ncells * sizeof *pb->E);
  pb->nu = malloc (m->ncells * sizeof *pb->nu);
  pb->F = calloc (ndof, sizeof *pb->F);
  for (size_t k = 0; k < m->ncells; k++)
    pb->E[k] = E_, pb->nu[k] = NU;
  lac_elastic mat = { LAC_PLANE_STRAIN, pb->E, pb->nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_assembly_stiffness (m, &mat, T);
  pb->K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  const lac_group *lob = lac_mesh_group (m, "lo.ymin");
  switch (kind)
    {
    case TAYLOR:
      lac_assembly_pressure (m, mat.model, lac_mesh_group (m, "up.ymax"), 25.0, pb->F);
      lac_dirichlet_add_group (D, m, lac_mesh_group (m, "lo.xmin"), 0, 0.0);
      lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.xmin"), 0, 0.0);
      lac_dirichlet_add_group (D, m, lob, 1, 0.0);
      break;
    case LIFT:
    case PUSH:
      lac_dirichlet_add_group (D, m, lac_mesh_group (m, "lo.xmin"), 0, 0.0);
      lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.xmin"), 0, 0.0);
      lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.ymax"), 1, 0.0);
      lac_dirichlet_add_group (D, m, lob, 1, kind == LIFT ? -w : w);
      break;
    case TILT:
      lac_assembly_pressure (m, mat.model, lac_mesh_group (m, "up.load"), 25.0, pb->F);
      lac_dirichlet_add_group (D, m, lob, 0, 0.0);
      lac_dirichlet_add_group (D, m, lob, 1, 0.0);
      lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.corner"), 0, 0.0);
      break;
    }
  st = lac_dirichlet_apply (D, pb->K, pb->F);
  if (!st)
    st = lac_contact_apply_dirichlet (pb->c, D->n, D->dof, D->val);
  lac_dirichlet_free (D);
  return st;
}

static void
release (problem *pb)
{
  lac_csc_free (pb->K);
  free (pb->F);
  free (pb->E);
  free (pb->nu);
  lac_contact_free (pb->c);
  lac_pairing_free (pb->P);
  lac_macromesh_free (pb->M);
  lac_mesh_free (pb->m);
}

static const lac_strategy_kind kinds[4] = { LAC_STRATEGY_DENSE, LAC_STRATEGY_SADDLE,
                                          LAC_STRATEGY_SCHUR, LAC_STRATEGY_AUGMENTED };

/* Solve; returns the workspace (caller frees) or NULL on failure. */
static lac_newton *
solve (const problem *pb, lac_strategy_kind kind, const double *rho, int *st)
{
  lac_contact_system sys = { pb->K, pb->F, pb->c->C, pb->c->G, rho, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  *st = lac_newton_solve_system (kind, &sys, 20, 1e-10, &s);
  return s;
}

static void
exercise1 (void)
{
  problem pb;
  int st = build (TAYLOR, 0, 0, &pb);
  check_status (st, LAC_SUCCESS, "ex1: set-up");
  if (!st)
    {
      for (int b = 0; b < 4; b++)
        {
          if (kinds[b] == LAC_STRATEGY_SCHUR)
            continue;            /* the upper block is held by contact alone */
          lac_newton *s = solve (&pb, kinds[b], NULL, &st);
          check_status (st, LAC_SUCCESS, "ex1 %s: solve", lac_strategy_name (kinds[b]));
          check_int ((long) s->nhist, 1, "ex1 %s: one iteration", lac_strategy_name (kinds[b]));
          check_int ((long) lac_newton_nactive (s), (long) pb.c->k, "ex1: all active");
          for (size_t i = 0; i < pb.c->k; i++)
            check_rel (s->lambda[i], -25, 1e-12, "ex1 %s: lambda_%zu",
                       lac_strategy_name (kinds[b]), i);
          lac_newton_free (s);
        }
      lac_newton *s = solve (&pb, LAC_STRATEGY_SCHUR, NULL, &st);
      check_status (st, LAC_ESING, "ex1: schur refuses the singular K");
      check_message ("singular", "ex1: schur message");
      lac_newton_free (s);
    }
  release (&pb);
}

static void
exercise2 (void)
{
  problem pb;
  double w = 0.01;
  int st = build (LIFT, w, 0, &pb);
  check_status (st, LAC_SUCCESS, "ex2: set-up");
  for (int b = 0; !st && b < 4; b++)
    {
      const char *kn = lac_strategy_name (kinds[b]);
      lac_newton *s = solve (&pb, kinds[b], NULL, &st);
      check_status (st, LAC_SUCCESS, "ex2 %s: solve", kn);
      if (!st)
        {
          check_int ((long) s->nhist, 2, "ex2 %s: two iterations", kn);
          check_int ((long) s->hist[0].nactive, (long) pb.c->k, "ex2 %s: starts all active", kn);
          check_int ((long) s->hist[1].nchanged, (long) pb.c->k, "ex2 %s: all released at once", kn);
          check_int ((long) lac_newton_nactive (s), 0, "ex2 %s: none active", kn);
          for (size_t i = 0; i < pb.c->k; i++)
            {
              check_abs (s->lambda[i], 0, 0, "ex2 %s: lambda_%zu = 0", kn, i);
              check_rel (s->d[i], w * pb.c->area[i], 1e-12, "ex2 %s: d_%zu = w area", kn, i);
            }
        }
      lac_newton_free (s);
    }
  release (&pb);
}

/* The statuses of s's first iteration (initial: 1) or at its end, in
 * words: all, none, or how many of k. */
static const char *
statuses (const lac_newton *s, size_t k, int initial, char *buf, size_t n)
{
  size_t a = initial ? s->hist[0].nactive : (size_t) lac_newton_nactive (s);
  if (initial)
    snprintf (buf, n, "%s", a == k ? "all active" : a == 0 ? "all inactive" : "mixed");
  else if (a == k || a == 0)
    snprintf (buf, n, "%s", a == k ? "all" : "none");
  else
    snprintf (buf, n, "%zu of %zu", a, k);
  return buf;
}

static void
exercise3 (void)
{
  static const double g0s[3] = { 0.0, 0.05, 0.2 };
  static const long it[3] = { 1, 2, 1 };
  double w = 0.1, Ep = E_ / (1 - NU * NU);
  /* LAC_DOC_TABLE=ex3: the answer's table (the dense strategy's run) */
  if (check_doc_table ("ex3"))
    printf ("| $g_0$ | initial statuses | iterations | final active set | $\\lambda_i$ |\n"
            "|---|---|---|---|---|\n");
  for (int g = 0; g < 3; g++)
    {
      problem pb;
      double g0 = g0s[g];
      int st = build (PUSH, w, g0, &pb);
      check_status (st, LAC_SUCCESS, "ex3 g0 = %g: set-up", g0);
      for (int b = 0; !st && b < 4; b++)
        {
          const char *kn = lac_strategy_name (kinds[b]);
          lac_newton *s = solve (&pb, kinds[b], NULL, &st);
          check_status (st, LAC_SUCCESS, "ex3 g0 = %g %s: solve", g0, kn);
          if (!st)
            {
              check_int ((long) s->nhist, it[g], "ex3 g0 = %g %s: iterations", g0, kn);
              check_int ((long) s->hist[0].nactive, g0 > 0 ? 0 : (long) pb.c->k,
                         "ex3 g0 = %g %s: initial active set", g0, kn);
              check_int ((long) lac_newton_nactive (s), g0 < w ? (long) pb.c->k : 0,
                         "ex3 g0 = %g %s: final active set", g0, kn);
              for (size_t i = 0; i < pb.c->k; i++)
                {
                  if (g0 < w)
                    check_rel (s->lambda[i], -Ep * (w - g0) / 100, 1e-10,
                               "ex3 g0 = %g %s: lambda_%zu", g0, kn, i);
                  else
                    {
                      check_abs (s->lambda[i], 0, 0, "ex3 g0 = %g: lambda 0", g0);
                      check_rel (s->d[i], (g0 - w) * pb.c->area[i], 1e-12,
                                 "ex3 g0 = %g %s: d_%zu", g0, kn, i);
                    }
                }
              if (b == 0 && check_doc_table ("ex3"))
                {
                  char s0[32], s1[32];
                  printf ("| %g | %s | %zu | %s | %.4f |\n", g0,
                          statuses (s, pb.c->k, 1, s0, sizeof s0), s->nhist,
                          statuses (s, pb.c->k, 0, s1, sizeof s1),
                          s->lambda[0] + 0.0);
                }
            }
          lac_newton_free (s);
        }
      release (&pb);
    }
}

/* The example's chain: 13 dofs, dof 0 fixed, springs 100, unit loads,
 * obstacles at 3, 6, 9, 12 with gaps 0.3, 0.1, 2.0, 0.5. */
static void
exercise4 (void)
{
  enum { N = 13, KC = 4 };
  static const int at[KC] = { 3, 6, 9, 12 };
  double gap[KC] = { 0.3, 0.1, 2.0, 0.5 }, F[N];
  lac_triplet *T = lac_triplet_alloc (N, N, 3 * N);
  lac_triplet_add (T, 0, 0, 1.0);
  for (int j = 1; j < N; j++)
    {
      lac_triplet_add (T, j, j, j + 1 < N ? 200.0 : 100.0);
      if (j + 1 < N)
        {
          lac_triplet_add (T, j, j + 1, -100.0);
          lac_triplet_add (T, j + 1, j, -100.0);
        }
    }
  lac_csc *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  T = lac_triplet_alloc (N, KC, KC);
  for (int i = 0; i < KC; i++)
    lac_triplet_add (T, at[i], i, 1.0);
  lac_csc *C = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  for (int j = 0; j < N; j++)
    F[j] = j == 0 ? 0.0 : 1.0;
  static const double rhos[3] = { 1.0, 1e-3, 1e3 };
  for (int r = 0; r < 3; r++)
    {
      double rho[KC] = { rhos[r], rhos[r], rhos[r], rhos[r] };
      lac_contact_system sys = { K, F, C, gap, r ? rho : NULL, 0, NULL, NULL, NULL };
      for (int b = 0; b < 4; b++)
        {
          const char *kn = lac_strategy_name (kinds[b]);
          lac_newton *s = NULL;
          int st = lac_newton_solve_system (kinds[b], &sys, 20, 1e-10, &s);
          check_status (st, LAC_SUCCESS, "ex4 %s rho = %g: solve", kn, rhos[r]);
          if (!st)
            {
              check_int ((long) s->nhist, 3, "ex4 %s rho = %g: three iterations",
                         kn, rhos[r]);
              check_int ((long) lac_newton_nactive (s), 1, "ex4 %s rho = %g: one active", kn, rhos[r]);
              check_true (s->active[1], "ex4 %s rho = %g: the obstacle at dof 6", kn, rhos[r]);
              check_rel (s->lambda[1], -47.0 / 6, 1e-12, "ex4 %s rho = %g: lambda_1", kn, rhos[r]);
              check_rel (s->U[3], 0.095, 1e-12, "ex4 %s rho = %g: u_3", kn, rhos[r]);
              check_rel (s->U[6], 0.1, 1e-12, "ex4 %s rho = %g: u_6", kn, rhos[r]);
              check_rel (s->U[9], 0.25, 1e-12, "ex4 %s rho = %g: u_9", kn, rhos[r]);
              check_rel (s->U[12], 0.31, 1e-12, "ex4 %s rho = %g: u_12", kn, rhos[r]);
              if (getenv ("LAC_TEST_VERBOSE"))
                printf ("ex4 %s rho = %g: %zu iterations\n", kn, rhos[r], s->nhist);
            }
          lac_newton_free (s);
        }
    }
  lac_csc_free (C);
  lac_csc_free (K);
}

static void
exercise5 (void)
{
  problem pb;
  int st = build (TILT, 0, 0, &pb);
  check_status (st, LAC_SUCCESS, "ex5: set-up");
  for (int b = 0; !st && b < 2; b++)
    {
      const char *kn = lac_strategy_name (kinds[b]);
      lac_newton *s = solve (&pb, kinds[b], NULL, &st);
      check_status (st, LAC_SUCCESS, "ex5 %s: solve", kn);
      if (!st)
        {
          check_int ((long) s->nhist, 3, "ex5 %s: three iterations", kn);
          check_int ((long) pb.c->k, 10, "ex5: ten multipliers");
          double f = 0;
          for (size_t i = 0; i < pb.c->k; i++)
            {
              check_int (s->active[i], i < 7, "ex5 %s: status %zu", kn, i);
              check_abs (s->lambda[i] * s->d[i], 0, 1e-10, "ex5 %s: complementarity %zu", kn, i);
              f += s->lambda[i] * pb.c->area[i];
            }
          check_rel (f, -625, 1e-10, "ex5 %s: total force", kn);
        }
      lac_newton_free (s);
    }
  release (&pb);
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
