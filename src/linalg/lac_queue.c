/* lac_queue.c -- see lac_queue.h.  One mutex guards the counters; a worker
 * holds it only to take a run or to count one finished, never while it
 * does a run; every finished run wakes the workers that wait (for a phase
 * to start, or for the last runs to finish). */
#include "linalg/lac_queue.h"

#include <stdint.h>
#include <stdio.h>
#include "base/lac_status.h"

int
lac_queue_init (lac_queue *q, size_t nphase, const size_t *phase)
{
  if (phase[0] != 0)
    LAC_ERROR (LAC_EINVAL, "the first phase starts at run %zu, not 0",
               phase[0]);
  for (size_t k = 0; k < nphase; k++)
    if (phase[k + 1] < phase[k])
      LAC_ERROR (LAC_EINVAL, "phase %zu ends at run %zu before it starts "
                 "(%zu)", k, phase[k + 1], phase[k]);
  *q = (lac_queue) { .phase = phase, .nphase = nphase, .nrun = phase[nphase],
                     .failed = phase[nphase] };
  if (pthread_mutex_init (&q->lock, NULL))
    LAC_ERROR (LAC_ENOMEM, "a mutex for %zu runs", q->nrun);
  if (pthread_cond_init (&q->moved, NULL))
    {
      pthread_mutex_destroy (&q->lock);
      LAC_ERROR (LAC_ENOMEM, "a condition variable for %zu runs", q->nrun);
    }
  return LAC_SUCCESS;
}

void
lac_queue_destroy (lac_queue *q)
{
  pthread_cond_destroy (&q->moved);
  pthread_mutex_destroy (&q->lock);
}

/* The first run of the phase of run r: r may start once that many runs
 * are finished (runs are taken in order, and none of r's phase is taken
 * before its phase starts: the runs finished are those before it). */
static size_t
phase_start (const lac_queue *q, size_t r)
{
  size_t k = 0;
  while (q->phase[k + 1] <= r)
    k++;
  return q->phase[k];
}

/* Run r finished with status; the lock is held. */
static void
finished (lac_queue *q, size_t r, int status)
{
  q->done++;
  if (status && r < q->failed)            /* the first failure in order */
    {
      q->failed = r;
      q->status = status;
      snprintf (q->message, sizeof q->message, "%s", lac_error_message ());
    }
  pthread_cond_broadcast (&q->moved);
}

int
lac_queue_work (lac_queue *q, lac_queue_fn *fn, void *ctx, size_t most)
{
  size_t taken = 0;
  pthread_mutex_lock (&q->lock);
  while (taken < most && q->next < q->failed)   /* failed <= nrun */
    {
      size_t r = q->next;
      if (q->done < phase_start (q, r))         /* its phase: not yet */
        {
          pthread_cond_wait (&q->moved, &q->lock);
          continue;
        }
      q->next++;
      taken++;
      pthread_mutex_unlock (&q->lock);
      int status = fn (ctx, r);
      pthread_mutex_lock (&q->lock);
      finished (q, r, status);
    }
  while (q->done < q->next)                 /* the others' last runs */
    pthread_cond_wait (&q->moved, &q->lock);
  int status = q->status ? lac_error_restore (q->status, q->message)
                         : LAC_SUCCESS;       /* the message: this thread's */
  pthread_mutex_unlock (&q->lock);
  return status;
}

size_t
lac_queue_done (lac_queue *q)
{
  pthread_mutex_lock (&q->lock);
  size_t done = q->done;
  pthread_mutex_unlock (&q->lock);
  return done;
}
