/* t015: two tasks at the same time (linalg/lac_tasks.h)
 *
 *   1. two CHOLMOD factorizations of different matrices (the 3D Laplacian
 *      of an m^3 grid, two sizes), one core each, run side by side: both
 *      solutions match those of factorizations made one after the other,
 *      and the second task ran in another thread;
 *   2. a failing task: its status is returned and its message, set in
 *      another thread, is the caller's; when both fail, the first one's;
 *   3. a task that asks for a pair of its own gets both of its tasks in
 *      its own thread, one after the other.
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include "check.h"
#include "base/lac_status.h"
#include "linalg/lac_linalg.h"
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

int
main (void)
{
  lac_init ();
  side_by_side ();
  failures ();
  nested ();
  lac_finalize ();
  return check_summary ();
}
