/* LAC chapter 05 -- Admissible macro-elements              [LAC §3.1, Def. 1]
 *
 * Build:        make build/chapters/05-admissibility
 * Sample runs:  build/chapters/05-admissibility           (quad8, L = 37)
 *               build/chapters/05-admissibility --elem quad4
 *               build/chapters/05-admissibility --master 31.5
 *               build/chapters/05-admissibility --strategy dense
 * Description:  Two plane-strain blocks, the upper (slave) one 50 wide, the
 *               lower (master) one only L = 37 wide: the contact zone
 *               Gamma_C = [0, L] cuts a macro-element of the slave surface.
 *               The program prints, per macro-element T^m, the covered
 *               fraction delta, the mean phibar of its interior basis
 *               function over T^m cap Gamma_C and the criterion
 *               phibar sqrt(delta) of [LAC Def. 1]; then the admissible set
 *               for growing epsilon; then it presses the upper block and
 *               shows what becomes of a macro-element that is not
 *               admissible: no multiplier, and no control of the gap.
 *               Short, deterministic output.
 * Read first:   chapters 01 (the problem) and 02 (spaces: the averages of
 *               trace basis functions).
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
  fprintf (stderr, "ex05: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* Turn -0 into +0 and tiny roundoff into 0 for a stable printout. */
static double
clean (double v, double scale)
{
  return fabs (v) < 1e-12 * scale ? 0.0 : v + 0.0;
}

/* The x-range of macro-element m: its sub-facets' node abscissae. */
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

/* Solve the contact problem with the multipliers of c and return the mean
 * gaps d_m / |T^m cap Gamma_C| of ALL covered macro-elements, measured with
 * the columns of `all` (built with a small epsilon). */
static void
press (const lac_csc *K, const double *F, const lac_contact *c,
       const lac_contact *all, lac_strategy_kind kind, double *lambda_m,
       double *gap_m)
{
  lac_contact_system sys = { K, F, c->C, c->G, NULL, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  check_status (lac_newton_solve_system (kind, &sys, 20, 1e-10, &s),
                "lac_newton_solve_system");
  for (size_t m = 0; m < c->nmacro; m++)
    lambda_m[m] = c->mult[m] >= 0 ? s->lambda[c->mult[m]] : NAN;
  for (size_t m = 0; m < all->nmacro; m++)
    {
      gap_m[m] = NAN;
      long i = all->mult[m];
      if (i < 0)
        continue;
      double d = all->G[i];                               /* d = G - C^T U */
      for (int p = all->C->p[i]; p < all->C->p[i + 1]; p++)
        d -= all->C->x[p] * s->U[all->C->i[p]];
      gap_m[m] = d / all->area[i];
    }
  lac_newton_free (s);
}

int
main (int argc, char **argv)
{
  lac_elem_type type = LAC_QUAD8;
  double Lm = 37.0;
  lac_strategy_kind kind = LAC_STRATEGY_SADDLE;
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--elem") && k + 1 < argc
          && (!strcmp (argv[k + 1], "quad8") || !strcmp (argv[k + 1], "quad4")))
        type = !strcmp (argv[++k], "quad8") ? LAC_QUAD8 : LAC_QUAD4;
      else if (!strcmp (argv[k], "--master") && k + 1 < argc
               && atof (argv[k + 1]) > 0 && atof (argv[k + 1]) <= 50)
        Lm = atof (argv[++k]);
      else if (!strcmp (argv[k], "--strategy") && k + 1 < argc
               && lac_strategy_from_name (argv[k + 1]) > 0
               && strcmp (argv[k + 1], "schur") != 0)
        kind = (lac_strategy_kind) lac_strategy_from_name (argv[++k]);
      else
        {
          fprintf (stderr, "usage: ex05 [--elem quad8|quad4] [--master L]"
                   " [--strategy dense|saddle|augmented]   (0 < L <= 50)\n");
          return 2;
        }
    }
  lac_init ();

  // @sect Two bodies that do not have the same length
  /* 1. The master body $\Omega^1 = [0, L] \times [0, 50]$ (4 x 4 cells)
   *    and the slave body $\Omega^2 = [0, 50] \times [50, 100]$ (5 x 5
   *    cells of quad8, or 4 x 4 quad4 so that the trace segments pair up),
   *    meshed independently and merged into one mesh whose groups are
   *    prefixed "lo." and "up.".  The candidate zones are the top of the
   *    lower block and the bottom of the upper block, so
   *    $\Gamma_C = \Gamma_C^1 \cap \Gamma_C^2 = [0, L] \times \{50\}$: it
   *    is not a union of slave facets [LAC §3.1, Fig. 1]. */
  size_t nlo[2] = { 4, 4 }, nup[2] = { 5, 5 };
  if (type == LAC_QUAD4)
    nup[0] = nup[1] = 4;
  double Llo[2] = { Lm, 50 }, Lup[2] = { 50, 50 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  check_status (lac_mesh_box (type, nlo, Llo, 0.0, &lo), "lac_mesh_box");
  check_status (lac_mesh_box (type, nup, Lup, 0.0, &up), "lac_mesh_box");
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 50.0;                             /* stack on top */
  check_status (lac_mesh_merge (lo, "lo.", up, "up.", &m), "lac_mesh_merge");
  lac_mesh_free (lo);
  lac_mesh_free (up);
  printf ("1. master [0, %g] x [0, 50], slave [0, 50] x [50, 100], %s\n",
          Lm, lac_refelem_get (type)->name);

  // @sect The macro-mesh and the pairing
  /* 2. The macro-mesh $T^M$ of the slave surface [LAC Hyp. 1]: with quad8
   *    every seg3 trace facet is a macro-element (its mid node is the
   *    interior d.o.f.); with quad4 two seg2 facets are gathered (the
   *    shared vertex).  Then the pairing cuts each sub-facet by the master
   *    facets facing it and puts integration points on the pieces: the
   *    points of a sub-facet cover exactly its part of $\Gamma_C$. */
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, "up.ymin", NULL, &M),
                "lac_macromesh_build");
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (m, lac_mesh_group (m, "lo.ymax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P = NULL;
  check_status (lac_pairing_build (&S, &Mf, &po, &P), "lac_pairing_build");

  // @sect Definition 1, macro-element by macro-element
  /* 3. For every macro-element $T^m$, with $\phi_{m^*+1}$ the basis
   *    function of its interior node,
   *    $$\delta = \frac{|T^m\cap\Gamma_C|}{|T^m|},\qquad
   *      \overline{\phi} = \frac{1}{|T^m\cap\Gamma_C|}
   *      \int_{T^m\cap\Gamma_C}\phi_{m^*+1}\,d\Gamma,\qquad
   *      \text{admissible iff } \overline{\phi}\sqrt{\delta} \ge \varepsilon .$$
   *    lac_contact_build computes them (fields meas, covered, phiint,
   *    crit) and numbers the multipliers of the admissible ones (mult). */
  lac_model model = LAC_PLANE_STRAIN;
  lac_contact *c = NULL;
  check_status (lac_contact_build (m, model, M, P, &Mf, LAC_EPSILON_DEFAULT, &c),
                "lac_contact_build");
  printf ("2. macro-elements (epsilon = %g):\n", LAC_EPSILON_DEFAULT);
  printf ("    m   x-range       |T^m|  covered   delta  phibar"
          "  phibar*sqrt(delta)  mult\n");
  for (size_t k = 0; k < M->n; k++)
    {
      double x0, x1;
      macro_range (m, M, k, &x0, &x1);
      double delta = c->covered[k] / c->meas[k];
      double phibar = c->covered[k] > 0 ? c->phiint[k] / c->covered[k] : 0;
      printf ("   %2zu  [%4.1f, %4.1f]  %6.2f  %7.3f  %6.4f  %6.4f  %18.6f  %4ld\n",
              k, x0, x1, c->meas[k], clean (c->covered[k], c->meas[k]),
              clean (delta, 1), clean (phibar, 1), clean (c->crit[k], 1),
              c->mult[k]);
    }

  // @sect The admissible set as epsilon grows
  /* 4. A fully covered macro-element has $\delta = 1$ and
   *    $\overline{\phi}\sqrt{\delta} = \overline{\phi}$ = 2/3 (seg3) or 1/2
   *    (two seg2): it stays admissible for every $\varepsilon$ below that,
   *    in particular for the default $10^{-2}$.  An uncovered one
   *    ($\delta = 0$) never is.  The partly covered one drops out when
   *    $\varepsilon$ passes its criterion; above 2/3 (1/2) nothing is left
   *    and lac_contact_build refuses with LAC_EADMISS. */
  static const double eps[] = { 1e-2, 0.1, 0.2, 0.4, 0.6, 0.65, 0.7 };
  printf ("3. admissible set T_ad^M (a: admissible, .: not):\n");
  for (size_t e = 0; e < sizeof eps / sizeof *eps; e++)
    {
      lac_contact *ce = NULL;
      int st = lac_contact_build (m, model, M, P, &Mf, eps[e], &ce);
      if (st == LAC_EADMISS)
        {
          printf ("   epsilon = %-5g  none: %s\n", eps[e], lac_error_message ());
          continue;
        }
      check_status (st, "lac_contact_build");
      printf ("   epsilon = %-5g  ", eps[e]);
      double ad = 0, rest = 0;
      for (size_t k = 0; k < M->n; k++)
        {
          putchar (ce->admissible[k] ? 'a' : '.');
          *(ce->admissible[k] ? &ad : &rest) += ce->covered[k];
        }
      printf ("  k = %zu  |Gamma_C^ad| = %5.2f  |Gamma_C^eps| = %5.2f\n",
              ce->k, ad, clean (rest, 1));
      lac_contact_free (ce);
    }

  // @sect What happens to a macro-element that is not admissible
  /* 5. Press the upper block with p = 25 on its top (the lower block is
   *    clamped at its bottom, both have $u_x = 0$ on their left side; the
   *    upper block is held by the contact alone, so K is singular and the
   *    saddle system is solved by UMFPACK or dense LU).  Solve twice: with
   *    the default $\varepsilon$ and with $\varepsilon$ just above the
   *    partly covered macro-element's criterion.  A non-admissible
   *    macro-element gets no multiplier: its $\lambda$ is "--" and its
   *    mean gap $d_m/|T^m\cap\Gamma_C|$ is left free, here negative
   *    (interpenetration), while it is 0 wherever the contact is active. */
  size_t ndof = 2 * m->nnodes;
  double *Ec = lac_malloc (m->ncells * sizeof *Ec);
  double *nuc = lac_malloc (m->ncells * sizeof *nuc);
  double *F = lac_calloc (ndof, sizeof *F);
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  check_status (Ec && nuc && F && T && D ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t k = 0; k < m->ncells; k++)
    Ec[k] = 2000, nuc[k] = 0.3;
  lac_elastic mat = { model, Ec, nuc };
  check_status (lac_assembly_stiffness (m, &mat, T), "lac_assembly_stiffness");
  lac_csc *K = lac_csc_from_triplet (T);
  check_status (K ? LAC_SUCCESS : LAC_ENOMEM, "lac_csc_from_triplet");
  check_status (lac_assembly_pressure (m, model, lac_mesh_group (m, "up.ymax"),
                                       25.0, F), "lac_assembly_pressure");
  check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "lo.ymin"), 0, 0.0), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "lo.ymin"), 1, 0.0), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "lo.xmin"), 0, 0.0), "dirichlet");
  check_status (lac_dirichlet_add_group (D, m, lac_mesh_group (m, "up.xmin"), 0, 0.0), "dirichlet");
  check_status (lac_dirichlet_apply (D, K, F), "lac_dirichlet_apply");
  check_status (lac_contact_apply_dirichlet (c, D->n, D->dof, D->val),
                "lac_contact_apply_dirichlet");

  double crit_partial = 0;        /* the largest criterion below 1/2 or 2/3 */
  for (size_t k = 0; k < M->n; k++)
    if (c->crit[k] > 0 && c->covered[k] < (1 - 1e-12) * c->meas[k])
      crit_partial = fmax (crit_partial, c->crit[k]);
  double eps2 = crit_partial > 0 ? ceil (crit_partial * 100 + 1e-9) / 100 : 0.3;
  lac_contact *c2 = NULL;
  check_status (lac_contact_build (m, model, M, P, &Mf, eps2, &c2),
                "lac_contact_build");
  check_status (lac_contact_apply_dirichlet (c2, D->n, D->dof, D->val),
                "lac_contact_apply_dirichlet");

  double *l1 = lac_malloc (M->n * sizeof *l1), *g1 = lac_malloc (M->n * sizeof *g1);
  double *l2 = lac_malloc (M->n * sizeof *l2), *g2 = lac_malloc (M->n * sizeof *g2);
  check_status (l1 && g1 && l2 && g2 ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  press (K, F, c, c, kind, l1, g1);
  press (K, F, c2, c, kind, l2, g2);
  printf ("4. pressed by p = 25 (%s): lambda_m and mean gap d_m/|T^m cap Gamma_C|\n",
          lac_strategy_name (kind));
  printf ("    m   epsilon = %-4g            epsilon = %-4g\n",
          LAC_EPSILON_DEFAULT, eps2);
  for (size_t k = 0; k < M->n; k++)
    {
      char b1[40], b2[40];
      if (isnan (g1[k]))
        {
          printf ("   %2zu   (no contact zone: delta = 0)\n", k);
          continue;
        }
      snprintf (b1, sizeof b1, "%9.4f %+.2e", l1[k], clean (g1[k], 1));
      if (isnan (l2[k]))
        snprintf (b2, sizeof b2, "%9s %+.2e", "--", g2[k]);
      else
        snprintf (b2, sizeof b2, "%9.4f %+.2e", l2[k], clean (g2[k], 1));
      printf ("   %2zu   %s   %s\n", k, b1, b2);
    }

  lac_free (l1);
  lac_free (g1);
  lac_free (l2);
  lac_free (g2);
  lac_contact_free (c2);
  lac_contact_free (c);
  lac_dirichlet_free (D);
  lac_csc_free (K);
  lac_triplet_free (T);
  lac_free (F);
  lac_free (nuc);
  lac_free (Ec);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
  lac_finalize ();
  return 0;
}
