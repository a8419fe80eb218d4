/* scaffold/scaffold_build: the scaffold triangulation around the charts.
 *
 * Collects the chart boundary vertices (in first-seen order of the edge
 * list, so the result is deterministic), adds the box points, hands points
 * and segments to cdt_triangulate with the chart edges unsplittable and
 * marked "chart on the left", and renumbers the output: CDT points that
 * are boundary vertices get their mesh id back, the others (box points and
 * Steiner points) become scaffold-only vertices numbered from nmesh on.
 * Errors of the mesher are passed on with a prefix.
 */
#include "scaffold/scaffold_build.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/cdt.h"
#include "scaffold/scaffold_defaults.h"

scaffold_options scaffold_default_options(void)
{
    scaffold_options o;
    o.box_scale = SCAFFOLD_DEFAULT_BOX_SCALE;
    o.box_square = 0;
    o.box_points_per_side = SCAFFOLD_DEFAULT_BOX_POINTS_PER_SIDE;
    o.min_angle_deg = SCAFFOLD_DEFAULT_MIN_ANGLE_DEG;
    o.box_splittable = 0;
    return o;
}

void scaffold_box(const double *uv, int nmesh, double scale, int square, double box[4])
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < nmesh; i++)
        for (int k = 0; k < 2; k++) {
            double x = uv[2 * (size_t)i + k];
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }
    if (nmesh == 0) lo[0] = lo[1] = hi[0] = hi[1] = 0.0;
    if (scale < 1.0) scale = 1.0;
    double half[2], mid[2];
    for (int k = 0; k < 2; k++) {
        mid[k] = 0.5 * (lo[k] + hi[k]);
        half[k] = 0.5 * (hi[k] - lo[k]);
    }
    /* A flat bbox side would give a flat box: widen it to the other side. */
    double longest = half[0] > half[1] ? half[0] : half[1];
    if (longest <= 0.0) longest = 1.0;
    for (int k = 0; k < 2; k++) {
        if (square || half[k] < 1e-3 * longest) half[k] = longest;
        /* Strictly outside the bbox even when scale is 1. */
        half[k] = half[k] * scale + 1e-9 * longest;
    }
    box[0] = mid[0] - half[0];
    box[1] = mid[1] - half[1];
    box[2] = mid[0] + half[0];
    box[3] = mid[1] + half[1];
}

void scaffold_free(scaffold *s)
{
    if (!s) return;
    free(s->extra_uv);
    free(s->extra_fixed);
    free(s->T);
    memset(s, 0, sizeof *s);
}

/* Which CDT points lie on the box boundary (exact coordinate tests: box
 * points and Steiner points inserted on box edges have an exact box
 * coordinate, since the box edges are axis-aligned). */
static int on_box(const double *p, const double box[4])
{
    return p[0] == box[0] || p[0] == box[2] || p[1] == box[1] || p[1] == box[3];
}

scaf_status scaffold_build(const double *uv, int nmesh, const int *edges, int nedges,
                           const double box[4], const scaffold_options *opt, scaffold *out,
                           scaf_error *err)
{
    memset(out, 0, sizeof *out);
    scaffold_options o = opt ? *opt : scaffold_default_options();
    int per_side = o.box_points_per_side < 1 ? 1 : o.box_points_per_side;
    scaf_status st = SCAF_OK;

    /* ---- boundary vertices: mesh id <-> CDT index ---------------------- */
    int *cdt_of = malloc(sizeof(int) * (size_t)(nmesh ? nmesh : 1));
    int *mesh_of = malloc(sizeof(int) * (size_t)(2 * nedges + 1));
    int npts_max = 2 * nedges + 4 * per_side;
    double *pts = malloc(sizeof(double) * 2 * (size_t)(npts_max ? npts_max : 1));
    int nseg = nedges + 4 * per_side;
    int *seg = malloc(sizeof(int) * 2 * (size_t)nseg);
    unsigned char *split = malloc((size_t)nseg);
    unsigned char *hole = malloc((size_t)nseg);
    cdt_output co = {0};
    if (!cdt_of || !mesh_of || !pts || !seg || !split || !hole) {
        st = err_nomem(err, "scaffold input");
        goto done;
    }
    for (int i = 0; i < nmesh; i++) cdt_of[i] = -1;
    int nb = 0;
    double min_edge2 = INFINITY;
    for (int e = 0; e < nedges; e++) {
        for (int j = 0; j < 2; j++) {
            int v = edges[2 * e + j];
            if (v < 0 || v >= nmesh) {
                st = err_set(err, SCAF_ERR_INTERNAL,
                             "scaffold: boundary edge %d references vertex %d of %d", e, v, nmesh);
                goto done;
            }
            if (cdt_of[v] < 0) {
                cdt_of[v] = nb;
                mesh_of[nb] = v;
                pts[2 * nb] = uv[2 * (size_t)v];
                pts[2 * nb + 1] = uv[2 * (size_t)v + 1];
                nb++;
            }
        }
        const double *a = uv + 2 * (size_t)edges[2 * e], *b = uv + 2 * (size_t)edges[2 * e + 1];
        double dx = a[0] - b[0], dy = a[1] - b[1];
        double l2 = dx * dx + dy * dy;
        if (l2 < min_edge2) min_edge2 = l2;
        seg[2 * e] = cdt_of[edges[2 * e]];
        seg[2 * e + 1] = cdt_of[edges[2 * e + 1]];
        split[e] = 0;
        hole[e] = 1;
    }
    for (int i = 0; i < nb; i++) {
        const double *p = pts + 2 * i;
        if (!(p[0] > box[0] && p[0] < box[2] && p[1] > box[1] && p[1] < box[3])) {
            st = err_set(err, SCAF_ERR_INTERNAL,
                         "scaffold: boundary vertex %d at (%g, %g) is not inside the box",
                         mesh_of[i], p[0], p[1]);
            goto done;
        }
    }

    /* ---- box: per_side points on each side, counter-clockwise ---------- */
    int nbox = 4 * per_side;
    double w = box[2] - box[0], h = box[3] - box[1];
    for (int i = 0; i < per_side; i++) {
        double t = (double)i / per_side;
        double *p = pts + 2 * (nb + i);
        p[0] = box[0] + t * w;
        p[1] = box[1]; /* bottom, left to right */
        p = pts + 2 * (nb + per_side + i);
        p[0] = box[2];
        p[1] = box[1] + t * h; /* right, bottom to top */
        p = pts + 2 * (nb + 2 * per_side + i);
        p[0] = box[2] - t * w;
        p[1] = box[3]; /* top, right to left */
        p = pts + 2 * (nb + 3 * per_side + i);
        p[0] = box[0];
        p[1] = box[3] - t * h; /* left, top to bottom */
    }
    for (int i = 0; i < nbox; i++) {
        int e = nedges + i;
        seg[2 * e] = nb + i;
        seg[2 * e + 1] = nb + (i + 1) % nbox;
        split[e] = (unsigned char)(o.box_splittable != 0);
        hole[e] = 0; /* the scaffold is on the left of the CCW box */
    }

    /* ---- triangulate ---------------------------------------------------- */
    cdt_input in;
    memset(&in, 0, sizeof in);
    in.npoints = nb + nbox;
    in.points = pts;
    in.nsegments = nseg;
    in.segments = seg;
    in.splittable = split;
    in.left_is_hole = hole;
    cdt_options co_opt = cdt_default_options();
    co_opt.min_angle_deg = o.min_angle_deg;
    st = cdt_triangulate(&in, &co_opt, &co, err);
    if (st != SCAF_OK) {
        err_prefix(err, "building the scaffold");
        goto done;
    }

    /* ---- renumber ------------------------------------------------------- */
    out->nmesh = nmesh;
    out->nextra = co.npoints - nb;
    out->extra_uv = malloc(sizeof(double) * 2 * (size_t)(out->nextra ? out->nextra : 1));
    out->extra_fixed = malloc((size_t)(out->nextra ? out->nextra : 1));
    out->T = malloc(sizeof(int) * 3 * (size_t)(co.ntriangles ? co.ntriangles : 1));
    if (!out->extra_uv || !out->extra_fixed || !out->T) {
        st = err_nomem(err, "scaffold");
        goto done;
    }
    for (int i = nb; i < co.npoints; i++) {
        const double *p = co.points + 2 * (size_t)i;
        out->extra_uv[2 * (i - nb)] = p[0];
        out->extra_uv[2 * (i - nb) + 1] = p[1];
        out->extra_fixed[i - nb] = (unsigned char)on_box(p, box);
    }
    out->ntri = co.ntriangles;
    for (int t = 0; t < co.ntriangles; t++)
        for (int j = 0; j < 3; j++) {
            int c = co.triangles[3 * t + j];
            out->T[3 * t + j] = c < nb ? mesh_of[c] : nmesh + (c - nb);
        }
    memcpy(out->box, box, sizeof out->box);
    out->min_edge = sqrt(min_edge2);
    out->eps = min_edge2 / 4.0;

done:
    cdt_output_free(&co);
    free(cdt_of);
    free(mesh_of);
    free(pts);
    free(seg);
    free(split);
    free(hole);
    if (st != SCAF_OK) scaffold_free(out);
    return st;
}
