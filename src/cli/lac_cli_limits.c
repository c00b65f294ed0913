/* lac_cli_limits.c -- an address-space limit and OpenBLAS
 * (see lac_cli_limits.h)
 *
 * OpenBLAS is found by its own symbols (dlsym in the libraries lac was
 * started with: SuiteSparse loads libblas.so.3, which Debian points at
 * OpenBLAS or at the reference BLAS), so nothing here links against it.
 *
 * Measured on Debian 12 (OpenBLAS 0.3.21, 2 cores): lac holds about
 * 430 MB of address space when main starts with OPENBLAS_NUM_THREADS=1
 * and about 570 MB with the default 2 threads (the worker's buffer, stack
 * and malloc arena); a product of 200 x 200 matrices maps the main
 * thread's buffer, 132 MB (smaller ones may use OpenBLAS's small-matrix
 * kernels, which map nothing).
 */
#define _GNU_SOURCE            /* RTLD_DEFAULT */
#include "cli/lac_cli_limits.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#include "cli/lac_cli.h"

typedef void dgemm_fn (const char *, const char *, const int *, const int *,
                       const int *, const double *, const double *,
                       const int *, const double *, const int *,
                       const double *, double *, const int *);

/* The address space this process holds (bytes), from /proc. */
static double
address_space (void)
{
  FILE *f = fopen ("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (f)
    {
      if (fscanf (f, "%lu", &pages) != 1)
        pages = 0;
      fclose (f);
    }
  return (double) pages * (double) sysconf (_SC_PAGESIZE);
}

/* One product through OpenBLAS's buffer (see the file's comment). */
static void
map_buffer (dgemm_fn *dgemm)
{
  const int n = 200;
  const double one = 1, zero = 0;
  double *a = calloc (3 * (size_t) n * (size_t) n, sizeof *a);
  if (!a)
    return;
  dgemm ("N", "N", &n, &n, &n, &one, a, &n, a + n * n, &n, &zero,
         a + 2 * n * n, &n);
  free (a);
}

int
lac_cli_fit_limits (char **argv, int compute)
{
  struct rlimit rl;
  dgemm_fn *dgemm = (dgemm_fn *) dlsym (RTLD_DEFAULT, "dgemm_");
  double held, need;
  char msg[400];
  if (getrlimit (RLIMIT_AS, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY
      || !dlsym (RTLD_DEFAULT, "openblas_get_num_threads") || !dgemm)
    return 0;
  if (!getenv ("OPENBLAS_NUM_THREADS")
      && setenv ("OPENBLAS_NUM_THREADS", "1", 1) == 0)
    execv ("/proc/self/exe", argv);      /* returns only if it failed */
  if (!compute)
    return 0;
  held = address_space ();
  need = held + LAC_CLI_BLAS_BUFFER + 16e6;
  if (need <= (double) rl.rlim_cur)
    {
      map_buffer (dgemm);
      return 0;
    }
  snprintf (msg, sizeof msg, "the address space is limited to %.0f MB "
            "(ulimit -v %.0f) and lac's libraries take %.0f MB of it: "
            "OpenBLAS needs %.0f MB more for its work buffer and would wait "
            "for it forever; raise the limit to at least %.0f MB (ulimit -v "
            "%.0f), and limit gmsh's memory with --max-memory if need be",
            (double) rl.rlim_cur / 1e6, (double) rl.rlim_cur / 1024,
            held / 1e6, LAC_CLI_BLAS_BUFFER / 1e6, need / 1e6, need / 1024);
  lac_cli_print_error (msg);
  return LAC_CLI_FAILURE;
}
