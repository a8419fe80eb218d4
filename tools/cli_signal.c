/* tools/cli_signal: see cli_signal.h. */
#include "cli_signal.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t caught;
static struct sigaction previous_int, previous_term;
static int installed;
static int wake[2] = {-1, -1}; /* the handler writes, cli_signal_wait reads */

static void on_signal(int sig)
{
    caught = sig;
    if (wake[1] >= 0) {
        int saved = errno; /* write is async-signal-safe; errno is kept */
        ssize_t r = write(wake[1], "", 1);
        (void)r;
        errno = saved;
    }
}

void cli_signal_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND; /* the second interrupt is not caught */
    caught = 0;
    if (wake[0] < 0 && pipe(wake) == 0) {
        for (int k = 0; k < 2; k++) fcntl(wake[k], F_SETFD, FD_CLOEXEC);
        fcntl(wake[1], F_SETFL, O_NONBLOCK); /* a full pipe never blocks the handler */
    }
    sigaction(SIGINT, &sa, &previous_int);
    sigaction(SIGTERM, &sa, &previous_term);
    installed = 1;
}

void cli_signal_restore(void)
{
    if (!installed) return;
    sigaction(SIGINT, &previous_int, NULL);
    sigaction(SIGTERM, &previous_term, NULL);
    installed = 0;
    for (int k = 0; k < 2; k++) {
        if (wake[k] >= 0) close(wake[k]);
        wake[k] = -1;
    }
}

int cli_signal_run(int (*body)(int argc, char **argv), int argc, char **argv)
{
    cli_signal_install();
    int rc = body(argc, argv);
    cli_signal_restore();
    return rc;
}

int cli_signal_caught(void) { return caught; }

int cli_signal_wait(void)
{
    while (!caught) {
        char c;
        if (wake[0] < 0) {
            pause(); /* no pipe (out of descriptors): the old way */
            continue;
        }
        if (read(wake[0], &c, 1) < 0 && errno != EINTR) pause();
    }
    return caught;
}

int cli_signal_report(const char *cmd)
{
    if (!caught) return 0;
    fprintf(stderr, "scaf %s: interrupted by %s; nothing written\n", cmd,
            caught == SIGTERM ? "SIGTERM" : "SIGINT");
    return 1;
}

void cli_signal_test_point(int iteration)
{
    const char *e = getenv("SCAF_TEST_RAISE_SIGNAL_AT");
    if (!e || !*e || !installed || caught) return; /* once: the handler resets itself */
    const char *colon = strchr(e, ':');
    size_t n = colon ? (size_t)(colon - e) : strlen(e);
    int hit;
    if (iteration > 0) {
        char *end;
        long at = strtol(e, &end, 10);
        hit = end == e + n && end != e && at == iteration;
    } else {
        hit = n == 5 && !strncmp(e, "write", 5);
    }
    if (hit) raise(colon && !strcmp(colon + 1, "TERM") ? SIGTERM : SIGINT);
}
