/* opt/fill_split: which columns each thread of a parallel fill writes,
 * batch by batch.
 *
 * A parallel fill (opt/proxy_block, opt/newton_fill) takes its simplices in
 * batches; within a batch thread k writes only the vertex columns
 * [cb[k], cb[k+1]) and the rhs entries of those dofs, so no two threads
 * write one value and every value receives its terms in simplex order (the
 * serial fill's numbers, bit for bit). The split is the batch's own: its
 * columns are cut where the batch's writes are halved (thirded, ...). One
 * split for the whole set would leave a thread idle whenever a batch's
 * simplices share a neighbourhood, as the chart's do once ordered by their
 * last vertex (opt_simplices_order_by_last_vertex): their writes then all
 * fall in one thread's columns.
 */
#ifndef SCAF_OPT_FILL_SPLIT_H
#define SCAF_OPT_FILL_SPLIT_H

#include <stddef.h>

#include "opt/simplices.h"

/* Simplices per batch of the parallel fills (one table serves the SLIM
 * and the Newton fill); between batches every thread waits. */
#define OPT_FILL_BATCH 65536

typedef struct opt_fill_split {
    int nc;       /* ranges per batch; 0: nothing cached */
    size_t batch; /* simplices per batch */
    size_t n;     /* simplices of the set */
    int *cb;      /* per batch nc + 1 values: cb[0] = 0, cb[nc] = INT_MAX */
} opt_fill_split;

/* Make f hold the splits of S's simplices (vertex dofs dof, -1 fixed) in
 * batches of `batch` into nc ranges; keeps what f holds when it was made
 * for the same nc, batch and set size (the caller frees f whenever the set
 * or the numbering change: a proxy block does so with its pattern).
 * Returns 0, or -1 when memory runs out (f is then empty). */
int opt_fill_split_prepare(opt_fill_split *f, const opt_simplices *S, const int *dof, int nc,
                           size_t batch);

/* The nc + 1 range bounds of the batch that starts at simplex b0. */
static inline const int *opt_fill_split_ranges(const opt_fill_split *f, size_t b0)
{
    return f->cb + (b0 / f->batch) * (size_t)(f->nc + 1);
}

/* Whether simplex s of S has a corner with a dof in [lo, hi). */
int opt_fill_split_touches(const opt_simplices *S, int s, const int *dof, int lo, int hi);

/* Free f's table; safe on a zeroed one. */
void opt_fill_split_free(opt_fill_split *f);

#endif /* SCAF_OPT_FILL_SPLIT_H */
