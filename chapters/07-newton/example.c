/* LAC chapter 07 -- The generalized Newton method (active set)
 *                                               [LAC §4.5, (18), Alg. 1]
 *
 * Build:        make build/chapters/07-newton
 * Sample runs:  build/chapters/07-newton                 (UMFPACK)
 *               build/chapters/07-newton --strategy dense
 *               build/chapters/07-newton --strategy schur   (part 1 refused)
 * Description:  Part 1: a block [0,50] x [50,100] (quad8) rests on a lower
 *               block [0,50] x [0,50]; a pressure on the LEFT half of its
 *               top tilts it, so the right part of the interface opens.
 *               The loop of [LAC Alg. 1] is driven step by step on the
 *               linear model of this system (lac_linear_model_init,
 *               lac_newton_begin / _iterate) and the statuses of the 10
 *               macro-elements are printed after every iteration, with
 *               the history records; then the final pressures.  The upper
 *               block is held by the contact alone: K is singular, so the
 *               saddle-point path (UMFPACK or dense LU) is needed.
 *               Part 2: a chain of springs pushed against obstacles; K is
 *               SPD and the Schur-complement path (CHOLMOD, one
 *               factorization) solves it.  Short, deterministic output.
 * Read first:   chapter 06 (C, G and the sign convention).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "base/lac_mem.h"
#include "solve/lac_linear_model.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

// @sect Printing the statuses
/* The program drives the loop of Algorithm 1 itself and prints what it
 * does; these helpers turn its state into short, solver-independent
 * text.  First, a library call that fails stops the program with the
 * one-line message the library stored (library code never prints). */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex07: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* The statuses as a string: A active (in contact), . inactive. */
static const char *
statuses (const lac_newton *s)
{
  static char buf[128];
  size_t k = s->nslot < sizeof buf - 1 ? s->nslot : sizeof buf - 1;
  for (size_t i = 0; i < k; i++)
    buf[i] = s->active[i] ? 'A' : '.';
  buf[k] = 0;
  return buf;
}

/* A non-negative number, or "<1e-10" when it is below the tolerance of
 * the test (roundoff: so that the output is the same with every solver). */
static const char *
small (double v, char *buf)
{
  if (fabs (v) < 1e-10)
    return "  <1e-10";
  snprintf (buf, 16, "%8.1e", v);
  return buf;
}

/* The x-range of macro-element k: its sub-facets' node abscissae. */
static void
macro_range (const lac_mesh *m, const lac_macro *M, size_t k, double *x0,
             double *x1)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  *x0 = INFINITY;
  *x1 = -INFINITY;
  for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
    {
      int nn = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], nodes, &ft);
      for (int a = 0; a < nn; a++)
        {
          *x0 = fmin (*x0, m->x[2 * (size_t) nodes[a]]);
          *x1 = fmax (*x1, m->x[2 * (size_t) nodes[a]]);
        }
    }
}

// @sect The loop of Algorithm 1, one iteration at a time
/* lac_newton_solve would run the whole loop; here it is opened up:
 * lac_newton_begin sets the initial statuses from the gaps (lines 2-8),
 * then each call of lac_newton_iterate evaluates the model, updates the
 * statuses (lines 26-33), tests (line 10) and, unless the test passed,
 * solves the saddle system of the active set (line 21) and updates U and
 * lambda (lines 22-24).  Its record, s->hist, is what this function
 * prints.
 *
 * The loop of [LAC Alg. 1] on the linear model of sys (K, C, G
 * constant: lac_linear_model.h), one line per iteration: the statuses of
 * its solve, how many are active and how many the rule changed to get
 * them, and the residuals of the test at the iterate it started from. */
static lac_newton *
run (lac_strategy_kind kind, const lac_contact_system *sys,
     lac_linear_model *lin, int maxit)
{
  lac_contact_model model;
  lac_newton_opts o;
  check_status (lac_linear_model_init (lin, sys, 0, &model),
                "lac_linear_model_init");
  lac_newton_opts_init (&o);
  o.kind = kind;
  o.maxit = maxit;
  lac_newton *s = lac_newton_alloc (&model, &o);
  check_status (s ? LAC_SUCCESS : LAC_ENOMEM, "lac_newton_alloc");
  check_status (lac_newton_begin (s), "lac_newton_begin");
  printf ("   it  active set used  #act  #chg  residual  gap res.  max pen.\n");
  int st;
  while ((st = lac_newton_iterate (s)) == LAC_CONTINUE)
    {
      char b1[16], b2[16], b3[16];
      const lac_newton_record *r = &s->hist[s->nhist - 1];
      printf ("   %2d  %-15s  %4zu  %4zu  %s  %s  %s\n", r->iter,
              statuses (s), r->nactive, r->nchanged,
              small (r->residual, b1), small (r->gap_residual, b2),
              small (fmax (r->max_penetration, 0), b3));
    }
  check_status (st, "Algorithm 1");
  printf ("       %-15s  converged: no status changed\n", statuses (s));
  return s;
}

// @sect Part 1: a tilted block
/* A block resting on another, pressed on the left half of its top only:
 * the right part of the interface lifts off, so the loop has to find which
 * macro-elements stay in contact.  Nothing holds the upper block
 * vertically but the contact, which decides the strategies that apply. */
static void
tilted_block (lac_strategy_kind kind)
{
  // @sect Two blocks, meshed independently
  /* 1. Two quad8 blocks stacked, meshed independently (8 x 4 below, 10 x 4
   *    above), E = 2000, nu = 0.3, plane strain.  The slave is the bottom
   *    of the upper block: 10 seg3 macro-elements of length 5. */
  size_t nlo[2] = { 8, 4 }, nup[2] = { 10, 4 };
  double L[2] = { 50, 50 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  check_status (lac_mesh_box (LAC_QUAD8, nlo, L, 0.0, &lo), "lac_mesh_box");
  check_status (lac_mesh_box (LAC_QUAD8, nup, L, 0.0, &up), "lac_mesh_box");
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 50.0;
  check_status (lac_mesh_merge (lo, "lo.", up, "up.", &m), "lac_mesh_merge");
  lac_mesh_free (lo);
  lac_mesh_free (up);

  // @sect The load and the supports
  /* 2. The load: a pressure p = 25 on the left half of the top only (a
   *    facet group made of the top facets with x < 25), and the supports:
   *    the lower block clamped at its bottom, the upper block held in x at
   *    its top-left corner only, so that it is free to sink and to tilt;
   *    only the contact holds it vertically. */
  const lac_group *top = lac_mesh_group (m, "up.ymax");
  size_t *fc = lac_malloc (top->n * sizeof *fc), nf = 0, corner = 0;
  int *ff = lac_malloc (top->n * sizeof *ff);
  check_status (fc && ff ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t j = 0; j < top->n; j++)
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
  check_status (lac_mesh_add_group (m, "up.load", 1, 0, nf, fc, ff), "add_group");
  check_status (lac_mesh_add_node_group (m, "up.corner", 0, 0, 1, &corner),
                "add_node_group");
  lac_free (fc);
  lac_free (ff);

  // @sect The contact matrices and the stiffness
  /* 3. Macro-mesh, pairing, C and G (chapters 05, 06), then K and F with
   *    the Dirichlet conditions eliminated, in K and in C/G alike. */
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, "up.ymin", NULL, &M), "macromesh");
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (m, lac_mesh_group (m, "lo.ymax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P = NULL;
  check_status (lac_pairing_build (&S, &Mf, &po, &P), "lac_pairing_build");
  lac_contact *c = NULL;
  check_status (lac_contact_build (m, LAC_PLANE_STRAIN, M, P, &Mf,
                                   LAC_EPSILON_DEFAULT, &c), "lac_contact_build");
  size_t ndof = 2 * m->nnodes;
  double *Ec = lac_malloc (m->ncells * sizeof *Ec);
  double *nuc = lac_malloc (m->ncells * sizeof *nuc);
  double *F = lac_calloc (ndof, sizeof *F);
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  check_status (Ec && nuc && F && T && D ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t k = 0; k < m->ncells; k++)
    Ec[k] = 2000, nuc[k] = 0.3;
  lac_elastic mat = { LAC_PLANE_STRAIN, Ec, nuc };
  check_status (lac_assembly_stiffness (m, &mat, T), "lac_assembly_stiffness");
  lac_csc *K = lac_csc_from_triplet (T);
  check_status (K ? LAC_SUCCESS : LAC_ENOMEM, "lac_csc_from_triplet");
  check_status (lac_assembly_pressure (m, mat.model, lac_mesh_group (m, "up.load"),
                                       25.0, F), "lac_assembly_pressure");
  const lac_group *bot = lac_mesh_group (m, "lo.ymin");
  check_status (lac_dirichlet_add_group (D, m, bot, 0, 0.0), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, bot, 1, 0.0), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.corner"),
                                         0, 0.0), "dirichlet");
  check_status (lac_dirichlet_apply (D, K, F), "lac_dirichlet_apply");
  check_status (lac_contact_apply_dirichlet (c, D->n, D->dof, D->val),
                "lac_contact_apply_dirichlet");
  printf ("1. tilted block: %zu dofs, %zu multipliers, p = 25 on x < 25, %s\n",
          ndof, c->k, lac_strategy_name (kind));

  // @sect The loop on the tilted block
  /* 4. The loop.  G = 0 (the blocks touch), so every macro-element starts
   *    active.  Each iteration updates the statuses (active iff
   *    lambda_i + rho_i d_i < 0), tests, then solves the saddle system
   *    for the active set A (identity rows lambda_i = 0 for the others). */
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_linear_model lin;
  lac_newton *s = NULL;
  if (kind == LAC_STRATEGY_SCHUR)
    {
      /* The Schur strategy factorizes K alone: singular here (the upper
       * block has no vertical support but the contact, one free rigid
       * motion), and it is refused before anything is factorized. */
      lac_strategy_kind k1 = lac_strategy_choose (kind, ndof, c->k, 1);
      printf ("   schur refused, as it must: %s\n",
              k1 == LAC_NSTRATEGIES ? lac_error_message () : "(no error?)");
    }
  else
    {
      s = run (kind, &sys, &lin, 20);

      // @sect Complementarity in the result
      /* 5. The result: lambda per macro-element (<= 0, 0 where open) and
       *    the mean gap d_i / |T^i| (0 where active, > 0 where open); their
       *    product vanishes: complementarity.  The total contact force
       *    sum_i lambda_i |T^i| balances the load, -25 x 25. */
      double total = 0;
      printf ("   i  x-range         lambda_i   d_i/|T^i|\n");
      for (size_t i = 0; i < c->k; i++)
        {
          double x0, x1;
          macro_range (m, M, c->macro[i], &x0, &x1);
          printf ("   %zu  [%4.1f, %4.1f]  %9.4f   %9.2e\n", i, x0, x1,
                  s->lambda[i] + 0.0, fabs (s->d[i]) < 1e-12 ? 0.0 : s->d[i] / c->area[i]);
          total += s->lambda[i] * c->area[i];
        }
      printf ("   sum lambda_i |T^i| = %.6f (load: -625)\n", total);
      lac_newton_free (s);
      lac_linear_model_clear (&lin);
    }
  /* Everything the program allocated, freed in the reverse order. */
  lac_dirichlet_free (D);
  lac_triplet_free (T);
  lac_csc_free (K);
  lac_free (F);
  lac_free (nuc);
  lac_free (Ec);
  lac_contact_free (c);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

// @sect Part 2: springs against obstacles
/* The same loop on a problem small enough to solve by hand (exercise 4):
 * one dof per spring end, each obstacle a column of C with a single 1. */
static void
spring_chain (void)
{
  /* 6. n = 12 unit springs of stiffness 100 between dofs 0..12; dof 0 is
   *    fixed; a force 1 pushes every free dof to the right; obstacles at
   *    dofs 3, 6, 9, 12 with gaps G = (0.3, 0.1, 2.0, 0.5): u_j <= G_i,
   *    i.e. C(:,i) = e_j.  K is SPD (the chain is fixed at dof 0), so the
   *    Schur path factorizes K once and then solves only k x k systems
   *    S_AA lambda_A = G_A - C_A^T K^{-1} F per iteration. */
  enum { N = 13, KC = 4 };
  static const int at[KC] = { 3, 6, 9, 12 };
  static const double gap[KC] = { 0.3, 0.1, 2.0, 0.5 };
  lac_triplet *T = lac_triplet_alloc (N, N, 3 * N);
  check_status (T ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  check_status (lac_triplet_add (T, 0, 0, 1.0), "triplet");     /* u_0 = 0 */
  for (int j = 1; j < N; j++)
    {
      check_status (lac_triplet_add (T, j, j, j + 1 < N ? 200.0 : 100.0), "triplet");
      if (j + 1 < N)
        {
          check_status (lac_triplet_add (T, j, j + 1, -100.0), "triplet");
          check_status (lac_triplet_add (T, j + 1, j, -100.0), "triplet");
        }
    }
  lac_csc *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);

  /* 7. C: one column per obstacle, e_j at its dof; F: the unit forces;
   *    then the loop, and the multipliers and the displacements at the
   *    obstacles it ends with. */
  T = lac_triplet_alloc (N, KC, KC);
  check_status (K && T ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (int i = 0; i < KC; i++)
    check_status (lac_triplet_add (T, at[i], i, 1.0), "triplet");
  lac_csc *C = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  check_status (C ? LAC_SUCCESS : LAC_ENOMEM, "lac_csc_from_triplet");
  double F[N];
  for (int j = 0; j < N; j++)
    F[j] = j == 0 ? 0.0 : 1.0;
  lac_contact_system sys = { K, F, C, gap, NULL, 0, NULL, NULL, NULL };
  lac_linear_model lin;
  printf ("2. spring chain, %d dofs, obstacles at dofs 3 6 9 12, schur\n", N);
  lac_newton *s = run (LAC_STRATEGY_SCHUR, &sys, &lin, 20);
  printf ("   lambda =");
  for (int i = 0; i < KC; i++)
    printf (" %.4f", s->lambda[i] + 0.0);
  printf ("   u(obstacles) =");
  for (int i = 0; i < KC; i++)
    printf (" %.4f", s->U[at[i]]);
  printf ("\n");
  lac_newton_free (s);
  lac_linear_model_clear (&lin);
  lac_csc_free (C);
  lac_csc_free (K);
}

// @sect The main program
/* The strategy of part 1 from the command line (saddle, the UMFPACK LU of
 * the whole saddle matrix, unless told otherwise); part 2 always uses
 * schur. */
int
main (int argc, char **argv)
{
  lac_strategy_kind kind = LAC_STRATEGY_SADDLE;
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--strategy") && k + 1 < argc
          && lac_strategy_from_name (argv[k + 1]) > 0)
        kind = (lac_strategy_kind) lac_strategy_from_name (argv[++k]);
      else
        {
          fprintf (stderr, "usage: ex07 [--strategy dense|saddle|schur|augmented|split]\n");
          return 2;
        }
    }
  lac_init ();
  tilted_block (kind);
  spring_chain ();
  lac_finalize ();
  return 0;
}
