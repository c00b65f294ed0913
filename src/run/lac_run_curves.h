/* lac_run_curves.h -- the loads of a small-strain scene by load curve
 *                                                     [LAC (8), Alg. 1]
 *
 * Part of stages 4 and 5 of a small-strain run with [steps]
 * (run/lac_run_steps.h).  At the load factor t every [load] and
 * [dirichlet] section is its value times its factor f(t): its `curve`, or
 * t (ramped), or 1 (ramp = no) (io/lac_scene_query.h, lac_scene_factor).
 * The sections with the same f are one curve c.  The system is linear in
 * the loads and the Dirichlet values, so that at t
 *
 *   F(t) = sum_c f_c(t) F_c,    b(t) = sum_c f_c(t) b_c,
 *   g_i(t) = f_c(i)(t) g_i      (entry i of the Dirichlet data, of curve
 *                                c(i), g_i its value at f = 1),
 *
 * F_c the loads of the sections of curve c, b_c the right-hand side that
 * the elimination of the fixed dofs (fem/lac_assembly.h,
 * lac_dirichlet_apply) makes of F_c and the values of curve c alone
 * (the others zero).  The b_c are made once, in stage 4, while K still
 * has the columns of the fixed dofs (lac_run_curves_lift), or from the
 * cells (lac_run_curves_digest); a load step only sums them
 * (lac_run_curves_set).  K, C and the pairing do not change; the mean
 * gaps take the new values through the linear model
 * (solve/lac_linear_model.h, lac_linear_model_dirichlet).
 *
 * A dof takes the curve of the section whose value it takes (the last
 * one); two sections that fix one dof with non-zero values on different
 * curves are an error naming both, and so, at a node with a frame
 * (rollers, run/lac_run_roller.h), where the values of the fixed axes mix
 * every condition of the node, are two non-zero conditions on different
 * curves.
 *
 * Ownership: the curves' points are borrowed from the scene, which must
 * outlive the struct; the arrays are owned (lac_run_curves_free).
 */
#ifndef LAC_RUN_CURVES_H
#define LAC_RUN_CURVES_H

#include <stddef.h>
#include "fem/lac_assembly.h"
#include "io/lac_scene.h"
#include "linalg/lac_linalg.h"
#include "run/lac_run_plate.h"

/* f(t) of a section: a curve, or the ramp flag. */
typedef struct lac_run_curve
{
  const double *pt;       /* borrowed, n numbers t0 f0 t1 f1 ..., or NULL */
  int n;
  int ramp;               /* without points: 1: f = t, 0: f = 1          */
} lac_run_curve;

typedef struct lac_run_curves
{
  size_t n;               /* curves                                       */
  lac_run_curve *curve;   /* owned, n                                     */
  size_t *of_load;        /* owned, nload: the curve of each [load]       */
  size_t *of_dirichlet;   /* owned, ndirichlet: of each [dirichlet]       */
  size_t ndof;
  double *F;              /* owned, n x ndof: F_c (rigid plates: P^T F_c) */
  double *b;              /* owned, n x ndof: b_c                         */
  size_t nentry;          /* Dirichlet entries with a curve (the rigid
                             plates' tied dofs come after: value 0)       */
  size_t *of_entry;       /* owned, nentry: the curve of entry i          */
  double *g;              /* owned, nentry: its value at f = 1            */
} lac_run_curves;

/* The curves of the sections of sc, room for F_c and b_c (zero). */
lac_run_curves *lac_run_curves_alloc (const lac_scene *sc, size_t ndof);
void lac_run_curves_free (lac_run_curves *cv);       /* NULL allowed */
/* f_c(t). */
double lac_run_curves_factor (const lac_run_curves *cv, size_t c, double t);
/* The curve of each entry of dir (after the rollers, before the rigid
 * plates) and its value; a message naming both sections when a dof or a
 * node with a frame has non-zero values on two curves. */
int lac_run_curves_entries (const lac_scene *sc, lac_model model,
                            const lac_mesh *m, const lac_dirichlet *dir,
                            lac_run_curves *cv);
/* F_c <- P^T F_c: each tied dof's load to its plate dof, in the order of
 * lac_run_plate_tie. */
void lac_run_curves_tie (lac_run_curves *cv, const lac_run_ties *ties);
/* b_c from K before the elimination (turned to the frames of dir):
 * T^T F_c, less K(:, j) g_j for the fixed dofs j of curve c, and d_j g_j
 * in row j (d_j = K(j, j), 1 if not positive), as lac_dirichlet_apply. */
int lac_run_curves_lift (lac_run_curves *cv, const lac_csc *K,
                         const lac_dirichlet *dir);
/* The same without K (no frames): lac_assembly_digest on the cells. */
int lac_run_curves_digest (lac_run_curves *cv, const lac_mesh *m,
                           const lac_elastic *mat, const lac_dirichlet *dir);
/* The system at the load factor t: F, b (ndof) and the values of dir's
 * entries with a curve. */
void lac_run_curves_set (const lac_run_curves *cv, double t, double *F,
                         double *b, lac_dirichlet *dir);

#endif /* LAC_RUN_CURVES_H */
