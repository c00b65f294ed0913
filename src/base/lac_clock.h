/* lac_clock.h -- seconds on a monotonic clock, for the times a run reports
 *
 * Header only: lac_seconds () differences are elapsed wall time (POSIX
 * clock_gettime with CLOCK_MONOTONIC: not changed by setting the date).
 */
#ifndef LAC_CLOCK_H
#define LAC_CLOCK_H

#include <time.h>

static inline double
lac_seconds (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

#endif /* LAC_CLOCK_H */
