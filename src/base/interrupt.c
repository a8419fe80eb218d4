/* base/interrupt: see interrupt.h. */
#include "base/interrupt.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>

static volatile sig_atomic_t requested;
static volatile sig_atomic_t armed;
static int hook_fired; /* the hook raises once per process */

void interrupt_request(int sig)
{
    if (!requested) requested = sig; /* the first one is the one reported */
}

int interrupt_pending(void) { return requested; }

void interrupt_clear(void)
{
    requested = 0;
    hook_fired = 0;
}

void interrupt_arm(int on) { armed = on; }

const char *interrupt_signal_name(int sig)
{
    switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
    }
}

static int signal_of(const char *s, size_t n)
{
    if (n == 3 && !strncmp(s, "INT", 3)) return SIGINT;
    if (n == 4 && !strncmp(s, "TERM", 4)) return SIGTERM;
    if (n == 3 && !strncmp(s, "HUP", 3)) return SIGHUP;
    return 0;
}

void interrupt_test_point(const char *name)
{
    const char *e = getenv("SCAF_TEST_RAISE_SIGNAL_AT");
    if (!e || !*e || !armed || hook_fired) return;
    const char *colon = strchr(e, ':');
    size_t n = colon ? (size_t)(colon - e) : strlen(e);
    if (strlen(name) != n || strncmp(e, name, n)) return;
    hook_fired = 1;
    if (!colon) {
        raise(SIGINT);
        return;
    }
    /* each listed signal in turn; an unknown name raises SIGINT */
    for (const char *p = colon + 1;;) {
        const char *q = strchr(p, ':');
        size_t k = q ? (size_t)(q - p) : strlen(p);
        int sig = signal_of(p, k);
        raise(sig ? sig : SIGINT);
        if (!q) break;
        p = q + 1;
    }
}

scaf_status interrupt_check(const char *point, const char *during, scaf_error *err)
{
    if (point) interrupt_test_point(point);
    int sig = requested;
    if (!sig) return SCAF_OK;
    return err_set(err, SCAF_ERR_CANCELLED, "interrupted by %s while %s",
                   interrupt_signal_name(sig), during);
}
