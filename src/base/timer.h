/* base/timer: a monotonic clock for phase timings.
 *
 * timer_now() reads CLOCK_MONOTONIC, so intervals are never negative even
 * when the wall clock is adjusted. It cannot fail on a POSIX system; if the
 * clock is unavailable it returns 0 and every interval reads as 0.
 */
#ifndef SCAF_BASE_TIMER_H
#define SCAF_BASE_TIMER_H

/* Seconds since an arbitrary fixed origin (monotonic). */
double timer_now(void);

#endif /* SCAF_BASE_TIMER_H */
