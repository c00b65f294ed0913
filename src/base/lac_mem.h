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

/* Room for `need` elements in an array that grows by doubling.  `array`
 * is the address of the array's pointer (a T **, passed as void *), *cap
 * its capacity, size = sizeof (T).  When need > *cap the array is
 * reallocated to twice *cap elements (`first` when it is empty), or to
 * `need` if that is more, and *cap is updated.  Returns 0, or -1 when out
 * of memory (the array and *cap as they were).  Two arrays that share one
 * capacity: grow the first on a copy of it, then the second on it. */
int lac_grow (void *array, size_t need, size_t *cap, size_t size,
              size_t first);

/* Test hook: fail the k-th allocation from now on (k = 0 is the next one);
 * k < 0 disables.  Returns the number of allocations since the last call. */
long lac_mem_fail_after (long k);

#endif /* LAC_MEM_H */
