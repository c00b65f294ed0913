/* lac_blas.c -- see lac_blas.h.  OpenBLAS's own functions are looked up
 * at run time (dlsym), so that lac links against any BLAS. */
#define _DEFAULT_SOURCE                           /* RTLD_DEFAULT */
#include "linalg/lac_blas.h"

#include <dlfcn.h>
#include <sys/resource.h>

typedef void (*set_threads_fn) (int);
typedef int (*get_int_fn) (void);

static void
set_threads (int n)
{
  set_threads_fn set;
  *(void **) &set = dlsym (RTLD_DEFAULT, "openblas_set_num_threads");
  if (set)
    set (n);
}

int
lac_blas_limited (void)
{
  struct rlimit rl;
  return getrlimit (RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY;
}

void
lac_blas_parallel (void)
{
  get_int_fn procs;
  if (lac_blas_limited ())
    return;
  *(void **) &procs = dlsym (RTLD_DEFAULT, "openblas_get_num_procs");
  if (procs)
    set_threads (procs ());
}

void
lac_blas_serial (void)
{
  set_threads (1);
}
