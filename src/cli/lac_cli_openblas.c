/* lac_cli_openblas.c -- OpenBLAS's kernels and spin (see lac_cli_openblas.h)
 *
 * OpenBLAS is found by its own symbols (dlsym in the libraries lac was
 * started with), so nothing here links against it.  The CPU's
 * instructions are read with the compiler's __builtin_cpu_supports,
 * which also checks that the operating system saves the wide registers.
 */
#define _GNU_SOURCE            /* RTLD_DEFAULT */
#include "cli/lac_cli_openblas.h"

#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef char *name_fn (void);
typedef int int_fn (void);

/* OpenBLAS's string function NAME (openblas_get_corename, ...), or
 * NULL. */
static const char *
openblas_string (const char *name)
{
  name_fn *f;
  *(void **) &f = dlsym (RTLD_DEFAULT, name);
  return f ? f () : NULL;
}

/* The best kernels of OpenBLAS 0.3.21 for the instructions of this CPU,
 * or NULL if it has neither AVX2 nor AVX-512. */
static const char *
kernels_for_cpu (void)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_cpu_init ();
  if (__builtin_cpu_supports ("avx512f") && __builtin_cpu_supports ("avx512dq")
      && __builtin_cpu_supports ("avx512bw")
      && __builtin_cpu_supports ("avx512vl"))
    return "SkylakeX";
  if (__builtin_cpu_supports ("avx2") && __builtin_cpu_supports ("fma"))
    return "Haswell";
#endif
  return NULL;
}

const char *
lac_cli_better_kernels (void)
{
  const char *core = openblas_string ("openblas_get_corename");
  if (!core || strcmp (core, "Prescott") != 0
      || getenv ("OPENBLAS_CORETYPE"))
    return NULL;                 /* OpenBLAS knew the CPU, or you chose */
  return kernels_for_cpu ();
}

/* The threads OpenBLAS runs (1 with another BLAS). */
static int
openblas_threads (void)
{
  int_fn *f;
  *(void **) &f = dlsym (RTLD_DEFAULT, "openblas_get_num_threads");
  return f ? f () : 1;
}

void
lac_cli_fit_openblas (char **argv)
{
  const char *better = lac_cli_better_kernels ();
  const char *preload = getenv ("LD_PRELOAD");
  int spin = openblas_threads () > 1 && !getenv ("OPENBLAS_THREAD_TIMEOUT");
  if ((!better && !spin) || (preload && strstr (preload, "vgpreload")))
    return;                                          /* valgrind's */
  if ((!better || setenv ("OPENBLAS_CORETYPE", better, 1) == 0)
      && (!spin || setenv ("OPENBLAS_THREAD_TIMEOUT", LAC_OPENBLAS_SPIN, 1)
                   == 0))
    execv ("/proc/self/exe", argv);      /* returns only if it failed */
  if (better)
    unsetenv ("OPENBLAS_CORETYPE");
  if (spin)
    unsetenv ("OPENBLAS_THREAD_TIMEOUT");
}

const char *
lac_cli_blas_config (void)
{
  return openblas_string ("openblas_get_config");
}
