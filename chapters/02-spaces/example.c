/* example.c -- chapter 02: finite element spaces              [LAC §3.1]
 *
 * Build:        make build/chapters/02-spaces
 * Sample run:   build/chapters/02-spaces
 * Description:
 *   A tour of lac_spaces and lac_quadrature: the six quadratic shape
 *   functions of tri6 at one point, their partition of unity, an exact
 *   integral on the unit tetrahedron, the outward faces of hex8, and the
 *   averages of trace basis functions that Hypothesis 1 of [LAC §3.1] is
 *   about.  The output is short and deterministic.
 */
#include <math.h>
#include <stdio.h>

#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"

/* Round to the printed 4 digits, and turn -0 into +0, so that the output
 * does not depend on the last bits of the arithmetic. */
static double
clean (double v)
{
  return round (v * 1e4) / 1e4 + 0.0;
}

// @sect Shape functions at a point
/* 1. The shape functions $N_a(\xi)$ of the P2 triangle at one point.
 *    In barycentric coordinates $\lambda$, the vertex functions are
 *    $\lambda_a(2\lambda_a - 1)$ and the mid-edge ones $4\lambda_i\lambda_j$;
 *    they add up to one (partition of unity). */
static void
tri6_at_a_point (void)
{
  const lac_refelem *re = lac_refelem_by_name ("tri6");
  double xi[2] = { 0.2, 0.3 }, N[LAC_MAX_NODES], dN[LAC_MAX_NODES * 3];
  double sum = 0;
  lac_refelem_eval (re, xi, N, dN);
  printf ("1. %s (gmsh type %d, VTK type %d) at xi = (%.1f, %.1f):\n",
          re->name, re->gmsh_type, re->vtk_type, xi[0], xi[1]);
  for (int a = 0; a < re->nnodes; a++)
    {
      printf ("   N_%d = %+.4f   grad = (%+.4f, %+.4f)\n", a, clean (N[a]),
              clean (dN[2 * a]), clean (dN[2 * a + 1]));
      sum += N[a];
    }
  printf ("   sum N_a = %.12f\n", sum);
}

// @sect Quadrature
/* 2. Quadrature: $\int_K x\,y\,z\,dx = 1!\,1!\,1!/6! = 1/720$ on the unit
 *    tetrahedron, integrated exactly by any rule of degree >= 3 (here the
 *    8-point symmetric rule). */
static void
tet_integral (void)
{
  lac_quad *q = lac_quad_alloc (LAC_SHAPE_TET, 3);
  double s = 0;
  if (q == NULL)
    return;
  for (int p = 0; p < q->n; p++)
    s += q->w[p] * q->xi[3 * p] * q->xi[3 * p + 1] * q->xi[3 * p + 2];
  printf ("2. tet rule of degree %d, %d points: int xyz = %.12e"
          " (1/720 = %.12e)\n", q->degree, q->n, s, 1.0 / 720);
  lac_quad_free (q);
}

// @sect The faces of a cell
/* 3. The faces of hex8, counter-clockwise seen from outside, with the unit
 *    normal $t_1 \times t_2 / |t_1 \times t_2|$ of each face's own map. */
static void
hex8_faces (void)
{
  const lac_refelem *re = lac_refelem_get (LAC_HEX8);
  printf ("3. faces of hex8 (local nodes, outward normal):\n");
  for (int f = 0; f < re->nfaces; f++)
    {
      const lac_refelem *fe = lac_refelem_get (re->face_type[f]);
      double xf[LAC_MAX_FACE_NODES * 3], c[2] = { 0, 0 };
      lac_map m;
      for (int k = 0; k < fe->nnodes; k++)
        for (int i = 0; i < 3; i++)
          xf[3 * k + i] = re->xi[3 * re->face_node[f][k] + i];
      if (lac_map_face (fe, 3, xf, c, &m) != LAC_SUCCESS)
        return;
      printf ("   face %d: %s (%d %d %d %d)  n = (%+.0f, %+.0f, %+.0f)\n",
              f, fe->name, re->face_node[f][0], re->face_node[f][1],
              re->face_node[f][2], re->face_node[f][3],
              clean (m.normal[0]), clean (m.normal[1]), clean (m.normal[2]));
    }
}

// @sect Averages over a face
/* 4. Averages of the basis functions of a face element,
 *    $\overline{N_a} = \frac{1}{|F|}\int_F N_a$: Hypothesis 1 and
 *    Definition 1 of [LAC §3.1] need an "internal" function of positive
 *    average on each macro-element. */
static void
face_means (const char *name)
{
  const lac_refelem *re = lac_refelem_by_name (name);
  lac_quad *q = lac_quad_alloc (re->shape, 2 * re->degree);
  double mean[LAC_MAX_NODES] = { 0 }, N[LAC_MAX_NODES];
  double meas = lac_quad_ref_measure (re->shape);
  if (q == NULL)
    return;
  for (int p = 0; p < q->n; p++)
    {
      lac_refelem_eval (re, q->xi + p * re->dim, N, NULL);
      for (int a = 0; a < re->nnodes; a++)
        mean[a] += q->w[p] * N[a] / meas;
    }
  printf ("   %-5s:", name);
  for (int a = 0; a < re->nnodes; a++)
    printf (" %+.4f", clean (mean[a]));
  printf ("\n");
  lac_quad_free (q);
}

// @sect The program
/* Each part prints its numbers; the output is in the chapter. */
int
main (void)
{
  lac_init ();
  tri6_at_a_point ();
  tet_integral ();
  hex8_faces ();
  printf ("4. averages of the face basis functions over the face:\n");
  face_means ("seg2");
  face_means ("seg3");
  face_means ("tri3");
  face_means ("tri6");
  face_means ("quad8");
  face_means ("quad9");
  lac_finalize ();
  return 0;
}
