/* t101-spaces-shape.c -- shape functions of every reference element.
 *
 * For each of the 13 element types: the table is consistent (queries by
 * type, name and gmsh code agree), N_a(x_b) = delta_ab at the nodes (1e-13),
 * sum_a N_a = 1 and sum_a N_a x_a = x at random points (1e-13), the
 * analytic gradients equal central finite differences (1e-7), the gradients
 * sum to 0, vtk_perm is a permutation, and quadratic elements reproduce the
 * quadratics of their space (P2: all of degree <= 2; quad8/hex20: the
 * serendipity monomials; quad9/hex27: Q2).
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "fem/lac_spaces.h"

/* A pseudo-random point inside the reference element (deterministic). */
static double
urand (void)
{
  return rand () / (RAND_MAX + 1.0);
}

static void
random_point (const lac_refelem *re, double *xi)
{
  for (;;)
    {
      for (int k = 0; k < re->dim; k++)
        xi[k] = (re->shape == LAC_SHAPE_TRI || re->shape == LAC_SHAPE_TET)
          ? urand () : 2 * urand () - 1;
      if (re->shape == LAC_SHAPE_PYR)
        {
          xi[2] = 0.95 * urand ();
          xi[0] *= 1 - xi[2], xi[1] *= 1 - xi[2];
        }
      if (lac_refelem_contains (re, xi, -1e-3))
        return;
    }
}

static void
check_table (const lac_refelem *re, lac_elem_type t)
{
  check_true (re->type == t, "%s: type", re->name);
  check_true (lac_refelem_by_name (re->name) == re, "%s: by_name", re->name);
  check_true (lac_refelem_by_gmsh (re->gmsh_type) == re, "%s: by_gmsh",
              re->name);
  int seen[LAC_MAX_NODES] = { 0 }, ok = 1;
  for (int k = 0; k < re->nnodes; k++)
    {
      int p = re->vtk_perm[k];
      if (p < 0 || p >= re->nnodes || seen[p]++)
        ok = 0;
    }
  check_true (ok, "%s: vtk_perm is a permutation", re->name);
  for (int a = 0; a < re->nnodes; a++)     /* nodes inside the element */
    check_true (lac_refelem_contains (re, re->xi + a * re->dim, 1e-14),
                "%s: node %d inside", re->name, a);
}

static void
check_kronecker (const lac_refelem *re)
{
  double N[LAC_MAX_NODES];
  for (int b = 0; b < re->nnodes; b++)
    {
      lac_refelem_eval (re, re->xi + b * re->dim, N, NULL);
      for (int a = 0; a < re->nnodes; a++)
        check_abs (N[a], a == b, 1e-13, "%s: N_%d(x_%d)", re->name, a, b);
    }
}

/* sum N = 1, sum N x_a = x, sum dN = 0, sum dN x_a = I. */
static void
check_reproduction (const lac_refelem *re, const double *xi)
{
  double N[LAC_MAX_NODES], dN[LAC_MAX_NODES * 3];
  int d = re->dim;
  lac_refelem_eval (re, xi, N, dN);
  double s = 0, x[3] = { 0, 0, 0 }, g[3] = { 0, 0, 0 }, G[9] = { 0 };
  for (int a = 0; a < re->nnodes; a++)
    {
      s += N[a];
      for (int k = 0; k < d; k++)
        {
          x[k] += N[a] * re->xi[a * d + k];
          g[k] += dN[a * d + k];
          for (int j = 0; j < d; j++)
            G[k * d + j] += re->xi[a * d + k] * dN[a * d + j];
        }
    }
  check_abs (s, 1, 1e-13, "%s: partition of unity", re->name);
  for (int k = 0; k < d; k++)
    {
      check_abs (x[k], xi[k], 1e-13, "%s: linear reproduction %d", re->name,
                 k);
      check_abs (g[k], 0, 1e-12, "%s: sum of gradients %d", re->name, k);
      for (int j = 0; j < d; j++)
        check_abs (G[k * d + j], k == j, 1e-12, "%s: grad x", re->name);
    }
}

static void
check_gradient_fd (const lac_refelem *re, const double *xi)
{
  double dN[LAC_MAX_NODES * 3], Np[LAC_MAX_NODES], Nm[LAC_MAX_NODES];
  const double h = 1e-6;
  int d = re->dim;
  lac_refelem_eval (re, xi, NULL, dN);
  for (int k = 0; k < d; k++)
    {
      double xp[3], xm[3];
      for (int j = 0; j < d; j++)
        xp[j] = xm[j] = xi[j];
      xp[k] += h, xm[k] -= h;
      lac_refelem_eval (re, xp, Np, NULL);
      lac_refelem_eval (re, xm, Nm, NULL);
      for (int a = 0; a < re->nnodes; a++)
        {
          double fd = (Np[a] - Nm[a]) / (2 * h);
          check_abs (dN[a * d + k], fd, 1e-7 * (1 + fabs (fd)),
                     "%s: dN_%d/dxi_%d by FD", re->name, a, k);
        }
    }
}

/* Does element re contain the monomial xi^e in its space? */
static int
in_space (const lac_refelem *re, const int *e)
{
  int tot = 0, mx = 0, nq = 0;
  for (int k = 0; k < re->dim; k++)
    {
      tot += e[k];
      mx = e[k] > mx ? e[k] : mx;
      nq += e[k] == 2;
    }
  switch (re->type)
    {
    case LAC_SEG3: case LAC_TRI6: case LAC_TET10:
      return tot <= 2;
    case LAC_QUAD9: case LAC_HEX27:
      return mx <= 2;
    case LAC_QUAD8: case LAC_HEX20:   /* serendipity: at most one square */
      return mx <= 2 && nq <= 1;
    default:
      return 0;
    }
}

/* Quadratic elements interpolate every monomial of their space exactly. */
static void
check_quadratic (const lac_refelem *re)
{
  int d = re->dim, e[3] = { 0, 0, 0 };
  double N[LAC_MAX_NODES], xi[3];
  if (re->order != 2)
    return;
  for (e[0] = 0; e[0] <= 2; e[0]++)
    for (e[1] = 0; e[1] <= (d > 1 ? 2 : 0); e[1]++)
      for (e[2] = 0; e[2] <= (d > 2 ? 2 : 0); e[2]++)
        {
          if (!in_space (re, e))
            continue;
          for (int r = 0; r < 5; r++)
            {
              random_point (re, xi);
              lac_refelem_eval (re, xi, N, NULL);
              double f = 0, want = 1;
              for (int k = 0; k < d; k++)
                want *= pow (xi[k], e[k]);
              for (int a = 0; a < re->nnodes; a++)
                {
                  double v = 1;
                  for (int k = 0; k < d; k++)
                    v *= pow (re->xi[a * d + k], e[k]);
                  f += N[a] * v;
                }
              check_abs (f, want, 1e-13, "%s: reproduces x^%d y^%d z^%d",
                         re->name, e[0], e[1], e[2]);
            }
        }
}

int
main (void)
{
  srand (101);
  check_true (lac_refelem_get (LAC_NELEM_TYPES) == NULL, "get out of range");
  check_true (lac_refelem_by_name ("tri7") == NULL, "unknown name");
  check_true (lac_refelem_by_gmsh (6) == NULL, "prism not supported");
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    {
      const lac_refelem *re = lac_refelem_get ((lac_elem_type) t);
      double xi[3];
      check_table (re, (lac_elem_type) t);
      check_kronecker (re);
      for (int r = 0; r < 20; r++)
        {
          random_point (re, xi);
          check_reproduction (re, xi);
          check_gradient_fd (re, xi);
        }
      check_quadratic (re);
    }
  return check_summary ();
}
