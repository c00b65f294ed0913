/* lac_output_batch.h -- the files of a run appear together, or not at all
 *
 * A batch writes its files into a temporary directory beside the output
 * directory DIR, `.NAME.lac-new-PID` (NAME: the last part of DIR), and
 * lac_output_commit publishes them at once: it exchanges the temporary
 * directory and DIR in one atomic step (renameat2 with RENAME_EXCHANGE,
 * Linux), moves back into DIR what the earlier DIR held that a run never
 * writes (pictures, notes, subdirectories: see lac_output_batch_ours),
 * and removes the earlier run's files.  Where the file system cannot
 * exchange, DIR becomes `.NAME.lac-old-PID` and the new directory DIR:
 * two renames, between which DIR is missing for an instant; the next
 * batch that finds DIR missing and such an old copy beside it puts it
 * back.  Either way DIR holds the complete files of one run, the earlier
 * or the new, at every moment.
 *
 * Refusals: a DIR that is not a writable directory (read-only, a file,
 * a link to a file) fails at lac_output_batch_alloc, and at the commit a
 * foreign subdirectory that could not be moved back: DIR is never
 * replaced by a directory without its foreign files.  The new DIR takes
 * the earlier one's permission bits.
 *
 * Interruption: a batch freed without commit removes its temporary
 * directory, so a run that fails leaves DIR as it was.  A run killed
 * outright leaves its temporary directory behind; lac_output_batch_alloc
 * removes those of processes that no longer exist, and the hidden
 * `.NAME.tmpPID` files that lac wrote into DIR before batches had their
 * own directory.  A caller that handles SIGINT or SIGTERM passes the flag
 * its handler sets (lac_output_batch_alloc): once it is set, adding a file
 * and committing fail with LAC_EIO ("interrupted"), so the run stops
 * between two files and publishes nothing.
 *
 * Ownership: the batch owns its paths; lac_output_batch_free releases it.
 */
#ifndef LAC_OUTPUT_BATCH_H
#define LAC_OUTPUT_BATCH_H

#include <signal.h>
#include <stddef.h>

typedef struct lac_output_batch lac_output_batch;

/* A batch for DIR: its parents are created if needed, stale temporaries
 * beside it removed (and a DIR lost between two renames put back), the
 * temporary directory made.  stop (may be NULL): a flag a signal handler
 * sets to interrupt.  NULL with a message on failure. */
lac_output_batch *lac_output_batch_alloc (const char *dir,
                                          const volatile sig_atomic_t *stop);

/* What can be known before a run writes anything: DIR, if it exists, is
 * a directory (a symbolic link to one stands for it) that this process
 * may write into, and so is its parent; if it does not exist, the deepest
 * part of its path that does is a writable directory.  LAC_EIO with a
 * message naming the path and the reason otherwise. */
int lac_output_batch_check (const char *dir);

/* Remove the temporary directory unless committed.  NULL allowed. */
void lac_output_batch_free (lac_output_batch *b);

/* The temporary path to write the file `name` to (owned by the batch);
 * NULL with a message on failure or when interrupted. */
const char *lac_output_batch_add (lac_output_batch *b, const char *name);

/* Publish the files: see above.  LAC_EIO with a message if it cannot (DIR
 * then holds the earlier files) or if interrupted before it began. */
int lac_output_commit (lac_output_batch *b);

/* The final path of the k-th file (NULL past the last). */
const char *lac_output_batch_path (const lac_output_batch *b, size_t k);

/* Is `name` a file a run may write (solution.vtu, nodes.csv, contact.csv,
 * contact_steps.csv, curve.csv, K.mtx, summary.txt, steps.pvd,
 * step_NNN.vtu)?  Those of an earlier run are not kept beside a new one. */
int lac_output_batch_ours (const char *name);

#endif /* LAC_OUTPUT_BATCH_H */
