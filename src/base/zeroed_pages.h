/* base/zeroed_pages: a large zeroed array written once, in huge pages
 * where the kernel offers them.
 *
 * calloc maps a large block straight from the kernel (zero, untouched),
 * and each first write to a 4 KB page then faults: on this project's
 * virtual machines ~12 us a fault, a third of a large factorization's
 * time when its values are fresh. Asking for transparent huge pages
 * (Linux, madvise mode) makes that one fault per 2 MB. Free with free().
 */
#ifndef SCAF_BASE_ZEROED_PAGES_H
#define SCAF_BASE_ZEROED_PAGES_H

#include <stddef.h>

/* calloc(n, size), with the huge-page hint when the block is large;
 * NULL when out of memory. */
void *zeroed_pages(size_t n, size_t size);

#endif /* SCAF_BASE_ZEROED_PAGES_H */
