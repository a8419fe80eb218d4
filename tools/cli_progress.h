/* tools/cli_progress: the one self-overwriting progress line of a long run.
 *
 * When stderr is a terminal (isatty) and the run is not quiet, a command
 * draws one line that it rewrites in place ("\r" + erase to the end of the
 * line): the command, the phase, a bar with the iteration i/N when N is a
 * real count, or, when N is only a cap that convergence ends first, the
 * convergence criterion against the tolerance; the energy; an ETA. At the
 * end cli_progress_done erases it and prints one summary line that stays.
 * On a pipe or a file (and with -q) every call here does nothing at all,
 * so what scripts and tests read is exactly what the commands printed
 * before this module existed: the commands print their per-iteration
 * lines only when cli_progress_live is 0.
 *
 * Redraws are throttled (at most ~10 per second, and always the first and
 * a phase's last): a terminal scrolling thousands of lines slows a run
 * down (the environment variable SCAF_PROGRESS=every draws every
 * iteration: for tests, which must not depend on timing). The ETA: for i/N, the mean time of the phase's iterations times
 * N - i; for a criterion against a tolerance, the iterations the criterion
 * still needs at its recent geometric rate of decrease (never more than
 * the cap allows); "?" until there are two judged iterations. Never
 * fails: a terminal whose width cannot be read is taken as 80 columns.
 */
#ifndef SCAF_TOOLS_CLI_PROGRESS_H
#define SCAF_TOOLS_CLI_PROGRESS_H

typedef struct cli_progress {
    int live;         /* 1: draw (stderr is a terminal, not quiet) */
    const char *cmd;  /* "param", ... */
    char phase[32];   /* the current phase's name */
    int total;        /* iterations of the phase: a count (exact = 1) or a cap */
    int exact;        /* 1: total is the real count, 0: only a cap */
    double tolerance; /* the criterion's goal when !exact (0: none) */
    double t_phase;   /* start of the phase (timer_now) */
    double t_drawn;   /* last redraw */
    int drawn;        /* a line is on the screen now */
    double c_first;   /* first judged criterion of the phase, and its iteration */
    int i_first;
    int every; /* SCAF_PROGRESS=every: no throttle */
} cli_progress;

/* Start: live when stderr is a terminal and !quiet. The environment
 * variable SCAF_PROGRESS=0 turns the line off on a terminal too. */
void cli_progress_init(cli_progress *p, const char *cmd, int quiet);

/* Is the line drawn? (The commands print their per-iteration lines only
 * when it is not.) */
int cli_progress_live(const cli_progress *p);

/* A new phase: name, total iterations (<= 0: unknown), exact (1: total is
 * the count the phase will run, 0: a cap ended first by the criterion
 * reaching tolerance). Draws the phase with no iteration yet. */
void cli_progress_phase(cli_progress *p, const char *name, int total, int exact, double tolerance);

/* Iteration i (1-based) of the phase is done: its energy (NAN: none to
 * show), its convergence criterion (INFINITY / NAN: not judged). extra:
 * NULL or a short text appended (e.g. "efficiency 0.71"). */
void cli_progress_step(cli_progress *p, int i, double energy, double criterion, const char *extra);

/* Erase the line (when one is drawn) so that an ordinary line can follow;
 * the next cli_progress_step draws it again. */
void cli_progress_clear(cli_progress *p);

/* The end: erase the line; when live and summary is not NULL, print
 * "scaf CMD: summary" and a newline: the line that stays. The commands
 * that print a summary of their own anyway pass NULL. */
void cli_progress_done(cli_progress *p, const char *summary);

/* Format one progress line into buf (size bytes, width columns at most):
 * what cli_progress_step draws; exposed for the unit test. elapsed: the
 * phase's seconds so far. */
void cli_progress_format(const cli_progress *p, int i, double energy, double criterion,
                         const char *extra, double elapsed, int width, char *buf, int size);

#endif
