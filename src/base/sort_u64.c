/* base/sort_u64: see sort_u64.h. */
#include "base/sort_u64.h"

#include <stdlib.h>

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

void sort_u64(uint64_t *k, int n)
{
    if (n > 32) {
        qsort(k, (size_t)n, sizeof *k, cmp_u64);
        return;
    }
    for (int i = 1; i < n; i++) {
        uint64_t x = k[i];
        int j = i - 1;
        while (j >= 0 && k[j] > x) {
            k[j + 1] = k[j];
            j--;
        }
        k[j + 1] = x;
    }
}
