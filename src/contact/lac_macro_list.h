/* lac_macro_list.h -- the macro-elements of T^M under construction
 *                                                      [LAC Hyp. 1, §4.4]
 *
 * lac_macromesh_build (lac_macromesh.c) builds T^M in four steps, and this
 * list is what they pass on: step 2 (lac_macromesh_gather.h) starts it,
 * step 3 (the refinement rounds) remaps it through each round's map, step
 * 4 (lac_macromesh_nodes.h) reads it, and the driver moves its facet lists
 * into the lac_macro it returns.  Same layout as lac_macro: T^k has the
 * facets (cell[j], face[j]) for j = ptr[k] .. ptr[k+1]-1.
 *
 * Ownership: the struct is the caller's (zeroed or on the stack); its
 * arrays are allocated by lac_macro_list_init and freed by
 * lac_macro_list_free.
 */
#ifndef LAC_MACRO_LIST_H
#define LAC_MACRO_LIST_H

#include <stddef.h>
#include "base/lac_status.h"
#include "fem/lac_mesh.h"
#include "contact/lac_refine.h"

/* The steps are parts of lac_macromesh_build: their messages carry its
 * name. */
#define LAC_MACRO_ERRMSG(status, ...) \
  lac_error_set ((status), "lac_macromesh_build", __VA_ARGS__)
#define LAC_MACRO_ERROR(status, ...) \
  return LAC_MACRO_ERRMSG ((status), __VA_ARGS__)

/* Sub-facets of one macro-element (5 at most here) and their nodes. */
#define LAC_MACRO_MAXSUBF 16
#define LAC_MACRO_MAXPATCH (LAC_MACRO_MAXSUBF * LAC_MAX_FACE_NODES)

/* T^k has the facets ptr[k]..ptr[k+1]-1; pending[k]: its single (whole)
 * facet still has to be cut. */
typedef struct lac_macro_list
{
  size_t n;
  size_t *ptr, *cell;          /* owned */
  int *face;                   /* owned */
  unsigned char *pending;      /* owned */
} lac_macro_list;

/* construct / destroy */

/* An empty list (n = 0) with room for nfacets facets, one macro-element
 * each at most.  LAC_ENOMEM (L is then freed). */
int lac_macro_list_init (lac_macro_list *L, size_t nfacets);
void lac_macro_list_free (lac_macro_list *L);   /* L zeroed; arrays NULL ok */

/* modify */

/* Append the macro-element made of the facets e[0..n-1] of group G. */
void lac_macro_list_push (lac_macro_list *L, const lac_group *G,
                          const size_t *e, size_t n, int pending);

/* The facet lists through the map of one refinement round: each facet is
 * replaced by its pieces.  LAC_ENOMEM (L unchanged). */
int lac_macro_list_remap (lac_macro_list *L, const lac_refine_map *map);

#endif /* LAC_MACRO_LIST_H */
