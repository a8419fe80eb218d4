/* tools/cli_signal: SIGINT / SIGTERM end a run cleanly (exit 8).
 *
 * The handler only records the signal. The commands look at it at their
 * safe points (between iterations: the progress callback asks the loop to
 * stop; before and while writing: tools/cli_outputs removes every
 * temporary file and leaves existing files as they were) and then exit 8
 * with one line saying so. The handler is installed with SA_RESETHAND: a
 * second interrupt ends the program at once, as usual.
 *
 * Test hook (for tests only; timing-free): the environment variable
 * SCAF_TEST_RAISE_SIGNAL_AT=POINT[:TERM] makes the program raise SIGINT
 * (SIGTERM with ":TERM") itself at POINT: a number N = in the progress
 * callback of iteration N, or "write" = after the first output file has
 * been written to its temporary file.
 */
#ifndef SCAF_TOOLS_CLI_SIGNAL_H
#define SCAF_TOOLS_CLI_SIGNAL_H

/* Install the handlers (the previous ones are kept for cli_signal_restore)
 * and forget any earlier signal. */
void cli_signal_install(void);

/* Put the previous handlers back (in-process callers such as the fuzz
 * target run several commands in one process). */
void cli_signal_restore(void);

/* Run a command's body between cli_signal_install and cli_signal_restore;
 * its exit status. */
int cli_signal_run(int (*body)(int argc, char **argv), int argc, char **argv);

/* The signal received since cli_signal_install, or 0. */
int cli_signal_caught(void);

/* Block until SIGINT or SIGTERM has been caught; returns it. The handler
 * also writes a byte to a pipe that this reads (the self-pipe trick), so
 * the wait ends whichever thread the kernel runs the handler in: threads
 * that libraries start (OpenBLAS's, at load time) do not block the
 * signals, and sigsuspend in one thread misses a signal handled in
 * another. */
int cli_signal_wait(void);

/* When a signal was received: print "scaf CMD: interrupted by SIGINT;
 * nothing written" and return 1; else 0. */
int cli_signal_report(const char *cmd);

/* The test hook: raise the signal when SCAF_TEST_RAISE_SIGNAL_AT names
 * this point (iteration >= 1, or 0 for "write"). */
void cli_signal_test_point(int iteration);

#endif
