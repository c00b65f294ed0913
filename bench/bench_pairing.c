/* bench_pairing -- pairing time per slave facet on flat non-matching 3D
 * interfaces, from 1e3 to 1e6 slave facets                    [LAC §4.6]
 *
 * Build:        make B=build/pair build/pair/bench/bench_pairing
 * Sample runs:  build/pair/bench/bench_pairing            (1e3 .. 1e6, quad4)
 *               build/pair/bench/bench_pairing 1e5 tri3   (up to 1e5, tri3)
 *               build/pair/bench/bench_pairing 1e6 quad4 4 (degree 4)
 *               build/pair/bench/bench_pairing 1e5 quad4 4 0
 *                 (degree_nonaffine 0: the library default, degree + 14)
 * Description:  The slave is an n x n jittered grid on the unit square, the
 *               master a jittered grid of 1.65 n x 1.65 n cells of the
 *               square [-0.25, 1.25]^2 rotated by 0.3 rad, which covers
 *               the slave (facets 0.9 times the slave's).  Prints the sizes, the pairing time (the
 *               mesh construction is not timed; wall clock and CPU time of
 *               the process, which is less sensitive to a loaded machine),
 *               the CPU time per slave facet, which should stay flat (the
 *               search is linear), the tests per facet, the seeds taken
 *               from the bucket grid, the failed projections and the error
 *               of the total area.  Default rule degree 2 (3 points per
 *               triangle), and the same degree on the jittered (not
 *               parallelogram) quads, to keep the result of 1e6 facets
 *               within ~2 GB; the library's default degree_nonaffine would
 *               put 81 points on each triangle of a quad pair.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "contact/lac_pairing.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

static double
now (clockid_t c)
{
  struct timespec ts;
  clock_gettime (c, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

int
main (int argc, char **argv)
{
  double nmax = argc > 1 ? atof (argv[1]) : 1e6;
  const char *type = argc > 2 ? argv[2] : "quad4";
  int degree = argc > 3 ? atoi (argv[3]) : 2;
  int dna = argc > 4 ? atoi (argv[4]) : degree;
  const lac_refelem *re = lac_refelem_by_name (type);
  double zs[2] = { 0, 1 }, zm[2] = { 0, -1 };
  lac_pairing_opts o;

  lac_init ();
  if (!re || re->dim != 2)
    {
      fprintf (stderr, "bench_pairing: %s is not a 3D facet type\n", type);
      return 2;
    }
  int tri = re->shape == LAC_SHAPE_TRI;
  lac_pairing_opts_init (&o);
  o.degree = degree;
  o.degree_nonaffine = dna;
  printf ("# flat non-matching interface, %s facets on both sides, rule "
          "degree %d (non-affine pairs: %d)\n", type, degree, dna);
  printf ("# %9s %9s %9s %10s %8s %8s %9s %7s %5s %4s %9s\n", "slave",
          "master", "pairs", "points", "wall_s", "cpu_s", "cpu_us/f",
          "tests/f", "grid", "fail", "|A-1|");
  for (double target = 1e3; target <= nmax * 1.01; target *= 10)
    {
      size_t n = (size_t) llround (sqrt (target / (tri ? 2 : 1)));
      size_t nm = (size_t) llround (1.65 * (double) n);
      pm_builder B;
      pm_surf a, b;
      lac_pairing *P = NULL;
      pm_builder_init (&B, 3);
      pm_seed = 1234;
      pm_grid (&a, 0, 1, n, n, 0, 0.2, tri);
      pm_grid (&b, -0.25, 1.25, nm, nm, 0.3, 0.2, tri);
      double th = 0.5 / (double) n;
      pm_side ss = pm_add_side (&B, &a, re->type, pm_flat3, zs, th);
      pm_side ms = pm_add_side (&B, &b, re->type, pm_flat3, zm, th);
      pm_surf_free (&a), pm_surf_free (&b);
      lac_mesh *m = pm_finish (&B);
      pm_builder_free (&B);
      if (!m)
        {
          fprintf (stderr, "bench_pairing: %s\n", lac_error_message ());
          return 1;
        }
      lac_pairing_facets fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
      double t0 = now (CLOCK_MONOTONIC), c0 = now (CLOCK_PROCESS_CPUTIME_ID);
      int status = lac_pairing_build (&fs, &fm, &o, &P);
      double t1 = now (CLOCK_MONOTONIC), c1 = now (CLOCK_PROCESS_CPUTIME_ID);
      if (status)
        {
          fprintf (stderr, "bench_pairing: %s\n", lac_error_message ());
          return 1;
        }
      printf ("  %9zu %9zu %9zu %10zu %8.3f %8.3f %9.2f %7.1f %5zu %4zu "
              "%9.1e\n", fs.n, fm.n, P->npairs, P->npoints, t1 - t0,
              c1 - c0, 1e6 * (c1 - c0) / (double) fs.n,
              (double) P->ntests / (double) fs.n, P->nseeds, P->nfail,
              fabs (lac_pairing_total (P) - 1));
      fflush (stdout);
      lac_pairing_free (P);
      lac_mesh_free (m);
      pm_side_free (&ss), pm_side_free (&ms);
    }
  return 0;
}
