/* lac_pairing_geom.h -- the geometry of one (slave, master) pair
 *                                                 [LAC §4.6, items 2-3]
 *
 * Pure functions of two facets, used by the search (which pairs overlap,
 * lac_pairing_search.h) and by the driver (the points of each pair,
 * lac_pairing.h): the facet's geometry and plane chart, the overlap of the
 * linearised facets in the slave's chart (Sutherland-Hodgman clipping in
 * 3D), and the integration points on that overlap, carried to the master
 * by lac_pairing_project (lac_pairing_project.h).  The method is described
 * in lac_pairing.h and lac_pairing_geom.c.
 *
 * References: I. E. Sutherland, G. W. Hodgman, "Reentrant polygon
 * clipping", CACM 17 (1974).
 */
#ifndef LAC_PAIRING_GEOM_H
#define LAC_PAIRING_GEOM_H

#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"

/* Sutherland-Hodgman: clip the polygon q (n = 3 or 4 points of a plane,
 * either orientation) against the convex counter-clockwise polygon c
 * (nc = 3 or 4 points).  out holds up to LAC_PAIRING_MAXPOLY points;
 * returns their number (0: empty). */
#define LAC_PAIRING_MAXPOLY 16
int lac_pairing_clip (int nc, const double *c, int n, const double *q,
                      double *out);

/* Signed area of the polygon q (n points; > 0 counter-clockwise). */
double lac_pairing_polygon_area (int n, const double *q);

/* The geometry of one facet, gathered once per test.  In 3D its chart is
 * the plane x = o + z_1 e_1 + z_2 e_2 on which overlaps are computed: the
 * affine map of the linearised triangle (chart = reference coordinates),
 * or the plane tangent to the bilinear map of a quadrangle at its centre
 * (chart = reference coordinates for a parallelogram). */
typedef struct lac_pairing_facet
{
  const lac_refelem *re;    /* the facet element (seg3, tri6, quad9, ...)  */
  const lac_refelem *lin;   /* its linear counterpart (seg2, tri3, quad4)  */
  int sdim;                 /* space dimension, 2 or 3                     */
  double xe[LAC_MAX_FACE_NODES * 3]; /* node coordinates in re's order;
                               the first lin->nnodes are the vertices      */
  double c[3];              /* centre (vertex average)                     */
  double n[3];              /* unit normal of the linearised facet at its
                               reference centre                            */
  double h;                 /* diameter: largest distance between vertices */
  double o[3], e[6];        /* 3D chart: origin, e_1 = e[0..2], e_2 = e[3..5] */
  double g[3];              /* inverse Gram matrix of e_1, e_2 (g11 g12 g22) */
  int nz;                   /* 3D: the vertices projected to the chart,    */
  double z[8];              /*   counter-clockwise (the chart polygon)     */
  int affine;               /* 1: chart coordinates = reference ones       */
} lac_pairing_facet;

/* The fraction of slave facet f that an overlap (np points of its chart,
 * as lac_pairing_overlap returns it) covers. */
double lac_pairing_overlap_fraction (const lac_pairing_facet *f, int np,
                                     const double *poly);

/* Fill f from a facet type and its nodes (xe: nnodes*sdim).  Returns
 * LAC_EINVAL for a type that is not a facet of an sdim-D cell, LAC_ESING
 * for a degenerate facet or a non-convex quadrangle. */
int lac_pairing_facet_set (lac_pairing_facet *f, lac_elem_type type,
                           int sdim, const double *xe);

/* Outcome of lac_pairing_overlap. */
enum
{
  LAC_PAIRING_OVERLAP = 0,   /* a non-empty overlap, within reach          */
  LAC_PAIRING_DISJOINT,      /* empty (or of measure ~1e-14 |T^s|)          */
  LAC_PAIRING_NOT_FACING,    /* -n_s.n_m <= facing                          */
  LAC_PAIRING_TOO_FAR        /* normal gap at the overlap centroid > dmax   */
};

/* The overlap of master facet m with slave facet s, computed on the
 * linearised facets: in 2D the interval poly[0] < poly[1] of the slave's
 * reference segment [-1,1] (*np = 2); in 3D a counter-clockwise polygon of
 * the slave's chart, inside its chart polygon (*np >= 3 points, at most
 * LAC_PAIRING_MAXPOLY).  Returns one of the LAC_PAIRING_* outcomes. */
int lac_pairing_overlap (const lac_pairing_facet *s,
                         const lac_pairing_facet *m, double dmax,
                         double facing, double *poly, int *np);

/* Integration points on an overlap (poly, np from lac_pairing_overlap):
 * `sub` is the rule put on each piece (line in 2D, triangle in 3D), `full`
 * the slave cell's own rule (reference coordinates), used when the
 * overlap is the whole facet.
 * Writes *npts = lac_pairing_npoints (...) points to xs, xm
 * (npts*(sdim-1)), w and gap (npts).  Returns LAC_SUCCESS, or the
 * status of a failed projection onto m / of a degenerate slave map. */
int lac_pairing_npoints (const lac_pairing_facet *s, int np,
                         const double *poly, const lac_quad *sub,
                         const lac_quad *full);   /* how many it writes */
int lac_pairing_points (const lac_pairing_facet *s,
                        const lac_pairing_facet *m, int np,
                        const double *poly, const lac_quad *sub,
                        const lac_quad *full, double *xs, double *xm,
                        double *w, double *gap, int *npts);

#endif /* LAC_PAIRING_GEOM_H */
