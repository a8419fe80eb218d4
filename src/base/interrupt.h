/* base/interrupt: a process-wide request to stop, for the long phases.
 *
 * The program's signal handler (tools/cli_signal) records SIGINT, SIGTERM
 * or SIGHUP here (interrupt_request: one store to a sig_atomic_t, safe in
 * a handler). Every phase that can take more than a second and has no
 * progress callback of its own (reading a mesh, the atlas's setup and
 * packing, the solver's analysis) polls interrupt_pending at its own safe
 * points and returns SCAF_ERR_CANCELLED, leaving its outputs freed; the
 * program then exits 8 with nothing written. Nothing is requested unless a
 * handler was installed, so a library user who never calls
 * interrupt_request sees no change.
 *
 * Test hook (tests only, timing-free; see tools/cli_signal.h):
 * interrupt_test_point("NAME") raises the signals listed in
 * SCAF_TEST_RAISE_SIGNAL_AT=NAME[:SIG...] when it names this point, once
 * per process, and only while a handler is armed (interrupt_arm), so the
 * variable never kills a program that does not catch the signal.
 */
#ifndef SCAF_BASE_INTERRUPT_H
#define SCAF_BASE_INTERRUPT_H

#include "base/error.h"

/* Record signal sig (nonzero). Async-signal-safe. */
void interrupt_request(int sig);

/* The signal recorded since the last interrupt_clear, or 0. */
int interrupt_pending(void);

/* Forget any request (a new command starts). */
void interrupt_clear(void);

/* Whether a handler that records requests is installed (1) or not (0):
 * only then does interrupt_test_point raise anything. */
void interrupt_arm(int armed);

/* The test hook: raise the signals that SCAF_TEST_RAISE_SIGNAL_AT lists
 * for point `name` ("write", "parse", "setup", ...; "12" for an
 * iteration). Several signals ("write:INT:INT", "write:HUP") are raised in
 * order, each one handled before the next. */
void interrupt_test_point(const char *name);

/* A safe point of a long phase: the test hook for `point` (NULL: none),
 * then SCAF_ERR_CANCELLED "interrupted by SIGINT while DURING" when a
 * signal is pending, else SCAF_OK. Cheap: call it every few thousand
 * items of a loop. */
scaf_status interrupt_check(const char *point, const char *during, scaf_error *err);

/* "SIGINT", "SIGTERM", "SIGHUP", ... for messages. */
const char *interrupt_signal_name(int sig);

#endif /* SCAF_BASE_INTERRUPT_H */
