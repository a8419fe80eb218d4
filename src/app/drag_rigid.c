/* app/drag_rigid: the drag API's rigid motions (scaf_drag_rigid_* and
 * scaf_drag_transform in include/scaf/drag.h).
 *
 * A frame: the grab pose copied, the selection moved by the similarity,
 * the other charts translated out of the way (app/rigid_push) with the
 * padding the loop's test asks at that layout (atlas_padding_need, times
 * a small margin), in rounds while the layout grows; then decided
 * exactly: every triangle of a moved chart positive (orient2d), the
 * loop's padding test, and the saved output's certificate
 * (atlas_output_verify: the exact checker and the exact padding
 * certificate), whose result becomes the context's verified output. A
 * frame that fails is retried on a fraction of the motion (bisection), so
 * what is kept is always a layout the steps and the save accept.
 *
 * Fails: SCAF_ERR_USAGE for bad arguments (nothing changed),
 * SCAF_ERR_NOMEM (the grab pose is put back).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app/drag_ctx.h"
#include "app/rigid_push.h"
#include "geom/chart_gap.h"
#include "geom/predicates.h"

#define PUSH_MARGIN                                                                                \
    1.0001           /* pushes keep this times the padding need, so a
                              layout that grows a little needs no new round */
#define MAX_ROUNDS 8 /* pushes again while the layout grows */
#define HALVINGS 8   /* bisection of a motion that fails */
#define FACTOR_MAX 1024.0

typedef struct drag_rigid {
    rigid_charts rc;
    int active;
    double *grab; /* nw by 2 */
    int grab_iter;
    unsigned char *sel, *fixed, *moved; /* ncharts */
    unsigned char *early;               /* ncharts: selected, not the anchor */
    int anchor;                         /* the selected chart that never moves
                                           relative to the motion */
    double centroid[2];                 /* the selection's, at the grab */
} drag_rigid;

void drag_rigid_free(scaf_drag_t *d)
{
    drag_rigid *r = d->rigid;
    if (!r) return;
    rigid_charts_free(&r->rc);
    free(r->grab);
    free(r->sel);
    free(r->fixed);
    free(r->moved);
    free(r->early);
    free(r);
    d->rigid = NULL;
}

static drag_rigid *rigid_of(scaf_drag_t *d)
{
    if (d->rigid) return d->rigid;
    drag_rigid *r = calloc(1, sizeof *r);
    if (!r) return NULL;
    size_t nc = (size_t)d->at.ncharts + 1;
    r->grab = malloc(sizeof(double) * 2 * (size_t)(d->at.nw ? d->at.nw : 1));
    r->sel = malloc(nc);
    r->fixed = malloc(nc);
    r->moved = malloc(nc);
    r->early = malloc(nc);
    scaf_error e;
    err_clear(&e);
    d->rigid = r;
    if (!r->grab || !r->sel || !r->fixed || !r->moved || !r->early ||
        rigid_charts_init(&r->rc, d->at.wchart, d->at.nw, d->at.ncharts, d->at.seg, d->at.nseg,
                          &e) != SCAF_OK) {
        drag_rigid_free(d);
        return NULL;
    }
    return r;
}

scaf_drag_motion_t scaf_drag_motion_identity(void)
{
    scaf_drag_motion_t m;
    memset(&m, 0, sizeof m);
    m.factor = 1.0;
    m.flip = SCAF_DRAG_FLIP_NONE;
    return m;
}

scaf_status scaf_drag_rigid_begin(scaf_drag_t *d, const int *charts, int n)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    if (!d->has_mesh)
        return err_set(&d->err, SCAF_ERR_USAGE, "no mesh: call scaf_drag_set_mesh first");
    if (!charts || n < 1)
        return err_set(&d->err, SCAF_ERR_USAGE, "no charts to move: give at least one chart id");
    int nc = d->at.ncharts;
    for (int i = 0; i < n; i++)
        if (charts[i] < 0 || charts[i] >= nc)
            return err_set(&d->err, SCAF_ERR_USAGE,
                           "chart %d does not exist: the layout has %d (0..%d)", charts[i], nc,
                           nc - 1);
    drag_rigid *r = rigid_of(d);
    if (!r) return err_nomem(&d->err, "rigid motion");
    memset(r->fixed, 0, (size_t)nc);
    for (int v = 0; v < d->at.nw; v++)
        if (scaf_loop_pinned(&d->at.loop, v)) r->fixed[d->at.wchart[v]] = 1;
    for (int i = 0; i < n; i++)
        if (r->fixed[charts[i]]) {
            r->active = 0;
            return err_set(&d->err, SCAF_ERR_USAGE,
                           "chart %d has a pinned vertex: it cannot move (unpin it first)",
                           charts[i]);
        }
    /* the selection moves rigidly; as the padding is relative to the
     * layout's side, a motion that grows the layout needs every gap to
     * grow, those inside the selection too: the selection's charts but
     * the first are pushable, placed before any other chart, so they move
     * off the motion only by such small translations (or when a scale
     * below 1 brings two of them too close) */
    memset(r->sel, 0, (size_t)nc);
    memset(r->early, 0, (size_t)nc);
    r->anchor = charts[0];
    for (int i = 0; i < n; i++) r->sel[charts[i]] = r->early[charts[i]] = 1;
    r->fixed[r->anchor] = 1;
    r->early[r->anchor] = 0;
    memcpy(r->grab, d->at.loop.uv, sizeof(double) * 2 * (size_t)d->at.nw);
    r->grab_iter = d->at.loop.iterations;
    /* the pivot: area-weighted centroid of the selection's UV triangles */
    double sx = 0.0, sy = 0.0, sa = 0.0;
    for (int f = 0; f < d->at.nf; f++) {
        if (!r->sel[d->at.chart[f]]) continue;
        const int *t = d->at.Fw + 3 * f;
        const double *p = r->grab + 2 * t[0], *q = r->grab + 2 * t[1], *s = r->grab + 2 * t[2];
        double ar = 0.5 * ((q[0] - p[0]) * (s[1] - p[1]) - (q[1] - p[1]) * (s[0] - p[0]));
        sx += ar * (p[0] + q[0] + s[0]) / 3.0;
        sy += ar * (p[1] + q[1] + s[1]) / 3.0;
        sa += ar;
    }
    r->centroid[0] = sa > 0.0 ? sx / sa : 0.0;
    r->centroid[1] = sa > 0.0 ? sy / sa : 0.0;
    r->active = 1;
    /* cancel goes back to the grab pose */
    memcpy(d->before.uv, r->grab, sizeof(double) * 2 * (size_t)d->at.nw);
    d->before.iterations = r->grab_iter;
    d->has_before = 1;
    return SCAF_OK;
}

scaf_status scaf_drag_rigid_end(scaf_drag_t *d)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    if (d->rigid) d->rigid->active = 0;
    return SCAF_OK;
}

/* Every triangle of a moved chart exactly positive. */
static int moved_positive(const scaf_drag_t *d, const unsigned char *moved)
{
    const double *X = d->at.loop.uv;
    for (int f = 0; f < d->at.nf; f++) {
        if (!moved[d->at.chart[f]]) continue;
        const int *t = d->at.Fw + 3 * f;
        if (!(orient2d(X + 2 * t[0], X + 2 * t[1], X + 2 * t[2]) > 0.0)) return 0;
    }
    return 1;
}

/* The layout of fraction t of motion m into the loop, decided exactly:
 * 1 kept (and the verified output with it), 0 refused, -1 out of memory. */
static int frame(scaf_drag_t *d, const scaf_drag_motion_t *m, double t)
{
    drag_rigid *r = d->rigid;
    double *X = d->at.loop.uv;
    int nw = d->at.nw;
    memcpy(X, r->grab, sizeof(double) * 2 * (size_t)nw);
    const double *piv = m->has_pivot ? m->pivot : r->centroid;
    double a = t * m->angle, f = pow(m->factor, t),
           mir = m->flip != SCAF_DRAG_FLIP_NONE ? -1.0 : 1.0;
    double c = f * cos(a) * mir, s = f * sin(a) * mir;
    double tx = t * m->dx, ty = t * m->dy;
    int identity = t == 0.0 || (a == 0.0 && f == 1.0 && mir == 1.0 && tx == 0.0 && ty == 0.0);
    if (!identity)
        for (int v = 0; v < nw; v++) {
            if (!r->sel[d->at.wchart[v]]) continue;
            double px = X[2 * v] - piv[0], py = X[2 * v + 1] - piv[1];
            X[2 * v] = piv[0] + (c * px - s * py) + tx;
            X[2 * v + 1] = piv[1] + (s * px + c * py) + ty;
        }
    scaf_error e;
    err_clear(&e);
    int nc = d->at.ncharts;
    unsigned char *any = r->moved; /* charts moved in any round */
    if (identity) memset(any, 0, (size_t)nc);
    else memcpy(any, r->sel, (size_t)nc);
    if (nc > 1) {
        unsigned char *round = malloc((size_t)nc);
        if (!round) return -1;
        double need = atlas_padding_need(&d->at, X);
        int ok = 0;
        const double dir[2] = {tx, ty};
        for (int k = 0; k < MAX_ROUNDS && !ok; k++) {
            /* (padding 0: charts only must not touch) */
            double keep = fmax(need * PUSH_MARGIN, 0x1p-40 * atlas_side(&d->at));
            if (rigid_push(&r->rc, X, r->fixed, r->early, r->centroid, dir, keep, round, &e) !=
                SCAF_OK) {
                free(round);
                return -1;
            }
            for (int i = 0; i < nc; i++) any[i] |= round[i];
            need = atlas_padding_need(&d->at, X);
            ok = need < keep; /* the layout did not outgrow the pushes */
            if (!(d->opt.padding > 0.0)) break;
        }
        free(round);
        double g;
        if (!(d->opt.padding > 0.0)) ok = 1, need = 0.0;
        if (!ok ||
            chart_gap_min_segments(X, d->at.seg, d->at.nseg, need, &g, NULL, &e) != SCAF_OK ||
            !(g > need))
            return 0;
    }
    if (!moved_positive(d, any)) return 0;
    err_clear(&e);
    scaf_status st = atlas_output_verify(&d->at, d->UVn, &d->out, &e);
    if (st == SCAF_ERR_NOMEM) return -1;
    if (st != SCAF_OK) return 0;
    d->out_state = 1; /* the verified output of this very layout */
    return 1;
}

scaf_status scaf_drag_rigid_move(scaf_drag_t *d, const scaf_drag_motion_t *m, double *reached)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    if (reached) *reached = 0.0;
    if (!d->has_mesh || !d->rigid || !d->rigid->active)
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "no grab: call scaf_drag_rigid_begin with the charts to move first");
    if (!m) return err_set(&d->err, SCAF_ERR_USAGE, "motion is NULL");
    const double num[4] = {m->dx, m->dy, m->angle, m->factor};
    for (int k = 0; k < 4; k++)
        if (!isfinite(num[k]))
            return err_set(&d->err, SCAF_ERR_USAGE, "motion: %s is not finite",
                           (const char *[]){"dx", "dy", "angle", "factor"}[k]);
    if (m->has_pivot && !(isfinite(m->pivot[0]) && isfinite(m->pivot[1])))
        return err_set(&d->err, SCAF_ERR_USAGE, "motion: the pivot is not finite");
    if (!(m->factor >= 1.0 / FACTOR_MAX && m->factor <= FACTOR_MAX))
        return err_set(&d->err, SCAF_ERR_USAGE, "motion: factor %g is out of [1/%g, %g]", m->factor,
                       FACTOR_MAX, FACTOR_MAX);
    if ((int)m->flip < 0 || m->flip > SCAF_DRAG_FLIP_V)
        return err_set(&d->err, SCAF_ERR_USAGE, "motion: flip %d is not a scaf_drag_flip",
                       (int)m->flip);
    if (m->flip != SCAF_DRAG_FLIP_NONE && !m->remirror)
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "flip refused: a mirror turns every triangle of the charts clockwise, so "
                       "the layout would not be bijective and could not be saved; set remirror "
                       "to apply it as a half turn (mirrored back across the other axis)");
    drag_ctx_changed(d);
    drag_cap_reset(d);
    int k = frame(d, m, 1.0);
    double lo = 0.0;
    if (k == 0 && m->flip == SCAF_DRAG_FLIP_NONE) {
        double hi = 1.0;
        for (int i = 0; i < HALVINGS && k >= 0; i++) {
            double mid = 0.5 * (lo + hi);
            k = frame(d, m, mid);
            if (k > 0) lo = mid;
            else hi = mid;
        }
        if (k >= 0 && lo > 0.0) k = frame(d, m, lo); /* the last one tried may have failed */
    } else if (k > 0) {
        lo = 1.0;
    }
    if (k < 0 || lo == 0.0) {
        memcpy(d->at.loop.uv, d->rigid->grab, sizeof(double) * 2 * (size_t)d->at.nw);
        d->out_state = 0;
        if (k < 0) return err_nomem(&d->err, "rigid motion");
    }
    d->at.loop.iterations = d->rigid->grab_iter;
    if (reached) *reached = lo;
    return SCAF_OK;
}

scaf_status scaf_drag_transform(scaf_drag_t *d, const int *charts, int n,
                                const scaf_drag_motion_t *m, double *reached)
{
    scaf_status st = scaf_drag_rigid_begin(d, charts, n);
    if (st != SCAF_OK) return st;
    st = scaf_drag_rigid_move(d, m, reached);
    if (d->rigid) d->rigid->active = 0;
    return st;
}
