/* lac_pairing_types.h -- the input of the pairing: facet lists, options
 *                                                                 [LAC §4.6]
 *
 * Header only.  The two types that the driver (lac_pairing.h) and the
 * search (lac_pairing_search.h) both read: one side of the contact as a
 * list of facets of a mesh, and the options of lac_pairing_build (their
 * defaults are set by lac_pairing_opts_init, lac_pairing.h).
 */
#ifndef LAC_PAIRING_TYPES_H
#define LAC_PAIRING_TYPES_H

#include <stddef.h>
#include "fem/lac_mesh.h"

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
  int allow_apart;   /* 1: no pair because nothing lies within the reach
                        (no facet pair faced away or failed its
                        projection) is a valid, empty result: the
                        surfaces start apart (one pair of several,
                        contact/lac_contact_set.h)                       */
} lac_pairing_opts;

#endif /* LAC_PAIRING_TYPES_H */
