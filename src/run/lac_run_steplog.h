/* lac_run_steplog.h -- the records of the load steps of a run
 *                                                    [LAC §4.5, Alg. 1]
 *
 * Part of stage 5 of a run with [steps]: large deformation
 * (run/lac_run_nonlinear.h) or small strain (run/lac_run_steps.h).  The
 * load factors, t_1 = `start` (if > 0), then n equal steps to `end`; and
 * for each converged step: its load factor and the loop's counts, the
 * displacement of the monitor node, the contact force, every multiplier
 * (its value, mean gap, status, and where it sits), and the displacement
 * of the steps that get a step_NNN.vtu (only those, only when [steps]
 * vtu_every = K > 0: (n / K) * dofs numbers), so that the output stage
 * writes them (curve.csv, contact_steps.csv, step_NNN.vtu, steps.pvd)
 * through the same batch as the other files: a run that fails at step 40
 * leaves the files of an earlier run untouched.
 *
 * Ownership: the arrays are owned (lac_run_steplog_clear).
 */
#ifndef LAC_RUN_STEPLOG_H
#define LAC_RUN_STEPLOG_H

#include <stddef.h>
#include "fem/lac_frames.h"
#include "io/lac_scene.h"
#include "run/lac_run_setup.h"
#include "run/lac_summary.h"
#include "solve/lac_loadstep.h"
#include "solve/lac_newton.h"

/* One converged load step, as written to the curve. */
typedef struct lac_run_step_record
{
  lac_nl_step solver;   /* the solver's record of it: load factor t,
                           iterations, cuts, sub-steps, residual,
                           multipliers, times                             */
  double imposed;       /* the reference imposed value at t               */
  double um[3];         /* displacement of the monitor node               */
  double force;         /* sum of lambda |T^m cap Gamma_C| (<= 0)          */
  double lambda_min;    /* the largest pressure (most negative lambda)     */
} lac_run_step_record;

/* Every multiplier at the end of a step (contact_steps.csv). */
typedef struct lac_run_mult_record
{
  int step;
  size_t macro;
  double x[3];          /* centroid of T^m cap Gamma_C (large deformation:
                           current coordinates)                           */
  double lambda, gap;   /* multiplier, mean gap d / |T^m cap Gamma_C|     */
  double covered;       /* |T^m cap Gamma_C| (2 pi r weighted if
                           axisymmetric): lambda covered is the normal
                           force of the macro-element                    */
  char active;
} lac_run_mult_record;

typedef struct lac_run_steplog
{
  double *factor;             /* owned, nfactor load factors              */
  size_t nfactor, next;       /* next: the step under way (0-based)       */
  size_t monitor;             /* node, SIZE_MAX: none                     */
  double imposed_ref;         /* the reference imposed value at t = 1     */
  lac_run_step_record *step;  /* owned, nfactor                           */
  size_t nmult, capmult;
  lac_run_mult_record *mult;  /* owned                                    */
  size_t nkept;               /* steps before the last with a step file   */
  size_t *kept;               /* owned, their indices j (0-based)         */
  double *ukept;              /* owned, nkept * ndof displacements        */
} lac_run_steplog;

/* The load factors of [steps] to `end`, the monitor node of the mesh (an
 * error naming the [steps] monitor key if the group has none), room for
 * the records and for the displacements of the step files. */
int lac_run_steplog_init (lac_run_steplog *log, const lac_scene *sc,
                          const lac_mesh *m, double end);
void lac_run_steplog_clear (lac_run_steplog *log);
/* 1 if step j (0-based) of n gets a step_NNN.vtu: every K-th, the last. */
int lac_run_steplog_file (size_t j, size_t n, int K);
/* The displacement of the monitor node in U (ndof, in the nodal frames
 * fr where it has one) along the axes, into um (dim). */
void lac_run_steplog_monitor (const lac_run_steplog *log,
                              const lac_frames *fr, const double *U, int dim,
                              double *um);
/* Step j converged: a copy of U (ndof) if it gets a step file and is not
 * the last; the copy, for the caller to turn to the axes, or NULL. */
double *lac_run_steplog_keep (lac_run_steplog *log, size_t j, int K,
                              const double *U, size_t ndof);
/* The multipliers of step `step` (1-based) with a column in c: value,
 * mean gap and status from the loop, the centroid of T^m cap Gamma_C on
 * the coordinates of geom (the pairing P of each pair on them). */
int lac_run_steplog_mults (lac_run_steplog *log, const lac_mesh *geom,
                           const lac_run_setup *st,
                           lac_pairing *const *P, const lac_contact *c,
                           const lac_newton *loop, int step);

/* With a monitor: its displacement at the last step (monitor_ux ...) and
 * the largest of its last component over the steps (monitor_extreme). */
int lac_run_steplog_summary (const lac_run_steplog *log, int dim,
                             lac_summary *sum);

#endif /* LAC_RUN_STEPLOG_H */
