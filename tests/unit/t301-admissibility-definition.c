/* t301-admissibility-definition.c -- Definition 1 by hand, the cases the
 *                                    chapter exercises do not cover
 *                                                        [LAC Def. 1]
 *
 * Slave: quad8 block [0,50] x [50,100] (5 x 2 cells, seg3 macro-elements of
 * length 10); master: quad8 block [0,Lm] x [0,50].
 *
 * 1. Axisymmetric (r = x): the measures carry 2 pi r.  Macro-element 3
 *    spans r in [30, 40], covered on [30, 30 + 10 delta]; with s in [-1,1],
 *    r = A + B s (A = 35, B = 5), phi = 1 - s^2, a = 2 delta - 1:
 *      |T^m|      = pi (40^2 - 30^2)
 *      covered    = pi ((30 + 10 delta)^2 - 30^2)
 *      int phi    = 2 pi B int_{-1}^{a} (A + B s)(1 - s^2) ds
 *    checked to 1e-12 for delta = 0.4 (and the criterion).
 * 2. epsilon outside (0, 1] -> LAC_EINVAL naming epsilon; epsilon = 1
 *    leaves nothing admissible -> LAC_EADMISS.
 * 3. A pairing whose slave list is not the macro-mesh's sub-facets ->
 *    LAC_EINVAL.
 * 4. Numbering: mult[m] = -1 exactly for the non-admissible macro-elements,
 *    macro[mult[m]] = m, C has k columns, lac_contact_mult_of_subfacet.
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "contact/lac_contact.h"
#include "base/lac_status.h"

#define PI 3.14159265358979323846

typedef struct setup
{
  lac_mesh *mesh;
  lac_macro *M;
  lac_pairing *P;
  lac_pairing_facets Mf;
} setup;

static int
build (double Lm, setup *s)
{
  size_t nlo[2] = { 4, 2 }, nup[2] = { 5, 2 };
  double Llo[2] = { Lm, 50 }, Lup[2] = { 50, 50 };
  lac_mesh *lo = NULL, *up = NULL;
  int st;
  s->mesh = NULL;
  s->M = NULL;
  s->P = NULL;
  if ((st = lac_mesh_box (LAC_QUAD8, nlo, Llo, 0.0, &lo))
      || (st = lac_mesh_box (LAC_QUAD8, nup, Lup, 0.0, &up)))
    {
      lac_mesh_free (lo);
      return st;
    }
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 50.0;
  st = lac_mesh_merge (lo, "lo.", up, "up.", &s->mesh);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  if (!st)
    st = lac_macromesh_build (&s->mesh, "up.ymin", NULL, &s->M);
  if (st)
    return st;
  lac_pairing_facets S = { s->mesh, s->M->ptr[s->M->n], s->M->cell, s->M->face };
  s->Mf = lac_pairing_facets_of (s->mesh, lac_mesh_group (s->mesh, "lo.ymax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  return lac_pairing_build (&S, &s->Mf, &po, &s->P);
}

static void
release (setup *s)
{
  lac_pairing_free (s->P);
  lac_macromesh_free (s->M);
  lac_mesh_free (s->mesh);
}

static void
axisymmetric (void)
{
  double delta = 0.4, a = 2 * delta - 1, A = 35, B = 5;
  setup s;
  lac_contact *c = NULL;
  int st = build (30 + 10 * delta, &s);
  check_status (st, LAC_SUCCESS, "axi: set-up");
  if (!st)
    st = lac_contact_build (s.mesh, LAC_AXISYMMETRIC, s.M, s.P, &s.Mf,
                            LAC_EPSILON_DEFAULT, &c);
  check_status (st, LAC_SUCCESS, "axi: contact");
  if (!st)
    {
      double I0 = (a - a * a * a / 3) - (-1 + 1.0 / 3);           /* int 1-s^2 */
      double I1 = (a * a / 2 - a * a * a * a / 4) - (0.5 - 0.25); /* int s(1-s^2) */
      double meas = PI * (40 * 40 - 30 * 30);
      double cov = PI * (pow (30 + 10 * delta, 2) - 30 * 30);
      double phi = 2 * PI * B * (A * I0 + B * I1);
      check_rel (c->meas[3], meas, 1e-12, "axi: |T^m|");
      check_rel (c->covered[3], cov, 1e-12, "axi: |T^m cap Gamma_C|");
      check_rel (c->phiint[3], phi, 1e-12, "axi: int phi");
      check_rel (c->crit[3], phi / sqrt (cov * meas), 1e-12, "axi: criterion");
      /* a fully covered seg3 at radius [0, 10]: int 2 pi r (1 - s^2) */
      double I0f = 4.0 / 3, phif = 2 * PI * 5 * (5 * I0f);     /* s-odd part 0 */
      check_rel (c->phiint[0], phif, 1e-12, "axi: int phi, full, on the axis");
      check_rel (c->crit[0], phif / (PI * 100), 1e-12, "axi: criterion = mean");
    }
  lac_contact_free (c);
  release (&s);
}

static void
bad_input (void)
{
  setup s;
  lac_contact *c = NULL;
  int st = build (50, &s);
  check_status (st, LAC_SUCCESS, "bad: set-up");
  if (st)
    {
      release (&s);
      return;
    }
  static const double eps[3] = { 0.0, -0.1, 1.5 };
  for (int e = 0; e < 3; e++)
    {
      st = lac_contact_build (s.mesh, LAC_PLANE_STRAIN, s.M, s.P, &s.Mf, eps[e], &c);
      check_status (st, LAC_EINVAL, "bad: epsilon = %g", eps[e]);
      check_message ("epsilon", "bad: message for epsilon = %g", eps[e]);
      check_true (c == NULL, "bad: no output for epsilon = %g", eps[e]);
    }
  st = lac_contact_build (s.mesh, LAC_PLANE_STRAIN, s.M, s.P, &s.Mf, 1.0, &c);
  check_status (st, LAC_EADMISS, "bad: epsilon = 1");
  check_true (c == NULL, "bad: no output for epsilon = 1");
  /* a pairing of the first 4 sub-facets only */
  lac_pairing_facets S4 = { s.mesh, 4, s.M->cell, s.M->face };
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P4 = NULL;
  st = lac_pairing_build (&S4, &s.Mf, &po, &P4);
  check_status (st, LAC_SUCCESS, "bad: short pairing");
  if (!st)
    {
      st = lac_contact_build (s.mesh, LAC_PLANE_STRAIN, s.M, P4, &s.Mf,
                              LAC_EPSILON_DEFAULT, &c);
      check_status (st, LAC_EINVAL, "bad: pairing / macro-mesh mismatch");
      check_message ("sub-facets", "bad: mismatch message");
    }
  lac_pairing_free (P4);
  release (&s);
}

static void
numbering (void)
{
  setup s;
  lac_contact *c = NULL;
  int st = build (37, &s);
  check_status (st, LAC_SUCCESS, "num: set-up");
  if (!st)
    st = lac_contact_build (s.mesh, LAC_PLANE_STRAIN, s.M, s.P, &s.Mf, 0.65, &c);
  check_status (st, LAC_SUCCESS, "num: contact");
  if (!st)
    {
      check_int ((long) c->k, 3, "num: k");
      check_int ((long) c->C->ncol, 3, "num: columns of C");
      for (size_t m = 0; m < c->nmacro; m++)
        {
          check_int (c->mult[m], m < 3 ? (long) m : -1, "num: mult[%zu]", m);
          if (c->mult[m] >= 0)
            check_int ((long) c->macro[c->mult[m]], (long) m, "num: macro[mult[%zu]]", m);
          for (size_t j = s.M->ptr[m]; j < s.M->ptr[m + 1]; j++)
            check_int (lac_contact_mult_of_subfacet (c, s.M, j), c->mult[m],
                       "num: sub-facet %zu", j);
        }
      check_int (lac_contact_mult_of_subfacet (c, s.M, s.M->ptr[s.M->n]), -1,
                 "num: sub-facet out of range");
    }
  lac_contact_free (c);
  release (&s);
}

int
main (void)
{
  lac_init ();
  axisymmetric ();
  bad_input ();
  numbering ();
  lac_finalize ();
  return check_summary ();
}
