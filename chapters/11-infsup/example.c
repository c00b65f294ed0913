/* LAC chapter 11 -- The inf-sup constant beta_h           [LAC (10), App. A]
 *
 * Build:        make build/chapters/11-infsup
 * Sample runs:  build/chapters/11-infsup              (delta = 1/4)
 *               build/chapters/11-infsup --delta 0.03125
 *               build/chapters/11-infsup --path sparse
 * Description:  Two plane-strain quad4 blocks, the upper (slave) one
 *               [0,50] x [50,100] with 4 cells per side, the lower
 *               (master) one [0, 25 + 25 delta] x [0,50]: Gamma_C covers
 *               the second slave macro-element on the fraction delta of
 *               its length.  The program forms the three matrices of the
 *               estimate (C, the H1 Gram matrix A, the multiplier norm M),
 *               prints S = C^T A^-1 C and M, solves S mu = beta^2 M mu and
 *               shows the least stable multiplier pattern; then beta_h as
 *               delta shrinks (two multiplier norms), as h shrinks in the
 *               conforming case, and, as a preview of the comparison
 *               methods, for P0 multipliers on the raw trace mesh, which
 *               break Hypothesis 1.  Short, deterministic output.
 * Read first:   chapters 05 (admissibility, the criterion of Def. 1) and
 *               06 (the matrix C and the sign convention).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem/lac_assembly.h"
#include "contact/lac_assembly_lac.h"
#include "contact/lac_contact.h"
#include "contact/lac_infsup.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

// @sect The set-up, from the chapters before
/* The program estimates $\beta_h$ on two stacked blocks, again and again
 * with other meshes; the helpers below build each set-up and the
 * matrices of the estimate.  A library call that fails stops the program
 * with the one-line message the library stored. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex09: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* Everything one estimate needs (built by setup, freed by teardown). */
typedef struct problem
{
  lac_mesh *m;
  lac_macro *M;
  lac_pairing *P;
  lac_pairing_facets master;
  lac_contact *c;
  char *fixed;
  lac_csc *A, *Mn;
  double h[64];
} problem;

/* The two blocks: upper nup x nup quad4 cells on [0,50]^2 + (0,50), lower
 * nlo x nlo cells on [0,Lm] x [0,50]; the chain of chapters 03-06 up to C
 * (epsilon tiny: a partly covered macro-element keeps its multiplier);
 * u_x = 0 on both left sides and the lower block clamped at its bottom
 * (the upper one is held by the contact alone); A and M of lac_infsup.h. */
static void
setup (problem *p, size_t nlo, size_t nup, double Lm)
{
  size_t nl[2] = { nlo, nlo }, nu[2] = { nup, nup };
  double Ll[2] = { Lm, 50 }, Lu[2] = { 50, 50 };
  lac_mesh *lo = NULL, *up = NULL;
  lac_pairing_opts po;
  memset (p, 0, sizeof *p);
  check_status (lac_mesh_box (LAC_QUAD4, nl, Ll, 0.0, &lo), "lac_mesh_box");
  check_status (lac_mesh_box (LAC_QUAD4, nu, Lu, 0.0, &up), "lac_mesh_box");
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 50.0;                             /* stack on top */
  check_status (lac_mesh_merge (lo, "lo.", up, "up.", &p->m), "merge");
  lac_mesh_free (lo);
  lac_mesh_free (up);
  check_status (lac_macromesh_build (&p->m, "up.ymin", NULL, &p->M),
                "lac_macromesh_build");
  lac_pairing_facets S = { p->m, p->M->ptr[p->M->n], p->M->cell, p->M->face };
  p->master = lac_pairing_facets_of (p->m, lac_mesh_group (p->m, "lo.ymax"));
  lac_pairing_opts_init (&po);
  check_status (lac_pairing_build (&S, &p->master, &po, &p->P), "pairing");
  check_status (lac_contact_build (p->m, LAC_PLANE_STRAIN, p->M, p->P,
                                   &p->master, 1e-9, &p->c), "contact");
  size_t ndof = 2 * p->m->nnodes;
  lac_dirichlet *D = lac_dirichlet_alloc ();
  check_status (D ? LAC_SUCCESS : LAC_ENOMEM, "lac_dirichlet_alloc");
  check_status (lac_dirichlet_add_group (D, p->m, lac_mesh_group (p->m, "lo.ymin"), 0, 0), "bc");
  check_status (lac_dirichlet_add_group (D, p->m, lac_mesh_group (p->m, "lo.ymin"), 1, 0), "bc");
  check_status (lac_dirichlet_add_group (D, p->m, lac_mesh_group (p->m, "lo.xmin"), 0, 0), "bc");
  check_status (lac_dirichlet_add_group (D, p->m, lac_mesh_group (p->m, "up.xmin"), 0, 0), "bc");
  p->fixed = lac_calloc (ndof, 1);
  check_status (p->fixed ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t k = 0; k < D->n; k++)
    p->fixed[D->dof[k]] = 1;
  check_status (lac_contact_apply_dirichlet (p->c, D->n, D->dof, D->val),
                "lac_contact_apply_dirichlet");
  lac_dirichlet_free (D);
  check_status (lac_infsup_gram_h1 (p->m, LAC_PLANE_STRAIN, p->fixed, 0.0,
                                    &p->A), "lac_infsup_gram_h1");
  check_status (p->c->k <= 64 ? LAC_SUCCESS : LAC_EINVAL, "k <= 64");
  check_status (lac_infsup_norm_lac (p->m, p->M, p->c, p->h, &p->Mn),
                "lac_infsup_norm_lac");
}

/* Everything setup made, freed (each _alloc or _build has its _free). */
static void
teardown (problem *p)
{
  lac_csc_free (p->Mn);
  lac_csc_free (p->A);
  lac_free (p->fixed);
  lac_contact_free (p->c);
  lac_pairing_free (p->P);
  lac_macromesh_free (p->M);
  lac_mesh_free (p->m);
}

// @sect The estimate and what it is made of
/* beta_h^2 is the smallest eigenvalue of the pencil (C^T A^-1 C, M):
 * lac_infsup_estimate takes A, C and M and finds it densely (S formed
 * with k solves, then GSL's symmetric eigensolver) or by shift-invert
 * Lanczos (one saddle-point solve per step), as PATH says.  The caller
 * frees the result. */
static lac_infsup *
estimate (const lac_csc *A, const lac_csc *C, const lac_csc *M,
          lac_infsup_path path)
{
  lac_infsup_opts o;
  lac_infsup *r = NULL;
  lac_infsup_opts_init (&o);
  o.path = path;
  check_status (lac_infsup_estimate (A, C, M, &o, &r), "lac_infsup_estimate");
  return r;
}

/* S = C^T A^-1 C, printed (k small): k solves with a CHOLMOD factor. */
static void
print_S (const problem *p)
{
  size_t n = p->A->ncol, k = p->c->k;
  lac_solver *s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  double *b = lac_calloc (n, sizeof *b), *x = lac_malloc (n * sizeof *x);
  check_status (s && b && x ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  check_status (lac_solver_factor (s, p->A), "factor A");
  for (size_t j = 0; j < k; j++)
    {
      const lac_csc *C = p->c->C;
      memset (b, 0, n * sizeof *b);
      for (int q = C->p[j]; q < C->p[j + 1]; q++)
        b[C->i[q]] = C->x[q];                            /* b = C(:, j) */
      check_status (lac_solver_solve (s, b, x), "solve");  /* x = A^-1 b */
      printf ("   S(:,%zu) =", j);
      for (size_t i = 0; i < k; i++)
        {
          double sij = 0;
          for (int q = C->p[i]; q < C->p[i + 1]; q++)
            sij += C->x[q] * x[C->i[q]];                 /* c_i . x */
          printf (" %10.4f", sij);
        }
      printf ("    M(%zu,%zu) = %.4f = h %.2f x |T^m cap Gamma_C| %.4f\n", j,
              j, p->Mn->x[j], p->h[j], p->c->area[j]);
    }
  lac_free (x);
  lac_free (b);
  lac_solver_free (s);
}

// @sect Two other choices: the norm, and the multipliers
/* The multiplier norm with h_i replaced by the length of T^m cap Gamma_C
 * (2D): M'_ii = |T^m cap Gamma_C|^2.  Step 3 compares the two norms on a
 * macro-element that the master covers less and less. */
static lac_csc *
norm_covered (const problem *p)
{
  lac_csc *M = lac_csc_alloc (p->c->k, p->c->k, p->c->k);
  check_status (M ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  for (size_t i = 0; i < p->c->k; i++)
    {
      M->p[i] = M->i[i] = (int) i;
      M->x[i] = p->c->area[i] * p->c->area[i];
    }
  M->p[p->c->k] = (int) p->c->k;
  return M;
}

/* The P0 multipliers of the raw trace mesh: one column per slave segment
 * (sub-facet), assembled by lac_assembly_lac on a macro-mesh whose
 * macro-elements are single segments (no interior node: Hypothesis 1
 * fails); M = diag(h_j |segment_j|). */
static void
raw_p0 (const problem *p, lac_csc **C, lac_csc **M)
{
  size_t ns = p->M->ptr[p->M->n];
  lac_macro R = *p->M;
  lac_contact *c = lac_contact_alloc (ns);     /* ns "macro-elements" */
  R.n = ns;
  R.ptr = lac_malloc ((ns + 1) * sizeof *R.ptr);
  R.meas = p->P->measure;                      /* |segment| */
  *M = lac_csc_alloc (ns, ns, ns);
  check_status (R.ptr && c && *M ? LAC_SUCCESS : LAC_ENOMEM, "allocation");
  c->k = ns;
  for (size_t j = 0; j <= ns; j++)
    R.ptr[j] = j;                              /* segment j alone */
  for (size_t j = 0; j < ns; j++)
    c->macro[j] = j;
  check_status (lac_assembly_lac (c, p->m, LAC_PLANE_STRAIN, &R, p->P,
                                  &p->master), "lac_assembly_lac");
  for (size_t j = 0; j < ns; j++)
    {
      (*M)->p[j] = (*M)->i[j] = (int) j;
      (*M)->x[j] = p->P->measure[j] * c->area[j];      /* h_j |T_j| */
    }
  (*M)->p[ns] = (int) ns;
  *C = c->C;             /* no Dirichlet rows to zero: none on the contact */
  c->C = NULL;
  lac_contact_free (c);
  lac_free (R.ptr);
}

// @sect The main program
/* --delta: the covered fraction of the partly covered macro-element of
 * steps 1 and 2 (0.25 unless given; step 3 runs through several);
 * --path: how the eigenvalue is found.  The steps below use the helpers
 * above in turn. */
int
main (int argc, char **argv)
{
  double delta = 0.25;
  lac_infsup_path path = LAC_INFSUP_DENSE;
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--delta") && k + 1 < argc
          && atof (argv[k + 1]) > 0 && atof (argv[k + 1]) <= 1)
        delta = atof (argv[++k]);
      else if (!strcmp (argv[k], "--path") && k + 1 < argc
               && (!strcmp (argv[k + 1], "dense")
                   || !strcmp (argv[k + 1], "sparse")))
        path = !strcmp (argv[++k], "dense") ? LAC_INFSUP_DENSE
               : LAC_INFSUP_SPARSE;
      else
        {
          fprintf (stderr, "usage: ex09 [--delta D] [--path dense|sparse]"
                   "   (0 < D <= 1)\n");
          return 2;
        }
    }
  lac_init ();
  problem p;

  // @sect The three matrices of the estimate
  /* 1. The inf-sup condition (10) asks for
   *    $\inf_\mu \sup_v b(\mu, v) / (\|\mu\| \|v\|) \ge \beta_h > 0$.
   *    With $b(\mu, v) = \mu^T C^T v$, $\|v\|^2 = v^T A v$ and
   *    $\|\mu\|^2 = \mu^T M \mu$ the supremum is reached at
   *    $v = A^{-1} C \mu$ (Cauchy-Schwarz in the $A$ inner product), so
   *    $$\beta_h^2 = \min_\mu \frac{\mu^T S \mu}{\mu^T M \mu}, \qquad
   *      S = C^T A^{-1} C .$$
   *    $C$ is the matrix of chapter 06 (Dirichlet rows zeroed), $A$ the H1
   *    Gram matrix $\int \nabla N_a\cdot\nabla N_b + N_a N_b/\ell^2$ per
   *    component ($\ell$ = the mesh diameter), $M = \mathrm{diag}(h_i
   *    |T^m_i\cap\Gamma_C|)$ the h-weighted $L^2$ norm that stands for
   *    $H^{-1/2}$. */
  setup (&p, 4, 4, 25 + 25 * delta);
  printf ("1. master [0, %g], slave [0, 50] (4 quad4 cells): k = %zu "
          "multipliers, %zu dofs (%s)\n", 25 + 25 * delta, p.c->k,
          p.A->ncol, lac_infsup_path_name (path));
  for (size_t i = 0; i < p.c->k; i++)
    printf ("   multiplier %zu: macro-element %zu, delta = %.4f, criterion "
            "phibar sqrt(delta) = %.5f\n", i, p.c->macro[i],
            p.c->covered[p.c->macro[i]] / p.c->meas[p.c->macro[i]],
            p.c->crit[p.c->macro[i]]);

  // @sect S, M and the smallest eigenvalue
  /* 2. For two multipliers everything fits on a line: the $2\times 2$
   *    matrices $S$ and $M$, the two eigenvalues of $S\mu = \beta^2 M\mu$
   *    and the eigenvector of the smallest, normalized by
   *    $\mu^T M \mu = 1$.  The least stable pattern sits on the cut
   *    macro-element: its multiplier is weakly seen by the displacements
   *    (its column of $C$ is small, $\sim\delta$) while its norm is
   *    $\sim\sqrt\delta$. */
  print_S (&p);
  lac_infsup *r = estimate (p.A, p.c->C, p.Mn, path);
  printf ("   eigenvalues %.6f %.6f -> beta_h = %.6f, mu = (%+.4f, %+.4f)\n",
          r->lambda_min, r->lambda_2, r->beta, r->mu[0], r->mu[1]);
  lac_infsup_free (r);
  teardown (&p);

  // @sect beta_h against the coverage delta
  /* 3. Appendix A proves $\beta_h \ge C\varepsilon$ when a macro-element
   *    is kept with a criterion $\overline\phi\sqrt\delta \approx
   *    \varepsilon$.  For two gathered seg2 the criterion is
   *    $\delta^{3/2}$ ($\delta \le 1/2$, chapter 05).  The measured
   *    $\beta_h$ decays only like $\sqrt\delta$: the bound holds, with
   *    room.  With $h_i$ replaced by the length of $T^m\cap\Gamma_C$ in
   *    $M$ (a norm closer to $H^{-1/2}$ for a multiplier living on a tiny
   *    piece), $\beta_h$ hardly moves at all.  The norm decides. */
  printf ("2. beta_h against delta (criterion = delta^{3/2} for delta <= 1/2)\n"
          "     delta   criterion   beta_h  beta/sqrt(delta)  beta_h with "
          "h_i = |T^m cap Gamma_C|\n");
  for (double d = 0.5; d > 0.003; d /= 4)
    {
      setup (&p, 4, 4, 25 + 25 * d);
      lac_csc *Mc = norm_covered (&p);
      lac_infsup *r1 = estimate (p.A, p.c->C, p.Mn, path);
      lac_infsup *r2 = estimate (p.A, p.c->C, Mc, path);
      printf ("   %7.5f  %10.3e  %7.4f  %16.4f  %10.4f\n", d,
              p.c->crit[p.c->macro[1]], r1->beta, r1->beta / sqrt (d),
              r2->beta);
      lac_infsup_free (r2);
      lac_infsup_free (r1);
      lac_csc_free (Mc);
      teardown (&p);
    }

  // @sect beta_h against h, geometrically conforming
  /* 4. With $\Gamma_C$ the whole common face ($L_m = 50$) every
   *    macro-element is fully covered and Hypothesis 1 holds: Appendix A's
   *    average-preserving operator gives an $h$-independent $\beta_h$.
   *    Refining both blocks, $\beta_h$ settles near 0.65.  The least
   *    stable pattern is a checkerboard (signs alternate) under a smooth
   *    envelope: the highest frequency the macro-mesh can carry. */
  printf ("3. conforming, refined (upper n cells, lower 4n/3 + 1):\n"
          "      n    k   beta_h   signs of mu\n");
  for (size_t n = 6; n <= 48; n *= 2)
    {
      char signs[64] = "";
      setup (&p, 4 * n / 3 + 1, n, 50);
      lac_infsup *r3 = estimate (p.A, p.c->C, p.Mn, path);
      for (size_t i = 0; i < r3->k && i < 63; i++)
        signs[i] = r3->mu[i] >= 0 ? '+' : '-';
      printf ("   %4zu %4zu  %7.4f   %s\n", n, r3->k, r3->beta, signs);
      lac_infsup_free (r3);
      teardown (&p);
    }

  // @sect Preview: P0 multipliers on the raw trace mesh
  /* 5. Drop Hypothesis 1: one constant multiplier per slave *segment*
   *    (no interior node).  With matching meshes ($n$ cells on both
   *    sides) the checkerboard $\mu = (+1, -1, +1, \dots)$ is orthogonal
   *    to every hat function of an interior node: $\int \phi_j \mu = h/2 -
   *    h/2 = 0$ on both sides.  Only the two end nodes see it, and
   *    $\beta_h \to 0$ as $h \to 0$.  The comparison methods of a later
   *    chapter build on this. */
  printf ("4. P0 on the raw trace, matching meshes (n cells on both sides):\n"
          "      n    k   beta_h   LAC beta_h (same mesh)\n");
  for (size_t n = 4; n <= 32; n *= 2)
    {
      lac_csc *C0 = NULL, *M0 = NULL;
      setup (&p, n, n, 50);
      raw_p0 (&p, &C0, &M0);
      lac_infsup *r0 = estimate (p.A, C0, M0, path);
      lac_infsup *rl = estimate (p.A, p.c->C, p.Mn, path);
      printf ("   %4zu %4zu  %7.4f   %7.4f\n", n, r0->k, r0->beta, rl->beta);
      lac_infsup_free (rl);
      lac_infsup_free (r0);
      lac_csc_free (C0);
      lac_csc_free (M0);
      teardown (&p);
    }
  lac_finalize ();
  return 0;
}
