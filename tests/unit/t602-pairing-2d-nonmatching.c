/* t602: 2D non-matching interfaces cut at random points, flat (seg2/seg3)
 * and curved (seg3 arcs): pieces sum to the covered length, which is the
 * facet length when covered, and the total is the overlap  [LAC §4.6] */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "contact/lac_pairing.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

#define PI 3.14159265358979323846

/* Slave: [a, b] cut at ns-1 random points; master: [c, d] cut at nm-1. */
static void
run (lac_elem_type fts, lac_elem_type ftm, pm_map *S, const double *cs,
     const double *cm, double a, double b, size_t ns, double c, double d,
     size_t nm, double tol, const char *what)
{
  pm_builder B;
  pm_surf sfs, sfm;
  lac_pairing *P = NULL;
  double sum_meas = 0, total = 0, worst = 0, gmax = 0;
  pm_builder_init (&B, 2);
  pm_line (&sfs, a, b, ns, 1);
  pm_line (&sfm, c, d, nm, 1);
  pm_side ss = pm_add_side (&B, &sfs, fts, S, cs, 0.01);
  pm_side ms = pm_add_side (&B, &sfm, ftm, S, cm, 0.01);
  lac_mesh *m = pm_finish (&B);
  lac_pairing_facets fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_SUCCESS,
                "%s: build", what);
  if (!P)
    goto done;
  for (size_t s = 0; s < ns; s++)
    {
      double lo = sfs.p[s], hi = sfs.p[s + 1], sum = 0, wsum = 0;
      for (size_t q = P->pair_ptr[s]; q < P->pair_ptr[s + 1]; q++)
        sum += P->pair_measure[q];
      for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
        wsum += P->w[p], gmax = fmax (gmax, fabs (P->gap[p]));
      check_rel (sum, P->covered[s], 1e-14, "%s: pairs of %zu", what, s);
      check_rel (wsum, P->covered[s], 1e-14, "%s: points of %zu", what, s);
      if (lo >= c && hi <= d)                    /* fully covered */
        {
          check_rel (P->covered[s], P->measure[s], tol, "%s: facet %zu covered",
                     what, s);
          worst = fmax (worst, fabs (P->covered[s] / P->measure[s] - 1));
        }
      sum_meas += P->measure[s];
      total += P->covered[s];
    }
  if (S == pm_flat2)               /* the overlap of [a,b] and [c,d] */
    check_rel (total, fmin (b, d) - fmax (a, c), 1e-13, "%s: total", what);
  else if (c <= a && d >= b)       /* the slave arc, as discretised */
    check_rel (total, sum_meas, tol, "%s: total", what);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: %zu pairs, %zu points, worst |covered/measure - 1| = %.2e, "
            "max |gap| = %.2e\n", what, P->npairs, P->npoints, worst, gmax);
done:
  lac_pairing_free (P);
  lac_mesh_free (m);
  pm_side_free (&ss), pm_side_free (&ms);
  pm_surf_free (&sfs), pm_surf_free (&sfm);
  pm_builder_free (&B);
}

int
main (void)
{
  double fs[2] = { 0, 1 }, fm[2] = { 0, -1 };
  double cs[2] = { 2, 1 }, cm[2] = { 2, -1 };
  lac_init ();
  /* Flat: master covers the slave, then only part of it. */
  run (LAC_SEG2, LAC_SEG2, pm_flat2, fs, fm, 0, 1, 37, -0.1, 1.1, 53, 1e-12,
       "flat seg2/seg2");
  run (LAC_SEG2, LAC_SEG3, pm_flat2, fs, fm, 0, 1, 41, 0.3, 0.8, 29, 1e-12,
       "flat seg2/seg3 partial");
  run (LAC_SEG3, LAC_SEG3, pm_flat2, fs, fm, -1, 2, 64, -3, 0.5, 100, 1e-12,
       "flat seg3/seg3 partial");
  /* Curved: a quarter of a circle of radius 2, seg3 on both sides with
   * different counts.  The pieces of a slave facet tile it exactly, but
   * each piece integrates the surface element |dx/dxi| (not a polynomial
   * on a curved seg3) with a 3-point Gauss rule, while the measure uses a
   * 5-point rule on the whole facet: they agree to the quadrature error,
   * up to ~3e-7 for the largest random facets here (0.5 rad), hence 1e-6. */
  run (LAC_SEG3, LAC_SEG3, pm_circle, cs, cm, 0, 0.5 * PI, 17, -0.1,
       0.5 * PI + 0.1, 23, 1e-6, "arc seg3/seg3");
  run (LAC_SEG3, LAC_SEG2, pm_circle, cs, cm, 0, 0.5 * PI, 17, -0.1,
       0.5 * PI + 0.1, 40, 1e-6, "arc seg3/seg2");
  return check_summary ();
}
