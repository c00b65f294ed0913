/* lac_macromesh_internal.h -- internal: shared by the lac_macromesh*.c files
 *                                                 [LAC Hyp. 1, §4.4, Fig. 2]
 * Not part of the public interface.  lac_macromesh_build (lac_macromesh.c)
 * builds T^M in four steps; two of them have their own file:
 *
 *   lac_macromesh.c         steps 1 and 3 (the slave group, refinement
 *                           rounds) and the public functions;
 *   lac_macromesh_gather.c  step 2: the first macro-elements, 2D segments
 *                           gathered along their chains;
 *   lac_macromesh_nodes.c   step 4: measures and interior nodes.
 */
#ifndef LAC_MACROMESH_INTERNAL_H
#define LAC_MACROMESH_INTERNAL_H

#include "contact/lac_macromesh.h"
#include "base/lac_status.h"

/* Messages from the static helpers carry the public function's name. */
#define MM_ERRMSG(status, ...) \
  lac_error_set ((status), "lac_macromesh_build", __VA_ARGS__)
#define MM_ERROR(status, ...) return MM_ERRMSG ((status), __VA_ARGS__)

#define MAXSUBF 16   /* sub-facets of one macro-element (5 at most here) */
#define MAXPATCH (MAXSUBF * LAC_MAX_FACE_NODES)

enum { KEEP, CUT, GATHER };   /* what a slave facet needs */

/* Macro-elements under construction: T^k has the facets ptr[k]..ptr[k+1]-1;
 * pending[k]: its single (whole) facet still has to be cut. */
typedef struct mlist
{
  size_t n;
  size_t *ptr, *cell;          /* owned */
  int *face;                   /* owned */
  unsigned char *pending;      /* owned */
} mlist;

/* Step 2 (lac_macromesh_gather.c): the macro-elements before refinement,
 * in the order of the group's facets; kind[e] says what facet e needs. */
int lac_macromesh_start (const lac_mesh *m, const lac_group *G,
                         const unsigned char *kind, mlist *L);

/* Step 4 (lac_macromesh_nodes.c): M->meas, inode, phi of every
 * macro-element of L (arrays of L->n entries allocated by the caller). */
int lac_macromesh_finish (const lac_mesh *m, const mlist *L, lac_macro *M);

#endif /* LAC_MACROMESH_INTERNAL_H */
