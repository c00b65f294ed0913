/* lac_run_interference.h -- an interference fit against the chords of its
 *                           surfaces                  [LAC (18); §4.6]
 *
 * Part of stage 4 (assemble).  `[contact] interference = delta` takes
 * delta from every gap of a pair drawn with matching surfaces (chapter
 * 16, section 5): the gaps of the drawing are meant to be zero, the fit
 * is delta.  Meshed, the two sides of a curved interface are polygons
 * (polyhedra) with their vertices on the curve and chords between them,
 * and the chords of the two sides do not match: the mean gap of a
 * macro-element without the interference,
 *
 *   g_i = G_i / |T^m_i cap Gamma_C| + delta                  [LAC (18)]
 *
 * (G_i less delta |T^m_i cap Gamma_C|, lac_contact_set_offset), is the
 * discretization's alone, and adds to the fit or takes from it: the fit
 * the solve sees varies by g_i from macro-element to macro-element, the
 * pressure by about g_i / delta of itself.  A chord of length h on a
 * curve of radius R lies up to h^2 / (8 R) inside it; a quadratic facet
 * follows the curve to about h^4 / R^3.
 *
 * So the run measures, for every pair with delta > 0, over its columns
 * in the reference shape (before the Dirichlet values move into G),
 *
 *   ratio = max_i |g_i| / delta,
 *
 * the largest over the pairs in the summary (`interference_gap`), and
 *   ratio > the pair's interference_tolerance (0.1 by default): an error
 *     naming the pair, the macro-element, where it is, g_i and delta, and
 *     what to do (quadratic cells, refine, or raise the tolerance);
 *   ratio > a tenth of it: a warning in the progress line of the stage.
 */
#ifndef LAC_RUN_INTERFERENCE_H
#define LAC_RUN_INTERFERENCE_H

#include <stddef.h>
#include "contact/lac_contact_set.h"
#include "io/lac_scene.h"

#define LAC_INTERFERENCE_TOLERANCE 0.1  /* interference_tolerance default */

/* What the fits of a run's pairs leave to the discretization. */
typedef struct lac_run_fit
{
  int measured;          /* 1: some pair has an interference             */
  double ratio;          /* max over those pairs of max_i |g_i| / delta  */
  size_t pair;           /* the pair and macro-element of that largest   */
  size_t macro;          /*   ratio (the macro-element in its pair)      */
  double gap;            /* its g_i                                      */
  double x[3];           /* its centroid                                 */
} lac_run_fit;

/* The fits of the pairs of set (the scene's [contact] sections, in
 * order) from their contact data d, made in the reference shape with
 * each pair's interference taken (G_i less delta |T^m_i cap Gamma_C|)
 * and before the Dirichlet values were moved into G.  An error (placed
 * at the pair's section) when a ratio passes its tolerance. */
int lac_run_interference_check (const lac_scene *sc,
                                const lac_contact_set *set,
                                const lac_contact_set_data *d,
                                lac_run_fit *fit);

/* "; warning: ..." when the largest ratio passes a tenth of its pair's
 * tolerance (appended to progress), else nothing. */
void lac_run_interference_warning (const lac_scene *sc,
                                   const lac_run_fit *fit, char *progress,
                                   size_t size);

#endif /* LAC_RUN_INTERFERENCE_H */
