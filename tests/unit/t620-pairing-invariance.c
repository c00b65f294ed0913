/* t620: the pairing is invariant under rigid motions of both sides, and
 * swapping slave and master gives the same total contact area  [LAC §4.6] */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "contact/lac_pairing.h"
#include "contact/lac_pairing_geom.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

/* x <- R x + t on every node (R: rotation by angle a about the unit axis
 * u in 3D, by a in 2D). */
static void
rigid_motion (lac_mesh *m, double a, const double *u, const double *t)
{
  double c = cos (a), s = sin (a), R[9];
  if (m->dim == 2)
    R[0] = c, R[1] = -s, R[3] = s, R[4] = c;
  else
    for (int i = 0; i < 3; i++)         /* Rodrigues: c I + s [u]x + (1-c) uu^T */
      for (int j = 0; j < 3; j++)
        {
          double ux = (i == j) ? 0 : ((j == (i + 1) % 3) ? -u[(i + 2) % 3]
                                      : u[(i + 1) % 3]);
          R[3 * i + j] = (i == j) * c + s * ux + (1 - c) * u[i] * u[j];
        }
  size_t d = (size_t) m->dim;
  for (size_t n = 0; n < m->nnodes; n++)
    {
      double *x = m->x + d * n, y[3] = { 0, 0, 0 };
      for (size_t i = 0; i < d; i++)
        for (size_t j = 0; j < d; j++)
          y[i] += R[3 * i + j] * x[j];
      for (size_t i = 0; i < d; i++)
        x[i] = y[i] + t[i];
    }
}

/* The same pairs, with the same measures (relative to the total area: the
 * rounding of a facet's map is ~ eps |x| / h relative to the facet, large
 * for the tiny random facets of the 2D case). */
static void
compare (const lac_pairing *P, const lac_pairing *Q, double tol,
         const char *what)
{
  check_int ((long) Q->npairs, (long) P->npairs, "%s: number of pairs", what);
  if (Q->npairs != P->npairs)
    return;
  double worst = 0, total = lac_pairing_total (P);
  for (size_t s = 0; s < P->nslave; s++)
    for (size_t q = P->pair_ptr[s]; q < P->pair_ptr[s + 1]; q++)
      {
        check_int ((long) Q->pair_master[q], (long) P->pair_master[q],
                   "%s: pair %zu", what, q);
        worst = fmax (worst, fabs (Q->pair_measure[q] - P->pair_measure[q])
                      / total);
      }
  check_abs (worst, 0, tol, "%s: pair measures", what);
}

/* One configuration: slave and master surfaces (already built in m). */
static void
run (lac_mesh *m, const pm_side *ss, const pm_side *ms, double exact,
     double tol, const char *what)
{
  lac_pairing_facets fs = pm_facets (m, ss), fm = pm_facets (m, ms);
  lac_pairing *P = NULL, *Q = NULL, *W = NULL;
  double u[3] = { 2, -1, 3 }, t[3] = { 3, -2, 1.5 }, nu = sqrt (14);
  for (int k = 0; k < 3; k++)
    u[k] /= nu;
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_SUCCESS,
                "%s: build", what);
  check_status (lac_pairing_build (&fm, &fs, NULL, &W), LAC_SUCCESS,
                "%s: build swapped", what);
  rigid_motion (m, 0.7, u, t);
  check_status (lac_pairing_build (&fs, &fm, NULL, &Q), LAC_SUCCESS,
                "%s: build moved", what);
  if (P && Q && W)
    {
      compare (P, Q, tol, what);
      double tp = lac_pairing_total (P), tq = lac_pairing_total (Q);
      double tw = lac_pairing_total (W);
      check_rel (tq, tp, tol, "%s: total, moved", what);
      check_rel (tw, tp, tol, "%s: total, swapped", what);
      if (exact > 0)
        check_rel (tp, exact, tol, "%s: total = exact overlap", what);
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("%s: total %.15g, moved %.3e, swapped %.3e\n", what, tp,
                tq / tp - 1, tw / tp - 1);
    }
  lac_pairing_free (P), lac_pairing_free (Q), lac_pairing_free (W);
}

/* Area of the overlap of the unit square and the square [a, b]^2 rotated
 * by theta about its centre (both in the plane). */
static double
square_overlap (double a, double b, double theta)
{
  double c = 0.5 * (a + b), h = 0.5 * (b - a), sq[8], rq[8], out[32];
  double corner[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  for (int k = 0; k < 4; k++)
    {
      sq[2 * k] = 0.5 + 0.5 * corner[k][0], sq[2 * k + 1] = 0.5 + 0.5 * corner[k][1];
      double x = h * corner[k][0], y = h * corner[k][1];
      rq[2 * k] = c + cos (theta) * x - sin (theta) * y;
      rq[2 * k + 1] = c + sin (theta) * x + cos (theta) * y;
    }
  int n = lac_pairing_clip (4, sq, 4, rq, out);
  return lac_pairing_polygon_area (n, out);
}

int
main (void)
{
  lac_init ();
  /* 3D flat: jittered tri3 on the unit square, rotated quad4 square
   * [0.5, 1.4]^2 overlapping a corner of it; then rotated tri3. */
  {
    double zs[2] = { 0, 1 }, zm[2] = { 0, -1 };
    pm_builder B;
    pm_surf a, b, c;
    pm_builder_init (&B, 3);
    pm_seed = 11;
    pm_grid (&a, 0, 1, 9, 9, 0, 0.2, 1);
    pm_grid (&b, 0.5, 1.4, 7, 7, 0.3, 0.2, 0);
    pm_grid (&c, 0.5, 1.4, 6, 6, 0.3, 0.2, 1);
    pm_side sa = pm_add_side (&B, &a, LAC_TRI3, pm_flat3, zs, 0.05);
    pm_side sb = pm_add_side (&B, &b, LAC_QUAD4, pm_flat3, zm, 0.05);
    pm_side sc = pm_add_side (&B, &c, LAC_TRI6, pm_flat3, zm, 0.05);
    lac_mesh *m = pm_finish (&B);
    double ex = square_overlap (0.5, 1.4, 0.3);
    run (m, &sa, &sb, ex, 1e-12, "3D tri3 / quad4");
    run (m, &sa, &sc, ex, 1e-12, "3D tri3 / tri6");
    lac_mesh_free (m);
    pm_side_free (&sa), pm_side_free (&sb), pm_side_free (&sc);
    pm_surf_free (&a), pm_surf_free (&b), pm_surf_free (&c);
    pm_builder_free (&B);
  }
  /* 3D curved: cylinder quad9 / tri6 (moved only; the swap is checked to
   * the quadrature error of the curved pieces, see t611) */
  {
    double cs[2] = { 1, 1 }, cm[2] = { 1, -1 };
    pm_builder B;
    pm_surf a, b;
    pm_builder_init (&B, 3);
    pm_grid (&a, 0, 1, 6, 6, 0, 0.2, 0);
    pm_grid (&b, 0, 1, 7, 7, 0, 0.2, 1);
    pm_side sa = pm_add_side (&B, &a, LAC_QUAD9, pm_cylinder, cs, 0.02);
    pm_side sb = pm_add_side (&B, &b, LAC_TRI6, pm_cylinder, cm, 0.02);
    lac_mesh *m = pm_finish (&B);
    run (m, &sa, &sb, 0, 1e-6, "3D cylinder quad9 / tri6");
    lac_mesh_free (m);
    pm_side_free (&sa), pm_side_free (&sb);
    pm_surf_free (&a), pm_surf_free (&b);
    pm_builder_free (&B);
  }
  /* 2D flat: random cuts of [0, 1] and [0.4, 1.7] */
  {
    double fs[2] = { 0, 1 }, fm[2] = { 0, -1 };
    pm_builder B;
    pm_surf a, b;
    pm_builder_init (&B, 2);
    pm_line (&a, 0, 1, 23, 1);
    pm_line (&b, 0.4, 1.7, 31, 1);
    pm_side sa = pm_add_side (&B, &a, LAC_SEG2, pm_flat2, fs, 0.01);
    pm_side sb = pm_add_side (&B, &b, LAC_SEG3, pm_flat2, fm, 0.01);
    lac_mesh *m = pm_finish (&B);
    run (m, &sa, &sb, 0.6, 1e-12, "2D seg2 / seg3");
    lac_mesh_free (m);
    pm_side_free (&sa), pm_side_free (&sb);
    pm_surf_free (&a), pm_surf_free (&b);
    pm_builder_free (&B);
  }
  return check_summary ();
}
