/* lac_quadrature.h -- quadrature rules on the reference elements
 *
 * Lines, quadrangles and hexahedra: tensor products of Gauss-Legendre rules
 * (GSL's tables).  Triangles and tetrahedra: fully symmetric rules with
 * positive weights where known, collapsed (Stroud conical-product) rules
 * above.  Pyramids: collapsed Gauss rule, exact for the rational pyramid
 * basis products used in the stiffness.  Every rule states the total degree
 * it integrates exactly; the weights sum to the reference measure.
 *
 * Reference domains as in lac_spaces.h.
 */
#ifndef LAC_QUADRATURE_H
#define LAC_QUADRATURE_H

#include "fem/lac_spaces.h"

typedef struct lac_quad
{
  lac_shape shape;
  int dim;
  int degree;   /* exact for all polynomials of total degree <= degree */
  int n;        /* number of points                                     */
  double *xi;   /* owned, n*dim                                          */
  double *w;    /* owned, n                                              */
} lac_quad;

/* A rule on `shape` exact to at least `degree` (the cheapest one known).
 * Returns NULL with a message if degree is negative or out of range. */
lac_quad *lac_quad_alloc (lac_shape shape, int degree);
void lac_quad_free (lac_quad *q);   /* NULL allowed */

/* Measure of the reference domain (2, 4, 8, 1/2, 1/6, 4/3). */
double lac_quad_ref_measure (lac_shape shape);

/* Highest degree lac_quad_alloc accepts for `shape` (-1 if unknown). */
int lac_quad_max_degree (lac_shape shape);

/* A cache of rules, one per (shape, degree), allocated on first use: a
 * zeroed struct (memset or = { 0 }) is an empty cache.  Degrees above the
 * best rule of a shape, or above LAC_QUAD_CACHE_MAXDEG, get that rule.
 * lac_quad_cache_get returns NULL (message set) if a rule cannot be made;
 * the rules stay owned by the cache until lac_quad_cache_free. */
#define LAC_QUAD_CACHE_MAXDEG 16

/* The shape functions of a cell type at the points of a rule, evaluated
 * once (lac_refelem_eval) for all the cells of that type:
 * N[p*nnodes + a], dN[(p*nnodes + a)*dim + k], as lac_map_cell_at takes
 * them. */
typedef struct lac_quad_table
{
  const lac_quad *q;  /* borrowed from the cache                          */
  double *N, *dN;     /* owned                                            */
} lac_quad_table;

typedef struct lac_quad_cache
{
  lac_quad *q[LAC_SHAPE_PYR + 1][LAC_QUAD_CACHE_MAXDEG + 1];   /* owned */
  lac_quad_table *t[LAC_NELEM_TYPES][LAC_QUAD_CACHE_MAXDEG + 1]; /* owned */
} lac_quad_cache;

const lac_quad *lac_quad_cache_get (lac_quad_cache *qc, lac_shape shape,
                                    int degree);
/* The rule of re's shape for `degree` (as lac_quad_cache_get) with re's
 * shape functions at its points; NULL (message set) if it cannot be
 * made. */
const lac_quad_table *lac_quad_cache_table (lac_quad_cache *qc,
                                            const lac_refelem *re,
                                            int degree);
void lac_quad_cache_free (lac_quad_cache *qc);   /* empties the cache */

#endif /* LAC_QUADRATURE_H */
