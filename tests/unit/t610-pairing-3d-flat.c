/* t610: 3D flat non-matching interfaces (tri3, quad4, tri6, quad8, quad9;
 * rotated and jittered grids of different sizes): the pieces of every
 * covered slave facet sum to its area, the total is the area of the
 * overlap, the front finds what the exhaustive search finds  [LAC §4.6] */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "contact/lac_pairing.h"
#include "contact/lac_pairing_geom.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

typedef struct grid_spec
{
  lac_elem_type ft;
  double a, b;          /* the square [a, b]^2 before rotation */
  size_t n;             /* n x n cells                           */
  double theta, jitter;
  unsigned long long seed;   /* of the jitter; equal specs: equal grids */
} grid_spec;

static void
make_surf (pm_surf *s, const grid_spec *g)
{
  lac_shape sh = lac_refelem_get (g->ft)->shape;
  pm_seed = g->seed;
  pm_grid (s, g->a, g->b, g->n, g->n, g->theta, g->jitter,
           sh == LAC_SHAPE_TRI);
}

/* X(xi) of facet i of a side. */
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

/* The exact area of the intersection of slave facet s and master facet m
 * (flat, straight-sided, in the plane z = 0), clipped in physical x, y
 * coordinates: an oracle independent of the charts. */
static double
exact_overlap (const lac_pairing_facets *fs, size_t s,
               const lac_pairing_facets *fm, size_t m)
{
  const lac_pairing_facets *f[2] = { fs, fm };
  size_t i[2] = { s, m };
  double xy[2][8], out[2 * LAC_PAIRING_MAXPOLY];
  int nv[2];
  for (int k = 0; k < 2; k++)
    {
      int nodes[LAC_MAX_FACE_NODES];
      lac_elem_type t;
      lac_mesh_facet_nodes (f[k]->mesh, f[k]->cell[i[k]], f[k]->face[i[k]],
                            nodes, &t);
      nv[k] = lac_refelem_get (t)->nvertices;
      for (int a = 0; a < nv[k]; a++)
        for (int j = 0; j < 2; j++)
          xy[k][2 * a + j] = f[k]->mesh->x[3 * (size_t) nodes[a] + (size_t) j];
    }
  int n = lac_pairing_clip (nv[0], xy[0], nv[1], xy[1], out);
  return n ? fabs (lac_pairing_polygon_area (n, out)) : 0;
}

/* Pair slave grid gs with master grid gm; expected total area `area`;
 * a slave facet is covered if all its vertices are inside the master's
 * square (test `inside`). */
static void
run (const grid_spec *gs, const grid_spec *gm, double area, double lo,
     double hi, const char *what)
{
  double zs[2] = { 0, 1 }, zm[2] = { 0, -1 };
  pm_builder B;
  pm_surf ss_, ms_;
  lac_pairing *P = NULL, *R = NULL;
  lac_pairing_opts o;
  pm_builder_init (&B, 3);
  make_surf (&ss_, gs), make_surf (&ms_, gm);
  pm_side ss = pm_add_side (&B, &ss_, gs->ft, pm_flat3, zs, 0.05);
  pm_side ms = pm_add_side (&B, &ms_, gm->ft, pm_flat3, zm, 0.05);
  lac_mesh *m = pm_finish (&B);
  lac_pairing_facets fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_SUCCESS,
                "%s: build", what);
  lac_pairing_opts_init (&o);
  o.robust = 1;
  check_status (lac_pairing_build (&fs, &fm, &o, &R), LAC_SUCCESS,
                "%s: build (robust)", what);
  if (!P || !R)
    goto done;
  double total = 0, gmax = 0, xerr = 0;
  size_t ncov = 0;
  for (size_t s = 0; s < fs.n; s++)
    {
      int covered = 1;
      double sum = 0;
      for (int a = 0; a < 4; a++)
        {
          int v = ss_.fv[4 * s + (size_t) a];
          if (v < 0)
            continue;
          const double *p = ss_.p + 2 * v;
          covered &= p[0] >= lo && p[0] <= hi && p[1] >= lo && p[1] <= hi;
        }
      for (size_t q = P->pair_ptr[s]; q < P->pair_ptr[s + 1]; q++)
        {
          sum += P->pair_measure[q];
          check_abs (P->pair_measure[q],
                     exact_overlap (&fs, s, &fm, P->pair_master[q]),
                     1e-13 * P->measure[s], "%s: pair (%zu, %zu) = exact "
                     "overlap", what, s, P->pair_master[q]);
        }
      check_abs (sum, P->covered[s], 1e-14 * area, "%s: pieces of %zu", what, s);
      if (covered)
        {
          ncov++;
          check_rel (P->covered[s], P->measure[s], 1e-12, "%s: facet %zu "
                     "covered", what, s);
        }
      total += P->covered[s];
      for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
        {
          double xs[3], xm[3], ns[3], nm[3];
          gmax = fmax (gmax, fabs (P->gap[p]));
          facet_point (&fs, s, P->xs + 2 * p, xs, ns);
          facet_point (&fm, P->master[p], P->xm + 2 * p, xm, nm);
          for (int j = 0; j < 3; j++)
            xerr = fmax (xerr, fabs (xs[j] - xm[j]));
        }
      /* the exhaustive search finds the same pairs and pieces */
      check_int ((long) (R->pair_ptr[s + 1] - R->pair_ptr[s]),
                 (long) (P->pair_ptr[s + 1] - P->pair_ptr[s]),
                 "%s: pairs of %zu, front vs robust", what, s);
      for (size_t q = P->pair_ptr[s], r = R->pair_ptr[s];
           q < P->pair_ptr[s + 1] && r < R->pair_ptr[s + 1]; q++, r++)
        {
          check_int ((long) R->pair_master[r], (long) P->pair_master[q],
                     "%s: master, front vs robust", what);
          check_abs (R->pair_measure[r], P->pair_measure[q], 1e-15 * area,
                     "%s: measure, front vs robust", what);
        }
    }
  check_true (ncov > 0, "%s: some slave facets are covered", what);
  if (gs == gm)
    check_int ((long) P->npairs, (long) fs.n, "%s: one pair per facet", what);
  check_rel (total, area, 1e-12, "%s: total area", what);
  check_abs (gmax, 0, 1e-14, "%s: gaps", what);
  check_abs (xerr, 0, 1e-13, "%s: X_m(xm) = X_s(xs)", what);
  check_int ((long) P->nfail, 0, "%s: no failed projection", what);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: %zu slave, %zu master facets, %zu pairs, %zu points, %zu "
            "tests, %zu grid queries\n", what, fs.n, fm.n, P->npairs,
            P->npoints, P->ntests, P->nseeds);
done:
  lac_pairing_free (P), lac_pairing_free (R);
  lac_mesh_free (m);
  pm_side_free (&ss), pm_side_free (&ms);
  pm_surf_free (&ss_), pm_surf_free (&ms_);
  pm_builder_free (&B);
}

/* A master in two pieces that share no vertex: many small quads on the
 * left, one big quad on the right (much larger than the mean facet: kept
 * apart by the bucket grid).  Slave facets across the seam overlap both
 * pieces: the front must find the second piece (completion step). */
static void
two_pieces (void)
{
  double zs[2] = { 0, 1 }, zm[2] = { 0, -1 };
  pm_builder B;
  pm_surf a, b, c;
  lac_pairing *P = NULL, *R = NULL;
  lac_pairing_opts o;
  pm_builder_init (&B, 3);
  pm_seed = 3;
  pm_grid (&a, 0, 1, 9, 9, 0, 0.2, 1);
  pm_rect (&b, -0.2, 0.45, -0.2, 1.2, 30, 60, 0, 0.2, 0);
  pm_rect (&c, 0.45, 1.2, -0.2, 1.2, 1, 1, 0, 0, 0);
  pm_side sa = pm_add_side (&B, &a, LAC_TRI3, pm_flat3, zs, 0.02);
  pm_side sb = pm_add_side (&B, &b, LAC_QUAD4, pm_flat3, zm, 0.02);
  pm_side sc = pm_add_side (&B, &c, LAC_QUAD4, pm_flat3, zm, 0.02);
  lac_mesh *m = pm_finish (&B);
  size_t nm = sb.n + sc.n, cell[2000];
  int face[2000];
  for (size_t i = 0; i < nm; i++)
    cell[i] = i < sb.n ? sb.cell[i] : sc.cell[i - sb.n],
      face[i] = i < sb.n ? sb.face[i] : sc.face[i - sb.n];
  lac_pairing_facets fs = pm_facets (m, &sa), fm = { m, nm, cell, face };
  lac_pairing_opts_init (&o);
  o.robust = 1;
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_SUCCESS,
                "two pieces: build");
  check_status (lac_pairing_build (&fs, &fm, &o, &R), LAC_SUCCESS,
                "two pieces: build (robust)");
  if (P && R)
    {
      for (size_t s = 0; s < fs.n; s++)
        check_rel (P->covered[s], P->measure[s], 1e-12, "two pieces: %zu", s);
      check_rel (lac_pairing_total (P), 1, 1e-12, "two pieces: total");
      check_int ((long) P->npairs, (long) R->npairs, "two pieces: pairs");
      if (getenv ("LAC_TEST_VERBOSE"))
        printf ("two pieces: %zu slave, %zu master facets, %zu pairs, %zu "
                "tests, %zu grid queries\n", fs.n, fm.n, P->npairs,
                P->ntests, P->nseeds);
    }
  lac_pairing_free (P), lac_pairing_free (R);
  lac_mesh_free (m);
  pm_side_free (&sa), pm_side_free (&sb), pm_side_free (&sc);
  pm_surf_free (&a), pm_surf_free (&b), pm_surf_free (&c);
  pm_builder_free (&B);
}

int
main (void)
{
  lac_init ();
  /* matching grids: each facet meets its twin only */
  grid_spec t6 = { LAC_TRI3, 0, 1, 6, 0, 0.2, 1 }, q5 = { LAC_QUAD4, 0, 1, 5, 0, 0.2, 2 };
  grid_spec t9 = { LAC_QUAD9, 0, 1, 4, 0, 0.2, 3 };
  run (&t6, &t6, 1, 0, 1, "matching tri3");
  run (&q5, &q5, 1, 0, 1, "matching quad4");
  run (&t9, &t9, 1, 0, 1, "matching quad9");
  /* non-matching: jittered slave, rotated master grid covering it */
  grid_spec st = { LAC_TRI3, 0, 1, 9, 0, 0.2, 7 };
  grid_spec sq = { LAC_QUAD4, 0, 1, 8, 0, 0.2, 7 };
  grid_spec mq = { LAC_QUAD4, -0.5, 1.5, 13, 0.3, 0, 7 };
  grid_spec mt = { LAC_TRI3, -0.5, 1.5, 11, -0.4, 0.2, 7 };
  run (&st, &mq, 1, 0, 1, "tri3 / rotated quad4");
  run (&sq, &mt, 1, 0, 1, "quad4 / rotated tri3");
  run (&st, &mt, 1, 0, 1, "tri3 / rotated tri3");
  run (&sq, &mq, 1, 0, 1, "quad4 / rotated quad4");
  /* quadratic facets (straight-sided) */
  grid_spec s6 = { LAC_TRI6, 0, 1, 7, 0, 0.25, 7 }, s8 = { LAC_QUAD8, 0, 1, 6, 0, 0.25, 7 };
  grid_spec s9 = { LAC_QUAD9, 0, 1, 5, 0, 0.25, 7 };
  grid_spec m6 = { LAC_TRI6, -0.5, 1.5, 9, 0.7, 0.1, 7 };
  grid_spec m8 = { LAC_QUAD8, -0.5, 1.5, 10, -0.2, 0.1, 7 };
  grid_spec m9 = { LAC_QUAD9, -0.5, 1.5, 8, 0.5, 0, 7 };
  run (&s6, &m8, 1, 0, 1, "tri6 / rotated quad8");
  run (&s8, &m9, 1, 0, 1, "quad8 / rotated quad9");
  run (&s9, &m6, 1, 0, 1, "quad9 / rotated tri6");
  run (&s6, &mq, 1, 0, 1, "tri6 / rotated quad4");
  /* partial cover: the master is the square [0.3, 0.8]^2 */
  grid_spec mp = { LAC_QUAD4, 0.3, 0.8, 4, 0, 0.2, 7 }, mp3 = { LAC_TRI3, 0.3, 0.8, 5, 0, 0.2, 7 };
  run (&st, &mp, 0.25, 0.3, 0.8, "tri3 / partial quad4");
  run (&sq, &mp3, 0.25, 0.3, 0.8, "quad4 / partial tri3");
  two_pieces ();
  return check_summary ();
}
