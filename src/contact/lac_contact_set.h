/* lac_contact_set.h -- several contact pairs as one contact problem
 *                                  [LAC §4.3, §4.6, Def. 1, (16)-(18)]
 *
 * A scene may press several pairs of surfaces together: three stacked
 * blocks (two interfaces), a body slave in one pair and master in
 * another, a body held between two others.  Each pair is a
 * lac_contact_pair (its own slave macro-mesh, master or obstacle,
 * epsilon, method, pairing options); the set puts them side by side:
 *
 *   slots     the macro-elements of pair p are the slots offset[p] ..
 *             offset[p+1] - 1 of the multipliers of the loop
 *             (solve/lac_contact_model.h): one index space for all pairs;
 *   columns   the contact data of every pair at given coordinates
 *             (lac_contact_set_build: pairing, admissibility, C, G), and
 *             their concatenation `all`, a lac_contact like the one of a
 *             single pair whose columns are those of pair 0, then pair 1,
 *             ..., with macro[i] the slot of column i:
 *                 C = [C_0  C_1  ...],   G = [G_0; G_1; ...];
 *             a node on the surfaces of two pairs (a crosspoint, where two
 *             contact faces of one body meet) simply has rows in the
 *             columns of both; with one pair, `all` is that pair's data;
 *   uncovered the macro-elements without a multiplier that penetrate, the
 *             deepest over all pairs (contact/lac_contact_pair.h).
 * The macro-meshes of the slave surfaces must have been built in one
 * pass on the mesh the pairs share (lac_macromesh_build_set), so that
 * their cell indices are all valid.
 *
 * The comparison method node-to-segment (its slots are the slave nodes,
 * not macro-elements) is a set of one pair only.
 *
 * Ownership: lac_contact_set borrows the pairs (they must outlive it) and
 * owns its offsets; lac_contact_set_data owns the pairings, the contact
 * data and their concatenation (lac_contact_set_data_clear).
 */
#ifndef LAC_CONTACT_SET_H
#define LAC_CONTACT_SET_H

#include <stddef.h>
#include "contact/lac_contact_pair.h"

typedef struct lac_contact_set
{
  size_t n;                  /* pairs                                     */
  lac_contact_pair *pair;    /* borrowed, n (widening changes popts)      */
  size_t *offset;            /* owned, n + 1: the slots of pair p are
                                offset[p] .. offset[p+1] - 1            */
} lac_contact_set;

/* The contact data of a set at some coordinates. */
typedef struct lac_contact_set_data
{
  size_t n;                  /* pairs (0: nothing made yet)               */
  lac_pairing **P;           /* owned, n: the pairing of pair p           */
  lac_contact **c;           /* owned, n: its contact data (NULL: none)   */
  lac_contact *all;          /* every column, slots as macro-elements
                                (NULL: no column at all); owned, except
                                when n == 1: then it is c[0]             */
  size_t *col;               /* owned, n + 1: the columns of pair p in all
                                are col[p] .. col[p+1] - 1               */
  size_t failed;             /* after an error: the pair that failed      */
} lac_contact_set_data;

/* construct / destroy */

/* The set of the n pairs (n >= 1).  LAC_EINVAL (a pair without a
 * macro-mesh, node-to-segment among several pairs), LAC_ENOMEM. */
int lac_contact_set_init (lac_contact_set *s, lac_contact_pair *pair,
                          size_t n);
void lac_contact_set_clear (lac_contact_set *s);
void lac_contact_set_data_clear (lac_contact_set_data *d);

/* compute */

/* The pairings of every pair with the nodes at x (NULL: the mesh's),
 * into d (whatever it held is freed first).  With several pairs, a pair
 * that has nothing within its reach is paired to nothing (P->npairs = 0,
 * no column) when its surfaces face each other farther away
 * (lac_contact_pair_facing) and some other pair has something in reach:
 * its surfaces start apart, and the loop pairs it again when the
 * solution closes the gap, as it does for the far part of one pair's
 * surface.  Otherwise (every pair apart, surfaces that never face) the
 * error of its pairing. */
int lac_contact_set_pairing (const lac_contact_set *s, const double *x,
                             lac_contact_set_data *d);
/* The contact data of every pair from the pairings of d (made at the same
 * x), and their concatenation d->all. */
int lac_contact_set_assemble (const lac_contact_set *s, const double *x,
                              lac_contact_set_data *d);
/* Both. */
int lac_contact_set_build (const lac_contact_set *s, const double *x,
                           lac_contact_set_data *d);

/* The macro-elements without a column in d that penetrate their master
 * at x by more than tol times their size (lac_contact_pair_uncovered for
 * each pair; u->macro is the slot, u->count the sum over the pairs). */
int lac_contact_set_uncovered (const lac_contact_set *s, const double *x,
                               const lac_contact_set_data *d, double reach,
                               double tol, lac_contact_uncovered *u);

/* query */

size_t lac_contact_set_nslot (const lac_contact_set *s);
/* The pair of a slot (n for a slot out of range). */
size_t lac_contact_set_pair_of (const lac_contact_set *s, size_t slot);
/* The pairing points dropped by the projections over all pairs, and the
 * slave measure they covered. */
size_t lac_contact_set_dropped (const lac_contact_set_data *d, double *lost);

#endif /* LAC_CONTACT_SET_H */
