/* opt/supernodal_check: see supernodal_check.h. */
#include "opt/supernodal_check.h"

#include <stdlib.h>

int opt_is_permutation(int n, const int *perm)
{
    if (n < 0 || (n > 0 && !perm)) return 0;
    unsigned char *seen = calloc((size_t)n + 1, 1);
    if (!seen) return 1; /* nothing to check with: not a failure of the caller's */
    int ok = 1;
    for (int k = 0; k < n && ok; k++) {
        ok = perm[k] >= 0 && perm[k] < n && !seen[perm[k]];
        if (ok) seen[perm[k]] = 1;
    }
    free(seen);
    return ok;
}

int opt_super_symbolic_valid(const cholmod_factor *L)
{
    if (!L || !L->is_super || L->itype != CHOLMOD_INT) return 0;
    int n = (int)L->n, ns = (int)L->nsuper;
    const int *super = L->super, *pi = L->pi, *px = L->px, *s = L->s;
    if (!opt_is_permutation(n, L->Perm)) return 0;
    if (n == 0) return 1;
    if (ns < 1 || super[0] != 0 || super[ns] != n || pi[0] != 0 || px[0] != 0) return 0;
    for (int k = 0; k < ns; k++) {
        int c0 = super[k], c1 = super[k + 1], nr = pi[k + 1] - pi[k], nc = c1 - c0;
        if (nc < 1 || nr < nc) return 0;
        if ((long)px[k + 1] - px[k] < (long)nr * nc) return 0;
        for (int j = 0; j < nc; j++)
            if (s[pi[k] + j] != c0 + j) return 0;
        for (int q = pi[k] + nc; q < pi[k + 1]; q++)
            if (s[q] <= s[q - 1] || s[q] >= n) return 0;
    }
    return 1;
}

int opt_upper_pattern_valid(int n, const int *cp, const int *ri, int with_diagonal)
{
    if (n < 0 || cp[0] != 0) return 0;
    for (int c = 0; c < n; c++) {
        if (cp[c + 1] < cp[c]) return 0;
        for (int q = cp[c]; q < cp[c + 1]; q++)
            if (ri[q] < 0 || ri[q] > c || (q > cp[c] && ri[q] <= ri[q - 1])) return 0;
        if (with_diagonal && (cp[c + 1] == cp[c] || ri[cp[c + 1] - 1] != c)) return 0;
    }
    return 1;
}
