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
 * Files.  lac_pairing.c: the driver and the result (this header);
 * lac_pairing_search.[ch]: which pairs overlap (pass 1);
 * lac_pairing_geom.[ch]: the geometry of one pair (chart, overlap,
 * points); lac_pairing_project.[ch]: the projection onto a face map;
 * lac_pairing_types.h: the facet lists and options that the driver and
 * the search share.
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
#include "contact/lac_pairing_types.h"

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
  double *normal;        /* owned or NULL, npoints*dim: the direction of
                            the constraint when it is not n_s (a rigid
                            obstacle, lac_obstacle.h: nu = -n^O, and g the
                            signed distance); NULL: n_s everywhere        */

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
  double *lost;          /* owned, nslave: the part of each slave facet
                            that those pairs covered (a measure, without
                            the axisymmetric weight); the contact data
                            miss it                                       */
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

#endif /* LAC_PAIRING_H */
