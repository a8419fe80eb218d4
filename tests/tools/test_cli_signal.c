/* tools/cli_signal: cli_signal_wait returns when the handler runs in
 * another thread, even though the waiting thread blocks the signal the
 * whole time (threads that libraries start, OpenBLAS's at load time, do
 * not block SIGINT / SIGTERM; `scaf edit` waited in sigsuspend and hung
 * when such a thread took the signal). Ordering-free: the other thread
 * sends the signal after a barrier, before or after the wait begins. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include "cli_signal.h"

static pthread_barrier_t both;

static void *sender(void *arg)
{
    int sig = *(const int *)arg;
    pthread_barrier_wait(&both);
    kill(getpid(), sig); /* the waiting thread blocks sig: it runs here */
    return NULL;
}

static void wait_for(int sig)
{
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, sig);
    pthread_sigmask(SIG_BLOCK, &block, &old); /* this thread never takes it */
    cli_signal_install();
    pthread_t t;
    pthread_barrier_init(&both, NULL, 2);
    pthread_sigmask(SIG_SETMASK, &old, NULL); /* the sender: sig unblocked */
    assert_int_equal(pthread_create(&t, NULL, sender, &sig), 0);
    pthread_sigmask(SIG_BLOCK, &block, NULL);
    pthread_barrier_wait(&both);
    assert_int_equal(cli_signal_wait(), sig);
    assert_int_equal(pthread_join(t, NULL), 0);
    pthread_barrier_destroy(&both);
    cli_signal_restore();
    pthread_sigmask(SIG_SETMASK, &old, NULL);
}

static void wait_ends_when_another_thread_handles_sigint(void **state)
{
    (void)state;
    wait_for(SIGINT);
}

static void wait_ends_when_another_thread_handles_sigterm(void **state)
{
    (void)state;
    wait_for(SIGTERM);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wait_ends_when_another_thread_handles_sigint),
        cmocka_unit_test(wait_ends_when_another_thread_handles_sigterm),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
