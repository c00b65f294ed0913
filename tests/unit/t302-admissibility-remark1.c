/* t302: the designated interior node of a macro-element with several
 *       interior nodes is the one whose support meets Gamma_C most
 *                                                 [LAC Remark 1, Def. 1]
 *
 * A quad4 slave of 5 cells on [0, 50] (y = 50) is gathered into a pair
 * [0, 20] and a triple [20, 50] with interior vertices x = 30 and x = 40.
 * The master covers only [x0, 50].  With x0 = 45 the hat of x = 40 gives
 * int = 1.25, criterion 1.25/sqrt(5*30); the hat of x = 30 (the one the
 * macro-mesh proposes) would give 0.  With x0 = 38: the hat of x = 40
 * gives int_{38}^{40} (x-30)/10 + int_{40}^{50} (50-x)/10 = 1.8 + 5 = 6.8,
 * so 6.8/sqrt(12*30) (and x = 30 only 0.02/sqrt(360) = 0.0105).
 */
#include <math.h>
#include "check.h"
#include "contact/lac_contact.h"
#include "base/lac_status.h"

static void
run (double x0, double want_int)
{
  size_t nlo[3] = { 1, 1, 1 }, nup[3] = { 5, 1, 1 };
  double Llo[3] = { 50 - x0, 50, 1 }, Lup[3] = { 50, 50, 1 };
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  lac_mesh_box (LAC_QUAD4, nlo, Llo, 0.0, &lo);
  lac_mesh_box (LAC_QUAD4, nup, Lup, 0.0, &up);
  for (size_t a = 0; a < lo->nnodes; a++)
    lo->x[2 * a] += x0;
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[2 * a + 1] += 50.0;
  lac_mesh_merge (lo, "lo.", up, "up.", &m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, "up.ymin", NULL, &M), LAC_SUCCESS, "macromesh");
  check_int ((long) M->n, 2, "a pair and a triple");
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (m, lac_mesh_group (m, "lo.ymax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P = NULL;
  check_status (lac_pairing_build (&S, &Mf, &po, &P), LAC_SUCCESS, "pairing");
  lac_contact *c = NULL;
  check_status (lac_contact_build (m, LAC_PLANE_STRAIN, M, P, &Mf,
                                   LAC_EPSILON_DEFAULT, &c), LAC_SUCCESS, "contact");
  if (c)
    {
      size_t t = M->ptr[1] - M->ptr[0] == 3 ? 0 : 1;     /* the triple */
      check_abs (m->x[2 * c->inode[t]], 40.0, 1e-12, "x0 = %g: designated node at x = 40", x0);
      check_rel (c->phiint[t], want_int, 1e-12, "x0 = %g: int phi", x0);
      check_rel (c->crit[t], want_int / sqrt ((50 - x0) * 30), 1e-12, "x0 = %g: criterion", x0);
      check_true (c->admissible[t], "x0 = %g: the triple is admissible", x0);
      check_true (!c->admissible[1 - t], "x0 = %g: the uncovered pair is not", x0);
      check_int ((long) c->k, 1, "x0 = %g: one multiplier", x0);
    }
  lac_contact_free (c);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  run (45.0, 1.25);
  run (38.0, 6.8);
  lac_finalize ();
  return check_summary ();
}
