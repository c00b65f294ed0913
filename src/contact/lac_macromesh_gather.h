/* lac_macromesh_gather.h -- the first macro-elements: 2D segments gathered
 *                                                 [LAC §4.4 item 1, Fig. 2]
 *
 * Step 2 of lac_macromesh_build (lac_macromesh.c): one macro-element per
 * slave facet, except for 2D linear segments, which are gathered two by
 * two along their chains (lac_macromesh_gather.c).  What each facet needs
 * was decided in step 1, from its face type.
 */
#ifndef LAC_MACROMESH_GATHER_H
#define LAC_MACROMESH_GATHER_H

#include "fem/lac_mesh.h"
#include "contact/lac_macro_list.h"

/* What a slave facet needs. */
enum
{
  LAC_MACRO_KEEP,     /* it has an interior node: one macro-element       */
  LAC_MACRO_CUT,      /* its cell is to be cut (step 3): one, pending     */
  LAC_MACRO_GATHER    /* a seg2: gathered with its neighbours             */
};

/* The macro-elements before refinement, in the order of the facets of G
 * (a chain of segments where its first facet appears), appended to L
 * (lac_macro_list_init: room for G->n more facets); kind[e] is the
 * LAC_MACRO_* of facet e; corners = 1: chains break where they turn by
 * more than LAC_MESH_CORNER_DEG (the corner rule of fem/lac_mesh.h; 0:
 * they do not).  LAC_ENOMEM. */
int lac_macromesh_start (const lac_mesh *m, const lac_group *G,
                         const unsigned char *kind, int corners,
                         lac_macro_list *L);

#endif /* LAC_MACROMESH_GATHER_H */
