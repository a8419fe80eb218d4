/* tools/cli_signal: see cli_signal.h. */
#include "cli_signal.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static volatile sig_atomic_t caught;
static struct sigaction previous_int, previous_term;
static int installed;

static void on_signal(int sig) { caught = sig; }

void cli_signal_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND; /* the second interrupt is not caught */
    caught = 0;
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
}

int cli_signal_run(int (*body)(int argc, char **argv), int argc, char **argv)
{
    cli_signal_install();
    int rc = body(argc, argv);
    cli_signal_restore();
    return rc;
}

int cli_signal_caught(void) { return caught; }

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
