/* tests/geom/cdt_uv_boundary: a mesher input from the UV charts of a mesh.
 *
 * Header-only (static functions), shared by the tests and bench_cdt. The
 * chart boundary edges of the vt triangulation (edges used by one face,
 * oriented so the chart lies on their left, as face orientation in UV
 * says) become unsplittable chart segments; their end points are added in
 * order of first use; the 3x scaffold box follows. All boundary segments
 * form one pseudo-loop of the builder, enough for its winding test.
 * Fails only when memory runs out (returns 0; the builder is then empty).
 */
#ifndef SCAF_TESTS_CDT_UV_BOUNDARY_H
#define SCAF_TESTS_CDT_UV_BOUNDARY_H

#include "cdt_check.h" /* same folder: also found from bench/ */
#include "geom/predicates.h"
#include "mesh/mesh.h"

/* One face side of the vt triangulation: a -> b, the face's UV orientation
 * (ccw), and the sorted ends (lo, hi) to find the side's twins. */
typedef struct cb_uv_side {
    int a, b, ccw, lo, hi;
} cb_uv_side;

static inline int cb_uv_side_cmp(const void *x, const void *y)
{
    const cb_uv_side *p = x, *q = y;
    if (p->lo != q->lo) return p->lo < q->lo ? -1 : 1;
    return (p->hi > q->hi) - (p->hi < q->hi);
}

/* b := the UV chart boundaries of m (which has UVs: m->FT, m->UV) and the
 * 3x box. Returns 1, or 0 when out of memory. */
static inline int cb_uv_boundary(const mesh *m, cdt_builder *b)
{
    cb_init(b);
    cb_uv_side *e = malloc((size_t)m->nf * 3 * sizeof *e + 1);
    int *map = malloc((size_t)m->nuv * sizeof(int) + 1);
    if (!e || !map) {
        free(e);
        free(map);
        return 0;
    }
    for (int f = 0; f < m->nf; f++) {
        const int *t = m->FT + 3 * f;
        double o = orient2d(m->UV + 2 * t[0], m->UV + 2 * t[1], m->UV + 2 * t[2]);
        for (int k = 0; k < 3; k++) {
            cb_uv_side *q = e + 3 * f + k;
            q->a = t[k];
            q->b = t[(k + 1) % 3];
            q->ccw = o >= 0;
            q->lo = q->a < q->b ? q->a : q->b;
            q->hi = q->a < q->b ? q->b : q->a;
        }
    }
    qsort(e, (size_t)m->nf * 3, sizeof *e, cb_uv_side_cmp);
    for (int i = 0; i < m->nuv; i++) map[i] = -1;
    b->loop_start[0] = 0;
    b->nloops = 1;
    for (int i = 0; i < 3 * m->nf;) {
        int j = i;
        while (j < 3 * m->nf && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        if (j - i == 1) {
            int ends[2] = {e[i].ccw ? e[i].a : e[i].b, e[i].ccw ? e[i].b : e[i].a};
            for (int k = 0; k < 2; k++)
                if (map[ends[k]] < 0)
                    map[ends[k]] = cb_point(b, m->UV[2 * ends[k]], m->UV[2 * ends[k] + 1]);
            cb_segment(b, map[ends[0]], map[ends[1]], 0, 1);
        }
        i = j;
    }
    b->loop_len[0] = b->ns;
    free(e);
    free(map);
    cb_box(b, 3.0, NULL);
    return 1;
}

#endif /* SCAF_TESTS_CDT_UV_BOUNDARY_H */
