/* lac_run_sliding.h -- the small sliding of a linear run, checked
 *                                          [LAC §4.6, (16)-(18), Alg. 1]
 *
 * Part of stage 6 (post) of a small-strain run with contact.  The pairing
 * is made once, in the reference shape (chapter 04): every point of a
 * slave macro-element is paired with the master point along its normal,
 * and C and G keep those pairs for the whole solve, d(U) = G - C^T U.
 * That is the small-sliding assumption.  Where the surfaces are flat a
 * slave point that slides along the master keeps its gap (two columns
 * pressed apart sideways by 0.74 mm, one and a half macro-elements, keep
 * their force to 3e-4); where
 * they turn, the slid points are no longer opposite each other, and the
 * normals of the reference shape carry what they should not (two equal
 * cylinders pressed by 0.02 mm and pushed sideways slide by 0.27 mm and
 * their normal force grows by 3 %, by 0.57 mm and it grows by 44 %).  The
 * size of the slide alone does not tell the two apart; the gaps of the
 * deformed shape do.
 *
 * So the pairs are made again on the deformed shape x = X + u (the
 * large-deformation model does that at every iteration, chapter 10), and
 * for every active macro-element i the mean gap there, g_i(x), is set
 * against the small-strain one, d_i / |T^m_i cap Gamma_C|:
 *
 *   e_i = | g_i(x) - d_i / |T^m_i cap Gamma_C| |
 *
 * (about the slide times the angle the surfaces turn over it; zero on
 * flat surfaces).  An error e in a gap moves the contact as an imposed
 * displacement e would, and what it is to be compared with is the
 * displacement the pressure comes from: v, the largest displacement
 * along the macro-element's mean normal of a node of the slave's and the
 * master's bodies (for the worst macro-element of the pair, the one of
 * largest e_i).  r = e / v above the pair's sliding_tolerance (0.1 by
 * default) is an error naming the pair, that macro-element, where it is,
 * how far it slid (the mean tangential part of u_S - u_M over its points,
 * a rigid obstacle's u_M = 0) and its two gaps.  The scenes of the book
 * stay below 0.026 (the five blocks, rotated by their loads: 0.009 to
 * 0.025 over the element types and levels 0-2; Hertz contacts below
 * 0.003, patch tests at rounding); the two cylinders reach 0.024, 0.077,
 * 0.69, 1.3 and 2.0 for sideways pushes of 1, 3, 10, 30 and 100 N/mm
 * (normal force 0.00 %, 0.01 %, 3 %, 44 %, 157 % above the press alone).
 *
 * A slide can also carry slave macro-elements past the end of their
 * master, where the deformed shape pairs them with nothing: the part of
 * the pair's active contact that faces no master there (a macro-element
 * i loses (1 - |T^m_i cap Gamma_C|(x) / |T^m_i cap Gamma_C|) of its
 * contact, all of it when it has no column at all), above the same
 * tolerance, is an error too, naming the macro-element that lost the
 * most (a block slid 3 off the end of another was pressed on nothing,
 * exit status 0: tests/bad/slide-off.scene).  A slide of the size of the
 * displacements loses a part of that order at the edges, which the
 * small-strain model neglects (the friction patch tests: 0.025).  The
 * deformed shape is paired within delta more than the pair's reach (an
 * interference leaves its surfaces about delta apart).  Node-to-segment
 * is checked the same way, its slots being the slave nodes (the two
 * cylinders with method = nts: 1.39; its normal force was 45 % high).
 * Large-deformation runs pair the deformed shape and are not checked.
 */
#ifndef LAC_RUN_SLIDING_H
#define LAC_RUN_SLIDING_H

#include "fem/lac_rigid.h"
#include "io/lac_scene.h"
#include "run/lac_run_setup.h"
#include "solve/lac_newton.h"

#define LAC_SLIDING_TOLERANCE 0.1   /* sliding_tolerance by default */

/* The largest r and off of setup's pairs (their pairings and contact
 * data setup->data, the statuses and mean gaps of nw), u the displacement
 * in the axes on the mesh m; an error (placed at the pair's section)
 * above its tolerance.  *ratio: that largest r or off (0 without
 * contact). */
int lac_run_sliding_check (const lac_scene *sc, const lac_mesh *m,
                           const lac_bodies *B, const lac_run_setup *setup,
                           const lac_newton *nw, const double *u,
                           double *ratio);

#endif /* LAC_RUN_SLIDING_H */
