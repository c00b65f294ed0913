/* LAC chapter 04 -- Pairing: search, projection, intersection    [LAC §4.6]
 *
 * Build:        make build/chapters/04-pairing
 * Sample runs:  build/chapters/04-pairing               (upper box turned 10 deg)
 *               build/chapters/04-pairing --angle 0     (aligned grids)
 *               build/chapters/04-pairing --robust      (grid query per facet)
 *               build/chapters/04-pairing --degree 2    (3 points per triangle)
 * Description:  Two hex8 boxes stacked with non-matching meshes: the
 *               bottom of a 3 x 3 box (slave) lies 0.01 above the top of a
 *               2 x 2 box (master) and is turned about the vertical axis.
 *               lac_pairing_build cuts every slave facet by the master
 *               facets it overlaps; the program prints the pairs, the
 *               area of every intersection T^s cap T^m, the covered part
 *               of every slave facet against its area, and the points of
 *               one pair in both reference spaces, with their weights and
 *               normal gaps.  Then the same for a curved 2D interface: the
 *               seg3 arcs between two quad8 annular sectors, where the
 *               pieces are cut on the chords but the points and weights
 *               live on the exact (quadratic) slave arcs.  Short,
 *               deterministic output.
 * Read first:   chapter 02 (spaces: face maps and quadrature), chapter 03
 *               (the slave surface).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem/lac_mesh.h"
#include "contact/lac_pairing.h"
#include "base/lac_status.h"

#define PI 3.14159265358979323846

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex04: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* Turn -0 into +0 for a stable printout. */
static double
clean (double v)
{
  return fabs (v) < 5e-13 ? 0.0 : v;
}

/* The facet list of a named boundary group. */
static lac_pairing_facets
facets_of (const lac_mesh *m, const char *group)
{
  const lac_group *g = lac_mesh_group (m, group);
  if (!g)
    {
      fprintf (stderr, "ex04: no group %s\n", group);
      exit (1);
    }
  return lac_pairing_facets_of (m, g);
}

/* A 2D quad8 box [0,1]^2 of n x 1 cells bent into the annular sector
 * r0 <= r <= r0 + 1 of opening alpha, centred on the y axis: x runs
 * clockwise along the arc, y outward.  Every node, mid-nodes included, is
 * placed by the map, so the facets on r = r0 and r = r0 + 1 are seg3 arcs
 * with their three nodes on the circle. */
static lac_mesh *
sector (size_t n, double r0, double alpha)
{
  size_t nn[3] = { n, 1, 1 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (LAC_QUAD8, nn, L, 0.0, &m), "lac_mesh_box");
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double *x = m->x + 2 * a;
      double th = 0.5 * PI - (x[0] - 0.5) * alpha, r = r0 + x[1];
      x[0] = r * cos (th), x[1] = r * sin (th);
    }
  return m;
}

int
main (int argc, char **argv)
{
  double angle = 10;                    /* degrees, about the vertical axis */
  lac_pairing_opts opts;
  lac_pairing_opts_init (&opts);
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--angle") && k + 1 < argc
          && fabs (atof (argv[k + 1])) <= 45)
        angle = atof (argv[++k]);
      else if (!strcmp (argv[k], "--degree") && k + 1 < argc
               && atoi (argv[k + 1]) >= 1 && atoi (argv[k + 1]) <= 20)
        opts.degree = atoi (argv[++k]);
      else if (!strcmp (argv[k], "--robust"))
        opts.robust = 1;
      else
        {
          fprintf (stderr, "usage: %s [--angle DEG (|DEG| <= 45)] "
                   "[--degree 1..20] [--robust]\n", argv[0]);
          return 2;
        }
    }
  lac_init ();

  // @sect Two non-matching flat surfaces
  /* 1. The master is the top z = 1 of a 2 x 2 x 1 box [0,1]^3 (group
   *    `zmax`, outward normal +z).  The slave is the bottom of a 3 x 3 x 1
   *    box of the same size, lifted to z = 1.01 and turned by `angle`
   *    about the vertical line through (1/2, 1/2) (group `zmin`, outward
   *    normal -z).  The two boxes are two meshes: the pairing only asks
   *    that they have the same dimension.  The facets face each other,
   *    $-n_s \cdot n_m = 1$, and are $0.01$ apart, well within the default
   *    bound `dist_rel` $= 1$ facet diameter. */
  size_t nlo[3] = { 2, 2, 1 }, nup[3] = { 3, 3, 1 };
  double L[3] = { 1, 1, 1 }, th = angle * PI / 180;
  lac_mesh *lo = NULL, *up = NULL;
  check_status (lac_mesh_box (LAC_HEX8, nlo, L, 0.0, &lo), "lac_mesh_box");
  check_status (lac_mesh_box (LAC_HEX8, nup, L, 0.0, &up), "lac_mesh_box");
  for (size_t a = 0; a < up->nnodes; a++)
    {
      double *x = up->x + 3 * a, u = x[0] - 0.5, v = x[1] - 0.5;
      x[0] = 0.5 + cos (th) * u - sin (th) * v;
      x[1] = 0.5 + sin (th) * u + cos (th) * v;
      x[2] += 1.01;
    }
  lac_pairing_facets slave = facets_of (up, "zmin");
  lac_pairing_facets master = facets_of (lo, "zmax");

  /* 2. The pairing.  The advancing front starts at slave facet 0 with a
   *    seed from the bucket grid, floods over the master facets that
   *    overlap it, and hands its masters on to its slave neighbours as
   *    their seeds.  `ntests` counts the (slave, master) overlap tests,
   *    `nseeds` the bucket-grid queries (first seed, failed seeds,
   *    completion of partly covered facets). */
  lac_pairing *P = NULL;
  check_status (lac_pairing_build (&slave, &master, &opts, &P),
                "lac_pairing_build");
  printf ("1. slave: bottom of a 3 x 3 box turned by %g deg, 0.01 above "
          "master: top of a 2 x 2 box\n", angle);
  printf ("   %zu slave, %zu master facets: %zu pairs, %zu points, "
          "%zu tests, %zu grid queries\n", P->nslave, P->nmaster, P->npairs,
          P->npoints, P->ntests, P->nseeds);

  /* 3. Slave facet by slave facet: its masters (sorted by index) and the
   *    areas $|T^s \cap T^m|$, the sum of the weights of each pair.  They
   *    add up to `covered[s]`; on flat facets the pieces are the exact
   *    intersections, so covered = |T^s| (1/9) up to rounding when the
   *    facet lies over the master, and less where it overhangs. */
  printf ("2. per slave facet: masters m (area of T^s cap T^m)\n");
  printf ("    s  |T^s|     covered   masters\n");
  for (size_t s = 0; s < P->nslave; s++)
    {
      printf ("   %2zu  %.6f  %.6f ", s, P->measure[s],
              clean (P->covered[s]));
      for (size_t q = P->pair_ptr[s]; q < P->pair_ptr[s + 1]; q++)
        printf (" %zu (%.6f)", P->pair_master[q], P->pair_measure[q]);
      printf ("\n");
    }
  double area = 0;
  for (size_t s = 0; s < P->nslave; s++)
    area += P->measure[s];
  printf ("   total covered %.12f of the slave's %.12f\n",
          lac_pairing_total (P), area);

  /* 4. The points of one pair: the first pair of the central slave facet
   *    (s = 4).  Each point has its coordinates xs in the slave's
   *    reference square and xm in the master's, a physical weight w
   *    (reference weight x Jacobian of the fan triangle x surface element)
   *    and the normal gap g, defined by $X_m(x_m) = x_s + g\, n_s$: here
   *    g = 0.01 at every point (separated, g > 0). */
  {
    size_t s = 4, q = P->pair_ptr[s];
    printf ("3. points of pair (slave %zu, master %zu): %zu points\n", s,
            P->pair_master[q], P->pair_pt[q + 1] - P->pair_pt[q]);
    printf ("        xs                  xm                  w         gap\n");
    for (size_t p = P->pair_pt[q]; p < P->pair_pt[q + 1]; p++)
      printf ("   (%8.5f, %8.5f)  (%8.5f, %8.5f)  %.6f  %.6f\n",
              clean (P->xs[2 * p]), clean (P->xs[2 * p + 1]),
              clean (P->xm[2 * p]), clean (P->xm[2 * p + 1]), P->w[p],
              P->gap[p]);
  }
  lac_pairing_free (P);
  lac_mesh_free (lo);
  lac_mesh_free (up);

  // @sect A curved interface in 2D: seg3 arcs
  /* 5. Two quad8 annular sectors of opening 1 rad: the master 1 <= r <= 2
   *    in 4 cells, the slave 2 <= r <= 3 in 3 cells.  Both contact
   *    surfaces are polygons of seg3 arcs on the circle r = 2, with their
   *    vertices and mid-nodes on it, but the two quadratic interpolations
   *    of the circle differ between the vertices.  The pieces of each
   *    slave facet are cut on the chords (the master vertices projected
   *    orthogonally onto the slave chord); the points sit on the exact
   *    slave arc and are projected along its normal onto the master arc,
   *    so the weights integrate the arc length, not the chord length, and
   *    the gaps measure how far apart the two quadratic arcs are. */
  {
    const double R = 2, alpha = 1;
    lac_mesh *mm = sector (4, R - 1, alpha), *ms = sector (3, R, alpha);
    slave = facets_of (ms, "ymin");
    master = facets_of (mm, "ymax");
    lac_pairing_opts_init (&opts);
    check_status (lac_pairing_build (&slave, &master, &opts, &P),
                  "lac_pairing_build");
    printf ("4. seg3 arcs on r = %g: %zu slave, %zu master facets, %zu "
            "pairs, %zu points\n", R, P->nslave, P->nmaster, P->npairs,
            P->npoints);
    printf ("    s  chord     |T^s|     covered   max|gap|  masters "
            "(length of the piece)\n");
    double chord = 2 * R * sin (alpha / 2 / 3);
    for (size_t s = 0; s < P->nslave; s++)
      {
        double gmax = 0;
        for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
          gmax = fmax (gmax, fabs (P->gap[p]));
        printf ("   %2zu  %.6f  %.6f  %.6f  %.1e ", s, chord, P->measure[s],
                P->covered[s], gmax);
        for (size_t q = P->pair_ptr[s]; q < P->pair_ptr[s + 1]; q++)
          printf (" %zu (%.6f)", P->pair_master[q], P->pair_measure[q]);
        printf ("\n");
      }
    printf ("   total covered %.6f, circle arc R alpha = %.6f, "
            "3 chords %.6f\n", lac_pairing_total (P), R * alpha, 3 * chord);
    lac_pairing_free (P);
    lac_mesh_free (mm);
    lac_mesh_free (ms);
  }

  lac_finalize ();
  return 0;
}
