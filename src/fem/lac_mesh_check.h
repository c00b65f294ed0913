/* lac_mesh_check.h -- a mesh that can be trusted             [LAC §2, §3.1]
 *
 * A mesh read from a file may be wrong in ways that no later stage
 * notices and that change the answer without a word: a cell listed twice
 * under another tag doubles its stiffness, a face shared by three cells or
 * two cells folded over their common face make the bodies overlap.  Two
 * checks, one line naming the cells when they fail:
 *
 *   lac_mesh_validate        the arrays fit together: every cell has a
 *                            known type of the mesh's dimension and the
 *                            node count of that type, every index is in
 *                            range, every coordinate finite and at most
 *                            LAC_MESH_COORD_MAX, every group consistent;
 *                            any mesh that crossed a process or a file
 *                            passes here before anything reads it;
 *   lac_mesh_check_topology  the cells form a mesh: no cell flat next to its
 *                            size (measure <= LAC_MESH_FLAT diameter^d,
 *                            from its straight-sided faces), no two cells with the
 *                            same vertices, no face of more than two
 *                            cells, and the two cells of an interior face
 *                            on opposite sides of it (else they overlap:
 *                            the volume of the cells would exceed the
 *                            volume the boundary encloses, by the
 *                            divergence theorem).
 *
 * Nodes that no cell uses are not an error here (the gmsh reader drops
 * them and counts them in lac_mesh.ndropped, see lac_mesh.h).
 */
#ifndef LAC_MESH_CHECK_H
#define LAC_MESH_CHECK_H

#include "fem/lac_mesh.h"

/* Coordinates beyond this are refused: products of them with a modulus or
 * a load would overflow long before a result. */
#define LAC_MESH_COORD_MAX 1e30

/* A cell whose measure is at most this times its diameter^d is flat: a
 * sliver of aspect ratio 10^6 has about 10^-6 (2D) or 10^-12 (3D). */
#define LAC_MESH_FLAT 1e-14

/* LAC_SUCCESS, or LAC_EINVAL with a message naming the cell, node or
 * group (tags as in the file). */
int lac_mesh_validate (const lac_mesh *m);

/* LAC_SUCCESS, LAC_EINVAL (a message naming the cells) or LAC_ENOMEM.
 * m must have passed lac_mesh_validate. */
int lac_mesh_check_topology (const lac_mesh *m);

/* The flattest cell of m (validated): the one of smallest thickness /
 * diameter, its thickness the measure over diameter^(d-1) (the height of
 * a sliver), from its straight-sided faces as above.  Returns that ratio
 * (1 for a mesh without cells), the cell in *cell, its thickness and
 * diameter in *thick and *diam.  A ratio a makes the stiffness of the
 * cell's body ill-conditioned like 1/a^2. */
double lac_mesh_flattest (const lac_mesh *m, size_t *cell, double *thick,
                          double *diam);

#endif /* LAC_MESH_CHECK_H */
