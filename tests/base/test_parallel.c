/* Tests for base/parallel's pool: every chunk runs exactly once and the
 * caller sees all of their writes, job after job and with thread counts
 * changing in between; reductions give the same bits at any thread count; two threads starting loops at the same time (two
 * handles) both get complete results (one of them then runs its chunks
 * itself). No timing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <pthread.h>
#include <signal.h>
#include <string.h>

#include "base/parallel.h"

typedef struct job {
    int nc, seed;
    long out[PAR_MAX_CHUNKS];
    int runs[PAR_MAX_CHUNKS];
} job;

static void chunk(void *ctx, int k)
{
    job *j = ctx;
    long acc = 0;
    for (int i = 0; i < 1000; i++) acc += (long)(i ^ (k + j->seed));
    j->out[k] = acc;
    j->runs[k]++;
}

static void check(const job *j)
{
    for (int k = 0; k < j->nc; k++) {
        long acc = 0;
        for (int i = 0; i < 1000; i++) acc += (long)(i ^ (k + j->seed));
        assert_int_equal(j->out[k], acc);
        assert_int_equal(j->runs[k], 1);
    }
}

static void jobs(int rounds)
{
    for (int r = 0; r < rounds; r++) {
        job j;
        memset(&j, 0, sizeof j);
        j.nc = 1 + r % PAR_MAX_CHUNKS;
        j.seed = r;
        par_run(j.nc, chunk, &j);
        check(&j);
    }
}

static void many_jobs(void **state)
{
    (void)state;
    for (int t = 1; t <= 4; t++) {
        par_set_threads(t);
        jobs(200);
    }
    par_set_threads(2);
    jobs(200);
    par_set_threads(1);
}

static void *other_thread(void *arg)
{
    (void)arg;
    jobs(300);
    return NULL;
}

static void concurrent_callers(void **state)
{
    (void)state;
    par_set_threads(3);
    pthread_t t;
    assert_int_equal(pthread_create(&t, NULL, other_thread, NULL), 0);
    jobs(300);
    assert_int_equal(pthread_join(t, NULL), 0);
    par_set_threads(1);
}

/* par_sum / par_min: every item counted once whatever the chunks; the
 * minimum is the smallest chunk's; the sum is added in chunk order (the
 * same bits as adding the chunks' results by hand in that order). */
static double range_len(const void *ctx, size_t lo, size_t hi)
{
    (void)ctx;
    return (double)(hi - lo) + 1.0 / (double)(lo + 3); /* order-sensitive bits */
}

static double range_lo(const void *ctx, size_t lo, size_t hi)
{
    (void)hi;
    return (double)lo - *(const double *)ctx;
}

static void reductions(void **state)
{
    (void)state;
    size_t n = 7 * (size_t)PAR_MIN_CHUNK + 5;
    /* the reductions' chunks follow n only: the same sum at any thread
     * count, added in chunk order */
    int nc = par_sum_chunks(n);
    assert_int_equal(nc, 7);
    double want = 0;
    for (int k = 0; k < nc; k++)
        want += range_len(NULL, par_chunk_begin(n, nc, k), par_chunk_begin(n, nc, k + 1));
    for (int t = 1; t <= 3; t++) {
        par_set_threads(t);
        assert_int_equal(par_chunks(n), t);
        assert_int_equal(par_sum_chunks(n), 7);
        assert_true(par_sum(n, range_len, NULL) == want);
        double shift = 2.5;
        assert_true(par_min(n, range_lo, &shift) == -2.5);
    }
    par_set_threads(1);
    /* SCAF_MIN_CHUNK's setting: smaller chunks, still by n only */
    assert_int_equal(par_min_chunk(), PAR_MIN_CHUNK);
    par_set_min_chunk(64);
    assert_int_equal(par_sum_chunks(640), 10);
    assert_int_equal(par_sum_chunks(100000), PAR_MAX_CHUNKS);
    par_set_min_chunk(0);
    assert_int_equal(par_min_chunk(), 1);
    par_set_min_chunk(PAR_MIN_CHUNK);
}

/* Both chunks wait for each other, so the pool's worker runs one: it must
 * have SIGINT and SIGTERM blocked (a program waiting for them in
 * sigsuspend, like `scaf edit`, would otherwise miss them), whatever the
 * mask of the thread that started the pool. */
typedef struct mask_job {
    pthread_barrier_t both;
    pthread_t caller;
    int worker_ran, worker_blocks_int, worker_blocks_term;
} mask_job;

static void mask_chunk(void *ctx, int k)
{
    (void)k;
    mask_job *j = ctx;
    pthread_barrier_wait(&j->both);
    if (pthread_equal(pthread_self(), j->caller)) return;
    sigset_t cur;
    pthread_sigmask(SIG_BLOCK, NULL, &cur);
    j->worker_ran = 1;
    j->worker_blocks_int = sigismember(&cur, SIGINT) == 1;
    j->worker_blocks_term = sigismember(&cur, SIGTERM) == 1;
}

static void workers_block_signals(void **state)
{
    (void)state;
    sigset_t none, old;
    sigemptyset(&none);
    pthread_sigmask(SIG_SETMASK, &none, &old); /* the caller blocks nothing */
    par_set_threads(2);
    mask_job j;
    memset(&j, 0, sizeof j);
    pthread_barrier_init(&j.both, NULL, 2);
    j.caller = pthread_self();
    par_run(2, mask_chunk, &j);
    pthread_barrier_destroy(&j.both);
    par_set_threads(1);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    assert_true(j.worker_ran);
    assert_true(j.worker_blocks_int);
    assert_true(j.worker_blocks_term);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(many_jobs),
        cmocka_unit_test(concurrent_callers),
        cmocka_unit_test(reductions),
        cmocka_unit_test(workers_block_signals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
