/* lac_spaces.h -- reference finite elements and isoparametric maps  [LAC §3.1]
 *
 * The displacement spaces V_l^h of [LAC §3.1] are spanned by the nodal shape
 * functions of Lagrange elements of degree k = 1, 2 (serendipity quad8 and
 * hex20 included).  This module holds, for every element type, its reference
 * nodes, shape functions and their gradients, its faces (with local nodes,
 * oriented so that the face normal points out of the cell), its VTK cell
 * type and node permutation, and evaluates the isoparametric map of a cell
 * or of a face (curved quadratic geometry included).
 *
 * Conventions (gmsh's, so that connectivity read from gmsh needs no
 * reordering): lines, quadrangles and hexahedra live on [-1,1]^d; triangles
 * and tetrahedra on the unit simplex; the pyramid has its base on
 * [-1,1]^2 x {0} and its apex at (0,0,1).  Node order is gmsh's.
 *
 * Degrees of freedom are nodal and interleaved: dof = dim*node + component.
 *
 * Everything here is constant data or a pure function; nothing to free.
 */
#ifndef LAC_SPACES_H
#define LAC_SPACES_H

#include <stddef.h>

typedef enum
{
  LAC_ELEM_NONE = -1,
  LAC_SEG2 = 0, LAC_SEG3,
  LAC_TRI3, LAC_TRI6,
  LAC_QUAD4, LAC_QUAD8, LAC_QUAD9,
  LAC_TET4, LAC_TET10,
  LAC_HEX8, LAC_HEX20, LAC_HEX27,
  LAC_PYR5,
  LAC_NELEM_TYPES
} lac_elem_type;

typedef enum
{
  LAC_SHAPE_LINE, LAC_SHAPE_TRI, LAC_SHAPE_QUAD,
  LAC_SHAPE_TET, LAC_SHAPE_HEX, LAC_SHAPE_PYR
} lac_shape;

#define LAC_MAX_NODES 27       /* hex27 */
#define LAC_MAX_FACES 6
#define LAC_MAX_FACE_NODES 9   /* quad9 */

typedef struct lac_refelem
{
  lac_elem_type type;
  const char *name;       /* "tri6", as used in scenes and messages       */
  int gmsh_type;          /* gmsh element type code                       */
  int vtk_type;           /* VTK cell type                                */
  lac_shape shape;
  int dim;                /* reference dimension 1, 2, 3                  */
  int nnodes;
  int nvertices;          /* the first nvertices nodes are the vertices   */
  int order;              /* 1 linear, 2 quadratic                        */
  int degree;             /* highest total degree of a shape function     */
  const double *xi;       /* nnodes*dim reference coordinates             */
  int nfaces;             /* faces of a 2D/3D cell (edges for 2D cells)   */
  lac_elem_type face_type[LAC_MAX_FACES];
  /* Local nodes of face f, listed in the face element's own node order and
   * oriented so that its normal points out of the cell: for a 2D cell the
   * edge runs with the cell on its left (outward normal (t_y, -t_x)); for a
   * 3D cell the face vertices turn counter-clockwise seen from outside. */
  int face_node[LAC_MAX_FACES][LAC_MAX_FACE_NODES];
  int vtk_perm[LAC_MAX_NODES];  /* VTK node k is gmsh node vtk_perm[k]   */
} lac_refelem;

/* query */
const lac_refelem *lac_refelem_get (lac_elem_type t);        /* NULL if bad */
const lac_refelem *lac_refelem_by_name (const char *name);   /* NULL if unknown */
const lac_refelem *lac_refelem_by_gmsh (int gmsh_type);      /* NULL if unsupported */
/* The linear element with the same vertices (tri6 -> tri3, hex27 -> hex8;
 * t itself if t is linear). */
lac_elem_type lac_refelem_linear_type (lac_elem_type t);

/* N_a(xi) and dN_a/dxi_k at one reference point.
 *   [out] N   nnodes values (may be NULL)
 *   [out] dN  nnodes*dim values, dN[a*dim + k] = dN_a/dxi_k (may be NULL) */
void lac_refelem_eval (const lac_refelem *re, const double *xi,
                       double *N, double *dN);

/* The isoparametric map x(xi) = sum_a x_a N_a(xi) of one cell, evaluated at
 * one reference point.  sdim is the space dimension (>= re->dim). */
typedef struct lac_map
{
  double x[3];                     /* the point x(xi)                      */
  double N[LAC_MAX_NODES];         /* shape functions                      */
  double dNdx[LAC_MAX_NODES * 3];  /* [a*dim + k] = dN_a/dx_k (cells only) */
  double J[9];                     /* J[i*dim + k] = dx_i/dxi_k            */
  double detJ;                     /* cells: det J; faces: |normal|        */
  double normal[3];                /* faces only: unit normal               */
} lac_map;

/* Cell map (re->dim == sdim).  xe: nnodes*sdim node coordinates.
 * Fills x, N, dNdx, J, detJ.  Returns LAC_ESING (with a message) if
 * det J <= 0, LAC_SUCCESS otherwise. */
int lac_map_cell (const lac_refelem *re, int sdim, const double *xe,
                  const double *xi, lac_map *m);

/* The same with N and dN/dxi (as lac_refelem_eval gives them) already
 * evaluated at xi: a quadrature rule's tables, made once for all cells
 * (lac_quad_cache_table, fem/lac_quadrature.h).  The results are those of
 * lac_map_cell, bit for bit. */
int lac_map_cell_at (const lac_refelem *re, int sdim, const double *xe,
                     const double *xi, const double *N, const double *dN,
                     lac_map *m);

/* Face map (re->dim == sdim - 1): x, N, J (sdim x dim), the unit normal
 * (right-hand rule on the face's node order: for a segment in 2D the normal
 * is (t_y, -t_x) with t = dx/dxi; for a surface in 3D it is t_1 x t_2) and
 * detJ = the surface (length) element |t_y,-t_x| or |t_1 x t_2|.
 * Returns LAC_ESING if the element is degenerate. */
int lac_map_face (const lac_refelem *re, int sdim, const double *xe,
                  const double *xi, lac_map *m);

/* Inverse map: the xi with x(xi) = x for a cell, by Newton's method.
 * Returns LAC_EMAXITER if it does not converge. */
int lac_map_inverse (const lac_refelem *re, int sdim, const double *xe,
                     const double *x, double *xi);

/* Is xi inside the reference element (up to tol)? */
int lac_refelem_contains (const lac_refelem *re, const double *xi, double tol);

#endif /* LAC_SPACES_H */
