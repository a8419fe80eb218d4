/* tools/cli_signal: SIGINT / SIGTERM / SIGHUP end a run cleanly (exit 8).
 *
 * The handler only records the signal (here and in base/interrupt, which
 * the library's long phases poll). The commands look at it at their safe
 * points (between iterations: the progress callback asks the loop to
 * stop; while reading, setting up, analysing and packing: the phase
 * returns SCAF_ERR_CANCELLED; before and while writing: tools/cli_outputs
 * removes every temporary file and leaves existing files as they were) and
 * then exit 8 with one line saying so. The handler stays installed: a
 * second Ctrl-C, or a SIGHUP (the terminal closed) after it, ends the run
 * the same way, never halfway through a write. SIGXFSZ is ignored while a
 * command runs: a write beyond the file-size limit (ulimit -f) fails with
 * EFBIG, which is an ordinary write failure (exit 5, nothing left).
 *
 * Test hook (for tests only; timing-free): the environment variable
 * SCAF_TEST_RAISE_SIGNAL_AT=POINT[:SIG[:SIG...]] makes the program raise
 * the signals SIG (INT, TERM or HUP; SIGINT when none is given) itself, in
 * order, at POINT: a number N = in the progress callback of iteration N,
 * "write" = after the first output file has been written to its temporary
 * file, or a named phase: "parse" (reading the input mesh), "targets"
 * (reading `scaf deform --targets`), "setup" (the charts' setup),
 * "analysis" (the solver's analysis), "pack" (the atlas's packer).
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

/* Block until SIGINT, SIGTERM or SIGHUP has been caught; returns it. The handler
 * also writes a byte to a pipe that this reads (the self-pipe trick), so
 * the wait ends whichever thread the kernel runs the handler in: threads
 * that libraries start (OpenBLAS's, at load time) do not block the
 * signals, and sigsuspend in one thread misses a signal handled in
 * another. */
int cli_signal_wait(void);

/* When a signal was received: print "scaf CMD: interrupted by SIGINT;
 * nothing written" (SIGTERM, SIGHUP) and return 1; else 0. */
int cli_signal_report(const char *cmd);

/* The test hook: raise the signal when SCAF_TEST_RAISE_SIGNAL_AT names
 * this point (iteration >= 1, or 0 for "write"). */
void cli_signal_test_point(int iteration);

#endif
