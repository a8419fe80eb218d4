/* tests/support/loop_valid: whether a SCAF loop's state is what every
 * iteration must leave — the map bijective (exact checker) and every
 * scaffold triangle positively oriented (exact orient2d). d = 2. */
#ifndef SCAF_TESTS_LOOP_VALID_H
#define SCAF_TESTS_LOOP_VALID_H

#include "scaffold/scaf_loop.h"

/* 1 when valid, 0 otherwise (also when the checker fails). */
int test_loop_state_valid(const scaf_loop *L);

#endif
