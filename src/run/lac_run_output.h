/* lac_run_output.h -- stage 7 of a run: the files
 *
 * In:  the products of the earlier stages, the output directory.
 * Out: in the directory, as the scene's [output] asks: solution.vtu (mesh,
 *      displacement, stresses, von Mises: ParaView), nodes.csv, with
 *      contact contact.csv (one line per macro-element), K.mtx ([output]
 *      matrix), for large deformation the per-step curve, contact.csv of
 *      the last step, contact_steps.csv, step_NNN.vtu and steps.pvd
 *      ([steps] vtu_every), and summary.txt last.  Everything is written
 *      into a batch (io/lac_output.h) and renamed into place at the end,
 *      so that a failed run leaves the files of an earlier one.
 */
#ifndef LAC_RUN_OUTPUT_H
#define LAC_RUN_OUTPUT_H

#include <signal.h>
#include <stddef.h>
#include "run/lac_run_post.h"

/* What stage 7 reads: what stage 6 read, and its results. */
typedef struct lac_run_output_in
{
  lac_run_post_in post;
  const lac_run_results *res;
  const char *dir;                 /* the output directory                */
  const volatile sig_atomic_t *stop;  /* set by a signal handler: stop
                                     and publish nothing (NULL: never)    */
} lac_run_output_in;

int lac_run_output (const lac_run_output_in *in, char *progress,
                    size_t size);

#endif /* LAC_RUN_OUTPUT_H */
