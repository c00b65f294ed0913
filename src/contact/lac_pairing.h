/* lac_pairing.h -- slave/master pairing of contact facets     [LAC §4.6]
 *
 * The LAC contact matrices C^S, C^M and the mean gaps [LAC (16)-(17)] are
 * integrals over the slave contact surface of products of slave and master
 * quantities.  With non-matching meshes each slave facet T^s is cut by the
 * master facets T^m it overlaps; this module finds those (slave, master)
 * pairs and returns, for every slave facet, integration points that live on
 * the intersections, with their coordinates in both reference elements.
 *
 *   Search.  An advancing front in the spirit of PANG (Gander & Japhet): a
 *   slave facet is seeded with master facets known to be near it, and the
 *   front floods over master neighbours (facets sharing a vertex) while the
 *   intersections are non-empty; the slave neighbours of a paired facet are
 *   queued with its masters as seeds.  A bucket grid over the master facets
 *   seeds the first facet of every contact zone (disconnected zones are
 *   re-seeded) and any facet whose inherited seeds fail, and completes the
 *   facets that the flood leaves partly covered (the edge of a contact
 *   zone, or a master surface in pieces).  Linear in the number of facets
 *   [LAC §4.6, principles 1 and 4].  opts.robust replaces the front by a
 *   full grid query per slave facet (also linear, slower).
 *
 *   Intersection.  On the linearised facets (vertices only), in a plane
 *   chart of the slave facet: its reference plane for a segment, a
 *   triangle or a parallelogram, the plane tangent at its centre for other
 *   quadrangles [LAC §4.6, principle 3].  The master vertices are
 *   projected orthogonally onto the chart, the projected master polygon
 *   (interval in 2D) is clipped against the slave's own polygon
 *   (Sutherland-Hodgman) and cut into triangles (a fan from its first
 *   vertex) that carry a triangle rule; the points of the chart are taken
 *   to the slave reference cell by inverting the slave's bilinear map
 *   (Newton, inside the cell).
 *
 *   Points.  Integration points live on the exact (possibly curved) slave
 *   facet; each one is carried to the master facet by projection along the
 *   slave normal, X_m(xi_m) = x_s + g n_s, solved by Newton with line
 *   search in master reference coordinates [LAC §4.6, principle 2].  g is
 *   the normal gap (g > 0: separated, g < 0: penetration).
 *
 * Conventions.  Facet lists are (cell, local face) pairs of a mesh, as in
 * lac_group; the facet's nodes and outward normal come from the cell's
 * reference element.  Slave and master may belong to one mesh or to two
 * meshes of the same dimension.  Facets are seg2/seg3 in 2D and
 * tri3/tri6/quad4/quad8/quad9 in 3D.  Facet indices in the output are
 * positions in the slave and master lists, not cell numbers.  Reference
 * coordinates are those of the face elements (as lac_map_face); a master
 * point may lie slightly outside its reference cell on curved facets (by
 * the linearisation error of the overlap).  A pair
 * counts only if the facets face each other (-n_s.n_m > opts.facing) and
 * the normal gap at the centroid of their overlap is at most
 * opts.dist_abs + opts.dist_rel * max(diam T^s, diam T^m).
 *
 * Accuracy.  On flat facets the chart maps are affine, so every overlap is
 * the exact physical intersection of the two facets, and the pieces tile
 * each slave facet exactly: the covered measures sum to the facet measure
 * up to rounding.  On curved (quadratic) facets the pieces are those of the
 * linearised facets, which still tile each slave facet, and the measures
 * integrate the exact surface element.
 *
 * Ownership.  The facet lists and meshes are borrowed during
 * lac_pairing_build only; the lac_pairing it returns owns all its arrays and
 * keeps no pointer to the input (free it with lac_pairing_free).
 *
 * References: M. J. Gander, C. Japhet, "Algorithm 932: PANG: software for
 * nonmatching grid projections in 2D and 3D with linear complexity", ACM
 * TOMS 40 (2013); I. E. Sutherland, G. W. Hodgman, "Reentrant polygon
 * clipping", CACM 17 (1974).
 */
#ifndef LAC_PAIRING_H
#define LAC_PAIRING_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"

/* One side of the contact: facets of a mesh (everything borrowed). */
typedef struct lac_pairing_facets
{
  const lac_mesh *mesh;  /* borrowed                                      */
  size_t n;              /* number of facets                              */
  const size_t *cell;    /* borrowed, n: the cell owning facet i          */
  const int *face;       /* borrowed, n: its local face                   */
} lac_pairing_facets;

/* Options; lac_pairing_opts_init sets the defaults shown. */
typedef struct lac_pairing_opts
{
  int degree;        /* exact degree of the rule on each integration cell;
                        0: 5 in 2D (3 Gauss points), 4 in 3D (6 points)   */
  int degree_nonaffine; /* 0: degree + 14.  The degree for the pairs with
                        a quadrangle that is not a parallelogram (trapezoids
                        of a refined hex20 face, unstructured or curved
                        quads): in their charts phi^S or phi^M are not
                        polynomials and no rule is exact.  Taylor patch
                        test, hex20 (t450), error in sigma with degree 4 and
                        degree_nonaffine 4, 14, 16, 18: 3e-4, 2e-11, 5e-13,
                        3e-14.  Cost: 100 points per triangle instead of 6
                        (12 times the pairing time on a mesh of distorted
                        quads, bench_pairing)                             */
  double dist_rel;   /* 1.0: max normal gap, in facet diameters (the
                        larger of the pair) ...                           */
  double dist_abs;   /* 0.0: ... plus this absolute length                */
  double facing;     /* 0.0: a pair needs -n_s.n_m > facing (n at the
                        facet centres); < -1 accepts every orientation    */
  int robust;        /* 0: advancing front; 1: every slave facet tests all
                        master facets the bucket grid puts near it        */
  int allow_empty;   /* 0: no pair at all is an error (LAC_EINVAL);
                        1: an empty pairing is a valid result             */
} lac_pairing_opts;

/* The result.  Points of slave facet s are p = ptr[s] .. ptr[s+1]-1, grouped
 * by pair; pairs of slave facet s are q = pair_ptr[s] .. pair_ptr[s+1]-1,
 * sorted by master index, with points pair_pt[q] .. pair_pt[q+1]-1. */
typedef struct lac_pairing
{
  int dim;               /* space dimension (facets have dim-1)           */
  size_t nslave;         /* size of the slave list                        */
  size_t nmaster;        /* size of the master list                       */

  size_t npoints;
  size_t *ptr;           /* owned, nslave+1                               */
  double *xs;            /* owned, npoints*(dim-1): slave reference coords */
  double *xm;            /* owned, npoints*(dim-1): master reference coords */
  size_t *master;        /* owned, npoints: master facet of the point     */
  double *w;             /* owned, npoints: physical weights, so that
                            int_{T^s cap T^m} f dGamma = sum w_p f(x_p)
                            (reference weight x sub-cell Jacobian x slave
                            surface element)                              */
  double *gap;           /* owned, npoints: normal gap g, X_m = x_s + g n_s */

  double *covered;       /* owned, nslave: sum of w over the facet's points */
  double *measure;       /* owned, nslave: |T^s| (a rule of degree
                            opts.degree + 4 on the whole facet)           */

  size_t npairs;
  size_t *pair_ptr;      /* owned, nslave+1                               */
  size_t *pair_master;   /* owned, npairs                                 */
  double *pair_measure;  /* owned, npairs: |T^s cap T^m| (sum of its w)    */
  size_t *pair_pt;       /* owned, npairs+1: points of pair q             */

  /* statistics of the search (for benchmarks and messages) */
  size_t ntests;         /* (slave, master) intersection tests            */
  size_t nseeds;         /* bucket-grid queries (seeds, completions)      */
  size_t nfail;          /* pairs dropped: a projection did not converge  */
} lac_pairing;

/* construct / destroy */
void lac_pairing_opts_init (lac_pairing_opts *o);
lac_pairing_facets lac_pairing_facets_of (const lac_mesh *m,
                                          const lac_group *g);
int lac_pairing_build (const lac_pairing_facets *slave,
                       const lac_pairing_facets *master,
                       const lac_pairing_opts *opts, lac_pairing **out);
void lac_pairing_free (lac_pairing *P);                /* NULL allowed */

/* query */
double lac_pairing_total (const lac_pairing *P);   /* sum of covered[s] */

/* ---- geometry kernels (lac_pairing_geom.c, lac_pairing_project.c) ---- */

/* Projection onto a face map x = X(xi) (re: a seg/tri/quad face element,
 * sdim = re->dim + 1, xe: its nodes).  With dir != NULL, solve
 *   X(xi) = x + t dir                         (projection along dir)
 * by Newton's method with line search in (xi, t); with dir == NULL, find
 * the closest point, (X(xi) - x).dX/dxi_k = 0 (Gauss-Newton), and return
 * t = (x - X(xi)).n(xi).  xi is the starting point on input.
 * Returns LAC_SUCCESS, LAC_EMAXITER (no convergence, or xi left the
 * neighbourhood |xi| <= 100 of the reference cell), LAC_ESING (dir tangent
 * to the face, or degenerate face); never loops more than 50 iterations. */
int lac_pairing_project (const lac_refelem *re, int sdim, const double *xe,
                         const double *x, const double *dir, double *xi,
                         double *t);

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

#endif /* LAC_PAIRING_H */
