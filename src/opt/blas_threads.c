/* opt/blas_threads: see blas_threads.h. OpenBLAS is reached through weak
 * references (it is loaded with CHOLMOD), so with another BLAS nothing is
 * set and 0 is reported. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "opt/blas_threads.h"

#include <assert.h>
#include <sched.h>
#include <stdatomic.h>
#include <unistd.h>

#include "base/parallel.h"
#include "scaf/scaf.h"

extern void openblas_set_num_threads(int) __attribute__((weak));
extern int openblas_get_num_threads(void) __attribute__((weak));

int opt_blas_cores(void)
{
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        int n = CPU_COUNT(&set);
        if (n >= 1) return n;
    }
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 ? (int)n : 1;
}

int opt_blas_threads(void) { return openblas_get_num_threads ? openblas_get_num_threads() : 0; }

int scaf_set_threads(int n)
{
    if (n < 0) return -1;
    int t = n == 0 ? opt_blas_cores() : n;
    par_set_threads(t); /* scaf's own loops (base/parallel) */
    if (!openblas_set_num_threads) return 0;
    openblas_set_num_threads(t);
    return opt_blas_threads();
}

static atomic_int deterministic = 0;

void scaf_set_deterministic(int on) { atomic_store(&deterministic, on != 0); }

int opt_deterministic(void) { return atomic_load(&deterministic); }

int opt_blas_serial_begin(void)
{
    if (!openblas_get_num_threads || !openblas_set_num_threads) return 0;
    int saved = openblas_get_num_threads();
    if (saved > 1) openblas_set_num_threads(1);
    return saved;
}

void opt_blas_serial_end(int saved)
{
    assert(saved >= 0); /* what opt_blas_serial_begin returned */
    if (saved > 1 && openblas_set_num_threads) openblas_set_num_threads(saved);
}
