/* t015: two tasks at the same time (linalg/lac_tasks.h), runs in phases
 *       shared by the threads that come (linalg/lac_queue.h)
 *
 *   1. two CHOLMOD factorizations of different matrices (the 3D Laplacian
 *      of an m^3 grid, two sizes), one core each, run side by side: both
 *      solutions match those of factorizations made one after the other,
 *      and the second task ran in another thread;
 *   2. a failing task: its status is returned and its message, set in
 *      another thread, is the caller's; when both fail, the first one's;
 *   3. a task that asks for a pair of its own gets both of its tasks in
 *      its own thread, one after the other;
 *   4. a queue of runs in three phases: one worker does every run in
 *      order; two, one of them taking at most k runs first, do every run
 *      once, and no run starts before every run of the earlier phases has
 *      ended; a worker that comes when all is done returns at once;
 *   5. failures: run 3 fails while run 1, earlier, is still being done
 *      and fails after it: the queue reports run 1 (the first in order,
 *      as one worker alone), no run after 3 is done; a run that fails
 *      while the other worker waits for the next phase: that worker
 *      stops, the runs of the later phases are not done.
 */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>
#include "check.h"
#include "base/lac_status.h"
#include "linalg/lac_linalg.h"
#include "linalg/lac_queue.h"
#include "linalg/lac_tasks.h"

/* The 7-point Laplacian of an m^3 grid plus I (positive definite). */
static lac_csc *
laplacian (int m)
{
  size_t n = (size_t) m * m * m;
  lac_triplet *T = lac_triplet_alloc (n, n, 7 * n);
  lac_csc *A;
  for (int z = 0; z < m; z++)
    for (int y = 0; y < m; y++)
      for (int x = 0; x < m; x++)
        {
          size_t i = (size_t) x + (size_t) m * ((size_t) y + (size_t) m * z);
          int nb[6][3] = { { x - 1, y, z }, { x + 1, y, z }, { x, y - 1, z },
                           { x, y + 1, z }, { x, y, z - 1 }, { x, y, z + 1 } };
          lac_triplet_add (T, i, i, 7.0);
          for (int q = 0; q < 6; q++)
            if (nb[q][0] >= 0 && nb[q][0] < m && nb[q][1] >= 0
                && nb[q][1] < m && nb[q][2] >= 0 && nb[q][2] < m)
              lac_triplet_add (T, i, (size_t) nb[q][0] + (size_t) m
                               * ((size_t) nb[q][1] + (size_t) m * nb[q][2]),
                               -1.0);
        }
  A = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return A;
}

typedef struct
{
  lac_solver *chol;
  const lac_csc *A;
  pthread_t self;
} job;

static int
factor_task (void *ctx)
{
  job *j = ctx;
  j->self = pthread_self ();
  return lac_solver_factor (j->chol, j->A);
}

static int
failing_task (void *ctx)
{
  LAC_ERROR (*(int *) ctx, "task %d failed", *(int *) ctx);
}

/* max_i |x_i - y_i| / max_i |y_i| of the solutions of A x = 1. */
static double
solution_gap (lac_solver *a, lac_solver *b, size_t n)
{
  double *x = calloc (3 * n, sizeof *x), *y = x + n, *one = y + n;
  double d = 0, ymax = 0;
  for (size_t i = 0; i < n; i++)
    one[i] = 1.0;
  if (lac_solver_solve (a, one, x) || lac_solver_solve (b, one, y))
    d = 1;                                           /* fails the check */
  for (size_t i = 0; i < n; i++)
    {
      d = fmax (d, fabs (x[i] - y[i]));
      ymax = fmax (ymax, fabs (y[i]));
    }
  free (x);
  return d / ymax;
}

static void
side_by_side (void)
{
  lac_csc *A = laplacian (14), *B = laplacian (16);
  lac_solver *sa = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  lac_solver *sb = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  lac_solver *ra = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  lac_solver *rb = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  job ja = { sa, A, pthread_self () }, jb = { sb, B, pthread_self () };
  lac_solver_set_threads (sa, 1);
  lac_solver_set_threads (sb, 1);
  check_status (lac_tasks_pair (factor_task, &ja, factor_task, &jb),
                LAC_SUCCESS, "two factorizations side by side");
  check_true (pthread_equal (ja.self, pthread_self ()),
              "the first task runs in the calling thread");
  check_true (!pthread_equal (jb.self, pthread_self ()),
              "the second task runs in a thread of its own");
  check_status (lac_solver_factor (ra, A), LAC_SUCCESS, "A alone");
  check_status (lac_solver_factor (rb, B), LAC_SUCCESS, "B alone");
  check_abs (solution_gap (sa, ra, A->ncol), 0, 1e-13, "A: same solution");
  check_abs (solution_gap (sb, rb, B->ncol), 0, 1e-13, "B: same solution");
  lac_solver_free (sa);
  lac_solver_free (sb);
  lac_solver_free (ra);
  lac_solver_free (rb);
  lac_csc_free (A);
  lac_csc_free (B);
}

static int
ok_task (void *ctx)
{
  (void) ctx;
  return LAC_SUCCESS;
}

static void
failures (void)
{
  int ea = LAC_ESING, eb = LAC_EDEP;
  lac_error_clear ();
  check_status (lac_tasks_pair (ok_task, NULL, failing_task, &eb), LAC_EDEP,
                "the second task fails");
  check_message ("task 5 failed", "its message, set in its thread");
  check_status (lac_tasks_pair (failing_task, &ea, ok_task, NULL),
                LAC_ESING, "the first task fails");
  check_message ("task 6 failed", "its message");
  check_status (lac_tasks_pair (failing_task, &ea, failing_task, &eb),
                LAC_ESING, "both fail: the first one's status");
  check_message ("task 6 failed", "and message");
  check_status (lac_tasks_pair (ok_task, NULL, ok_task, NULL), LAC_SUCCESS,
                "neither fails");
}

/* A task that asks for a pair of its own (thread_of: where each ran). */
typedef struct
{
  pthread_t self, inner[2];
  int status;
} nest;

static int
where_task (void *ctx)
{
  *(pthread_t *) ctx = pthread_self ();
  return LAC_SUCCESS;
}

static int
nesting_task (void *ctx)
{
  nest *t = ctx;
  t->self = pthread_self ();
  t->status = lac_tasks_pair (where_task, &t->inner[0], where_task,
                              &t->inner[1]);
  return t->status;
}

/* 3. a pair asked for inside a task runs in that task's thread, one task
 *    after the other: never more threads than the two. */
static void
nested (void)
{
  nest a, b;
  check_status (lac_tasks_pair (nesting_task, &a, nesting_task, &b),
                LAC_SUCCESS, "two tasks that ask for pairs of their own");
  check_true (pthread_equal (a.inner[0], a.self)
              && pthread_equal (a.inner[1], a.self),
              "the first task's pair ran in its thread");
  check_true (pthread_equal (b.inner[0], b.self)
              && pthread_equal (b.inner[1], b.self)
              && !pthread_equal (b.self, pthread_self ()),
              "the second task's pair ran in its own thread");
  check_status (lac_tasks_pair (failing_task, &(int) { LAC_ESING }, ok_task,
                                NULL), LAC_ESING,
                "after nesting, a pair still reports its failure");
}

/* ---- 4, 5. the queue ------------------------------------------------------ */

#define NRUN 12

/* What the runs saw: when each began and ended (ticks of one clock), how
 * often each was done; run `block` waits (up to 5 s) until run `fail2`
 * failed, runs `fail1` and `fail2` fail; a run sleeps `nap` ns, run
 * `slow` 50 ms. */
typedef struct
{
  pthread_mutex_t lock;
  pthread_cond_t moved;
  long tick, begin[NRUN], end[NRUN];
  int count[NRUN];
  size_t fail1, fail2, block, slow;
  int fail2_done;
  long nap;
} trace;

static void
trace_init (trace *t, size_t fail1, size_t fail2, size_t block, long nap)
{
  *t = (trace) { .fail1 = fail1, .fail2 = fail2, .block = block,
                 .slow = SIZE_MAX, .nap = nap };
  pthread_mutex_init (&t->lock, NULL);
  pthread_cond_init (&t->moved, NULL);
}

static void
trace_clear (trace *t)
{
  pthread_cond_destroy (&t->moved);
  pthread_mutex_destroy (&t->lock);
}

/* Run r begins: waits for fail2 if it is the blocked one. */
static void
begin_run (trace *t, size_t r)
{
  pthread_mutex_lock (&t->lock);
  t->begin[r] = ++t->tick;
  t->count[r]++;
  if (r == t->block)
    {
      struct timespec until;
      clock_gettime (CLOCK_REALTIME, &until);
      until.tv_sec += 5;
      while (!t->fail2_done
             && pthread_cond_timedwait (&t->moved, &t->lock, &until)
                != ETIMEDOUT)
        ;
    }
  pthread_mutex_unlock (&t->lock);
}

static int
traced_run (void *ctx, size_t r)
{
  trace *t = ctx;
  struct timespec nap = { 0, r == t->slow ? 50000000 : t->nap };
  begin_run (t, r);
  nanosleep (&nap, NULL);
  pthread_mutex_lock (&t->lock);
  t->end[r] = ++t->tick;
  if (r == t->fail2)
    t->fail2_done = 1;
  pthread_cond_broadcast (&t->moved);
  pthread_mutex_unlock (&t->lock);
  if (r == t->fail1 || r == t->fail2)
    LAC_ERROR (LAC_ESING, "run %zu failed", r);
  return LAC_SUCCESS;
}

typedef struct
{
  lac_queue *q;
  trace *t;
  size_t most;
} worker;

static int
worker_task (void *ctx)
{
  worker *w = ctx;
  int status = lac_queue_work (w->q, traced_run, w->t, w->most);
  return w->most < SIZE_MAX ? lac_queue_work (w->q, traced_run, w->t,
                                              SIZE_MAX) : status;
}

static const size_t phases[4] = { 0, 5, 10, NRUN };     /* 5, 5, 2 runs */

/* Every run once, none before the earlier phases ended; runs from
 * `none` on not done. */
static void
check_trace (const char *name, const trace *t, size_t none)
{
  int once = 1, order = 1;
  for (size_t r = 0; r < NRUN; r++)
    {
      once = once && t->count[r] == (r < none);
      for (size_t k = 1; r < none && k < 3; k++)
        for (size_t e = 0; r >= phases[k] && e < phases[k]; e++)
          order = order && t->begin[r] > t->end[e];
    }
  check_true (once, "%s: the runs before %zu done once each, none after",
              name, none);
  check_true (order, "%s: no run began before the earlier phases ended",
              name);
}

static void
queue_phases (void)
{
  lac_queue q;
  trace t;
  check_status (lac_queue_init (&q, 3, phases), LAC_SUCCESS, "a queue");
  trace_init (&t, SIZE_MAX, SIZE_MAX, SIZE_MAX, 0);
  check_status (lac_queue_work (&q, traced_run, &t, SIZE_MAX), LAC_SUCCESS,
                "one worker");
  int inorder = 1;
  for (size_t r = 0; r + 1 < NRUN; r++)
    inorder = inorder && t.end[r] < t.begin[r + 1];
  check_true (inorder, "one worker: the runs in order");
  check_trace ("one worker", &t, NRUN);
  check_status (lac_queue_work (&q, traced_run, &t, SIZE_MAX), LAC_SUCCESS,
                "a worker that comes when all is done");
  check_trace ("a worker that comes when all is done", &t, NRUN);
  trace_clear (&t);
  lac_queue_destroy (&q);
  for (size_t k = 0; k < NRUN; k += 3)
    {
      trace_init (&t, SIZE_MAX, SIZE_MAX, SIZE_MAX, 1000000);
      lac_queue_init (&q, 3, phases);
      worker a = { &q, &t, k }, b = { &q, &t, SIZE_MAX };
      check_status (lac_tasks_pair (worker_task, &a, worker_task, &b),
                    LAC_SUCCESS, "two workers, one taking %zu runs first", k);
      check_trace ("two workers", &t, NRUN);
      trace_clear (&t);
      lac_queue_destroy (&q);
    }
  size_t back[3] = { 0, 3, 2 }, late[2] = { 1, 4 };
  check_status (lac_queue_init (&q, 2, back), LAC_EINVAL, "phases that go "
                "back");
  check_status (lac_queue_init (&q, 1, late), LAC_EINVAL, "a first phase "
                "after run 0");
}

static void
queue_failures (void)
{
  lac_queue q;
  trace t;
  worker a = { &q, &t, SIZE_MAX }, b = { &q, &t, SIZE_MAX };
  trace_init (&t, 1, 3, 1, 0);            /* 1 waits until 3 failed */
  lac_queue_init (&q, 3, phases);
  check_status (lac_tasks_pair (worker_task, &a, worker_task, &b),
                LAC_ESING, "run 3 fails, then run 1");
  check_message ("run 1 failed", "the first failing run in order");
  check_trace ("run 3 fails, then run 1", &t, 4);
  trace_clear (&t);
  lac_queue_destroy (&q);
  trace_init (&t, 4, SIZE_MAX, SIZE_MAX, 0);           /* one worker */
  lac_queue_init (&q, 3, phases);
  check_status (lac_queue_work (&q, traced_run, &t, SIZE_MAX), LAC_ESING,
                "one worker, run 4 fails");
  check_message ("run 4 failed", "its message");
  check_trace ("one worker, run 4 fails", &t, 5);
  trace_clear (&t);
  lac_queue_destroy (&q);
  trace_init (&t, 4, SIZE_MAX, SIZE_MAX, 0);
  t.slow = 4;                        /* the other worker waits at phase 1 */
  lac_queue_init (&q, 3, phases);
  check_status (lac_tasks_pair (worker_task, &a, worker_task, &b),
                LAC_ESING, "run 4 fails, the other worker at phase 1");
  check_message ("run 4 failed", "its message");
  check_trace ("run 4 fails, the other worker at phase 1", &t, 5);
  trace_clear (&t);
  lac_queue_destroy (&q);
}

int
main (void)
{
  lac_init ();
  side_by_side ();
  failures ();
  nested ();
  queue_phases ();
  queue_failures ();
  lac_finalize ();
  return check_summary ();
}
