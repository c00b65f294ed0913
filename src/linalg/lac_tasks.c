/* lac_tasks.c -- see lac_tasks.h.  OpenMP's knob is looked up at run time
 * (dlsym), as OpenBLAS's in lac_blas.c: lac itself does not use OpenMP,
 * the libraries it calls may. */
#define _DEFAULT_SOURCE                           /* RTLD_DEFAULT */
#include "linalg/lac_tasks.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include "base/lac_status.h"
#include "linalg/lac_blas.h"

typedef struct
{
  lac_task *fn;
  void *ctx;
  int status;
  char message[1024];      /* the task's message, from its own thread */
} job;

/* OpenMP's max-active-levels of the calling thread (-1 without OpenMP);
 * 0 makes every parallel region run on one thread. */
static int
omp_levels (int set)
{
  int (*get) (void);
  void (*put) (int);
  *(void **) &get = dlsym (RTLD_DEFAULT, "omp_get_max_active_levels");
  *(void **) &put = dlsym (RTLD_DEFAULT, "omp_set_max_active_levels");
  if (!get || !put)
    return -1;
  int old = get ();
  if (set >= 0)
    put (set);
  return old;
}

/* 1 in a thread while it runs a task: a pair asked for from there runs
 * in that thread, one task after the other (lac_tasks.h). */
static _Thread_local int in_task;

static void
run (job *j)
{
  int was = in_task;
  in_task = 1;
  lac_error_clear ();
  j->status = j->fn (j->ctx);
  snprintf (j->message, sizeof j->message, "%s", lac_error_message ());
  in_task = was;
}

static void *
thread_main (void *arg)
{
  omp_levels (0);
  run (arg);
  return NULL;
}

int
lac_tasks_pair (lac_task *a, void *ca, lac_task *b, void *cb)
{
  job ja = { a, ca, 0, "" }, jb = { b, cb, 0, "" };
  pthread_t th;
  int started, levels;
  if (in_task)                         /* both cores are busy already */
    {
      run (&ja);
      if (ja.status)
        return lac_error_restore (ja.status, ja.message);
      run (&jb);
      return lac_error_restore (jb.status, jb.message);
    }
  lac_blas_serial ();
  levels = omp_levels (0);
  started = !lac_blas_limited ()      /* a BLAS buffer each (lac_blas.h) */
            && pthread_create (&th, NULL, thread_main, &jb) == 0;
  run (&ja);
  if (started)
    pthread_join (th, NULL);
  else
    run (&jb);                           /* no thread: one after the other */
  if (levels >= 0)
    omp_levels (levels);
  if (ja.status)
    return lac_error_restore (ja.status, ja.message);
  return lac_error_restore (jb.status, jb.message);
}
