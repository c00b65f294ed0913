/* nomem_lac -- lac's command line with every allocation of src/ failing
 * from the k-th on                        (tests/nomem.sh; chapter 01, 9)
 *
 *   LAC_NOMEM_AT=k nomem_lac run SCENE ...
 *
 * src/cli/main.c is compiled with main renamed lac_cli_main (Makefile), so
 * this is the whole of `lac run`, with the allocation counter of
 * base/lac_mem.h armed before it starts: allocation k (0 = the first) and
 * every one after it fail, in lac's process and, since a fork copies the
 * counter, in gmsh's child process too.  Without LAC_NOMEM_AT nothing
 * fails.  With LAC_NOMEM_COUNT=FILE the number of allocations lac's
 * process made is written to FILE at the end (the range of k to sweep).
 *
 * Built again with tests/nomem_malloc.c and NOMEM_MALLOC as
 * nomem_lac_malloc: then k counts every malloc, calloc and realloc of lac's
 * process, those of the libraries and of the C library included.
 */
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_mem.h"

int lac_cli_main (int argc, char **argv);

#ifdef NOMEM_MALLOC       /* nomem_lac_malloc: every malloc of the process */
#include <limits.h>
void nomem_malloc_arm (long k);
long nomem_malloc_count (void);
#define ARM(k) nomem_malloc_arm ((k) < 0 ? LONG_MAX : (k))
#define COUNT() (n = nomem_malloc_count (), nomem_malloc_arm (-1), n)
#else
#define ARM(k) lac_mem_fail_after (k)
#define COUNT() lac_mem_fail_after (-1)
#endif

int
main (int argc, char **argv)
{
  const char *at = getenv ("LAC_NOMEM_AT"), *count = getenv ("LAC_NOMEM_COUNT");
  long n;
  int ret;
  ARM (at ? atol (at) : -1);
  ret = lac_cli_main (argc, argv);
  n = COUNT ();
  if (count)
    {
      FILE *f = fopen (count, "w");
      if (f)
        {
          fprintf (f, "%ld\n", n);
          fclose (f);
        }
    }
  return ret;
}
