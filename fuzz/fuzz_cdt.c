/* fuzz/fuzz_cdt: libFuzzer target for the scaffold mesher (geom/cdt).
 *
 * Input bytes: one option byte, a point count, then points (two signed
 * bytes each: a small lattice, so collinear and cocircular points and
 * points on segments are frequent; option bit 1 adds 1e-13-scale
 * perturbations from two more bytes), then segment index pairs with a flag
 * byte (splittable, left_is_hole). A box around everything is appended.
 * A success must give strictly counter-clockwise triangles with valid
 * indices, mutual neighbours, subsegments that are edges and unsplittable
 * segments that come out whole; a
 * failure must be SCAF_ERR_MESH with a message and an empty output.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geom/cdt.h"
#include "geom/predicates.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int has_edge(const cdt_output *o, int a, int b)
{
    for (int t = 0; t < o->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            int u = o->triangles[3 * t + (k + 1) % 3], w = o->triangles[3 * t + (k + 2) % 3];
            if ((u == a && w == b) || (u == b && w == a)) return 1;
        }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    size_t pos = 0;
    uint8_t opt_byte = data[pos++];
    int np = data[pos++] % 48;
    int per = (opt_byte & 2) ? 4 : 2;
    double pts[2 * 52];
    int n = 0;
    while (n < np && pos + (size_t)per <= size) {
        double x = (int8_t)data[pos], y = (int8_t)data[pos + 1];
        if (per == 4) {
            x += (int8_t)data[pos + 2] * 1e-13;
            y += (int8_t)data[pos + 3] * 1e-13;
        }
        pos += (size_t)per;
        pts[2 * n] = x;
        pts[2 * n + 1] = y;
        n++;
    }
    int segs[2 * 68];
    unsigned char split[68], hole[68];
    int ns = 0;
    while (n > 1 && ns < 64 && pos + 3 <= size) {
        int a = data[pos] % n, b = data[pos + 1] % n;
        uint8_t f = data[pos + 2];
        pos += 3;
        segs[2 * ns] = a;
        segs[2 * ns + 1] = b;
        split[ns] = f & 1;
        hole[ns] = (f >> 1) & 1;
        ns++;
    }
    /* the box */
    double box[8] = {-200, -200, 200, -200, 200, 200, -200, 200};
    for (int i = 0; i < 4; i++) {
        pts[2 * (n + i)] = box[2 * i];
        pts[2 * (n + i) + 1] = box[2 * i + 1];
        segs[2 * ns] = n + i;
        segs[2 * ns + 1] = n + (i + 1) % 4;
        split[ns] = 1;
        hole[ns] = 0;
        ns++;
    }
    n += 4;
    cdt_input in = {n, pts, ns, segs, split, hole, 0, NULL};
    cdt_options opt = cdt_default_options();
    opt.min_angle_deg = (opt_byte & 4) ? 0 : (opt_byte & 8) ? 33 : 20;
    opt.max_area = (opt_byte & 16) ? 400.0 : 0.0;
    opt.max_steiner = 1000;
    cdt_output out;
    scaf_error err;
    err_clear(&err);
    scaf_status s = cdt_triangulate(&in, &opt, &out, &err);
    if (s != SCAF_OK) {
        if (s != SCAF_ERR_MESH || err.message[0] == '\0' || out.triangles || out.ntriangles)
            abort();
        return 0;
    }
    for (int i = 0; i < n; i++)
        if (out.points[2 * i] != pts[2 * i] || out.points[2 * i + 1] != pts[2 * i + 1]) abort();
    for (int t = 0; t < out.ntriangles; t++) {
        const int *v = out.triangles + 3 * t;
        for (int k = 0; k < 3; k++)
            if (v[k] < 0 || v[k] >= out.npoints) abort();
        if (!(orient2d(out.points + 2 * v[0], out.points + 2 * v[1], out.points + 2 * v[2]) > 0))
            abort();
        for (int k = 0; k < 3; k++) {
            int nb = out.neighbors[3 * t + k];
            if (nb < -1 || nb >= out.ntriangles) abort();
            if (nb >= 0 && out.neighbors[3 * nb] != t && out.neighbors[3 * nb + 1] != t &&
                out.neighbors[3 * nb + 2] != t)
                abort();
        }
    }
    /* subsegments are edges; an unsplittable segment is one whole subsegment */
    for (int i = 0; i < out.nsubsegments; i++) {
        int sg = out.subsegment_of[i], u = out.subsegments[2 * i], w = out.subsegments[2 * i + 1];
        if (sg < 0 || sg >= ns || !has_edge(&out, u, w)) abort();
        if (!split[sg] &&
            !((u == segs[2 * sg] && w == segs[2 * sg + 1]) ||
              (w == segs[2 * sg] && u == segs[2 * sg + 1])))
            abort();
    }
    cdt_output_free(&out);
    return 0;
}
