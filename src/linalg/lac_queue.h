/* lac_queue.h -- numbered runs of work in phases, taken in order by the
 *                threads that come to them
 *
 * The assembly of K_T into a kept pattern (fem/lac_hyper.h) is cut into
 * runs of cells: the runs of one phase share no node, so that two threads
 * may add them at the same time; a phase starts when every run of the
 * phases before it is finished (fem/lac_pattern.h).  The threads do not
 * come at the same time: in an evaluation of the large-deformation model
 * (solve/lac_nonlinear.c) one core starts on the runs at once, the other
 * pairs the contact surfaces first and joins when it is done.  A queue
 * hands the runs out in order to whoever asks:
 *
 *   lac_queue_work: take the next run, do it, take the next one ...; a
 *   run waits until the phases before its own are finished; when no run
 *   is left, wait for the runs the other workers are still doing, and
 *   return the queue's status.
 *
 * Any number of workers may come, at any time, each with its own scratch
 * (its ctx): one alone does every run, in order; one that comes when
 * everything is done returns at once.  What a run writes must not depend
 * on who does it: the assembly's sums then do not depend on the timing.
 *
 * A run that fails stops the runs after it (no worker takes them); the
 * runs before it are finished, and the status and message the queue
 * returns are those of the first failing run in order: the failure one
 * worker alone would have met.  No worker waits for a phase that will not
 * start.
 *
 * Ownership: lac_queue_init / lac_queue_destroy on a caller's struct; the
 * phases are borrowed.
 */
#ifndef LAC_QUEUE_H
#define LAC_QUEUE_H

#include <pthread.h>
#include <stddef.h>

/* Run r of the worker with scratch ctx: a status (base/lac_status.h),
 * with its message. */
typedef int lac_queue_fn (void *ctx, size_t r);

typedef struct lac_queue
{
  const size_t *phase;   /* borrowed, nphase + 1: the runs of phase k are
                            phase[k] <= r < phase[k + 1]; phase[0] = 0    */
  size_t nphase;
  size_t nrun;           /* phase[nphase]                                 */
  pthread_mutex_t lock;  /* guards the fields below                       */
  pthread_cond_t moved;  /* a run was finished                            */
  size_t next;           /* the next run to take                          */
  size_t done;           /* runs finished                                 */
  size_t failed;         /* the first failing run so far; nrun: none      */
  int status;            /* its status and message                        */
  char message[1024];
} lac_queue;

/* A queue of the runs of the nphase phases.  LAC_SUCCESS, LAC_EINVAL
 * (phases not increasing from 0) or LAC_ENOMEM (no mutex). */
int lac_queue_init (lac_queue *q, size_t nphase, const size_t *phase);
void lac_queue_destroy (lac_queue *q);

/* A worker: fn (ctx, r) for the runs it takes, at most `most` of them
 * (SIZE_MAX: as many as there are), then wait until no run is being done.
 * Returns the queue's status (LAC_SUCCESS, or the first failing run's
 * status with its message). */
int lac_queue_work (lac_queue *q, lac_queue_fn *fn, void *ctx, size_t most);

/* The number of runs finished so far (for a test that waits for it). */
size_t lac_queue_done (lac_queue *q);

#endif /* LAC_QUEUE_H */
