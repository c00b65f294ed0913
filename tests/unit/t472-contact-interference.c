/* t472: an interference fit, the gaps less delta      [LAC (16)-(18)]
 *
 * contact/lac_contact.h, lac_contact_set_offset; contact/lac_contact_pair.h,
 * the pair's offset; contact/lac_contact_tangent.h, B with it.
 *   1. Two boxes (quad8, plane strain and axisymmetric) with a gap g0 =
 *      0.05: with delta = 0.2, every G_i is G_i - 0.2 |T^m cap Gamma_C|
 *      (the 2 pi r weighted area), exactly; delta set again replaces the
 *      former; a delta that is not finite is refused with a message.
 *   2. The pair with offset = delta builds the same G; the macro-elements
 *      without a column are as deep in the master as delta - g0.
 *   3. B = -d(d)/dU against central differences of the mean gaps of the
 *      pair with delta = 0.03 on a deformed state (as t435), and B without
 *      the delta terms fails that check.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "contact/lac_contact.h"
#include "contact/lac_contact_pair.h"
#include "contact/lac_contact_tangent.h"
#include "base/lac_status.h"

/* The lower box [-0.2, 1.2] x [0, 1] (master: its top) and the upper box
 * [0, 1] x [1 + g0, 1.5 + g0] (slave: its bottom), merged. */
static lac_mesh *
two_boxes (lac_elem_type type, double g0)
{
  size_t nlo[2] = { 5, 3 }, nup[2] = { 3, 2 };
  double Llo[2] = { 1.4, 1 }, Lup[2] = { 1, 0.5 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  lac_mesh_box (type, nlo, Llo, 0.0, &lo);
  lac_mesh_box (type, nup, Lup, 0.0, &up);
  for (size_t a = 0; a < lo->nnodes; a++)
    lo->x[2 * a] += 0.3;                   /* r > 0 for the axisymmetric */
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a] += 0.5, up->x[2 * a + 1] += 1 + g0;
  lac_mesh_merge (lo, "lo.", up, "up.", &m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  return m;
}

typedef struct setup
{
  lac_mesh *m;
  lac_macro *M;
  lac_pairing_facets master;
  lac_obstacle ob;
  lac_contact_pair pair;
} setup;

static void
setup_make (setup *s, lac_elem_type type, lac_model model, double g0)
{
  memset (s, 0, sizeof *s);
  s->m = two_boxes (type, g0);
  check_status (lac_macromesh_build (&s->m, "up.ymin", NULL, &s->M),
                LAC_SUCCESS, "macro-mesh");
  s->master = lac_pairing_facets_of (s->m, lac_mesh_group (s->m, "lo.ymax"));
  s->pair = (lac_contact_pair) { s->m, model, s->M, &s->master, &s->ob,
                                 0.01, 0, { 0 }, 0, 0, 0, 0 };
  lac_pairing_opts_init (&s->pair.popts);
  s->pair.popts.dist_abs = 0.1;
}

static void
setup_free (setup *s)
{
  lac_macromesh_free (s->M);
  lac_mesh_free (s->m);
}

/* 1 and 2: the shift of G, by the contact data and by the pair. */
static void
shift (lac_model model, const char *name)
{
  setup s;
  lac_pairing *P = NULL, *P2 = NULL;
  lac_contact *c = NULL, *c2 = NULL;
  double g0 = 0.05, emax = 0;
  setup_make (&s, LAC_QUAD8, model, g0);
  check_status (lac_contact_pair_build (&s.pair, NULL, &P, &c), LAC_SUCCESS,
                "%s: pair", name);
  double *G0 = malloc ((c->k + 1) * sizeof *G0);
  memcpy (G0, c->G, c->k * sizeof *G0);
  for (size_t i = 0; i < c->k; i++)
    emax = fmax (emax, fabs (G0[i] - g0 * c->area[i]) / c->area[i]);
  check_abs (emax, 0, 1e-12, "%s: G = g0 |T^m cap Gamma_C|", name);
  check_status (lac_contact_set_offset (c, 0.2), LAC_SUCCESS, "%s: offset",
                name);
  for (size_t i = 0; i < c->k; i++)
    check_abs (c->G[i], G0[i] - 0.2 * c->area[i], 1e-14 * c->area[i],
               "%s: G_%zu - delta |T|", name, i);
  lac_contact_set_offset (c, 0.1);
  for (size_t i = 0; i < c->k; i++)
    check_abs (c->G[i], G0[i] - 0.1 * c->area[i], 1e-14 * c->area[i],
               "%s: delta set again replaces it (%zu)", name, i);
  check_status (lac_contact_set_offset (c, NAN), LAC_EINVAL, "%s: NaN",
                name);
  check_message ("finite", "%s: the message says why", name);
  s.pair.offset = 0.1;                                /* 2: the pair's */
  check_status (lac_contact_pair_build (&s.pair, NULL, &P2, &c2),
                LAC_SUCCESS, "%s: pair with offset", name);
  check_int ((long) c2->k, (long) c->k, "%s: same multipliers", name);
  for (size_t i = 0; i < c->k && c2->k == c->k; i++)
    check_abs (c2->G[i], c->G[i], 1e-14 * c->area[i], "%s: pair's G_%zu",
               name, i);
  check_rel (c2->offset, 0.1, 0, "%s: the contact data keep delta", name);
  lac_contact_uncovered u;
  check_status (lac_contact_pair_uncovered (&s.pair, NULL, NULL, 0, 0, &u),
                LAC_SUCCESS, "%s: uncovered", name);
  check_abs (u.depth, 0.1 - g0, 1e-12, "%s: depth = delta - g0", name);
  check_int ((long) u.count, (long) s.M->n, "%s: every macro-element",
             name);
  lac_contact_free (c);
  lac_contact_free (c2);
  lac_pairing_free (P);
  lac_pairing_free (P2);
  free (G0);
  setup_free (&s);
}

/* The mean gaps of the pair at X + U (k of them). */
static size_t
gaps (const setup *s, const double *U, double *d)
{
  size_t n = 2 * s->m->nnodes, k = 0;
  double *x = malloc (n * sizeof *x);
  lac_pairing *P = NULL;
  lac_contact *c = NULL;
  for (size_t j = 0; j < n; j++)
    x[j] = s->m->x[j] + U[j];
  if (!lac_contact_pair_build (&s->pair, x, &P, &c) && c)
    {
      k = c->k;
      memcpy (d, c->G, k * sizeof *d);
    }
  lac_contact_free (c);
  lac_pairing_free (P);
  free (x);
  return k;
}

/* 3: B with delta against central differences of d. */
static void
tangent (double delta, int expect_ok)
{
  setup s;
  setup_make (&s, LAC_QUAD4, LAC_PLANE_STRAIN, 0.0);
  size_t n = 2 * s.m->nnodes, k;
  double *U = malloc (n * sizeof *U), *d = malloc (n * sizeof *d);
  double *dp = malloc (n * sizeof *dp), *dm = malloc (n * sizeof *dm);
  double *lam = malloc (n * sizeof *lam), h = 1e-6, err = 0, bmax = 0;
  unsigned seed = 4242;
  for (size_t a = 0; a < s.m->nnodes; a++)          /* the slave deformed */
    for (int c = 0; c < 2; c++)
      {
        seed = seed * 1103515245u + 12345u;
        double r = ((seed >> 8) & 0xffff) / 32767.5 - 1.0;
        U[2 * a + c] = s.m->x[2 * a + 1] > 1 - 1e-9
                       ? 0.01 * r + (c ? 0.02 * (s.m->x[2 * a] - 1) : 0) : 0;
      }
  s.pair.offset = delta;
  lac_mesh cur = *s.m;
  double *x = malloc (n * sizeof *x);
  for (size_t j = 0; j < n; j++)
    x[j] = s.m->x[j] + U[j];
  cur.x = x;
  lac_pairing_facets Mf = s.master;
  Mf.mesh = &cur;
  lac_pairing *P = NULL;
  lac_contact *c = NULL;
  lac_contact_tangent *t = NULL;
  check_status (lac_contact_pair_build (&s.pair, x, &P, &c), LAC_SUCCESS,
                "tangent: pair");
  k = c ? c->k : 0;
  for (size_t i = 0; i < k; i++)
    lam[i] = -1;
  if (!expect_ok && c)
    c->offset = 0;            /* B as if the gaps had no delta */
  check_status (lac_contact_tangent_build (&cur, LAC_PLANE_STRAIN, s.M, P,
                                           &Mf, NULL, c, lam, NULL, &t),
                LAC_SUCCESS, "tangent: build");
  for (size_t j = 0; t && j < n; j++)
    {
      double u0 = U[j];
      U[j] = u0 + h;
      size_t kp = gaps (&s, U, dp);
      U[j] = u0 - h;
      size_t km = gaps (&s, U, dm);
      U[j] = u0;
      check_true (kp == k && km == k, "tangent: k changed at dof %zu", j);
      for (size_t i = 0; i < k && kp == k && km == k; i++)
        {
          double b = 0;
          for (int q = t->B->p[i]; q < t->B->p[i + 1]; q++)
            if ((size_t) t->B->i[q] == j)
              b = t->B->x[q];
          bmax = fmax (bmax, fabs (b));
          err = fmax (err, fabs ((dp[i] - dm[i]) / (2 * h) + b));
        }
    }
  if (expect_ok)
    check_true (err <= 1e-6 * bmax, "B with delta = %g against -d(d)/dU: "
                "%.2e of %.2e", delta, err, bmax);
  else
    check_true (err > 1e-3 * bmax, "B without the delta terms fails the "
                "check (%.2e of %.2e)", err, bmax);
  lac_contact_tangent_free (t);
  lac_contact_free (c);
  lac_pairing_free (P);
  free (U), free (d), free (dp), free (dm), free (lam), free (x);
  setup_free (&s);
}

int
main (void)
{
  lac_init ();
  shift (LAC_PLANE_STRAIN, "plane strain");
  shift (LAC_AXISYMMETRIC, "axisymmetric");
  tangent (0.03, 1);
  tangent (0.03, 0);
  lac_finalize ();
  return check_summary ();
}
