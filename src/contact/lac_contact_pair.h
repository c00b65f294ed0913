/* lac_contact_pair.h -- one slave/master pair: from coordinates to its
 *                       contact data, and what it leaves uncovered
 *                                        [LAC §4.6, Def. 1, (16)-(18)]
 *
 * A contact pair is what the pairing and the contact data need: the
 * macro-mesh of the slave surface, the master facets (or a rigid
 * obstacle), the model of the integrals (the 2 pi r weight), epsilon of
 * Definition 1, the method (LAC or node-to-segment) and the options of
 * the pairing.  lac_contact_pair_build pairs and assembles it with the
 * nodes at given coordinates: the reference ones for small strain, the
 * current ones at every Newton iteration of large deformations.
 *
 * No silent penetration.  The pairing looks for master facets within
 * about one slave facet of every slave facet (lac_pairing.h: dist_rel
 * facet diameters plus dist_abs), and Definition 1 drops the
 * macro-elements too little covered: both leave macro-elements without a
 * multiplier, which nothing stops from passing into the master.
 * lac_contact_pair_uncovered pairs exactly those macro-elements again,
 * with the nodes where the solution put them, and measures how deep each
 * one is inside the master (its mean normal gap over its paired part).
 * The caller decides (solve/lac_newton.h): pair again with a longer reach
 * (`widened`, kept apart from the pair's own reach popts.dist_abs), or
 * stop with an error naming the macro-element.
 *
 * An interference fit (offset = delta, a shrink fit drawn with matching
 * surfaces) takes delta from every gap, in the contact data
 * (lac_contact_set_offset) and in the depth of the uncovered
 * macro-elements alike.
 *
 * Ownership: everything in lac_contact_pair is borrowed.
 */
#ifndef LAC_CONTACT_PAIR_H
#define LAC_CONTACT_PAIR_H

#include <stddef.h>
#include "contact/lac_contact.h"
#include "contact/lac_obstacle.h"

typedef struct lac_contact_pair
{
  const lac_mesh *mesh;             /* slave and master, reference nodes   */
  lac_model model;                  /* the weight of the integrals         */
  const lac_macro *M;               /* macro-mesh of the slave surface     */
  const lac_pairing_facets *master; /* master facets of mesh, or NULL      */
  const lac_obstacle *obstacle;     /* the rigid master when master = NULL */
  double epsilon;                   /* [LAC Def. 1]                        */
  int nts;                          /* 1: node-to-segment (lac_contact.h)  */
  lac_pairing_opts popts;           /* of lac_pairing_build: the pair's own
                                       reach is popts.dist_abs             */
  double offset;                    /* the interference delta: the gaps are
                                       g0 - delta (lac_contact_set_offset) */
  double widened;                   /* the reach a loop added to the pair's
                                       own (solve/lac_newton.h: widen): it
                                       pairs within popts.dist_abs +
                                       widened; 0 until a loop widens     */
  int tangential;                   /* 1: the tangential columns of friction
                                       too (lac_tangential.h)              */
  double friction;                  /* and the friction coefficient mu     */
} lac_contact_pair;

/* The deepest penetration of a macro-element without a multiplier. */
typedef struct lac_contact_uncovered
{
  double depth;          /* its mean penetration (a length; <= 0: none)   */
  double h;              /* its size, a length                            */
  size_t macro;          /* which macro-element                           */
  double x[3];           /* the centroid of its paired part               */
  int paired;            /* 1: it was paired, not admissible [LAC Def. 1];
                            0: out of the pairing's reach                 */
  size_t count;          /* macro-elements deeper than the test's limit   */
} lac_contact_uncovered;

/* Pairing and contact data with the nodes at x (mesh->nnodes * dim; NULL:
 * the mesh's), the gaps less p->offset.  No admissible macro-element is not an error: *c = NULL
 * (no constraint).  *P and *c are the caller's to free. */
int lac_contact_pair_build (const lac_contact_pair *p, const double *x,
                            lac_pairing **P, lac_contact **c);
/* The two halves of lac_contact_pair_build: the pairing alone, then the
 * contact data of a pairing made at the same x. */
int lac_contact_pair_pairing (const lac_contact_pair *p, const double *x,
                              lac_pairing **P);
int lac_contact_pair_contact (const lac_contact_pair *p, const double *x,
                              const lac_pairing *P, lac_contact **c);

/* Whether the pair's surfaces face each other anywhere, however far
 * apart (*facing = 1): up to 64 slave facets spread over its surface,
 * paired with the nodes at x (NULL: the mesh's) within the size of the
 * mesh.  Tells a pair whose surfaces start apart from one whose groups
 * can never touch (contact/lac_contact_set.h). */
int lac_contact_pair_facing (const lac_contact_pair *p, const double *x,
                             int *facing);

/* The macro-elements of p->M that have no column in c (all if c is NULL),
 * paired again with the nodes at x and `reach` added to the pairing
 * distance (the nodes moved by at most reach / 2 since c was made: a
 * penetration is at most that deep): u->count of them penetrate the
 * master by more than tol times their size, u->depth the deepest.
 * Node-to-segment: the slave nodes without a column, projected onto the
 * master at x (their slots do not depend on x; the size of a node is its
 * share of the slave surface). */
int lac_contact_pair_uncovered (const lac_contact_pair *p, const double *x,
                                const lac_contact *c, double reach,
                                double tol, lac_contact_uncovered *u);

/* The size of macro-element m as a length: |T^m| in 2D, sqrt(|T^m|) in
 * 3D (no axisymmetric weight). */
double lac_contact_pair_h (const lac_contact_pair *p, size_t m);

#endif /* LAC_CONTACT_PAIR_H */
