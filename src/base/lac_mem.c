/* lac_mem.c -- allocation wrappers with a fault-injection hook for tests. */
#include "base/lac_mem.h"

#include <stdlib.h>
#include <string.h>

static _Thread_local long fail_at = -1;  /* test hook only */
static _Thread_local long count;

static int
should_fail (void)
{
  long k = count++;
  return fail_at >= 0 && k >= fail_at;
}

long
lac_mem_fail_after (long k)
{
  long n = count;
  fail_at = k;
  count = 0;
  return n;
}

void *
lac_malloc (size_t size)
{
  return should_fail () ? NULL : malloc (size ? size : 1);
}

void *
lac_calloc (size_t n, size_t size)
{
  return should_fail () ? NULL : calloc (n ? n : 1, size ? size : 1);
}

void *
lac_realloc (void *p, size_t size)
{
  return should_fail () ? NULL : realloc (p, size ? size : 1);
}

void
lac_free (void *p)
{
  free (p);
}

char *
lac_strdup (const char *s)
{
  size_t n = strlen (s) + 1;
  char *d = lac_malloc (n);
  if (d)
    memcpy (d, s, n);
  return d;
}
