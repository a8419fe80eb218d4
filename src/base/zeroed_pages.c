/* base/zeroed_pages: see zeroed_pages.h. */
#define _DEFAULT_SOURCE /* madvise */
#include "base/zeroed_pages.h"

#include <stdint.h>
#include <stdlib.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

/* Blocks from this size on get the hint (smaller ones come from the heap,
 * already faulted in, or would not fill a huge page). */
#define HUGE_PAGE ((size_t)2 << 20)

void *zeroed_pages(size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size) return NULL;
    void *p = calloc(n ? n : 1, size ? size : 1);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    size_t bytes = n * size;
    if (p && bytes >= 4 * HUGE_PAGE) {
        /* the whole huge pages inside the block: a hint, its failure harmless */
        uintptr_t lo = ((uintptr_t)p + HUGE_PAGE - 1) & ~(uintptr_t)(HUGE_PAGE - 1);
        uintptr_t hi = ((uintptr_t)p + bytes) & ~(uintptr_t)(HUGE_PAGE - 1);
        if (hi > lo) (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
    }
#endif
    return p;
}
