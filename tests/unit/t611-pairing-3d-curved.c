/* t611: curved 3D interfaces (cylinder and sphere patches, quadratic
 * facets on both sides, different discretizations): total paired area
 * against the slave surface area, points consistent  [LAC §4.6] */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "contact/lac_pairing.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

/* X(xi) and n(xi) of facet i of a side. */
static void
facet_point (const lac_pairing_facets *f, size_t i, const double *xi,
             double *x, double *n)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type t;
  double xe[LAC_MAX_FACE_NODES * 3];
  lac_map m;
  int k = lac_mesh_facet_nodes (f->mesh, f->cell[i], f->face[i], nodes, &t);
  for (int a = 0; a < k; a++)
    for (int j = 0; j < 3; j++)
      xe[3 * a + j] = f->mesh->x[3 * (size_t) nodes[a] + (size_t) j];
  lac_map_face (lac_refelem_get (t), 3, xe, xi, &m);
  for (int j = 0; j < 3; j++)
    x[j] = m.x[j], n[j] = m.normal[j];
}

/* Slave: grid [0, L]^2 of the parameters, ns x ns; master: [-0.2, L+0.2]^2
 * rotated by 0.3 rad, nm x nm.  S maps parameters to the surface, Rm is
 * the master's radius (Rs = 1), area the exact slave area; tol bounds
 * |total / sum of measures - 1|. */
static void
run1 (pm_map *S, lac_elem_type fts, lac_elem_type ftm, double L, size_t ns,
      size_t nm, double Rm, double area, int dna, double tol,
      const char *what)
{
  lac_pairing_opts o;
  lac_pairing_opts_init (&o);
  o.degree_nonaffine = dna;
  double cs[2] = { 1, 1 }, cm[2] = { Rm, -1 };
  pm_builder B;
  pm_surf sfs, sfm;
  lac_pairing *P = NULL;
  pm_builder_init (&B, 3);
  pm_seed = 5;
  pm_grid (&sfs, 0, L, ns, ns, 0, 0.2,
           lac_refelem_get (fts)->shape == LAC_SHAPE_TRI);
  pm_grid (&sfm, -0.2, L + 0.2, nm, nm, 0.3, 0.1,
           lac_refelem_get (ftm)->shape == LAC_SHAPE_TRI);
  pm_side ss = pm_add_side (&B, &sfs, fts, S, cs, 0.02);
  pm_side ms = pm_add_side (&B, &sfm, ftm, S, cm, 0.02);
  lac_mesh *m = pm_finish (&B);
  lac_pairing_facets fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  check_status (lac_pairing_build (&fs, &fm, &o, &P), LAC_SUCCESS,
                "%s: build", what);
  if (!P)
    goto done;
  double total = 0, meas = 0, worst = 0, gmin = INFINITY, gmax = -INFINITY;
  double xerr = 0;
  for (size_t s = 0; s < fs.n; s++)
    {
      double sum = 0;
      for (size_t q = P->pair_ptr[s]; q < P->pair_ptr[s + 1]; q++)
        sum += P->pair_measure[q];
      check_abs (sum, P->covered[s], 1e-14 * area, "%s: pieces of %zu", what, s);
      worst = fmax (worst, fabs (P->covered[s] / P->measure[s] - 1));
      total += P->covered[s], meas += P->measure[s];
      for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
        {
          double xs[3], xm[3], ns_[3], nm_[3];
          gmin = fmin (gmin, P->gap[p]), gmax = fmax (gmax, P->gap[p]);
          facet_point (&fs, s, P->xs + 2 * p, xs, ns_);
          facet_point (&fm, P->master[p], P->xm + 2 * p, xm, nm_);
          for (int j = 0; j < 3; j++)     /* X_m = x_s + g n_s */
            xerr = fmax (xerr, fabs (xs[j] + P->gap[p] * ns_[j] - xm[j]));
        }
    }
  check_rel (total, meas, tol, "%s: total = slave surface", what);
  check_rel (worst, 0, tol, "%s: every facet covered", what);
  check_rel (total, area, 1e-3, "%s: total = exact area", what);
  check_abs (xerr, 0, 1e-12, "%s: X_m(xm) = x_s + g n_s", what);
  check_int ((long) P->nfail, 0, "%s: no failed projection", what);
  check_true (gmin > 0.9 * (Rm - 1) - 1e-4 && gmax < 1.1 * (Rm - 1) + 1e-4,
              "%s: gaps in [%g, %g], radii %g apart", what, gmin, gmax, Rm - 1);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s (degree_nonaffine %d): %zu/%zu facets, %zu pairs, "
            "|total/measure - 1| = %.2e, worst facet %.2e, |total/exact - 1| "
            "= %.2e, gap in [%.3e, %.3e], %zu grid queries\n", what, dna,
            fs.n, fm.n, P->npairs,
            fabs (total / meas - 1), worst, fabs (total / area - 1), gmin,
            gmax, P->nseeds);
done:
  lac_pairing_free (P);
  lac_mesh_free (m);
  pm_side_free (&ss), pm_side_free (&ms);
  pm_surf_free (&sfs), pm_surf_free (&sfm);
  pm_builder_free (&B);
}

/* Each case twice: with degree 4 everywhere (tolerance tol, see below),
 * and with the defaults (degree 18 on the pairs with a quadrangle that is
 * not a parallelogram, which is every pair here: tolerance 1e-10). */
static void
run (pm_map *S, lac_elem_type fts, lac_elem_type ftm, double L, size_t ns,
     size_t nm, double Rm, double area, double tol, const char *what)
{
  run1 (S, fts, ftm, L, ns, nm, Rm, area, 4, tol, what);
  run1 (S, fts, ftm, L, ns, nm, Rm, area, 0, 1e-10, what);
}

int
main (void)
{
  lac_init ();
  /* The slave facets are all covered, so each is tiled exactly by its
   * pieces (in its chart); with degree 4 the pieces integrate the exact
   * slave surface element with the 6-point rule on each triangle, the
   * measure uses a degree-8 rule on the whole facet.  The differences are
   * quadrature errors:
   *   triangles: the chart is the reference triangle, the integrand
   *     |dx/dxi| is smooth: ~1e-9 relative per facet for h ~ 0.1 R, so
   *     tol = 1e-7;
   *   quadrangles: the chart is the tangent plane, the integrand is
   *     |dx/dxi| / det(dz/dxi), constant on a flat facet but varying by
   *     O((h/R)^2 x distortion) on a curved, jittered one: ~1e-6 relative
   *     per facet here (and O(h^2): 6.5e-6 -> 1.9e-6 when h is halved),
   *     so tol = 1e-5.
   * The slave surface itself (quadratic interpolation) is within O(h^3)
   * ~ 1e-4 of the exact cylinder or sphere: 1e-3 above. */
  /* cylinder of radius 1 (x = cos u, sin u, v), u, v in [0, 1]: area 1 */
  run (pm_cylinder, LAC_QUAD9, LAC_TRI6, 1, 8, 11, 1, 1, 1e-5,
       "cylinder quad9 / tri6");
  run (pm_cylinder, LAC_TRI6, LAC_QUAD8, 1, 7, 9, 1.01, 1, 1e-7,
       "cylinder tri6 / quad8, gap 0.01");
  run (pm_cylinder, LAC_QUAD8, LAC_QUAD9, 1, 9, 7, 1.005, 1, 1e-5,
       "cylinder quad8 / quad9, gap 0.005");
  /* sphere patch: longitude, latitude in [0, 0.8]: area sin(0.8) 0.8 */
  run (pm_sphere, LAC_TRI6, LAC_QUAD9, 0.8, 8, 10, 1, 0.8 * sin (0.8), 1e-7,
       "sphere tri6 / quad9");
  run (pm_sphere, LAC_QUAD9, LAC_TRI6, 0.8, 6, 9, 1.01, 0.8 * sin (0.8),
       1e-5, "sphere quad9 / tri6, gap 0.01");
  return check_summary ();
}
