/* tools/cli_signal: see cli_signal.h. */
#include "cli_signal.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/interrupt.h"

static volatile sig_atomic_t caught;
static struct sigaction previous_int, previous_term, previous_hup, previous_xfsz;
static int installed;
static int wake[2] = {-1, -1}; /* the handler writes, cli_signal_wait reads */

static void on_signal(int sig)
{
    if (!caught) caught = sig; /* the first one names the interruption */
    interrupt_request(sig);    /* what the long phases of the library poll */
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
    sigemptyset(&sa.sa_mask); /* one handler at a time: the first signal is kept */
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    sigaddset(&sa.sa_mask, SIGHUP);
    /* no SA_RESETHAND: a second Ctrl-C (or a SIGHUP after a SIGINT) ends
     * the run as the first does, cleanly, instead of killing it halfway
     * through a write */
    sa.sa_flags = 0;
    caught = 0;
    interrupt_clear();
    if (wake[0] < 0 && pipe(wake) == 0) {
        for (int k = 0; k < 2; k++) fcntl(wake[k], F_SETFD, FD_CLOEXEC);
        fcntl(wake[1], F_SETFL, O_NONBLOCK); /* a full pipe never blocks the handler */
    }
    sigaction(SIGINT, &sa, &previous_int);
    sigaction(SIGTERM, &sa, &previous_term);
    sigaction(SIGHUP, &sa, &previous_hup); /* the terminal closed */
    /* a write beyond the file-size limit (ulimit -f) fails with EFBIG
     * instead of killing the program: exit 5, temporary files removed */
    struct sigaction ign;
    memset(&ign, 0, sizeof ign);
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    sigaction(SIGXFSZ, &ign, &previous_xfsz);
    installed = 1;
    interrupt_arm(1);
}

void cli_signal_restore(void)
{
    if (!installed) return;
    sigaction(SIGINT, &previous_int, NULL);
    sigaction(SIGTERM, &previous_term, NULL);
    sigaction(SIGHUP, &previous_hup, NULL);
    sigaction(SIGXFSZ, &previous_xfsz, NULL);
    installed = 0;
    interrupt_arm(0);
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
            interrupt_signal_name(caught));
    return 1;
}

void cli_signal_test_point(int iteration)
{
    if (!installed || caught) return;
    char name[16] = "write";
    if (iteration > 0) snprintf(name, sizeof name, "%d", iteration);
    interrupt_test_point(name);
}
