/* lac_run_output.h -- stage 7 of a run: the files
 *
 * In:  the products of the earlier stages, the output directory.
 * Out: in the directory, as the scene's [output] asks: solution.vtu (mesh,
 *      displacement, stresses, von Mises: ParaView), nodes.csv, with
 *      contact contact.csv (one line per macro-element), K.mtx ([output]
 *      matrix), for large deformation the per-step curve, contact.csv of
 *      the last step, contact_steps.csv, step_NNN.vtu and steps.pvd
 *      ([steps] vtu_every), and summary.txt last.  Everything is written
 *      into a batch (io/lac_output_batch.h) and put in place at the end,
 *      all at once, so that a failed run leaves the files of an earlier
 *      one; the caller may publish the batch itself, later.
 */
#ifndef LAC_RUN_OUTPUT_H
#define LAC_RUN_OUTPUT_H

#include <signal.h>
#include <stddef.h>
#include "io/lac_output_batch.h"
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

/* Write the files into a batch (io/lac_output_batch.h).  keep NULL: then
 * publish them.  Else *keep is the batch, complete but not published,
 * for the caller to commit once everything else that could fail has
 * been done (lac_run_publish).  A failure leaves the earlier files. */
int lac_run_output (const lac_run_output_in *in, lac_output_batch **keep,
                    char *progress, size_t size);

/* The message of a failed output stage or commit, stored with the scene
 * (scene: its path) and the assurance that the files in dir are those of
 * the earlier run; after an interruption (stop set) the batch's own
 * words, which say so, with LAC_EIO. */
int lac_run_output_failed (const char *scene, const char *dir, int status,
                           const volatile sig_atomic_t *stop);

#endif /* LAC_RUN_OUTPUT_H */
