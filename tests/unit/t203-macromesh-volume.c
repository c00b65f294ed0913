/* t203: refinement leaves the volume unchanged              [LAC §4.4]
 *
 * lac_mesh_measure before and after lac_macromesh_build, on distorted box
 * meshes (interior vertices moved, boundary faces planar, high-order nodes
 * at midpoints: straight-sided cells), slave = zmax and zmax + xmax.
 *
 * Why exact: the sub-cells share their inner faces exactly, and the outer
 * boundary of their union is the parent's (the untouched faces are the
 * same faces; the slave face's pieces tile it), so by the divergence
 * theorem the volume is the parent's, although the sub-cell maps need not
 * be the parent's map restricted.  The pieces tile the slave face exactly
 * when the face is planar (boxes, even distorted), when it is a bilinear
 * quadrangle (hex8, even twisted: the fan of 4 triangles around the centre
 * and the 5 bilinear pieces enclose the same volume) and for simplices
 * (the sub-maps are affine in the parent's reference coordinates, so a
 * curved tet10 is cut exactly).  Only a curved quad8 face (hex20 with
 * moved mid-nodes) is merely interpolated by its pieces: the "warped"
 * hex20 case checks that the change is small, not zero.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "base/lac_status.h"

static void
union_group (lac_mesh *m, const char *a, const char *b)
{
  const lac_group *A = lac_mesh_group (m, a), *B = lac_mesh_group (m, b);
  size_t n = A->n + B->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      cell[e] = e < A->n ? A->cell[e] : B->cell[e - A->n];
      face[e] = e < A->n ? A->face[e] : B->face[e - A->n];
    }
  lac_mesh_add_group (m, "u", A->dim, 0, n, cell, face);
  free (cell);
  free (face);
}

/* mode 1: x -> S x, a shear (parallelepipeds, affine cells);
 * mode 2: a smooth warp of every node, which twists bilinear faces and
 * bends quadratic ones (also the slave face). */
static void
transform (lac_mesh *m, int mode)
{
  for (size_t i = 0; i < m->nnodes && mode; i++)
    {
      double *x = m->x + i * (size_t) m->dim;
      int d = m->dim - 1;
      if (mode == 1)
        {
          x[0] += 0.3 * x[1] + (m->dim == 3 ? 0.2 * x[2] : 0);
          if (m->dim == 3)
            x[1] += -0.25 * x[2];
        }
      else
        x[d] += x[d] * (0.2 * x[0] * x[d - 1] + 0.1 * x[0] * x[0]);
    }
}

static double
run (lac_elem_type t, double distort, int mode, int two,
     const lac_macro_opts *opts, double tol, const char *label)
{
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 3, 3, 3 };
  double L[3] = { 1, 1.5, 2 }, v0, v1;
  const char *slave = re->dim == 3 ? "zmax" : "ymax";
  lac_mesh *m = NULL;
  lac_macro *M = NULL;
  char what[96];

  static const char *mname[3] = { "", " sheared", " warped" };
  snprintf (what, sizeof what, "%s %s distort %g%s%s", re->name, label,
            distort, mname[mode], two ? " 2 faces" : "");
  check_status (lac_mesh_box (t, n, L, distort, &m), LAC_SUCCESS, "%s: box",
                what);
  if (!m)
    return NAN;
  transform (m, mode);
  if (two)
    {
      union_group (m, slave, "xmax");
      slave = "u";
    }
  v0 = lac_mesh_measure (m);
  check_status (lac_macromesh_build (&m, slave, opts, &M), LAC_SUCCESS,
                "%s: build", what);
  v1 = lac_mesh_measure (m);
  check_rel (v1, v0, tol, "%s: volume", what);
  lac_macromesh_free (M);
  lac_mesh_free (m);
  return fabs (v1 - v0) / v0;
}

int
main (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 }, cut2d = { 0, 1 };
  lac_init ();
  for (int two = 0; two < 2; two++)
    for (int mode = 0; mode < 3; mode++)
      {
        double d = mode == 0 ? 0.25 : 0;
        run (LAC_TET4, d, mode, two, NULL, 1e-13, "");
        run (LAC_TET10, d, mode, two, NULL, 1e-13, "");
        run (LAC_HEX8, d, mode, two, NULL, 1e-13, "pyramids");
        run (LAC_HEX8, d, mode, two, &six, 1e-13, "six");
        run (LAC_HEX27, d, mode, two, NULL, 1e-13, "");
        run (LAC_TRI3, d, mode, two, &cut2d, 1e-13, "cut");
        run (LAC_QUAD4, d, mode, two, &cut2d, 1e-13, "cut");
        if (mode < 2)
          run (LAC_HEX20, d, mode, two, NULL, 1e-13, "six");
        else
          {
            double e = run (LAC_HEX20, d, mode, two, NULL, 1e-3, "six");
            check_true (e > 1e-10, "hex20 warped: a curved slave face is "
                        "interpolated, not kept (rel. change %g)", e);
          }
      }
  lac_finalize ();
  return check_summary ();
}
