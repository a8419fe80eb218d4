/* base/parallel: see parallel.h.
 *
 * A job is (fn, ctx, nc) and a counter of chunks handed out; the caller
 * and every awake worker take chunks from the counter until none is left.
 * A worker joins a job under the pool's mutex and leaves it under the
 * mutex; the next job is published only when every worker has left the
 * previous one, so a late worker never runs a new job's chunks with an old
 * job's function. The caller waits until all nc chunks have finished.
 */
#include "base/parallel.h"

#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>

static atomic_int threads = 1;

void par_set_threads(int n) { atomic_store(&threads, n < 1 ? 1 : n); }

int par_threads(void) { return atomic_load(&threads); }

static atomic_size_t min_chunk = PAR_MIN_CHUNK;

void par_set_min_chunk(size_t n) { atomic_store(&min_chunk, n < 1 ? 1 : n); }

size_t par_min_chunk(void) { return atomic_load(&min_chunk); }

int par_chunks(size_t n)
{
    int t = par_threads();
    if (t > PAR_MAX_CHUNKS) t = PAR_MAX_CHUNKS;
    size_t most = n / par_min_chunk();
    if (most < 1) return 1;
    return most < (size_t)t ? (int)most : t;
}

int par_sum_chunks(size_t n)
{
    size_t most = n / par_min_chunk();
    if (most < 1) return 1;
    return most < PAR_MAX_CHUNKS ? (int)most : PAR_MAX_CHUNKS;
}

static struct {
    pthread_mutex_t mu; /* guards the fields up to `active` */
    pthread_cond_t wake, done;
    unsigned long gen; /* job number */
    par_fn fn;
    void *ctx;
    int nc;
    int active;       /* workers inside the current job */
    int nworkers;     /* started (only the job's caller starts more) */
    atomic_int next;  /* next chunk to hand out */
    atomic_int ended; /* chunks finished */
} pool = {.mu = PTHREAD_MUTEX_INITIALIZER,
          .wake = PTHREAD_COND_INITIALIZER,
          .done = PTHREAD_COND_INITIALIZER};

/* One job at a time in the pool. */
static pthread_mutex_t busy = PTHREAD_MUTEX_INITIALIZER;

static void take_chunks(par_fn fn, void *ctx, int nc)
{
    int k;
    while ((k = atomic_fetch_add(&pool.next, 1)) < nc) {
        fn(ctx, k);
        if (atomic_fetch_add(&pool.ended, 1) + 1 == nc) {
            pthread_mutex_lock(&pool.mu);
            pthread_cond_broadcast(&pool.done);
            pthread_mutex_unlock(&pool.mu);
        }
    }
}

static void *worker(void *arg)
{
    unsigned long seen = (unsigned long)(size_t)arg;
    pthread_mutex_lock(&pool.mu);
    for (;;) {
        while (pool.gen == seen) pthread_cond_wait(&pool.wake, &pool.mu);
        seen = pool.gen;
        par_fn fn = pool.fn;
        void *ctx = pool.ctx;
        int nc = pool.nc;
        pool.active++;
        pthread_mutex_unlock(&pool.mu);
        take_chunks(fn, ctx, nc);
        pthread_mutex_lock(&pool.mu);
        if (--pool.active == 0) pthread_cond_broadcast(&pool.done);
    }
    return NULL;
}

/* Start workers up to `want` (called with `busy` held); fewer when the
 * system refuses threads: the caller then takes more chunks itself. */
static void grow(int want)
{
    while (pool.nworkers < want) {
        pthread_attr_t at;
        pthread_t t;
        if (pthread_attr_init(&at) != 0) return;
        pthread_attr_setdetachstate(&at, PTHREAD_CREATE_DETACHED);
        pthread_mutex_lock(&pool.mu);
        unsigned long gen = pool.gen;
        pthread_mutex_unlock(&pool.mu);
        /* the worker starts with every signal blocked (it inherits the
         * mask): a process signal must reach the program's own threads,
         * e.g. `scaf edit` waiting for SIGINT in sigsuspend, never a
         * worker that happens to be idle */
        sigset_t all, old;
        sigfillset(&all);
        pthread_sigmask(SIG_SETMASK, &all, &old);
        int ok = pthread_create(&t, &at, worker, (void *)(size_t)gen) == 0;
        pthread_sigmask(SIG_SETMASK, &old, NULL);
        pthread_attr_destroy(&at);
        if (!ok) return;
        pool.nworkers++;
    }
}

void par_run(int nc, par_fn fn, void *ctx)
{
    if (nc <= 1 || par_threads() < 2 || pthread_mutex_trylock(&busy) != 0) {
        for (int k = 0; k < nc; k++) fn(ctx, k);
        return;
    }
    int t = par_threads();
    grow((nc < t ? nc : t) - 1);
    pthread_mutex_lock(&pool.mu);
    while (pool.active > 0) pthread_cond_wait(&pool.done, &pool.mu);
    pool.fn = fn;
    pool.ctx = ctx;
    pool.nc = nc;
    atomic_store(&pool.next, 0);
    atomic_store(&pool.ended, 0);
    pool.gen++;
    pthread_cond_broadcast(&pool.wake);
    pthread_mutex_unlock(&pool.mu);
    take_chunks(fn, ctx, nc);
    pthread_mutex_lock(&pool.mu);
    while (atomic_load(&pool.ended) < nc) pthread_cond_wait(&pool.done, &pool.mu);
    pthread_mutex_unlock(&pool.mu);
    pthread_mutex_unlock(&busy);
}

/* ---- reductions ------------------------------------------------------------ */

typedef struct range_job {
    par_range_fn range;
    const void *ctx;
    size_t n;
    int nc;
    double part[PAR_MAX_CHUNKS];
} range_job;

static void range_chunk(void *ctx, int k)
{
    range_job *j = ctx;
    j->part[k] =
        j->range(j->ctx, par_chunk_begin(j->n, j->nc, k), par_chunk_begin(j->n, j->nc, k + 1));
}

/* Runs the chunks; their results in j->part[0 .. j->nc). */
static void run_ranges(range_job *j) { par_run(j->nc, range_chunk, j); }

double par_sum(size_t n, par_range_fn range, const void *ctx)
{
    range_job j = {range, ctx, n, par_sum_chunks(n), {0}};
    if (j.nc == 1) return range(ctx, 0, n);
    run_ranges(&j);
    double acc = 0;
    for (int k = 0; k < j.nc; k++) acc += j.part[k];
    return acc;
}

double par_min(size_t n, par_range_fn range, const void *ctx)
{
    range_job j = {range, ctx, n, par_sum_chunks(n), {0}};
    if (j.nc == 1) return range(ctx, 0, n);
    run_ranges(&j);
    double best = INFINITY; /* (a NaN chunk is skipped, as in a serial min) */
    for (int k = 0; k < j.nc; k++)
        if (j.part[k] < best) best = j.part[k];
    return best;
}
