/* base/min_heap: see min_heap.h. */
#include "base/min_heap.h"

#include <stdlib.h>

static int item_less(min_heap_item x, min_heap_item y)
{
    return x.key < y.key || (x.key == y.key && x.id < y.id);
}

int min_heap_push(min_heap *h, double key, int id)
{
    if (h->n == h->cap) {
        int cap = h->cap ? 2 * h->cap : 256;
        min_heap_item *a = realloc(h->a, sizeof *a * (size_t)cap);
        if (!a) return 0;
        h->a = a;
        h->cap = cap;
    }
    int i = h->n++;
    min_heap_item x = {key, id};
    while (i > 0) {
        int p = (i - 1) / 2;
        if (!item_less(x, h->a[p])) break;
        h->a[i] = h->a[p];
        i = p;
    }
    h->a[i] = x;
    return 1;
}

min_heap_item min_heap_pop(min_heap *h)
{
    min_heap_item top = h->a[0], x = h->a[--h->n];
    int i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && item_less(h->a[c + 1], h->a[c])) c++;
        if (!item_less(h->a[c], x)) break;
        h->a[i] = h->a[c];
        i = c;
    }
    if (h->n > 0) h->a[i] = x;
    return top;
}

void min_heap_free(min_heap *h)
{
    free(h->a);
    h->a = NULL;
    h->n = h->cap = 0;
}
