/* lac_mem.h -- the single point where src/ allocates memory.
 *
 * Every allocation in src/ goes through these wrappers, so that a test can
 * count allocations or make the k-th one fail (tests/malloc_fail.c).
 * lac_free accepts NULL.  A zero-size request returns a valid pointer.
 */
#ifndef LAC_MEM_H
#define LAC_MEM_H

#include <stddef.h>

void *lac_malloc (size_t size);
void *lac_calloc (size_t n, size_t size);
void *lac_realloc (void *p, size_t size);
void lac_free (void *p);
char *lac_strdup (const char *s);

/* Test hook: fail the k-th allocation from now on (k = 0 is the next one);
 * k < 0 disables.  Returns the number of allocations since the last call. */
long lac_mem_fail_after (long k);

#endif /* LAC_MEM_H */
