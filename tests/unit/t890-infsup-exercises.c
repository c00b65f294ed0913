/* t890-infsup-exercises.c -- the answers of chapters/11-infsup/exercises.md
 *                                                   [LAC (10), App. A]
 *
 * Exercise 1 (one multiplier by hand): the unit square, one quad4, bottom
 *   fixed, u_x fixed on top, the multiplier on the top side: c = 1/2 on
 *   the two top y-dofs, M = h |side| = 1.  beta = 1 with the gradient part
 *   alone (ell = 1e8), sqrt(3)/2 with ell = 1; the square of side L = 10
 *   with ell = L gives sqrt(3)/2 again, with ell = 1 (mm) beta^2 = (50 /
 *   (1/2 + 100/6)) / 100, beta = 0.170664.  To 1e-12.
 * Exercise 2 (halve the criterion): the chapter's blocks (quad4, 4 / 4
 *   cells, master [0, 25 + 25 delta]); delta = 1/64 and delta 2^{-2/3}:
 *   the criterion halves (delta^{3/2}, 1e-12), beta_h is multiplied by
 *   0.794 = 2^{-1/3} within 0.02 (beta ~ sqrt(delta)), not by 1/2.
 * Exercise 3 (P0 on the raw trace, matching meshes n = 8, 16, 32):
 *   beta_h halves with h (ratios 0.5 within 0.01); the least stable
 *   pattern is the checkerboard (signs alternate); C mu is non-zero only on
 *   dofs of the end nodes x = 0 and x = 50.
 * Exercise 4 (energy norm): with the upper block floating the estimate is
 *   refused (LAC_ESING); with its top clamped too, K is positive definite,
 *   and multiplying E by 4 multiplies beta_h by 1/2 (1e-10).
 * Exercise 5 (the least stable pattern, conforming, upper 24 cells): mu
 *   alternates in sign and its largest entry is one of the two middle
 *   ones (k = 12: index 5 or 6).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "t85-infsup-blocks.h"
#include "contact/lac_assembly_lac.h"

/* ---- exercise 1 ------------------------------------------------------ */

static double
square_beta (double L, double ell)
{
  size_t nc[2] = { 1, 1 };
  double Ls[2] = { L, L }, beta = NAN;
  lac_mesh *m = NULL;
  lac_csc *A = NULL, *C = NULL, *M = NULL;
  lac_infsup *r = NULL;
  char fixed[8] = { 0 };
  lac_triplet *T = lac_triplet_alloc (8, 1, 4);
  lac_mesh_box (LAC_QUAD4, nc, Ls, 0.0, &m);
  const lac_group *bot = lac_mesh_group (m, "ymin"), *top = lac_mesh_group (m, "ymax");
  for (size_t k = 0; k < bot->nnodes; k++)
    fixed[2 * bot->node[k]] = fixed[2 * bot->node[k] + 1] = 1;
  for (size_t k = 0; k < top->nnodes; k++)
    {
      fixed[2 * top->node[k]] = 1;
      lac_triplet_add (T, 2 * top->node[k] + 1, 0, L / 2);   /* int phi n_y */
    }
  C = lac_csc_from_triplet (T);
  M = lac_csc_alloc (1, 1, 1);
  M->p[1] = 1;
  M->i[0] = 0;
  M->x[0] = L * L;                                         /* h |side| */
  if (!lac_infsup_gram_h1 (m, LAC_PLANE_STRAIN, fixed, ell, &A)
      && !lac_infsup_estimate (A, C, M, NULL, &r))
    beta = r->beta;
  else
    check_true (0, "ex1: %s", lac_error_message ());
  lac_infsup_free (r);
  lac_csc_free (A);
  lac_csc_free (C);
  lac_csc_free (M);
  lac_triplet_free (T);
  lac_mesh_free (m);
  return beta;
}

static void
exercise1 (void)
{
  check_rel (square_beta (1, 1e8), 1.0, 1e-12, "ex1: gradient only, beta = 1");
  check_rel (square_beta (1, 1), sqrt (3.0) / 2, 1e-12, "ex1: ell = 1");
  check_rel (square_beta (10, 10), sqrt (3.0) / 2, 1e-12, "ex1: L = ell = 10");
  check_rel (square_beta (10, 1), sqrt (50 / (0.5 + 100.0 / 6) / 100), 1e-12,
             "ex1: L = 10, ell = 1");
  check_abs (square_beta (10, 1), 0.170664, 1e-6, "ex1: 0.170664");
}

/* ---- exercise 2 ------------------------------------------------------ */

static double
narrow_beta (double delta, double *crit)
{
  blocks b;
  double beta = NAN;
  *crit = NAN;
  if (!blocks_build (&b, LAC_QUAD4, 4, 4, 25 + 25 * delta, 1e-9))
    {
      lac_infsup *r = blocks_infsup (&b, LAC_INFSUP_DENSE);
      if (r)
        beta = r->beta;
      *crit = b.c->crit[1];                  /* macro-element [25, 50] */
      check_int ((long) (r ? r->imax : 99), 1, "ex2: least stable = cut");
      lac_infsup_free (r);
    }
  blocks_free (&b);
  return beta;
}

static void
exercise2 (void)
{
  double d = 1.0 / 64, c1, c2;
  double b1 = narrow_beta (d, &c1), b2 = narrow_beta (d * pow (2, -2.0 / 3), &c2);
  check_rel (c1, pow (d, 1.5), 1e-12, "ex2: criterion = delta^{3/2}");
  check_rel (c2 / c1, 0.5, 1e-12, "ex2: the criterion halves");
  check_abs (b2 / b1, pow (2, -1.0 / 3), 0.02, "ex2: beta ratio ~ 2^{-1/3}");
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("ex2: beta %.5f -> %.5f, ratio %.4f\n", b1, b2, b2 / b1);
}

/* ---- exercise 3: P0 on the raw trace --------------------------------- */

/* One column per slave segment (lac_assembly_lac on single-segment
 * macro-elements), M = diag(|T_j| |T_j|). */
static int
raw_p0 (const blocks *b, lac_csc **C, lac_csc **M)
{
  size_t ns = b->M->ptr[b->M->n];
  lac_macro R = *b->M;
  lac_contact c;
  lac_pairing_facets Mf = lac_pairing_facets_of (b->m, lac_mesh_group (b->m, "lo.ymax"));
  int st;
  memset (&c, 0, sizeof c);
  R.n = ns;
  R.ptr = malloc ((ns + 1) * sizeof *R.ptr);
  R.meas = b->P->measure;
  c.k = ns;
  c.macro = malloc (ns * sizeof *c.macro);
  c.G = malloc (ns * sizeof *c.G);
  c.area = malloc (ns * sizeof *c.area);
  c.size = malloc (ns * sizeof *c.size);
  c.lost = malloc (ns * sizeof *c.lost);
  for (size_t j = 0; j <= ns; j++)
    R.ptr[j] = j;
  for (size_t j = 0; j < ns; j++)
    c.macro[j] = j;
  st = lac_assembly_lac (&c, b->m, LAC_PLANE_STRAIN, &R, b->P, &Mf);
  *C = c.C;
  *M = lac_csc_alloc (ns, ns, ns);
  for (size_t j = 0; j < ns; j++)
    {
      (*M)->p[j] = (*M)->i[j] = (int) j;
      (*M)->x[j] = b->P->measure[j] * c.area[j];
    }
  (*M)->p[ns] = (int) ns;
  free (c.area);
  free (c.size);
  free (c.lost);
  free (c.G);
  free (c.macro);
  free (R.ptr);
  return st;
}

static void
exercise3 (void)
{
  double prev = NAN;
  for (size_t n = 8; n <= 32; n *= 2)
    {
      blocks b;
      lac_csc *C = NULL, *M = NULL;
      lac_infsup *r = NULL;
      int st = blocks_build (&b, LAC_QUAD4, n, n, 50, LAC_EPSILON_DEFAULT);
      if (!st)
        st = raw_p0 (&b, &C, &M);
      if (!st)
        st = lac_infsup_estimate (b.A, C, M, NULL, &r);
      check_status (st, LAC_SUCCESS, "ex3: n = %zu", n);
      if (r)
        {
          int alternates = 1;
          for (size_t i = 0; i + 1 < r->k; i++)
            alternates &= r->mu[i] * r->mu[i + 1] < 0;
          check_true (alternates, "ex3 n = %zu: checkerboard", n);
          if (!isnan (prev))
            check_abs (r->beta / prev, 0.5, 0.01, "ex3 n = %zu: beta halves",
                       n);
          double *Cmu = calloc (C->nrow, sizeof *Cmu);
          for (size_t j = 0; j < C->ncol; j++)
            for (int q = C->p[j]; q < C->p[j + 1]; q++)
              Cmu[C->i[q]] += C->x[q] * (j % 2 ? -1.0 : 1.0);  /* C (+-+-) */
          double inner = 0, ends = 0;
          for (size_t a = 0; a < C->nrow; a++)
            {
              double x = b.m->x[2 * (a / 2)];
              if (x > 1e-9 && x < 50 - 1e-9)
                inner = fmax (inner, fabs (Cmu[a]));
              else
                ends = fmax (ends, fabs (Cmu[a]));
            }
          check_true (inner < 1e-12 * ends, "ex3 n = %zu: C mu only at the "
                      "ends (%g vs %g)", n, inner, ends);
          free (Cmu);
          if (getenv ("LAC_TEST_VERBOSE"))
            printf ("ex3: n = %zu beta = %.5f\n", n, r->beta);
          prev = r->beta;
        }
      lac_infsup_free (r);
      lac_csc_free (C);
      lac_csc_free (M);
      blocks_free (&b);
    }
}

/* ---- exercise 4: the energy norm ------------------------------------- */

/* K for Young's modulus E, the dofs of b->fixed and of the upper top
 * (if clamp_top) eliminated. */
static lac_csc *
stiffness (const blocks *b, double E, int clamp_top)
{
  size_t nc = b->m->ncells, ndof = 2 * b->m->nnodes;
  double *Ec = malloc (nc * sizeof *Ec), *nu = malloc (nc * sizeof *nu);
  char *fixed = malloc (ndof);
  for (size_t c = 0; c < nc; c++)
    Ec[c] = E, nu[c] = 0.3;
  lac_elastic mat = { LAC_PLANE_STRAIN, Ec, nu };
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 0);
  lac_assembly_stiffness (b->m, &mat, T);
  lac_csc *K = lac_csc_from_triplet (T);
  memcpy (fixed, b->fixed, ndof);
  const lac_group *top = lac_mesh_group (b->m, "up.ymax");
  for (size_t k = 0; k < top->nnodes && clamp_top; k++)
    fixed[2 * top->node[k]] = fixed[2 * top->node[k] + 1] = 1;
  for (size_t j = 0; j < ndof; j++)                /* symmetric elimination */
    for (int q = K->p[j]; q < K->p[j + 1]; q++)
      if ((size_t) K->i[q] != j && (fixed[j] || fixed[K->i[q]]))
        K->x[q] = 0;
  lac_triplet_free (T);
  free (fixed);
  free (nu);
  free (Ec);
  return K;
}

static void
exercise4 (void)
{
  blocks b;
  lac_infsup *r1 = NULL, *r2 = NULL, *r0 = NULL;
  int st = blocks_build (&b, LAC_QUAD4, 9, 6, 50, LAC_EPSILON_DEFAULT);
  check_status (st, LAC_SUCCESS, "ex4: blocks");
  if (st)
    return;
  lac_csc *K0 = stiffness (&b, 2000, 0), *K1 = stiffness (&b, 2000, 1);
  lac_csc *K4 = stiffness (&b, 8000, 1);
  check_status (lac_infsup_estimate (K0, b.c->C, b.Mn, NULL, &r0), LAC_ESING,
                "ex4: floating upper block refused");
  check_status (lac_infsup_estimate (K1, b.c->C, b.Mn, NULL, &r1),
                LAC_SUCCESS, "ex4: E = 2000");
  check_status (lac_infsup_estimate (K4, b.c->C, b.Mn, NULL, &r2),
                LAC_SUCCESS, "ex4: E = 8000");
  if (r1 && r2)
    {
      check_rel (r2->beta / r1->beta, 0.5, 1e-10, "ex4: E x 4 -> beta / 2");
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("ex4: beta_energy = %.6f (E = 2000), %.6f (E = 8000)\n",
                r1->beta, r2->beta);
    }
  lac_infsup_free (r0);
  lac_infsup_free (r1);
  lac_infsup_free (r2);
  lac_csc_free (K0);
  lac_csc_free (K1);
  lac_csc_free (K4);
  blocks_free (&b);
}

/* ---- exercise 5: the least stable pattern ----------------------------- */

static void
exercise5 (void)
{
  blocks b;
  int st = blocks_build (&b, LAC_QUAD4, 33, 24, 50, LAC_EPSILON_DEFAULT);
  lac_infsup *r = st ? NULL : blocks_infsup (&b, LAC_INFSUP_DENSE);
  check_true (r != NULL, "ex5: estimate");
  if (r)
    {
      int alternates = 1;
      for (size_t i = 0; i + 1 < r->k; i++)
        alternates &= r->mu[i] * r->mu[i + 1] < 0;
      check_int ((long) r->k, 12, "ex5: k");
      check_true (alternates, "ex5: the signs alternate");
      check_true (r->imax == 5 || r->imax == 6, "ex5: largest in the middle "
                  "(imax = %zu)", r->imax);
    }
  lac_infsup_free (r);
  blocks_free (&b);
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
