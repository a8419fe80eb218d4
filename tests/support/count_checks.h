/* tests/support/count_checks: assert a list of expected counts at once.
 *
 * A test that knows many counts of a result (a report, a topology) writes
 * them as one list, EXPECT_COUNTS("case", HAS(r.charts, 2), HAS(r.flipped,
 * 0), ...), instead of one assertion a line. Every entry is checked; the
 * first one that differs fails the test (cmocka) with a message naming
 * the case, the expression and both values. */
#ifndef SCAF_TESTS_COUNT_CHECKS_H
#define SCAF_TESTS_COUNT_CHECKS_H

/* One expected count: the expression's text, its value, the value wanted. */
typedef struct count_check {
    const char *what;
    long long got, want;
} count_check;

#define HAS(expr, value)                                                                           \
    {                                                                                              \
#expr, (long long)(expr), (long long)(value)                                               \
    }

/* Asserts got == want for the n checks; label names the case. */
void test_expect_counts(const char *label, const count_check *checks, int n);

#define EXPECT_COUNTS(label, ...)                                                                  \
    test_expect_counts(label, (const count_check[]){__VA_ARGS__},                                  \
                       (int)(sizeof((const count_check[]){__VA_ARGS__}) / sizeof(count_check)))

#endif
