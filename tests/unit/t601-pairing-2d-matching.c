/* t601: 2D matching segments (seg2 and seg3, flat and curved): each slave
 * facet is paired with its twin only and fully covered  [LAC §4.6] */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "contact/lac_pairing.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

#define PI 3.14159265358979323846

/* Slave and master: the same cut of one curve, normals opposite. */
static void
run (lac_elem_type ft, pm_map *S, const double *cs, const double *cm,
     double a, double b, size_t n, double length, double tol,
     const char *what)
{
  pm_builder B;
  pm_surf sf;
  lac_pairing *P = NULL;
  pm_builder_init (&B, 2);
  pm_line (&sf, a, b, n, 1);
  pm_side ss = pm_add_side (&B, &sf, ft, S, cs, 0.1 * (b - a) / (double) n);
  pm_side ms = pm_add_side (&B, &sf, ft, S, cm, 0.1 * (b - a) / (double) n);
  lac_mesh *m = pm_finish (&B);
  lac_pairing_facets fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_SUCCESS,
                "%s: build", what);
  if (!P)
    goto done;
  check_int ((long) P->npairs, (long) n, "%s: one pair per slave facet", what);
  double total = 0, gmax = 0, xmax = 0;
  for (size_t s = 0; s < n; s++)
    {
      size_t q = P->pair_ptr[s];
      check_int ((long) (P->pair_ptr[s + 1] - q), 1, "%s: pairs of %zu", what, s);
      check_int ((long) P->pair_master[q], (long) s, "%s: twin of %zu", what, s);
      /* absolute, relative to the interface: rounding in the map of a
       * tiny facet far from the origin is ~eps |x| / h relative to it */
      check_abs (P->covered[s], P->measure[s], tol * fabs (length),
                 "%s: covered %zu", what, s);
      check_abs (P->pair_measure[q], P->covered[s], 1e-14 * fabs (length),
                 "%s: pair %zu", what, s);
      total += P->covered[s];
      for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
        {
          gmax = fmax (gmax, fabs (P->gap[p]));
          /* the twin runs the other way: xm = -xs */
          xmax = fmax (xmax, fabs (P->xm[p] + P->xs[p]));
        }
    }
  if (length > 0)
    check_rel (total, length, 1e-14, "%s: total length", what);
  else
    {                       /* curved: the seg3 arc's length, close to pi/2 */
      double meas = 0;
      for (size_t s = 0; s < n; s++)
        meas += P->measure[s];
      check_rel (total, meas, tol, "%s: total length", what);
      check_rel (total, -length, 1e-4, "%s: arc length", what);
    }
  check_abs (gmax, 0, 1e-14, "%s: gaps", what);
  check_abs (xmax, 0, 1e-13, "%s: master coordinates", what);
done:
  lac_pairing_free (P);
  lac_mesh_free (m);
  pm_side_free (&ss), pm_side_free (&ms), pm_surf_free (&sf);
  pm_builder_free (&B);
}

int
main (void)
{
  double fs[2] = { 0, 1 }, fm[2] = { 0, -1 };
  double cs[2] = { 1, 1 }, cm[2] = { 1, -1 };
  lac_init ();
  run (LAC_SEG2, pm_flat2, fs, fm, 0, 1, 10, 1, 1e-14, "seg2 flat");
  run (LAC_SEG3, pm_flat2, fs, fm, -2, 3, 17, 5, 1e-14, "seg3 flat");
  /* Curved: the total is the length of the seg3 interpolant of the arc.  A
   * facet is covered by its twin alone, integrated with the 3-point rule,
   * while its measure uses 5 points: |dx/dxi| is not a polynomial on a
   * curved seg3, and the two rules differ by up to ~2e-7 on the largest
   * random facets here (0.4 rad); hence 1e-6. */
  run (LAC_SEG3, pm_circle, cs, cm, 0, 0.5 * PI, 12, -0.5 * PI, 1e-6,
       "seg3 arc");
  return check_summary ();
}
