/* lac_run_cause.h -- a failed solve said with its cause      [LAC §5, (10)]
 *
 * A solve that fails reports what the solver saw: a pivot below its
 * threshold, a loop that did not stop, a body the active multipliers do
 * not hold.  Some inputs cause these failures in ways the solver cannot
 * see, and its words then point at another cause (a Dirichlet condition,
 * the inf-sup condition, a load, the iteration limit).  After a failed
 * solve stage, lac_run_cause looks for three of them and, when it finds
 * one, puts it in front of the solver's words:
 *
 *   a layer thin to rounding  a singular system (not a body the contact
 *        leaves free) on a mesh with cells more than 1e5 times wider than
 *        thick: the stiffness of their body is ill-conditioned like the
 *        square of that ratio, singular to rounding from about 1e7 (a
 *        1e-6 mm layer between 50 mm blocks); the body and the cell are
 *        named;
 *   an interference far beyond its macro-elements  (small strain) the
 *        loop stopped at its iteration limit with its statuses settled: its
 *        stopping test asks the mean gaps of the active macro-elements,
 *        |d_i| / (|T_i| h_i), to be below the tolerance, and the gaps carry
 *        the rounding of displacements of the size of delta, about
 *        1e-16 delta / h, above 1e-10 once delta passes some 1e6 facet
 *        sizes; the pair and its delta are named;
 *   an interference that separates the surfaces  (large deformation) a
 *        pair with delta > 0 left without any facet pair: the bodies move
 *        apart by t delta, and beyond about one facet the pairing no longer
 *        reaches the master.
 *
 * Everything is borrowed; nw (small strain with contact) and nl (large
 * deformation) may be NULL.
 */
#ifndef LAC_RUN_CAUSE_H
#define LAC_RUN_CAUSE_H

#include "fem/lac_mesh.h"
#include "io/lac_scene.h"
#include "run/lac_run_nonlinear.h"
#include "run/lac_run_setup.h"
#include "solve/lac_newton.h"

/* Cells this many times wider than thick are named as the cause of a
 * singular system. */
#define LAC_RUN_THIN 1e5

/* The failed status of the solve stage, its stored message replaced by
 * the cause and the solver's words when one of the above is found. */
int lac_run_cause (const lac_scene *sc, const lac_mesh *m,
                   const lac_run_setup *setup, const lac_newton *nw,
                   const lac_run_nl *nl, int status);

#endif /* LAC_RUN_CAUSE_H */
