/* tools/cli_signal: cli_signal_wait returns when the handler runs in
 * another thread, even though the waiting thread blocks the signal the
 * whole time (threads that libraries start, OpenBLAS's at load time, do
 * not block SIGINT / SIGTERM; `scaf edit` waited in sigsuspend and hung
 * when such a thread took the signal). Ordering-free: the other thread
 * sends the signal after a barrier, before or after the wait begins.
 *
 * Repeated signals: a second SIGINT, a SIGHUP and a SIGTERM after the
 * first are caught too (the handler used to reset itself, so the second
 * Ctrl-C killed the program halfway through a write, and SIGHUP was not
 * caught at all); the first one is the one reported, also to the
 * library's long phases (base/interrupt). SIGXFSZ is ignored while the
 * handlers are installed (a write past ulimit -f fails with EFBIG instead
 * of killing the program), and everything is put back by restore. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include "base/interrupt.h"
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

static void disposition_is(int sig, void (*handler)(int))
{
    struct sigaction now;
    assert_int_equal(sigaction(sig, NULL, &now), 0);
    assert_true(now.sa_handler == handler);
}

static void every_signal_is_caught_the_first_is_reported(void **state)
{
    (void)state;
    cli_signal_install();
    assert_int_equal(cli_signal_caught(), 0);
    assert_int_equal(interrupt_pending(), 0);
    raise(SIGINT);
    raise(SIGINT); /* the second Ctrl-C */
    raise(SIGHUP); /* the terminal closes */
    raise(SIGTERM);
    raise(SIGINT);
    assert_int_equal(cli_signal_caught(), SIGINT);
    assert_int_equal(interrupt_pending(), SIGINT);
    assert_string_equal(interrupt_signal_name(cli_signal_caught()), "SIGINT");
    cli_signal_restore();
    /* a new command forgets it; SIGHUP first is reported as SIGHUP */
    cli_signal_install();
    assert_int_equal(interrupt_pending(), 0);
    raise(SIGHUP);
    raise(SIGHUP);
    raise(SIGINT);
    assert_int_equal(cli_signal_caught(), SIGHUP);
    assert_string_equal(interrupt_signal_name(interrupt_pending()), "SIGHUP");
    cli_signal_restore();
}

static void file_size_signal_is_ignored_while_installed(void **state)
{
    (void)state;
    struct sigaction xfsz, hup, in;
    sigaction(SIGXFSZ, NULL, &xfsz);
    sigaction(SIGHUP, NULL, &hup);
    sigaction(SIGINT, NULL, &in);
    cli_signal_install();
    disposition_is(SIGXFSZ, SIG_IGN);
    raise(SIGXFSZ); /* the default would end the test program here */
    assert_int_equal(cli_signal_caught(), 0);
    cli_signal_restore();
    disposition_is(SIGXFSZ, xfsz.sa_handler); /* as before */
    disposition_is(SIGHUP, hup.sa_handler);
    disposition_is(SIGINT, in.sa_handler);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wait_ends_when_another_thread_handles_sigint),
        cmocka_unit_test(wait_ends_when_another_thread_handles_sigterm),
        cmocka_unit_test(every_signal_is_caught_the_first_is_reported),
        cmocka_unit_test(file_size_signal_is_ignored_while_installed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
