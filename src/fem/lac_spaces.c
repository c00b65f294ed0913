/* lac_spaces.c -- reference finite elements and isoparametric maps  [LAC §3.1]
 *
 * The spaces V_l^h of [LAC §3.1] are continuous, piecewise P_k (simplices)
 * or Q_k (quadrangles, hexahedra) Lagrange spaces, k = 1, 2, with the
 * serendipity variants quad8 and hex20 and the rational linear pyramid pyr5.
 * Each element type is one constant record (lac_refelem) holding its
 * reference nodes, faces and VTK data; lac_refelem_eval evaluates its
 * shape functions, lac_map_* its isoparametric map.
 *
 * Reference nodes and node order are gmsh's (see lac_spaces.h).
 *
 * Face numbering (the local number f of face_node[f]):
 *   tri   edges   0:(0,1)  1:(1,2)  2:(2,0)            counter-clockwise
 *   quad  edges   0:(0,1)  1:(1,2)  2:(2,3)  3:(3,0)   counter-clockwise
 *   tet   faces   0: z=0 (0,2,1)   1: y=0 (0,1,3)   2: x=0 (0,3,2)
 *                 3: x+y+z=1 (1,2,3)
 *   hex   faces   0: z=-1 (0,3,2,1)  1: y=-1 (0,1,5,4)  2: x=-1 (0,4,7,3)
 *                 3: x=+1 (1,2,6,5)  4: y=+1 (2,3,7,6)  5: z=+1 (4,5,6,7)
 *                 (the order of gmsh's hex27 face nodes 20..25)
 *   pyr   faces   0: base z=0 (0,3,2,1)  1: (0,1,4)  2: (1,2,4)  3: (2,3,4)
 *                 4: (3,0,4)
 * Each face lists its vertices (counter-clockwise seen from outside, so the
 * face's own map has an outward normal), then its edge mid-nodes in the
 * face element's order, then its centre node (quad9).
 *
 * Shape functions (lambda_0 = 1 - sum xi_k, lambda_i = xi_i on simplices):
 *   P1:  lambda_a             P2:  lambda_a (2 lambda_a - 1),  4 lambda_i lambda_j
 *   Q1/Q2: products of 1D Lagrange polynomials on {-1,1} / {-1,0,1}
 *   serendipity (quad8, hex20): corner  2^-d prod(1+xi_k c_k) (sum xi_k c_k - d + 1)
 *                               edge    2^-(d-1) (1 - xi_j^2) prod_{k!=j}(1+xi_k c_k)
 *   pyr5 (gmsh, Bedrosian): r = xi eta zeta / (1 - zeta),
 *     N_0..3 = [(1 -+ xi)(1 -+ eta) - zeta +- r] / 4,  N_4 = zeta.
 *
 * References: gmsh reference manual (node ordering), VTK file formats
 * (cell types and node ordering), Zienkiewicz & Taylor, The Finite Element
 * Method, vol. 1 (serendipity), Bedrosian, IJNME 35 (1992) 95-108
 * (pyramid).
 */
#include "fem/lac_spaces.h"

#include <math.h>
#include <string.h>

#include "base/lac_status.h"

/* ---- reference node coordinates ---------------------------------------- */

static const double xi_seg[] = { -1, 1, 0 };
static const double xi_tri[] = { 0, 0, 1, 0, 0, 1, 0.5, 0, 0.5, 0.5, 0, 0.5 };
static const double xi_quad[] = {
  -1, -1, 1, -1, 1, 1, -1, 1,             /* vertices   */
  0, -1, 1, 0, 0, 1, -1, 0,               /* edges      */
  0, 0                                    /* centre     */
};
static const double xi_tet[] = {
  0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1,     /* vertices                */
  0.5, 0, 0, 0.5, 0.5, 0, 0, 0.5, 0,      /* (0,1) (1,2) (2,0)       */
  0, 0, 0.5, 0, 0.5, 0.5, 0.5, 0, 0.5     /* (3,0) (2,3) (1,3)       */
};
static const double xi_hex[] = {
  -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,   /* vertices 0-3          */
  -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1,       /* vertices 4-7          */
  0, -1, -1, -1, 0, -1, -1, -1, 0,              /* (0,1) (0,3) (0,4)     */
  1, 0, -1, 1, -1, 0, 0, 1, -1,                 /* (1,2) (1,5) (2,3)     */
  1, 1, 0, -1, 1, 0, 0, -1, 1,                  /* (2,6) (3,7) (4,5)     */
  -1, 0, 1, 1, 0, 1, 0, 1, 1,                   /* (4,7) (5,6) (6,7)     */
  0, 0, -1, 0, -1, 0, -1, 0, 0,                 /* faces z-, y-, x-      */
  1, 0, 0, 0, 1, 0, 0, 0, 1,                    /* faces x+, y+, z+      */
  0, 0, 0                                       /* centre                */
};
static const double xi_pyr[] = {
  -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1
};

/* ---- the element table ------------------------------------------------ */

#define ID8 0, 1, 2, 3, 4, 5, 6, 7
#define ID10 ID8, 8, 9

static const lac_refelem table[LAC_NELEM_TYPES] = {
  [LAC_SEG2] = {
    .type = LAC_SEG2, .name = "seg2", .gmsh_type = 1, .vtk_type = 3,
    .shape = LAC_SHAPE_LINE, .dim = 1, .nnodes = 2, .nvertices = 2,
    .order = 1, .degree = 1, .xi = xi_seg, .nfaces = 0,
    .vtk_perm = { 0, 1 } },
  [LAC_SEG3] = {
    .type = LAC_SEG3, .name = "seg3", .gmsh_type = 8, .vtk_type = 21,
    .shape = LAC_SHAPE_LINE, .dim = 1, .nnodes = 3, .nvertices = 2,
    .order = 2, .degree = 2, .xi = xi_seg, .nfaces = 0,
    .vtk_perm = { 0, 1, 2 } },
  [LAC_TRI3] = {
    .type = LAC_TRI3, .name = "tri3", .gmsh_type = 2, .vtk_type = 5,
    .shape = LAC_SHAPE_TRI, .dim = 2, .nnodes = 3, .nvertices = 3,
    .order = 1, .degree = 1, .xi = xi_tri, .nfaces = 3,
    .face_type = { LAC_SEG2, LAC_SEG2, LAC_SEG2 },
    .face_node = { { 0, 1 }, { 1, 2 }, { 2, 0 } },
    .vtk_perm = { 0, 1, 2 } },
  [LAC_TRI6] = {
    .type = LAC_TRI6, .name = "tri6", .gmsh_type = 9, .vtk_type = 22,
    .shape = LAC_SHAPE_TRI, .dim = 2, .nnodes = 6, .nvertices = 3,
    .order = 2, .degree = 2, .xi = xi_tri, .nfaces = 3,
    .face_type = { LAC_SEG3, LAC_SEG3, LAC_SEG3 },
    .face_node = { { 0, 1, 3 }, { 1, 2, 4 }, { 2, 0, 5 } },
    .vtk_perm = { 0, 1, 2, 3, 4, 5 } },
  [LAC_QUAD4] = {
    .type = LAC_QUAD4, .name = "quad4", .gmsh_type = 3, .vtk_type = 9,
    .shape = LAC_SHAPE_QUAD, .dim = 2, .nnodes = 4, .nvertices = 4,
    .order = 1, .degree = 2, .xi = xi_quad, .nfaces = 4,
    .face_type = { LAC_SEG2, LAC_SEG2, LAC_SEG2, LAC_SEG2 },
    .face_node = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } },
    .vtk_perm = { 0, 1, 2, 3 } },
  [LAC_QUAD8] = {
    .type = LAC_QUAD8, .name = "quad8", .gmsh_type = 16, .vtk_type = 23,
    .shape = LAC_SHAPE_QUAD, .dim = 2, .nnodes = 8, .nvertices = 4,
    .order = 2, .degree = 3, .xi = xi_quad, .nfaces = 4,
    .face_type = { LAC_SEG3, LAC_SEG3, LAC_SEG3, LAC_SEG3 },
    .face_node = { { 0, 1, 4 }, { 1, 2, 5 }, { 2, 3, 6 }, { 3, 0, 7 } },
    .vtk_perm = { ID8 } },
  [LAC_QUAD9] = {
    .type = LAC_QUAD9, .name = "quad9", .gmsh_type = 10, .vtk_type = 28,
    .shape = LAC_SHAPE_QUAD, .dim = 2, .nnodes = 9, .nvertices = 4,
    .order = 2, .degree = 4, .xi = xi_quad, .nfaces = 4,
    .face_type = { LAC_SEG3, LAC_SEG3, LAC_SEG3, LAC_SEG3 },
    .face_node = { { 0, 1, 4 }, { 1, 2, 5 }, { 2, 3, 6 }, { 3, 0, 7 } },
    .vtk_perm = { ID8, 8 } },
  [LAC_TET4] = {
    .type = LAC_TET4, .name = "tet4", .gmsh_type = 4, .vtk_type = 10,
    .shape = LAC_SHAPE_TET, .dim = 3, .nnodes = 4, .nvertices = 4,
    .order = 1, .degree = 1, .xi = xi_tet, .nfaces = 4,
    .face_type = { LAC_TRI3, LAC_TRI3, LAC_TRI3, LAC_TRI3 },
    .face_node = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } },
    .vtk_perm = { 0, 1, 2, 3 } },
  [LAC_TET10] = {
    .type = LAC_TET10, .name = "tet10", .gmsh_type = 11, .vtk_type = 24,
    .shape = LAC_SHAPE_TET, .dim = 3, .nnodes = 10, .nvertices = 4,
    .order = 2, .degree = 2, .xi = xi_tet, .nfaces = 4,
    .face_type = { LAC_TRI6, LAC_TRI6, LAC_TRI6, LAC_TRI6 },
    .face_node = { { 0, 2, 1, 6, 5, 4 }, { 0, 1, 3, 4, 9, 7 },
                   { 0, 3, 2, 7, 8, 6 }, { 1, 2, 3, 5, 8, 9 } },
    .vtk_perm = { ID8, 9, 8 } },            /* gmsh (2,3),(1,3) swapped  */
  [LAC_HEX8] = {
    .type = LAC_HEX8, .name = "hex8", .gmsh_type = 5, .vtk_type = 12,
    .shape = LAC_SHAPE_HEX, .dim = 3, .nnodes = 8, .nvertices = 8,
    .order = 1, .degree = 3, .xi = xi_hex, .nfaces = 6,
    .face_type = { LAC_QUAD4, LAC_QUAD4, LAC_QUAD4, LAC_QUAD4, LAC_QUAD4,
                   LAC_QUAD4 },
    .face_node = { { 0, 3, 2, 1 }, { 0, 1, 5, 4 }, { 0, 4, 7, 3 },
                   { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 4, 5, 6, 7 } },
    .vtk_perm = { ID8 } },
  [LAC_HEX20] = {
    .type = LAC_HEX20, .name = "hex20", .gmsh_type = 17, .vtk_type = 25,
    .shape = LAC_SHAPE_HEX, .dim = 3, .nnodes = 20, .nvertices = 8,
    .order = 2, .degree = 4, .xi = xi_hex, .nfaces = 6,
    .face_type = { LAC_QUAD8, LAC_QUAD8, LAC_QUAD8, LAC_QUAD8, LAC_QUAD8,
                   LAC_QUAD8 },
    .face_node = { { 0, 3, 2, 1, 9, 13, 11, 8 },
                   { 0, 1, 5, 4, 8, 12, 16, 10 },
                   { 0, 4, 7, 3, 10, 17, 15, 9 },
                   { 1, 2, 6, 5, 11, 14, 18, 12 },
                   { 2, 3, 7, 6, 13, 15, 19, 14 },
                   { 4, 5, 6, 7, 16, 18, 19, 17 } },
    .vtk_perm = { ID8, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15 } },
  [LAC_HEX27] = {
    .type = LAC_HEX27, .name = "hex27", .gmsh_type = 12, .vtk_type = 29,
    .shape = LAC_SHAPE_HEX, .dim = 3, .nnodes = 27, .nvertices = 8,
    .order = 2, .degree = 6, .xi = xi_hex, .nfaces = 6,
    .face_type = { LAC_QUAD9, LAC_QUAD9, LAC_QUAD9, LAC_QUAD9, LAC_QUAD9,
                   LAC_QUAD9 },
    .face_node = { { 0, 3, 2, 1, 9, 13, 11, 8, 20 },
                   { 0, 1, 5, 4, 8, 12, 16, 10, 21 },
                   { 0, 4, 7, 3, 10, 17, 15, 9, 22 },
                   { 1, 2, 6, 5, 11, 14, 18, 12, 23 },
                   { 2, 3, 7, 6, 13, 15, 19, 14, 24 },
                   { 4, 5, 6, 7, 16, 18, 19, 17, 25 } },
    .vtk_perm = { ID8, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15,
                  22, 23, 21, 24, 20, 25, 26 } },
  /* pyr5: `degree` is the one its collapsed quadrature needs: in the
   * collapsed coordinates of lac_quadrature.c the rational basis is
   * trilinear and its gradients are polynomials, so mass and stiffness
   * products are integrated exactly by the degree-2 collapsed rule. */
  [LAC_PYR5] = {
    .type = LAC_PYR5, .name = "pyr5", .gmsh_type = 7, .vtk_type = 14,
    .shape = LAC_SHAPE_PYR, .dim = 3, .nnodes = 5, .nvertices = 5,
    .order = 1, .degree = 2, .xi = xi_pyr, .nfaces = 5,
    .face_type = { LAC_QUAD4, LAC_TRI3, LAC_TRI3, LAC_TRI3, LAC_TRI3 },
    .face_node = { { 0, 3, 2, 1 }, { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 },
                   { 3, 0, 4 } },
    .vtk_perm = { 0, 1, 2, 3, 4 } },
};

/* ---- queries ------------------------------------------------------------ */

const lac_refelem *
lac_refelem_get (lac_elem_type t)
{
  if ((int) t < 0 || (int) t >= LAC_NELEM_TYPES)
    return NULL;
  return &table[t];
}

const lac_refelem *
lac_refelem_by_name (const char *name)
{
  if (name == NULL)
    return NULL;
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    if (strcmp (table[t].name, name) == 0)
      return &table[t];
  return NULL;
}

const lac_refelem *
lac_refelem_by_gmsh (int gmsh_type)
{
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    if (table[t].gmsh_type == gmsh_type)
      return &table[t];
  return NULL;
}

/* The linear element with the same vertices as a quadratic one. */
lac_elem_type
lac_refelem_linear_type (lac_elem_type t)
{
  switch (t)
    {
    case LAC_SEG3: return LAC_SEG2;
    case LAC_TRI6: return LAC_TRI3;
    case LAC_QUAD8: case LAC_QUAD9: return LAC_QUAD4;
    case LAC_TET10: return LAC_TET4;
    case LAC_HEX20: case LAC_HEX27: return LAC_HEX8;
    default: return t;
    }
}

/* ---- shape functions ---------------------------------------------------- */

/* 1D Lagrange polynomial of the node at c in {-1, 0, 1} (Q2) and its
 * derivative: c = -1: xi (xi-1)/2,  c = 1: xi (xi+1)/2,  c = 0: 1 - xi^2. */
static void
lagrange2 (double c, double t, double *L, double *dL)
{
  if (c < -0.5)
    *L = 0.5 * t * (t - 1), *dL = t - 0.5;
  else if (c > 0.5)
    *L = 0.5 * t * (t + 1), *dL = t + 0.5;
  else
    *L = 1 - t * t, *dL = -2 * t;
}

/* Tensor-product Lagrange functions (seg, quad, hex; order 1 or 2):
 *   N_a(xi) = prod_k L_{c_ak}(xi_k),  c_a the coordinates of node a. */
static void
eval_tensor (const lac_refelem *re, const double *xi, double *N, double *dN)
{
  int d = re->dim;
  for (int a = 0; a < re->nnodes; a++)
    {
      double L[3], dL[3];
      for (int k = 0; k < d; k++)
        {
          double c = re->xi[a * d + k];
          if (re->order == 1)
            L[k] = 0.5 * (1 + c * xi[k]), dL[k] = 0.5 * c;
          else
            lagrange2 (c, xi[k], &L[k], &dL[k]);
        }
      double p = 1;
      for (int k = 0; k < d; k++)
        p *= L[k];
      if (N)
        N[a] = p;
      for (int j = 0; dN && j < d; j++)
        {
          double g = dL[j];
          for (int k = 0; k < d; k++)
            if (k != j)
              g *= L[k];
          dN[a * d + j] = g;
        }
    }
}

/* Serendipity functions (quad8, hex20), d = 2 or 3:
 *   corner c:      2^-d  prod_k (1 + c_k xi_k) (sum_k c_k xi_k - d + 1)
 *   edge (c_j=0):  2^-(d-1) (1 - xi_j^2) prod_{k != j} (1 + c_k xi_k)     */
static void
eval_serendipity (const lac_refelem *re, const double *xi, double *N,
                  double *dN)
{
  int d = re->dim;
  for (int a = 0; a < re->nnodes; a++)
    {
      const double *c = re->xi + a * d;
      double A[3], P = 1, S = 0;
      int j0 = -1;
      for (int k = 0; k < d; k++)
        {
          if (c[k] == 0)
            j0 = k, A[k] = 1 - xi[k] * xi[k];
          else
            A[k] = 1 + c[k] * xi[k], S += c[k] * xi[k];
          P *= A[k];
        }
      double s = (j0 < 0) ? ldexp (1.0, -d) : ldexp (1.0, -(d - 1));
      if (N)
        N[a] = (j0 < 0) ? s * P * (S - d + 1) : s * P;
      for (int j = 0; dN && j < d; j++)
        {
          double Q = 1;                 /* prod_{k != j} A_k */
          for (int k = 0; k < d; k++)
            if (k != j)
              Q *= A[k];
          double g;
          if (j0 < 0)                   /* d/dxi_j [A_j (S - d + 1)] */
            g = s * Q * c[j] * (S - d + 1 + A[j]);
          else if (j == j0)
            g = s * Q * (-2 * xi[j]);
          else
            g = s * Q * c[j];
          dN[a * d + j] = g;
        }
    }
}

/* Edges of tri6 and tet10, in the order of their mid-nodes. */
static const int simplex_edge[6][2] = {
  { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 0 }, { 2, 3 }, { 1, 3 }
};

/* P1/P2 on the unit simplex, in barycentric coordinates
 * lambda_0 = 1 - sum_k xi_k, lambda_i = xi_i. */
static void
eval_simplex (const lac_refelem *re, const double *xi, double *N, double *dN)
{
  int d = re->dim, nv = d + 1;
  double lam[4], dlam[4][3];
  lam[0] = 1;
  for (int k = 0; k < d; k++)
    {
      lam[0] -= xi[k];
      lam[k + 1] = xi[k];
      dlam[0][k] = -1;
      for (int i = 1; i < nv; i++)
        dlam[i][k] = (i == k + 1);
    }
  for (int a = 0; a < nv; a++)
    {
      double f = (re->order == 1) ? 1 : 4 * lam[a] - 1;
      if (N)
        N[a] = (re->order == 1) ? lam[a] : lam[a] * (2 * lam[a] - 1);
      for (int k = 0; dN && k < d; k++)
        dN[a * d + k] = f * dlam[a][k];
    }
  for (int e = 0; e < re->nnodes - nv; e++)
    {
      int i = simplex_edge[e][0], j = simplex_edge[e][1], a = nv + e;
      if (N)
        N[a] = 4 * lam[i] * lam[j];
      for (int k = 0; dN && k < d; k++)
        dN[a * d + k] = 4 * (lam[j] * dlam[i][k] + lam[i] * dlam[j][k]);
    }
}

/* The rational pyramid basis (gmsh's), r = xi eta zeta / (1 - zeta):
 *   N_a = [(1 + x_a xi)(1 + y_a eta) - zeta + x_a y_a r] / 4, N_4 = zeta.
 * At the apex r and its gradient have no limit; they are taken as 0. */
static void
eval_pyramid (const double *xi, double *N, double *dN)
{
  double u = xi[0], v = xi[1], w = xi[2];
  double r = 0, dr[3] = { 0, 0, 0 };
  if (w != 1)
    {
      double q = 1 / (1 - w);
      r = u * v * w * q;
      dr[0] = v * w * q;
      dr[1] = u * w * q;
      dr[2] = u * v * q * q;
    }
  for (int a = 0; a < 4; a++)
    {
      double xa = xi_pyr[3 * a], ya = xi_pyr[3 * a + 1];
      double A = 1 + xa * u, B = 1 + ya * v, s = xa * ya;
      if (N)
        N[a] = 0.25 * (A * B - w + s * r);
      if (dN)
        {
          dN[3 * a + 0] = 0.25 * (xa * B + s * dr[0]);
          dN[3 * a + 1] = 0.25 * (A * ya + s * dr[1]);
          dN[3 * a + 2] = 0.25 * (-1 + s * dr[2]);
        }
    }
  if (N)
    N[4] = w;
  if (dN)
    dN[12] = 0, dN[13] = 0, dN[14] = 1;
}

/* lac_refelem_eval: N_a(xi) and dN_a/dxi_k  [LAC §3.1]. */
void
lac_refelem_eval (const lac_refelem *re, const double *xi, double *N,
                  double *dN)
{
  switch (re->type)
    {
    case LAC_TRI3: case LAC_TRI6: case LAC_TET4: case LAC_TET10:
      eval_simplex (re, xi, N, dN);
      break;
    case LAC_QUAD8: case LAC_HEX20:
      eval_serendipity (re, xi, N, dN);
      break;
    case LAC_PYR5:
      eval_pyramid (xi, N, dN);
      break;
    default:                            /* seg, quad4/9, hex8/27 */
      eval_tensor (re, xi, N, dN);
      break;
    }
}

/* Is xi in the reference element, up to tol? */
int
lac_refelem_contains (const lac_refelem *re, const double *xi, double tol)
{
  double s = 0;
  switch (re->shape)
    {
    case LAC_SHAPE_LINE: case LAC_SHAPE_QUAD: case LAC_SHAPE_HEX:
      for (int k = 0; k < re->dim; k++)
        if (fabs (xi[k]) > 1 + tol)
          return 0;
      return 1;
    case LAC_SHAPE_TRI: case LAC_SHAPE_TET:
      for (int k = 0; k < re->dim; k++)
        {
          if (xi[k] < -tol)
            return 0;
          s += xi[k];
        }
      return s <= 1 + tol;
    case LAC_SHAPE_PYR:
      return xi[2] >= -tol && xi[2] <= 1 + tol
        && fabs (xi[0]) <= 1 - xi[2] + tol
        && fabs (xi[1]) <= 1 - xi[2] + tol;
    }
  return 0;
}

/* ---- isoparametric maps ------------------------------------------------- */

/* x = sum_a x_a N_a,  J[i*dim+k] = sum_a x_ai dN_a/dxi_k, with m->N and
 * dN at the point. */
static void
map_geometry (const lac_refelem *re, int sdim, const double *xe, lac_map *m,
              const double *dN)
{
  int d = re->dim;
  memset (m->x, 0, sizeof m->x);
  memset (m->J, 0, sizeof m->J);
  for (int a = 0; a < re->nnodes; a++)
    for (int i = 0; i < sdim; i++)
      {
        double xa = xe[a * sdim + i];
        m->x[i] += xa * m->N[a];
        for (int k = 0; k < d; k++)
          m->J[i * d + k] += xa * dN[a * d + k];
      }
}

static void
map_eval (const lac_refelem *re, int sdim, const double *xe,
          const double *xi, lac_map *m, double *dN)
{
  lac_refelem_eval (re, xi, m->N, dN);
  map_geometry (re, sdim, xe, m, dN);
}

/* det J and, if Jinv is not NULL and det != 0, J^{-1} (d x d). */
static double
det_inv (int d, const double *J, double *Jinv)
{
  double det;
  if (d == 1)
    {
      det = J[0];
      if (Jinv && det != 0)
        Jinv[0] = 1 / det;
      return det;
    }
  if (d == 2)
    {
      det = J[0] * J[3] - J[1] * J[2];
      if (Jinv && det != 0)
        {
          Jinv[0] = J[3] / det, Jinv[1] = -J[1] / det;
          Jinv[2] = -J[2] / det, Jinv[3] = J[0] / det;
        }
      return det;
    }
  double c[9];                                 /* cofactors */
  c[0] = J[4] * J[8] - J[5] * J[7];
  c[1] = J[2] * J[7] - J[1] * J[8];
  c[2] = J[1] * J[5] - J[2] * J[4];
  c[3] = J[5] * J[6] - J[3] * J[8];
  c[4] = J[0] * J[8] - J[2] * J[6];
  c[5] = J[2] * J[3] - J[0] * J[5];
  c[6] = J[3] * J[7] - J[4] * J[6];
  c[7] = J[1] * J[6] - J[0] * J[7];
  c[8] = J[0] * J[4] - J[1] * J[3];
  det = J[0] * c[0] + J[1] * c[3] + J[2] * c[6];
  if (Jinv && det != 0)
    for (int i = 0; i < 9; i++)
      Jinv[i] = c[i] / det;
  return det;
}

/* lac_map_cell: x(xi), N, dN/dx = J^{-T} dN/dxi, J, det J  [LAC §3.1].
 * dNdx[a*dim + i] = dN_a/dx_i. */
int
lac_map_cell (const lac_refelem *re, int sdim, const double *xe,
              const double *xi, lac_map *m)
{
  double N[LAC_MAX_NODES], dN[LAC_MAX_NODES * 3];
  lac_refelem_eval (re, xi, N, dN);
  return lac_map_cell_at (re, sdim, xe, xi, N, dN, m);
}

/* lac_map_cell_at: the same from N and dN/dxi at xi. */
int
lac_map_cell_at (const lac_refelem *re, int sdim, const double *xe,
                 const double *xi, const double *N, const double *dN,
                 lac_map *m)
{
  int d = re->dim;
  double Jinv[9];
  if (sdim != d)
    LAC_ERROR (LAC_EINVAL, "%s cell in %d-D space (need sdim == %d)",
               re->name, sdim, d);
  memcpy (m->N, N, (size_t) re->nnodes * sizeof *N);
  map_geometry (re, sdim, xe, m, dN);
  memset (m->normal, 0, sizeof m->normal);
  m->detJ = det_inv (d, m->J, Jinv);
  if (!(m->detJ > 0))
    LAC_ERROR (LAC_ESING, "%s cell has det J = %g <= 0 at xi = (%g, %g, %g)",
               re->name, m->detJ, xi[0], d > 1 ? xi[1] : 0.0,
               d > 2 ? xi[2] : 0.0);
  for (int a = 0; a < re->nnodes; a++)
    for (int i = 0; i < d; i++)
      {
        double g = 0;                     /* sum_k dN_a/dxi_k dxi_k/dx_i */
        for (int k = 0; k < d; k++)
          g += dN[a * d + k] * Jinv[k * d + i];
        m->dNdx[a * d + i] = g;
      }
  return LAC_SUCCESS;
}

/* lac_map_face: x(xi), N, J (sdim x dim), unit normal and surface element.
 *   2D: n = (t_y, -t_x) / |t|,  3D: n = t_1 x t_2 / |t_1 x t_2|. */
int
lac_map_face (const lac_refelem *re, int sdim, const double *xe,
              const double *xi, lac_map *m)
{
  int d = re->dim;
  double dN[LAC_MAX_NODES * 3], n[3] = { 0, 0, 0 };
  if (sdim != d + 1 || sdim < 2)
    LAC_ERROR (LAC_EINVAL, "%s face in %d-D space (need sdim == %d)",
               re->name, sdim, d + 1);
  map_eval (re, sdim, xe, xi, m, dN);
  memset (m->dNdx, 0, sizeof m->dNdx);
  const double *J = m->J;
  if (sdim == 2)
    n[0] = J[1], n[1] = -J[0];          /* t = (J[0], J[1]) */
  else
    {
      n[0] = J[2] * J[5] - J[4] * J[3];  /* t1 = column 0, t2 = column 1 */
      n[1] = J[4] * J[1] - J[0] * J[5];
      n[2] = J[0] * J[3] - J[2] * J[1];
    }
  m->detJ = sqrt (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(m->detJ > 0))
    LAC_ERROR (LAC_ESING, "%s face is degenerate (surface element %g)",
               re->name, m->detJ);
  for (int i = 0; i < 3; i++)
    m->normal[i] = n[i] / m->detJ;
  return LAC_SUCCESS;
}

/* Reference centroid: the Newton starting point. */
static void
ref_centroid (const lac_refelem *re, double *xi)
{
  double c = 0;
  if (re->shape == LAC_SHAPE_TRI)
    c = 1.0 / 3;
  else if (re->shape == LAC_SHAPE_TET)
    c = 0.25;
  for (int k = 0; k < re->dim; k++)
    xi[k] = c;
  if (re->shape == LAC_SHAPE_PYR)
    xi[2] = 0.25;
}

#define INVERSE_MAXITER 50
#define INVERSE_TOL 1e-13

/* lac_map_inverse: solve x(xi) = x by Newton's method,
 *   xi <- xi - J(xi)^{-1} (x(xi) - x),
 * from the reference centroid, until |dxi| <= 1e-13 (reference units). */
int
lac_map_inverse (const lac_refelem *re, int sdim, const double *xe,
                 const double *x, double *xi)
{
  int d = re->dim;
  double dN[LAC_MAX_NODES * 3], Jinv[9];
  lac_map m;
  if (sdim != d)
    LAC_ERROR (LAC_EINVAL, "%s cell in %d-D space", re->name, sdim);
  ref_centroid (re, xi);
  for (int it = 0; it < INVERSE_MAXITER; it++)
    {
      map_eval (re, sdim, xe, xi, &m, dN);
      if (det_inv (d, m.J, Jinv) == 0)
        LAC_ERROR (LAC_ESING, "%s: singular J at iteration %d", re->name, it);
      double step = 0;
      for (int k = 0; k < d; k++)
        {
          double s = 0;
          for (int i = 0; i < d; i++)
            s += Jinv[k * d + i] * (m.x[i] - x[i]);
          xi[k] -= s;
          if (!(fabs (s) <= step))         /* NaN-propagating max */
            step = fabs (s);
        }
      if (!isfinite (step))
        break;
      if (step <= INVERSE_TOL)
        return LAC_SUCCESS;
    }
  LAC_ERROR (LAC_EMAXITER, "%s: Newton did not converge in %d iterations",
             re->name, INVERSE_MAXITER);
}
