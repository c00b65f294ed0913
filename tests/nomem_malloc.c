/* nomem_malloc.c -- malloc, calloc and realloc of the whole process fail
 * from the k-th call on                   (tests/nomem.sh; chapter 01, 9)
 *
 * Linked into a second build of tests/nomem_lac.c (nomem_lac_malloc):
 * these definitions take the place of the C library's for every library
 * of the process (CHOLMOD, UMFPACK, GSL, the C library itself), not only
 * for lac's own allocations.  They count from nomem_malloc_arm on, in the
 * process that armed them only: gmsh's child process runs under a memory
 * limit instead (io/lac_mesh_child.h).  Not built under AddressSanitizer,
 * which replaces malloc itself.
 */
#include <errno.h>
#include <stddef.h>
#include <sys/types.h>
#include <unistd.h>

void *__libc_malloc (size_t n);
void *__libc_calloc (size_t n, size_t size);
void *__libc_realloc (void *p, size_t n);
void nomem_malloc_arm (long k);
long nomem_malloc_count (void);

static long fail_at = -1;
static _Atomic long count;         /* the split solve allocates in two threads */
static pid_t armed_pid;

void
nomem_malloc_arm (long k)
{
  fail_at = k;
  count = 0;
  armed_pid = getpid ();
}

long
nomem_malloc_count (void)
{
  return count;
}

static int
fail (void)
{
  if (fail_at < 0 || getpid () != armed_pid)
    return 0;
  if (count++ < fail_at)
    return 0;
  errno = ENOMEM;
  return 1;
}

void *
malloc (size_t n)
{
  return fail () ? NULL : __libc_malloc (n);
}

void *
calloc (size_t n, size_t size)
{
  return fail () ? NULL : __libc_calloc (n, size);
}

void *
realloc (void *p, size_t n)
{
  return fail () ? NULL : __libc_realloc (p, n);
}
