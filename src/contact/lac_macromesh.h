/* lac_macromesh.h -- the macro-mesh T^M of the slave contact boundary
 *                                                 [LAC Hyp. 1, §4.4, Fig. 2]
 *
 * The LAC method needs a macro-mesh T^M of the slave contact boundary whose
 * macro-elements T^m are unions of trace facets, each owning (at least) one
 * node x_{m*+1} whose trace basis function is supported inside T^m
 * [LAC Hyp. 1]; the contact condition is imposed on the integral over T^m
 * and the one multiplier of T^m lives on that node [LAC Def. 1, Remark 1].
 * This module builds T^M from a facet group of a mesh, refining the first
 * layer of cells where the trace mesh has no interior node [LAC §4.4]:
 *
 *   slave cell (facet)   what is done                   T^m; interior node
 *   tri3, quad4 (seg2)   gather 2 neighbouring segments 2 (or 3) segments;
 *                        (an odd chain ends with one    the shared node(s)
 *                        macro of 3; chains break at
 *                        corners; a lone segment:
 *                        its cell is cut: 2 / 3 tri3)
 *   tri6, quad8, quad9   nothing                        the segment; mid node
 *     (seg3)
 *   hex27 (quad9)        nothing                        the face; centre
 *   tet4 (tri3)          cones from the face centre c   3 tri3; c
 *                        over the other faces: 3 tet4
 *   hex8 (quad4)         cones: 5 pyr5 (default)        4 tri3; c
 *   pyr5 (quad4, tri3)   cones: 4 tet4 / pyr5 + 3 tet4  4 / 3 tri3; c
 *   tet10 (tri6)         cones, quadratic: 3 tet10      3 tri6; a c-vertex
 *                                                       midpoint
 *   hex20 (quad8)        six hexahedra: 6 hex20         5 quad8; see below
 *   hex8, option SIX     six hexahedra: 6 hex8          5 quad4; see below
 *
 * (drawings and counts in lac_refine.c).  Only the cell owning a slave facet
 * is cut; all new nodes lie inside that cell or inside the slave facet (none
 * on an edge or face shared with a neighbour), so untouched neighbours stay
 * conforming; new nodes are placed through the parent cell's isoparametric
 * map, so curved faces stay curved.  A cell owning several slave facets is
 * cut in rounds, one facet per cell and round, the mesh being rebuilt in
 * between (as code_aster's DECOUPE_LAC does).
 *
 * An interior node of T^m is a node of its sub-facets that lies on no
 * boundary edge of T^m (no end, in 2D) and on no other macro-element, so
 * that its trace basis function is supported in T^m.  When there are
 * several [LAC Remark 1] (tet10: 4, hex20: 12, hex8 SIX: 4, a gathered
 * triple: 2), the designated one, inode[m], is the one whose trace basis
 * function has the largest integral over T^m; ties go to the lowest node
 * index; the others are handled as standard nodes.  (A tri6 vertex function
 * has zero mean and a quad8 corner function a negative one, so the face
 * centre of a tet10 and the corners of the hex20 central square are never
 * chosen.)  Means phi/meas of the designated node on flat, undistorted
 * faces: seg2 pair 1/2, gathered triple 1/3, seg3 2/3, tri3 fan 1/3, tri6
 * split 2/9, quad9 4/9, hex8 SIX 7/48, hex20 SIX 5/36; a fully covered
 * T^m is admissible for any epsilon below its mean [LAC Def. 1].
 *
 * Conventions: macro-element m has the sub-facets (cell[j], face[j]) for
 * j = ptr[m] .. ptr[m+1]-1 of the returned mesh (same layout as a facet
 * group; lac_mesh_facet_nodes gives their nodes, oriented outward).  In 3D
 * and for 2D quadratic meshes macro-element m comes from facet m of the
 * slave group; for gathered 2D segments the macro-elements follow the
 * chains.  The refined
 * mesh is an ordinary lac_mesh: old nodes keep their indices, new nodes are
 * appended (node_tag continues after the largest tag); a cut cell is
 * replaced, in place, by its sub-cells (same cell_tag and body); every group
 * is remapped: cell groups to sub-cells, facet groups (the slave group, a
 * symmetry plane sharing an edge with it, ...) to the pieces of their faces,
 * node groups are kept.  The slave group of the new mesh lists the
 * sub-facets.
 *
 * Corners.  A macro-element never straddles an edge or a corner of the
 * slave surface, where its normal jumps: in 3D a macro-element is one
 * facet of the slave group, cut; in 2D the chains of segments break where
 * the curve turns by more than LAC_MESH_CORNER_DEG
 * (fem/lac_mesh.h, lac_macromesh_gather.c), and a piece of one segment has its cell cut.
 *
 * Several groups.  lac_macromesh_build_set builds the macro-meshes of n
 * slave groups (the slave surfaces of n contact pairs) in one pass over
 * the mesh: every index it returns is valid for the one mesh it returns
 * (building them one after the other would cut cells under the facet
 * lists of the earlier ones).  A facet in two groups is an error.
 *
 * Ownership: lac_macromesh_build replaces *mesh by the refined mesh (and
 * frees the old one) only on success; the lac_macro it returns owns all its
 * arrays and is freed with lac_macromesh_free.  It refers to the mesh by
 * cell and node indices only, so it is valid for the mesh returned with it.
 *
 * Files.  lac_macromesh.c: the driver (steps 1 and 3: the slave group, the
 * refinement rounds) and this header; lac_macromesh_gather.[ch]: step 2,
 * the first macro-elements (2D segments gathered along their chains);
 * lac_refine.[ch]: one refinement round, the templates and their options
 * (lac_macro_opts); lac_macromesh_nodes.[ch]: step 4, measures and interior
 * nodes; lac_macro_list.[ch]: the macro-elements under construction, which
 * the steps pass on.
 *
 * References: M. Abbas, G. Drouet, P. Hild, The Local Average Contact (LAC)
 * method, 2018 (Hypothesis 1, §4.4); code_aster's CREA_MAILLAGE /
 * DECOUPE_LAC, as summarized in chapter 03, for
 * the tet4, tet10 and hex8 templates and the rounds.
 */
#ifndef LAC_MACROMESH_H
#define LAC_MACROMESH_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "contact/lac_refine.h"

typedef struct lac_macro
{
  size_t n;        /* number of macro-elements T^m                         */
  size_t *ptr;     /* owned, n+1: T^m has sub-facets ptr[m]..ptr[m+1]-1 */
  size_t *cell;    /* owned, ptr[n]: cell of sub-facet j                    */
  int *face;       /* owned, ptr[n]: its local face                         */
  size_t *inode;   /* owned, n: the designated interior node x_{m*+1}
                      [LAC Hyp. 1, Remark 1]                               */
  double *meas;    /* owned, n: |T^m|                                       */
  double *phi;     /* owned, n: int_{T^m} phi_{inode}  (the mean is
                      phi/meas: 1/2 seg2, 2/3 seg3, 1/3 tri3, 2/9 tri6 ...) */
  size_t ncut;     /* cells cut (all rounds)                                */
  size_t nnew;     /* nodes added                                           */
  int nrounds;     /* refinement rounds (0: nothing refined)                */
} lac_macro;

/* construct / destroy */

/* Build T^M on facet group `slave` of *mesh, refining *mesh where needed
 * [LAC Hyp. 1, §4.4].  opts may be NULL (defaults).  On success *mesh is the
 * (possibly new) mesh and *out the macro-mesh; on failure both are
 * unchanged / NULL and the message names the group, cell or type at fault:
 * LAC_EINVAL (no such group, not a facet group, empty, facet listed twice,
 * interior facet, type that cannot be refined), LAC_ENOMEM. */
int lac_macromesh_build (lac_mesh **mesh, const char *slave,
                         const lac_macro_opts *opts, lac_macro **out);
/* The same for n slave groups at once: out[g] on slave[g] with the
 * options opts[g] (opts NULL: the defaults); a facet in two groups is
 * LAC_EINVAL.  On failure every out[g] is NULL.  ncut of out[g] counts
 * the cells cut for its group, nnew and nrounds those of the pass. */
int lac_macromesh_build_set (lac_mesh **mesh, size_t n,
                             const char *const *slave,
                             const lac_macro_opts *opts, lac_macro **out);
void lac_macromesh_free (lac_macro *M);          /* NULL allowed */

/* The raw trace as "macro-mesh": one element per facet of `slave`, no
 * gathering, no refinement (P0 multipliers on the slave trace, [LAC §4.2]:
 * for linear elements they violate Hypothesis 1; for comparisons only).
 * inode[m] = (size_t) -1 where the facet has no interior node, meas and
 * phi are left 0 (lac_admissibility computes the measures). */
int lac_macromesh_trace (const lac_mesh *mesh, const char *slave,
                         lac_macro **out);

/* query */

/* All interior nodes of T^m (nodes of its sub-facets not on its boundary
 * edges), sorted; writes at most nmax of them, returns how many there are
 * (0 also for a bad m). */
size_t lac_macromesh_interior (const lac_mesh *mesh, const lac_macro *M,
                               size_t m, size_t *nodes, size_t nmax);

#endif /* LAC_MACROMESH_H */
