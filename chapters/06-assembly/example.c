/* LAC chapter 06 -- The LAC matrices C^S, C^M and the mean gaps
 *                                                  [LAC §4.3, (16)-(18)]
 *
 * Build:        make build/chapters/06-assembly
 * Sample runs:  build/chapters/06-assembly                 (flat, gap 0.5)
 *               build/chapters/06-assembly --slope 0.01    (gap 0.5 + 0.01 x)
 *               build/chapters/06-assembly --strategy dense
 * Description:  The smallest two-body problem that shows every term: a
 *               lower block [0,30] x [0,10] of 3 quad4 (the master), an
 *               upper block [0,30] x [10.5,20.5] of 4 quad4 (the slave),
 *               an initial gap of 0.5.  The slave's 4 segments are gathered
 *               into 2 macro-elements, cut by the master's 3 segments.  The
 *               program prints the pieces of the pairing, the dense table
 *               of C = [C^S; -C^M], the areas M^LAC and the mean gaps G;
 *               then it raises the lower block as a rigid foundation (a
 *               Dirichlet condition on the master dofs, which moves into G)
 *               and presses the upper block: lambda = -p exactly.
 * Read first:   chapter 05 (admissibility); lac_newton.h (sign convention).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "base/lac_mem.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex06: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* Turn -0 and roundoff into +0 for a stable printout. */
static double
clean (double v)
{
  return fabs (v) < 1e-12 ? 0.0 : v + 0.0;
}

int
main (int argc, char **argv)
{
  double slope = 0.0, g0 = 0.5, rise = 0.8, p = 1.0;
  lac_strategy_kind kind = LAC_STRATEGY_SADDLE;
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--slope") && k + 1 < argc
          && fabs (atof (argv[k + 1])) <= 0.015)
        slope = atof (argv[++k]);
      else if (!strcmp (argv[k], "--strategy") && k + 1 < argc
               && lac_strategy_from_name (argv[k + 1]) > 0
               && strcmp (argv[k + 1], "schur") != 0)
        kind = (lac_strategy_kind) lac_strategy_from_name (argv[++k]);
      else
        {
          fprintf (stderr, "usage: ex06 [--slope b] [--strategy dense|saddle|augmented]"
                   "   (|b| <= 0.015)\n");
          return 2;
        }
    }
  lac_init ();

  // @sect Two small blocks
  /* 1. Master $\Omega^1 = [0,30]\times[0,10]$, 3 quad4; slave
   *    $\Omega^2 = [0,30]\times[10.5, 20.5]$, 4 quad4: the interface meshes
   *    do not match (nodes at 0, 10, 20, 30 below; 0, 7.5, 15, 22.5, 30
   *    above) and the initial gap is $g_0 = 0.5$.  With `--slope b` the top
   *    of the lower block slopes down, $y = 10 - b x$, so $g_0(x) = 0.5 +
   *    b x$.  Nodes 0-7 are the lower block's, 8-17 the upper one's. */
  size_t nlo[2] = { 3, 1 }, nup[2] = { 4, 1 };
  double L[2] = { 30, 10 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  check_status (lac_mesh_box (LAC_QUAD4, nlo, L, 0.0, &lo), "lac_mesh_box");
  check_status (lac_mesh_box (LAC_QUAD4, nup, L, 0.0, &up), "lac_mesh_box");
  for (size_t a = 0; a < lo->nnodes; a++)
    lo->x[2 * a + 1] -= lo->x[2 * a + 1] / 10 * slope * lo->x[2 * a];
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 10.0 + g0;
  check_status (lac_mesh_merge (lo, "lo.", up, "up.", &m), "lac_mesh_merge");
  size_t nmaster = lo->nnodes;           /* nodes below this are the master's */
  lac_mesh_free (lo);
  lac_mesh_free (up);
  size_t ndof = 2 * m->nnodes;
  printf ("1. %zu nodes, %zu dofs; initial gap g0(x) = %g + %g x\n",
          m->nnodes, ndof, g0, slope);

  // @sect Macro-elements and the pairing
  /* 2. The slave's 4 seg2 are gathered into 2 macro-elements of 2 segments
   *    [LAC Hyp. 1]; the pairing cuts every sub-facet $T^s$ by the master
   *    facets and puts 3 Gauss points on each piece $T^s \cap T^m$, with
   *    their weight (the length they stand for), the master point reached
   *    along $n^S$, and the normal gap $g_0$ there [LAC §4.6]. */
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, "up.ymin", NULL, &M),
                "lac_macromesh_build");
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  const lac_group *gm = lac_mesh_group (m, "lo.ymax");
  lac_pairing_facets Mf = lac_pairing_facets_of (m, gm);
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P = NULL;
  check_status (lac_pairing_build (&S, &Mf, &po, &P), "lac_pairing_build");
  printf ("2. pairing: slave sub-facet (macro) x master facet -> piece\n");
  for (size_t m_ = 0; m_ < M->n; m_++)
    for (size_t j = M->ptr[m_]; j < M->ptr[m_ + 1]; j++)
      for (size_t q = P->pair_ptr[j]; q < P->pair_ptr[j + 1]; q++)
        {
          size_t p0 = P->pair_pt[q], np = P->pair_pt[q + 1] - p0;
          double gmean = 0;
          for (size_t t = p0; t < p0 + np; t++)
            gmean += P->w[t] * P->gap[t] / P->pair_measure[q];
          printf ("   T^s_%zu (T^%zu) x T^m_%zu: length %6.3f, %zu points,"
                  " mean g0 %.4f\n", j, m_, P->pair_master[q],
                  P->pair_measure[q], np, gmean);
        }

  // @sect C, M^LAC and G
  /* 3. For multiplier $i$ (admissible $T^i$, here $i = m$) and every integration point
   *    $(x_s, x_m, w, g_0)$ on $T^i \cap \Gamma_C$:
   *    $C_{(a,c),i} \mathrel{+}= w\,\phi^S_a(x_s)\,n^S_c$ (the block $C^S$),
   *    $C_{(b,c),i} \mathrel{-}= w\,\phi^M_b(x_m)\,n^S_c$ (the block $C^M$,
   *    with $n^M = -n^S$), $G_i \mathrel{+}= w\,g_0$, $|T^i| \mathrel{+}= w$
   *    [LAC (16)-(18)].  Here $n^S = (0, -1)$, so only the y rows are
   *    non-zero.  $(C^T U)_i = \int_{T^i\cap\Gamma_C} (u^S - u^M)\cdot n^S$
   *    is the mean normal jump, positive when the slave moves into the
   *    master (lac_newton.h); $G_i$ is the integral of the gap, not its
   *    mean (chapter 06): $G_i / |T^i|$ is the mean. */
  lac_contact *c = NULL;
  check_status (lac_contact_build (m, LAC_PLANE_STRAIN, M, P, &Mf,
                                   LAC_EPSILON_DEFAULT, &c), "lac_contact_build");
  double *Cd = lac_calloc (ndof * c->k, sizeof *Cd);      /* dense copy */
  check_status (Cd ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t i = 0; i < c->k; i++)
    for (int q = c->C->p[i]; q < c->C->p[i + 1]; q++)
      Cd[(size_t) c->C->i[q] * c->k + i] = c->C->x[q];
  printf ("3. C (rows with a non-zero entry; all x rows are 0):\n"
          "   node  body    x       dof    C(:,0)    C(:,1)\n");
  for (size_t r = 0; r < ndof; r++)
    {
      int nz = 0;
      for (size_t i = 0; i < c->k; i++)
        nz |= clean (Cd[r * c->k + i]) != 0;
      if (!nz)
        continue;
      size_t a = r / 2;
      printf ("   %4zu  %-6s %5.1f  %2zu(%c)", a, a < nmaster ? "master"
              : "slave", m->x[2 * a], r, r % 2 ? 'y' : 'x');
      for (size_t i = 0; i < c->k; i++)
        printf ("  %8.4f", clean (Cd[r * c->k + i]));
      printf ("\n");
    }
  for (size_t i = 0; i < c->k; i++)
    {
      double ss = 0, sm = 0;
      for (size_t r = 1; r < ndof; r += 2)                /* y rows: n_y = -1 */
        *(r / 2 < nmaster ? &sm : &ss) += -Cd[r * c->k + i];
      printf ("   column %zu: sum_S C.n = %.4f, sum_M C.n = %+.4f, area = %.4f,"
              " G = %.4f (mean %.4f)\n", i, ss, sm, c->area[i], c->G[i],
              c->G[i] / c->area[i]);
    }

  // @sect Dirichlet data on contact dofs
  /* 4. Make the lower block a rigid foundation raised by 0.8: every one of
   *    its dofs is fixed, $u = (0, 0.8)$.  lac_contact_apply_dirichlet
   *    moves the known part of $C^T U$ into the gap,
   *    $G_i \mathrel{-}= C_{(b,c),i}\,\bar u_{(b,c)}$, and zeroes those rows
   *    of C: the constraint $d = G - C^T U \ge 0$ keeps its meaning with
   *    the fixed dofs out of U.  Raising the foundation by 0.8 closes a
   *    gap of 0.5: $G_i / |T^i|$ becomes $-0.3$ (an imposed penetration). */
  lac_dirichlet *D = lac_dirichlet_alloc ();
  check_status (D ? LAC_SUCCESS : LAC_ENOMEM, "lac_dirichlet_alloc");
  const lac_group *body = lac_mesh_group (m, "lo.body");
  check_status (body ? LAC_SUCCESS : LAC_EINVAL, "group lo.body");
  check_status (lac_dirichlet_add_group (D, m, body, 0, 0.0), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, body, 1, rise), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.xmin"),
                                         0, 0.0), "dirichlet");
  check_status (lac_contact_apply_dirichlet (c, D->n, D->dof, D->val),
                "lac_contact_apply_dirichlet");
  printf ("4. foundation raised by %g: G = ", rise);
  for (size_t i = 0; i < c->k; i++)
    printf ("%s%.4f (mean %+.4f)", i ? ", " : "", c->G[i], c->G[i] / c->area[i]);
  printf ("\n");

  // @sect Solving with these C and G
  /* 5. Press the upper block with p = 1.  It is held by the contact alone
   *    (only $u_x = 0$ on its left side), so K is singular and the saddle
   *    system of lac_newton goes through UMFPACK (or dense LU).  A uniform
   *    pressure crosses any interface unchanged, whatever the meshes: the
   *    multipliers must be $-p$ to roundoff (the patch test of [LAC §5.1]),
   *    and the mean gaps 0 (both macro-elements active). */
  double *Ec = lac_malloc (m->ncells * sizeof *Ec);
  double *nuc = lac_malloc (m->ncells * sizeof *nuc);
  double *F = lac_calloc (ndof, sizeof *F);
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  check_status (Ec && nuc && F && T ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t k = 0; k < m->ncells; k++)
    Ec[k] = 2000, nuc[k] = 0.3;
  lac_elastic mat = { LAC_PLANE_STRAIN, Ec, nuc };
  check_status (lac_assembly_stiffness (m, &mat, T), "lac_assembly_stiffness");
  lac_csc *K = lac_csc_from_triplet (T);
  check_status (K ? LAC_SUCCESS : LAC_ENOMEM, "lac_csc_from_triplet");
  check_status (lac_assembly_pressure (m, mat.model, lac_mesh_group (m, "up.ymax"),
                                       p, F), "lac_assembly_pressure");
  check_status (lac_dirichlet_apply (D, K, F), "lac_dirichlet_apply");
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  check_status (lac_newton_solve_system (kind, &sys, 10, 1e-10, &s),
                "lac_newton_solve_system");
  printf ("5. pressed by p = %g (%s, iterations: %zu): lambda =", p,
          lac_strategy_name (kind), s->nhist);
  for (size_t i = 0; i < c->k; i++)
    printf (" %.12f", s->lambda[i]);
  printf ("\n   mean gaps d = G - C^T U:");
  for (size_t i = 0; i < c->k; i++)
    printf (" %.1e", clean (s->d[i]));
  printf ("\n");

  lac_newton_free (s);
  lac_csc_free (K);
  lac_triplet_free (T);
  lac_free (F);
  lac_free (nuc);
  lac_free (Ec);
  lac_dirichlet_free (D);
  lac_free (Cd);
  lac_contact_free (c);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
  lac_finalize ();
  return 0;
}
