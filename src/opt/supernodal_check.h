/* opt/supernodal_check: invariant checks of the custom sparse code's
 * structures, for assert()s (Debug and sanitizer builds; Release builds
 * define NDEBUG and never call them).
 *
 * Each returns 1 when the structure holds its invariants and 0 otherwise
 * (never aborts itself: the assert at the call site names the caller).
 * They read the whole structure, so they are for checks, not for paths
 * that run in Release.
 *
 * Kept apart from cholmod_solver.h: only CHOLMOD-facing code includes it. */
#ifndef SCAF_OPT_SUPERNODAL_CHECK_H
#define SCAF_OPT_SUPERNODAL_CHECK_H

#include <cholmod.h>

/* Whether n entries are a permutation of 0..n-1. */
int opt_is_permutation(int n, const int *perm);

/* Whether L is a well-formed supernodal symbolic factor (int indices):
 * Perm a permutation of 0..n-1; supernode columns super[0] = 0 <
 * super[1] < ... < super[nsuper] = n; each supernode's rows start with its
 * own columns, in order, and continue strictly ascending below them, all
 * below n; row offsets pi and value offsets px (nrows x ncols values per
 * supernode) ascending from 0. */
int opt_super_symbolic_valid(const cholmod_factor *L);

/* Whether the upper pattern of n columns cp (n + 1) / ri has rows in
 * [0, column] strictly ascending in each column (with the diagonal when
 * with_diagonal). */
int opt_upper_pattern_valid(int n, const int *cp, const int *ri, int with_diagonal);

#endif /* SCAF_OPT_SUPERNODAL_CHECK_H */
