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

int
lac_grow (void *array, size_t need, size_t *cap, size_t size, size_t first)
{
  void *p, *q;
  size_t c;
  if (need <= *cap)
    return 0;
  c = *cap ? 2 * *cap : first;
  if (c < need)
    c = need;
  memcpy (&p, array, sizeof p);          /* the T * stored at array */
  if (!(q = lac_realloc (p, c * size)))
    return -1;
  memcpy (array, &q, sizeof q);
  *cap = c;
  return 0;
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
