/* tools/cli_threads: see cli_threads.h. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "cli_threads.h"

#include <sched.h>
#include <stdlib.h>
#include <unistd.h>

/* OpenBLAS, when linked (weak: absent -> nothing to set). */
extern void openblas_set_num_threads(int) __attribute__((weak));
extern int openblas_get_num_threads(void) __attribute__((weak));

int cli_threads_available(void)
{
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        int n = CPU_COUNT(&set);
        if (n >= 1) return n;
    }
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 ? (int)n : 1;
}

int cli_threads_apply(int requested)
{
    if (!openblas_set_num_threads) return 0;
    int n = requested;
    if (n < 1) {
        const char *e = getenv("OPENBLAS_NUM_THREADS");
        if (e && *e) return openblas_get_num_threads ? openblas_get_num_threads() : 0;
        n = cli_threads_available();
    }
    openblas_set_num_threads(n);
    return openblas_get_num_threads ? openblas_get_num_threads() : n;
}
