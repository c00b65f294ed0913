/* t190-spaces-exercises.c -- the answers of chapters/02-spaces/exercises.md.
 *
 * Exercise 1: a hex27 stiffness on an affine cell is integrated exactly by
 *   3x3x3 = 27 Gauss points (lac_quad_alloc (HEX, 5)), equal to the 216-point
 *   rule to 1e-13; 2x2x2 points are not enough (error > 1e-3).
 * Exercise 2: averages over the edge of the seg3 basis: 1/6, 1/6, 2/3.
 * Exercise 3: the admissibility bounds after Definition 1 of [LAC §3.1]:
 *   mean of the hat function of the internal vertex over its patch = 1/2
 *   (two seg2), 1/3 (six tri3 around a vertex), 1/4 (four quad4).
 * Exercise 4: integrals of face basis functions: tri6 vertices 0, tri6
 *   mid-edges |T|/3, quad8 corners -|Q|/12, mid-edges |Q|/3, quad9
 *   centre (2/3)^2 |Q| = 16/9.
 * Exercise 5: the rule sizes quoted in the chapter: triangle degree 6 ->
 *   12 points, degree 9 (collapsed) -> 25, tetrahedron degree 3 -> 8,
 *   degree 6 (collapsed) -> 64, pyramid degree 2 -> 8.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"

/* Laplace stiffness K_ab = int grad N_a . grad N_b of a hex27 cell. */
static void
hex27_stiffness (const double *xe, int degree, double *K, int *npts)
{
  const lac_refelem *re = lac_refelem_get (LAC_HEX27);
  lac_quad *q = lac_quad_alloc (LAC_SHAPE_HEX, degree);
  lac_map m;
  memset (K, 0, 27 * 27 * sizeof (double));
  *npts = q->n;
  for (int p = 0; p < q->n; p++)
    {
      lac_map_cell (re, 3, xe, q->xi + 3 * p, &m);
      for (int a = 0; a < 27; a++)
        for (int b = 0; b < 27; b++)
          for (int k = 0; k < 3; k++)
            K[27 * a + b] += q->w[p] * m.detJ * m.dNdx[3 * a + k]
              * m.dNdx[3 * b + k];
    }
  lac_quad_free (q);
}

static void
exercise1 (void)
{
  static const double A[9] = { 2, 0.5, 0, 0.3, 1, 0.2, 0, -0.4, 1.5 };
  const lac_refelem *re = lac_refelem_get (LAC_HEX27);
  double xe[27 * 3], K27[27 * 27], K216[27 * 27], K8[27 * 27];
  double e27 = 0, e8 = 0;
  int n27, n216, n8;
  for (int a = 0; a < 27; a++)            /* affine cell x = A xi */
    for (int i = 0; i < 3; i++)
      {
        xe[3 * a + i] = 0;
        for (int k = 0; k < 3; k++)
          xe[3 * a + i] += A[3 * i + k] * re->xi[3 * a + k];
      }
  hex27_stiffness (xe, 5, K27, &n27);
  hex27_stiffness (xe, 11, K216, &n216);
  hex27_stiffness (xe, 3, K8, &n8);
  for (int i = 0; i < 27 * 27; i++)
    {
      e27 = fmax (e27, fabs (K27[i] - K216[i]));
      e8 = fmax (e8, fabs (K8[i] - K216[i]));
    }
  check_int (n27, 27, "ex1: 3x3x3 points");
  check_int (n216, 216, "ex1: 6x6x6 points");
  check_abs (e27, 0, 1e-13, "ex1: 27 points are exact");
  check_true (e8 > 1e-3, "ex1: 8 points are not (%g)", e8);
}

/* (1/|K|) int_K N_a on the reference element. */
static void
means (const lac_refelem *re, double *mean)
{
  lac_quad *q = lac_quad_alloc (re->shape, 2 * re->degree);
  double N[LAC_MAX_NODES], meas = lac_quad_ref_measure (re->shape);
  for (int a = 0; a < re->nnodes; a++)
    mean[a] = 0;
  for (int p = 0; p < q->n; p++)
    {
      lac_refelem_eval (re, q->xi + p * re->dim, N, NULL);
      for (int a = 0; a < re->nnodes; a++)
        mean[a] += q->w[p] * N[a] / meas;
    }
  lac_quad_free (q);
}

static void
exercise2 (void)
{
  double m[3];
  means (lac_refelem_get (LAC_SEG3), m);
  check_rel (m[0], 1.0 / 6, 1e-14, "ex2: seg3 vertex 0");
  check_rel (m[1], 1.0 / 6, 1e-14, "ex2: seg3 vertex 1");
  check_rel (m[2], 2.0 / 3, 1e-14, "ex2: seg3 mid-node");
}

/* Mean over a patch of cells (all of type re, mapped by lac_map_cell) of
 * the hat function of the patch's centre node, local node `a` of each. */
static double
patch_mean (const lac_refelem *re, int ncells, const double *xe, const int *a)
{
  lac_quad *q = lac_quad_alloc (re->shape, 4);
  double area = 0, integral = 0;
  lac_map m;
  int d = re->dim;
  for (int c = 0; c < ncells; c++)
    for (int p = 0; p < q->n; p++)
      {
        lac_map_cell (re, d, xe + c * re->nnodes * d, q->xi + p * d, &m);
        area += q->w[p] * m.detJ;
        integral += q->w[p] * m.detJ * m.N[a[c]];
      }
  lac_quad_free (q);
  return integral / area;
}

static void
exercise3 (void)
{
  /* d = 2: two segments [-1,0], [0,1]; the hat of x = 0. */
  double seg[4] = { -1, 0, 0, 1 };
  int aseg[2] = { 1, 0 };
  check_rel (patch_mean (lac_refelem_get (LAC_SEG2), 2, seg, aseg), 0.5,
             1e-14, "ex3: d=2 linear, mean 1/2");
  /* d = 3, triangles: six around the origin; the hat of the origin. */
  double tri[6 * 6];
  int atri[6];
  for (int c = 0; c < 6; c++)
    {
      double t0 = acos (-1.0) / 3 * c, t1 = acos (-1.0) / 3 * (c + 1);
      double v[6] = { 0, 0, cos (t0), sin (t0), cos (t1), sin (t1) };
      memcpy (tri + 6 * c, v, sizeof v);
      atri[c] = 0;
    }
  check_rel (patch_mean (lac_refelem_get (LAC_TRI3), 6, tri, atri),
             1.0 / 3, 1e-14, "ex3: d=3 tri3, mean 1/3");
  /* d = 3, quadrangles: four unit squares around the origin. */
  double quad[4 * 8];
  int aquad[4];
  for (int c = 0; c < 4; c++)
    {
      double sx = (c == 0 || c == 3) ? 1 : -1, sy = (c < 2) ? 1 : -1;
      double v[8] = { 0, 0, sx, 0, sx, sy, 0, sy };
      if (sx * sy < 0)                   /* keep counter-clockwise */
        v[2] = 0, v[3] = sy, v[6] = sx, v[7] = 0;
      memcpy (quad + 8 * c, v, sizeof v);
      aquad[c] = 0;
    }
  check_rel (patch_mean (lac_refelem_get (LAC_QUAD4), 4, quad, aquad),
             0.25, 1e-14, "ex3: d=3 quad4, mean 1/4");
}

static void
exercise4 (void)
{
  double m[LAC_MAX_NODES];
  means (lac_refelem_get (LAC_TRI6), m);
  for (int a = 0; a < 3; a++)
    check_abs (m[a], 0, 1e-15, "ex4: tri6 vertex %d integrates to 0", a);
  for (int a = 3; a < 6; a++)
    check_rel (m[a], 1.0 / 3, 1e-14, "ex4: tri6 mid-edge %d mean 1/3", a);
  means (lac_refelem_get (LAC_QUAD8), m);
  for (int a = 0; a < 4; a++)
    check_rel (m[a], -1.0 / 12, 1e-14, "ex4: quad8 corner %d mean -1/12", a);
  for (int a = 4; a < 8; a++)
    check_rel (m[a], 1.0 / 3, 1e-14, "ex4: quad8 mid-edge %d mean 1/3", a);
  means (lac_refelem_get (LAC_QUAD9), m);
  check_rel (4 * m[8], 16.0 / 9, 1e-14, "ex4: quad9 centre integral 16/9");
}

static void
exercise5 (void)
{
  static const struct { lac_shape s; int degree, n; } c[] = {
    { LAC_SHAPE_TRI, 6, 12 }, { LAC_SHAPE_TRI, 9, 25 },
    { LAC_SHAPE_TET, 3, 8 }, { LAC_SHAPE_TET, 6, 64 },
    { LAC_SHAPE_PYR, 2, 8 },
  };
  for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
    {
      lac_quad *q = lac_quad_alloc (c[i].s, c[i].degree);
      check_int (q->n, c[i].n, "ex5: rule %zu size", i);
      lac_quad_free (q);
    }
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
  lac_finalize ();
  return check_summary ();
}
