/* Tests for base/parallel's pool: every chunk runs exactly once and the
 * caller sees all of their writes, job after job and with thread counts
 * changing in between; two threads starting loops at the same time (two
 * handles) both get complete results (one of them then runs its chunks
 * itself). No timing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <pthread.h>
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(many_jobs),
        cmocka_unit_test(concurrent_callers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
