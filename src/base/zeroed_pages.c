/* base/zeroed_pages: see zeroed_pages.h. */
#define _DEFAULT_SOURCE /* madvise */
#include "base/zeroed_pages.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

/* A transparent huge page on x86-64 Linux. */
#define HUGE_PAGE ((size_t)2 << 20)

/* Blocks from this size on get the hint: smaller ones mostly come from the
 * heap, already faulted in, and hold few whole huge pages. */
#define HINT_MIN (4 * HUGE_PAGE)

void *zeroed_pages(size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size) return NULL;
    void *p = calloc(n ? n : 1, size ? size : 1);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    size_t bytes = n * size;
    if (p && bytes >= HINT_MIN) {
        /* the whole huge pages inside the block: a hint, its failure harmless */
        uintptr_t lo = ((uintptr_t)p + HUGE_PAGE - 1) & ~(uintptr_t)(HUGE_PAGE - 1);
        uintptr_t hi = ((uintptr_t)p + bytes) & ~(uintptr_t)(HUGE_PAGE - 1);
        if (hi > lo) (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
    }
#endif
    /* zero from the first byte to the last (calloc's promise, kept) */
    assert(!p || !n || !size ||
           (((unsigned char *)p)[0] == 0 && ((unsigned char *)p)[n * size - 1] == 0));
    return p;
}
