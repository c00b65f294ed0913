/* t690: the answers of chapters/04-pairing/exercises.md        [LAC §4.6]
 *
 * Every number quoted in an answer is checked here (integers exactly,
 * reals to 1e-12 unless said otherwise).  The surfaces are box faces
 * (lac_mesh_box, hex8) moved by affine maps, as in the chapter's example:
 *   1. the bottom of a 3 x 3 box on the top of a 2 x 2 box, aligned: 16
 *      pairs (4 slave facets with 1 master, 4 with 2, 1 with 4), areas 4 x
 *      1/9, 8 x 1/18, 4 x 1/36, 180 points at the default degree (4 x 9 +
 *      12 x 2 x 6);
 *   2. the 3 x 3 box turned by theta about the vertical axis through the
 *      centre: total covered 1 - (sin t + cos t - 1)^2 / sin 2t for theta =
 *      5, 10, 20, 30, 45 degrees (2 (sqrt 2 - 1) at 45); the central slave
 *      facet keeps 4 pairs of 1/36 at every angle;
 *   3. a master plane z = 1 + c + a x over the flat slave z = 1 (c =
 *      -0.005, a = 0.02): gap g = c + a x at every point, sum w g = c + a/2
 *      = 0.005, per facet 0 (x < 1/2) and 0.0025 (x > 1/2); the closest
 *      point signed distance (c + a x) / sqrt(1 + a^2) (same sign as g:
 *      the master face map's normal points towards the slave);
 *   4. a rigid motion of both sides changes nothing (counts, masters,
 *      measures, weights, gaps, reference coordinates); a scaling by 2
 *      multiplies areas and weights by 4, gaps by 2, and leaves the
 *      reference coordinates alone;
 *   5. a unit square slave cut into the pentagon x + y <= 3/2 (area 7/8):
 *      3 fan triangles x 6 = 18 points under a parallelogram master, 9
 *      (the 3 x 3 Gauss rule) when the master covers the whole facet, and
 *      3 x 100 = 300 under a trapezoid master (degree_nonaffine = 18);
 *   6. under the trapezoid, sum_a int N_a = 7/8 and int x = 19/48 at every
 *      degree_nonaffine, while the integral of one master basis function
 *      converges geometrically: error > 1e-5 at degree 4, < 1e-12 from
 *      degree 14 on (against degree 31);
 *   7. search: a 30 x 30 slave on a 20 x 20 master, aligned: 1600 pairs
 *      (40^2), the front and the robust mode find the same pairs, with 1
 *      and 900 grid queries; the master in two pieces (x <= 0.4, x >= 0.6):
 *      1280 pairs (32 x 40), total 0.8, 182 grid queries for the front.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fem/lac_mesh.h"
#include "contact/lac_pairing.h"
#include "contact/lac_pairing_project.h"
#include "base/lac_status.h"

#define TOL 1e-12
#define PI 3.14159265358979323846

/* A hex8 box [0, Lx] x [0, 1] x [0, 1] of nx x ny x 1 cells. */
static lac_mesh *
box (size_t nx, size_t ny, double Lx)
{
  size_t n[3] = { nx, ny, 1 };
  double L[3] = { Lx, 1, 1 };
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (LAC_HEX8, n, L, 0.0, &m), LAC_SUCCESS,
                "box %zu x %zu", nx, ny);
  return m;
}

/* x <- A x + b on every node. */
static void
affine (lac_mesh *m, const double *A, const double *b)
{
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double *x = m->x + 3 * a, y[3];
      for (int i = 0; i < 3; i++)
        {
          y[i] = b[i];
          for (int j = 0; j < 3; j++)
            y[i] += A[3 * i + j] * x[j];
        }
      memcpy (x, y, sizeof y);
    }
}

/* Turn by th about the vertical line through (1/2, 1/2), then lift. */
static void
turn (lac_mesh *m, double th, double lift)
{
  double c = cos (th), s = sin (th);
  double A[9] = { c, -s, 0, s, c, 0, 0, 0, 1 };
  double b[3] = { 0.5 - 0.5 * c + 0.5 * s, 0.5 - 0.5 * s - 0.5 * c, lift };
  affine (m, A, b);
}

static lac_pairing_facets
facets (const lac_mesh *m, const char *name)
{
  const lac_group *g = lac_mesh_group (m, name);
  check_true (g != NULL, "group %s", name);
  return lac_pairing_facets_of (m, g);
}

static lac_pairing *
pair (const lac_pairing_facets *fs, const lac_pairing_facets *fm,
      const lac_pairing_opts *o, const char *what)
{
  lac_pairing *P = NULL;
  check_status (lac_pairing_build (fs, fm, o, &P), LAC_SUCCESS, "%s", what);
  return P;
}

/* Physical point of facet i at reference point xi. */
static void
facet_point (const lac_pairing_facets *f, size_t i, const double *xi,
             double *x)
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
  memcpy (x, m.x, 3 * sizeof *x);
}

/* Exercise 1: 3 x 3 slave on 2 x 2 master, aligned. */
static void
exercise1 (void)
{
  lac_mesh *lo = box (2, 2, 1), *up = box (3, 3, 1);
  turn (up, 0, 1.01);
  lac_pairing_facets fs = facets (up, "zmin"), fm = facets (lo, "zmax");
  lac_pairing *P = pair (&fs, &fm, NULL, "ex1");
  if (P)
    {
      long cnt[5] = { 0 }, area[3] = { 0 };
      check_int ((long) P->npairs, 16, "ex1: pairs");
      check_int ((long) P->npoints, 180, "ex1: points");
      for (size_t s = 0; s < P->nslave; s++)
        {
          size_t k = P->pair_ptr[s + 1] - P->pair_ptr[s];
          cnt[k < 5 ? k : 0]++;
          check_abs (P->covered[s], 1.0 / 9, TOL, "ex1: covered[%zu]", s);
        }
      check_int (cnt[1], 4, "ex1: slave facets with 1 master");
      check_int (cnt[2], 4, "ex1: slave facets with 2 masters");
      check_int (cnt[4], 1, "ex1: slave facets with 4 masters");
      for (size_t q = 0; q < P->npairs; q++)
        {
          double a = P->pair_measure[q];
          area[0] += fabs (a - 1.0 / 9) <= TOL;
          area[1] += fabs (a - 1.0 / 18) <= TOL;
          area[2] += fabs (a - 1.0 / 36) <= TOL;
        }
      check_int (area[0], 4, "ex1: pairs of area 1/9");
      check_int (area[1], 8, "ex1: pairs of area 1/18");
      check_int (area[2], 4, "ex1: pairs of area 1/36");
    }
  lac_pairing_free (P);
  lac_mesh_free (lo), lac_mesh_free (up);
}

/* Exercise 2: the slave turned by theta. */
static void
exercise2 (void)
{
  const double deg[5] = { 5, 10, 20, 30, 45 };
  for (int k = 0; k < 5; k++)
    {
      double t = deg[k] * PI / 180;
      lac_mesh *lo = box (2, 2, 1), *up = box (3, 3, 1);
      turn (up, t, 1.01);
      lac_pairing_facets fs = facets (up, "zmin"), fm = facets (lo, "zmax");
      lac_pairing *P = pair (&fs, &fm, NULL, "ex2");
      if (P)
        {
          double e = sin (t) + cos (t) - 1;
          check_abs (lac_pairing_total (P), 1 - e * e / sin (2 * t), TOL,
                     "ex2: total covered at %g deg", deg[k]);
          size_t c = P->nslave;
          for (size_t s = 0; s < P->nslave; s++)
            {
              double xi[2] = { 0, 0 }, x[3];
              facet_point (&fs, s, xi, x);
              if (fabs (x[0] - 0.5) + fabs (x[1] - 0.5) < 1e-9)
                c = s;
            }
          check_true (c < P->nslave, "ex2: central facet at %g deg", deg[k]);
          if (c < P->nslave)
            {
              check_int ((long) (P->pair_ptr[c + 1] - P->pair_ptr[c]), 4,
                         "ex2: pairs of the central facet at %g deg",
                         deg[k]);
              for (size_t q = P->pair_ptr[c]; q < P->pair_ptr[c + 1]; q++)
                check_abs (P->pair_measure[q], 1.0 / 36, TOL,
                           "ex2: quarter %zu at %g deg", q, deg[k]);
            }
        }
      if (k == 4)
        check_abs (lac_pairing_total (P), 2 * (sqrt (2) - 1), TOL,
                   "ex2: octagon at 45 deg");
      lac_pairing_free (P);
      lac_mesh_free (lo), lac_mesh_free (up);
    }
}

/* Exercise 3: the gap to a tilted master plane. */
static void
exercise3 (void)
{
  const double c = -0.005, a = 0.02;
  lac_mesh *lo = box (2, 2, 1), *up = box (3, 3, 1);
  double A[9] = { 1, 0, 0, 0, 1, 0, a, 0, 1 }, b[3] = { 0, 0, 1 + c };
  affine (up, A, b);                   /* z <- z + 1 + c + a x */
  lac_pairing_facets fs = facets (lo, "zmax"), fm = facets (up, "zmin");
  lac_pairing *P = pair (&fs, &fm, NULL, "ex3");
  if (P)
    {
      double worst = 0, sum = 0, x[3];
      long npen = 0, nwrong = 0;
      check_abs (lac_pairing_total (P), 1, TOL, "ex3: fully covered");
      for (size_t s = 0; s < P->nslave; s++)
        {
          double fs_int = 0, xc[3], xi0[2] = { 0, 0 };
          for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
            {
              facet_point (&fs, s, P->xs + 2 * p, x);
              worst = fmax (worst, fabs (P->gap[p] - (c + a * x[0])));
              fs_int += P->w[p] * P->gap[p];
              npen += P->gap[p] < 0;
              nwrong += (P->gap[p] < 0) != (x[0] < 0.25);
            }
          facet_point (&fs, s, xi0, xc);
          check_abs (fs_int, xc[0] < 0.5 ? 0 : 0.0025, TOL,
                     "ex3: int g over slave facet %zu", s);
          sum += fs_int;
        }
      check_abs (worst, 0, TOL, "ex3: g = c + a x at every point");
      check_abs (sum, c + a / 2, TOL, "ex3: sum w g");
      check_true (npen > 0, "ex3: some points penetrate");
      check_int (nwrong, 0, "ex3: g < 0 exactly where x < 1/4");
      /* closest point: the first point, onto its own master facet */
      size_t m = P->master[0];
      int nodes[LAC_MAX_FACE_NODES];
      lac_elem_type t;
      double xe[LAC_MAX_FACE_NODES * 3], xi[2] = { 0, 0 }, d;
      int k = lac_mesh_facet_nodes (up, fm.cell[m], fm.face[m], nodes, &t);
      for (int i = 0; i < k; i++)
        for (int j = 0; j < 3; j++)
          xe[3 * i + j] = up->x[3 * (size_t) nodes[i] + (size_t) j];
      facet_point (&fs, 0, P->xs, x);
      check_status (lac_pairing_project (lac_refelem_get (t), 3, xe, x, NULL,
                                         xi, &d), LAC_SUCCESS,
                    "ex3: closest point");
      check_abs (d, (c + a * x[0]) / sqrt (1 + a * a), TOL,
                 "ex3: closest-point signed distance");
    }
  lac_pairing_free (P);
  lac_mesh_free (lo), lac_mesh_free (up);
}

/* Exercise 4: rigid motion and scaling of the turned example. */
static void
exercise4 (void)
{
  lac_mesh *lo = box (2, 2, 1), *up = box (3, 3, 1);
  turn (up, 10 * PI / 180, 1.01);
  lac_pairing_facets fs = facets (up, "zmin"), fm = facets (lo, "zmax");
  lac_pairing *P = pair (&fs, &fm, NULL, "ex4"), *Q[2] = { NULL, NULL };
  /* Rodrigues rotation by 0.7 rad about (2, -1, 3)/sqrt(14), then a
   * translation; then a scaling by 2 about the origin. */
  double u[3] = { 2 / sqrt (14), -1 / sqrt (14), 3 / sqrt (14) };
  double cs = cos (0.7), sn = sin (0.7), R[9];
  double K[9] = { 0, -u[2], u[1], u[2], 0, -u[0], -u[1], u[0], 0 };
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      R[3 * i + j] = (i == j) * cs + sn * K[3 * i + j]
        + (1 - cs) * u[i] * u[j];
  double t[3] = { 3, -2, 1.5 }, S[9] = { 2, 0, 0, 0, 2, 0, 0, 0, 2 };
  double z[3] = { 0, 0, 0 };
  for (int k = 0; k < 2; k++)
    {
      const double *A = k ? S : R, *b = k ? z : t;
      double fw = k ? 4 : 1, fg = k ? 2 : 1;
      const char *what = k ? "scaled" : "moved";
      affine (lo, A, b), affine (up, A, b);
      Q[k] = pair (&fs, &fm, NULL, "ex4");
      if (!P || !Q[k])
        continue;
      check_int ((long) Q[k]->npairs, (long) P->npairs, "ex4 %s: pairs",
                 what);
      check_int ((long) Q[k]->npoints, (long) P->npoints, "ex4 %s: points",
                 what);
      if (Q[k]->npairs != P->npairs || Q[k]->npoints != P->npoints)
        continue;
      double e[5] = { 0, 0, 0, 0, 0 };
      long nm = 0;
      for (size_t q = 0; q < P->npairs; q++)
        {
          nm += Q[k]->pair_master[q] != P->pair_master[q];
          e[0] = fmax (e[0], fabs (Q[k]->pair_measure[q]
                                   - fw * P->pair_measure[q]));
        }
      for (size_t s = 0; s < P->nslave; s++)
        e[0] = fmax (e[0], fabs (Q[k]->covered[s] - fw * P->covered[s]));
      for (size_t p = 0; p < P->npoints; p++)
        {
          e[1] = fmax (e[1], fabs (Q[k]->w[p] - fw * P->w[p]));
          e[2] = fmax (e[2], fabs (Q[k]->gap[p] - fg * P->gap[p]));
          for (int j = 0; j < 2; j++)
            {
              e[3] = fmax (e[3], fabs (Q[k]->xs[2 * p + j] - P->xs[2 * p + j]));
              e[4] = fmax (e[4], fabs (Q[k]->xm[2 * p + j] - P->xm[2 * p + j]));
            }
        }
      check_int (nm, 0, "ex4 %s: same masters", what);
      check_abs (e[0], 0, TOL, "ex4 %s: pair measures and covered", what);
      check_abs (e[1], 0, TOL, "ex4 %s: weights", what);
      check_abs (e[2], 0, TOL, "ex4 %s: gaps", what);
      check_abs (e[3], 0, TOL, "ex4 %s: slave reference coordinates", what);
      check_abs (e[4], 0, TOL, "ex4 %s: master reference coordinates", what);
    }
  lac_pairing_free (P), lac_pairing_free (Q[0]), lac_pairing_free (Q[1]);
  lac_mesh_free (lo), lac_mesh_free (up);
}

/* A one-cell hex8 prism over the quadrangle q (4 points, counter-clockwise
 * from above), 0 <= z <= 1: its bottom (`zmin`) is the master facet. */
static lac_mesh *
prism (const double *q)
{
  lac_mesh *m = box (1, 1, 1);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double *x = m->x + 3 * a, u = x[0], v = x[1];
      double N[4] = { (1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v };
      x[0] = x[1] = 0;
      for (int k = 0; k < 4; k++)
        x[0] += N[k] * q[2 * k], x[1] += N[k] * q[2 * k + 1];
    }
  return m;
}

/* The unit square slave, top of [0,1]^2 x [-1, 0]. */
static lac_mesh *
unit_slave (void)
{
  lac_mesh *m = box (1, 1, 1);
  double I[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, b[3] = { 0, 0, -1 };
  affine (m, I, b);
  return m;
}

static const double diamond[8] = { 0, -1.5, 1.5, 0, 0, 1.5, -1.5, 0 };
static const double bigdiamond[8] = { 0, -3, 3, 0, 0, 3, -3, 0 };
static const double trapezoid[8] = { -0.5, -0.5, 1.6, -0.5, 1.6, -0.1,
                                     -0.5, 2.0 };

/* Exercise 5: points of a pentagonal overlap. */
static void
exercise5 (void)
{
  const double *q[3] = { diamond, bigdiamond, trapezoid };
  const long npts[3] = { 18, 9, 300 };
  const double area[3] = { 7.0 / 8, 1, 7.0 / 8 };
  lac_mesh *s = unit_slave ();
  lac_pairing_facets fs = facets (s, "zmax");
  for (int k = 0; k < 3; k++)
    {
      lac_mesh *m = prism (q[k]);
      lac_pairing_facets fm = facets (m, "zmin");
      lac_pairing *P = pair (&fs, &fm, NULL, "ex5");
      if (P)
        {
          check_int ((long) P->npairs, 1, "ex5 case %d: pairs", k);
          check_int ((long) P->npoints, npts[k], "ex5 case %d: points", k);
          check_abs (P->pair_measure[0], area[k], TOL, "ex5 case %d: area",
                     k);
        }
      lac_pairing_free (P);
      lac_mesh_free (m);
    }
  lac_mesh_free (s);
}

/* Exercise 6: degree_nonaffine under the trapezoid. */
static void
exercise6 (void)
{
  const int deg[9] = { 31, 4, 6, 8, 10, 12, 14, 16, 18 };
  double ref[4] = { 0, 0, 0, 0 }, err[9];
  size_t npoints[9] = { 0 };
  lac_mesh *s = unit_slave (), *m = prism (trapezoid);
  lac_pairing_facets fs = facets (s, "zmax"), fm = facets (m, "zmin");
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type t;
  lac_mesh_facet_nodes (m, fm.cell[0], fm.face[0], nodes, &t);
  const lac_refelem *re = lac_refelem_get (t);
  for (int k = 0; k < 9; k++)
    {
      lac_pairing_opts o;
      lac_pairing_opts_init (&o);
      o.degree_nonaffine = deg[k];
      lac_pairing *P = pair (&fs, &fm, &o, "ex6");
      if (!P)
        continue;
      double I[4] = { 0, 0, 0, 0 }, sum = 0, xm = 0;
      npoints[k] = P->npoints;
      for (size_t p = 0; p < P->npoints; p++)
        {
          double N[LAC_MAX_FACE_NODES], dN[2 * LAC_MAX_FACE_NODES];
          lac_refelem_eval (re, P->xm + 2 * p, N, dN);
          for (int a = 0; a < 4; a++)
            {
              I[a] += P->w[p] * N[a];
              sum += P->w[p] * N[a];
              xm += P->w[p] * N[a] * m->x[3 * (size_t) nodes[a]];
            }
        }
      check_abs (sum, 7.0 / 8, TOL, "ex6: sum_a int N_a at degree %d",
                 deg[k]);
      check_abs (xm, 19.0 / 48, TOL, "ex6: int x at degree %d", deg[k]);
      err[k] = 0;
      for (int a = 0; a < 4; a++)
        {
          if (k == 0)
            ref[a] = I[a];
          err[k] = fmax (err[k], fabs (I[a] - ref[a]));
        }
      lac_pairing_free (P);
    }
  check_true (err[1] > 1e-5, "ex6: error at degree 4 = %.3g > 1e-5",
              err[1]);
  for (int k = 2; k <= 5; k++)
    check_true (err[k] < err[k - 1] / 10, "ex6: error at degree %d = %.3g "
                "< error at degree %d / 10", deg[k], err[k], deg[k - 1]);
  for (int k = 6; k < 9; k++)
    check_true (err[k] < 1e-12, "ex6: error at degree %d = %.3g < 1e-12",
                deg[k], err[k]);
  /* LAC_DOC_TABLE=ex6: the answer's table, a column per degree */
  if (check_doc_table ("ex6"))
    {
      printf ("| `degree_nonaffine` |");
      for (int k = 1; k < 9; k++)
        printf (" %d |", deg[k]);
      printf ("\n|---|");
      for (int k = 1; k < 9; k++)
        printf ("---|");
      printf ("\n| points |");
      for (int k = 1; k < 9; k++)
        printf (" %zu |", npoints[k]);
      printf ("\n| max error |");
      for (int k = 1; k < 9; k++)
        printf (" %.1e |", err[k]);
      printf ("\n");
    }
  lac_mesh_free (s), lac_mesh_free (m);
}

/* Exercise 7: the search, front against robust, master in two pieces. */
static void
exercise7 (void)
{
  lac_mesh *lo = box (20, 20, 1), *up = box (30, 30, 1);
  turn (up, 0, 1.0);
  lac_pairing_facets fs = facets (up, "zmin"), fm = facets (lo, "zmax");
  lac_pairing_opts o;
  lac_pairing *P[2];
  lac_pairing_opts_init (&o);

  /* the whole master */
  for (int r = 0; r < 2; r++)
    {
      o.robust = r;
      P[r] = pair (&fs, &fm, &o, "ex7");
    }
  if (P[0] && P[1])
    {
      check_int ((long) P[0]->npairs, 1600, "ex7: pairs");
      check_int ((long) P[1]->npairs, 1600, "ex7: pairs, robust");
      check_int ((long) P[0]->nseeds, 1, "ex7: grid queries of the front");
      check_int ((long) P[1]->nseeds, 900, "ex7: grid queries, robust");
      check_true (P[0]->ntests < 20 * P[0]->nslave, "ex7: tests per facet "
                  "%.2f", (double) P[0]->ntests / (double) P[0]->nslave);
      check_abs (lac_pairing_total (P[0]), 1, TOL, "ex7: total");
    }
  lac_pairing_free (P[0]), lac_pairing_free (P[1]);

  /* the master in two pieces: [0, 0.4] and [0.6, 1] */
  lac_mesh *a = box (8, 20, 0.4), *b = box (8, 20, 0.4), *ab = NULL;
  double I[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, sh[3] = { 0.6, 0, 0 };
  affine (b, I, sh);
  check_status (lac_mesh_merge (a, "a_", b, "b_", &ab), LAC_SUCCESS,
                "ex7: merge");
  const lac_group *ga = lac_mesh_group (ab, "a_zmax");
  const lac_group *gb = lac_mesh_group (ab, "b_zmax");
  size_t n = ga->n + gb->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      cell[e] = e < ga->n ? ga->cell[e] : gb->cell[e - ga->n];
      face[e] = e < ga->n ? ga->face[e] : gb->face[e - ga->n];
    }
  lac_pairing_facets f2 = { ab, n, cell, face };
  for (int r = 0; r < 2; r++)
    {
      o.robust = r;
      P[r] = pair (&fs, &f2, &o, "ex7 two pieces");
    }
  if (P[0] && P[1])
    {
      check_int ((long) P[0]->npairs, 1280, "ex7 two pieces: pairs");
      check_int ((long) P[0]->nseeds, 182, "ex7 two pieces: grid queries");
      check_int ((long) P[1]->nseeds, 900, "ex7 two pieces: robust queries");
      check_abs (lac_pairing_total (P[0]), 0.8, TOL, "ex7 two pieces: total");
      check_int ((long) P[1]->npairs, (long) P[0]->npairs,
                 "ex7 two pieces: robust pairs");
      long diff = 0;
      for (size_t q = 0; P[1]->npairs == P[0]->npairs && q < P[0]->npairs;
           q++)
        diff += P[0]->pair_master[q] != P[1]->pair_master[q]
          || fabs (P[0]->pair_measure[q] - P[1]->pair_measure[q]) > TOL;
      check_int (diff, 0, "ex7 two pieces: front = robust");
    }
  lac_pairing_free (P[0]), lac_pairing_free (P[1]);
  free (cell), free (face);
  lac_mesh_free (a), lac_mesh_free (b), lac_mesh_free (ab);
  lac_mesh_free (lo), lac_mesh_free (up);
}

int
main (void)
{
  lac_init ();
  exercise1 ();
  exercise2 ();
  exercise3 ();
  exercise4 ();
  exercise5 ();
  exercise6 ();
  exercise7 ();
  lac_finalize ();
  return check_summary ();
}
