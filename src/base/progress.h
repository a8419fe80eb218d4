/* base/progress: the callback type long-running work reports through.
 *
 * A loop calls the callback once per iteration with the iteration number,
 * the current energy and the seconds elapsed; a nonzero return asks the
 * loop to stop (the loop then returns SCAF_ERR_CANCELLED). The callback is
 * the caller's: it may draw a live line, log, or do nothing.
 */
#ifndef SCAF_BASE_PROGRESS_H
#define SCAF_BASE_PROGRESS_H

/* user: the caller's pointer, passed back unchanged. iteration: 0-based
 * count of finished iterations. energy: the energy after that iteration.
 * seconds: time since the run started. Return 0 to continue. */
typedef int (*scaf_progress_fn)(void *user, int iteration, double energy, double seconds);

#endif /* SCAF_BASE_PROGRESS_H */
