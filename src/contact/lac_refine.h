/* lac_refine.h -- one round of local refinement of the first cell layer
 *                                             [LAC §4.4, Fig. 2, Remark 3]
 *
 * A slave face without an interior node cannot be a macro-element [LAC
 * Hyp. 1]: the cell that owns it is cut so that the face gets interior
 * nodes while every other face of the cell stays whole, and the mesh stays
 * conforming.  The templates (cones from the face centre, six hexahedra)
 * are drawn and counted in lac_refine.c; the options below choose them.
 * lac_macromesh_build (lac_macromesh.h) cuts in rounds, one face per cell
 * and round, with lac_refine_cut.
 *
 * Ownership: lac_refine_cut returns a new mesh (lac_mesh_free) and a
 * lac_refine_map that owns its arrays (lac_refine_map_free); the input
 * mesh is borrowed and left unchanged.
 *
 * References: code_aster's CREA_MAILLAGE / DECOUPE_LAC, as summarized in
 * chapter 03.
 */
#ifndef LAC_REFINE_H
#define LAC_REFINE_H

#include <stddef.h>
#include "fem/lac_mesh.h"

/* How to cut a hexahedron on a quadrangular slave face. */
enum
{
  LAC_MACRO_HEX_DEFAULT = 0,  /* hex8 -> 5 pyr5, hex20 -> 6 hex20          */
  LAC_MACRO_HEX_PYRAMIDS,     /* hex8 -> 5 pyr5; hex20: error (no pyr13)  */
  LAC_MACRO_HEX_SIX           /* hex8 -> 6 hex8, hex20 -> 6 hex20           */
};

/* The template choices (of lac_macromesh_build too). */
typedef struct lac_macro_opts
{
  int hex_cut;   /* LAC_MACRO_HEX_*                                        */
  int cut_2d;    /* 2D linear: 0 gather segments (default), the chains
                    broken at corners (lac_macromesh_gather.h); 1 cut the
                    cell of every seg2 facet (tri3 -> 2 tri3, quad4 -> 3
                    tri3); 2 gather across corners too                    */
} lac_macro_opts;

/* The sub-cells and face pieces of one refinement round.  Old cell c became
 * new cells cptr[c] .. cptr[c+1]-1; face g of old cell c became the pieces
 * (fcell[j], fface[j]) for j from fptr[q] to fptr[q+1]-1, q = c*LAC_MAX_FACES
 * + g (one piece for a face that was not cut, none for g >= nfaces). */
typedef struct lac_refine_map
{
  size_t ncells;   /* cells before the round                               */
  size_t *cptr;    /* owned, ncells+1                                       */
  size_t *fptr;    /* owned, ncells*LAC_MAX_FACES+1                         */
  size_t *fcell;   /* owned, fptr[ncells*LAC_MAX_FACES]                     */
  int *fface;      /* owned, likewise                                       */
} lac_refine_map;

/* One refinement round: cut face cut[c] of every cell with cut[c] >= 0
 * with the templates of lac_refine.c; returns the new mesh (all groups
 * remapped) and the map old -> new.  opts may be NULL (defaults).
 * LAC_EINVAL (bad face, type that cannot be cut), LAC_ENOMEM. */
int lac_refine_cut (const lac_mesh *m, const int *cut,
                    const lac_macro_opts *opts, lac_mesh **out,
                    lac_refine_map **map);
void lac_refine_map_free (lac_refine_map *map);  /* NULL allowed */

#endif /* LAC_REFINE_H */
