/* fuzz/fuzz_topology: libFuzzer target for mesh/topology and mesh/uv_charts.
 *
 * The input is parsed like fuzz_mesh_parse (first byte picks the format);
 * every mesh that parses goes through mesh_topology_compute and
 * mesh_charts_compute, and each chart through mesh_chart_check. Besides
 * the sanitizers' checks, the report must be self-consistent: chi = V - E
 * + F summed over components, boundary loops partition the boundary edges,
 * ordered loops close up; anything else aborts.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "mesh/uv_charts.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_complex(const tri_complex *cx, const int *F)
{
    int loops = 0;
    for (int g = 0; g < cx->ngroups; g++) {
        loops += cx->group_loops[g];
        if (cx->group_genus[g] < -1) abort();
    }
    if (loops != cx->nloops) abort();
    if (cx->loop_start[cx->nloops] != cx->boundary_edges) abort();
    for (int l = 0; l < cx->nloops; l++) {
        int s = cx->loop_start[l], t = cx->loop_start[l + 1];
        if (t <= s) abort();
        if (!cx->loop_ordered[l]) continue;
        for (int i = s; i < t; i++) {
            int h = cx->loop_he[i], hn = cx->loop_he[i + 1 < t ? i + 1 : s];
            if (he_to(F, h) != F[hn]) abort();
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    static const mesh_format formats[4] = {MESH_FORMAT_OBJ, MESH_FORMAT_OFF, MESH_FORMAT_PLY,
                                           MESH_FORMAT_UNKNOWN};
    mesh m;
    scaf_error err;
    if (mesh_parse((const char *)data + 1, size - 1, formats[data[0] % 4], "fuzz", &m, NULL,
                   &err) != SCAF_OK)
        return 0;
    mesh_topology t;
    if (mesh_topology_compute(&m, &t, &err) != SCAF_OK) abort();
    if (t.vertices + t.unreferenced_vertices != m.nv || t.faces != m.nf) abort();
    int chi = 0;
    for (int c = 0; c < t.components; c++) chi += t.cx.group_euler[c];
    if (chi != t.euler_characteristic) abort();
    /* no invalid faces reach topology from a reader: V - E + F exactly */
    if (t.cx.edges.invalid_faces == 0 && chi != t.vertices - t.edges + t.faces) abort();
    check_complex(&t.cx, m.F);
    mesh_topology_free(&t);

    mesh_charts c;
    if (mesh_charts_compute(&m, &c, &err) != SCAF_OK) abort();
    check_complex(&c.cx, c.uses_uv ? m.FT : m.F);
    for (int k = 0; k < c.ncharts; k++) {
        scaf_status s = mesh_chart_check(&c, k, 1, &err);
        mesh_chart_kind kind = mesh_chart_classify(&c, k);
        if ((s == SCAF_OK) != (kind == MESH_CHART_DISK || kind == MESH_CHART_DISK_WITH_HOLES))
            abort();
        if (kind == MESH_CHART_DISK && c.cx.group_loops[k] != 1) abort();
        const int *v, *vt;
        for (int i = 0; mesh_chart_loop(&c, k, i, &v, &vt, NULL) > 0; i++)
            if (v[0] < 0 || v[0] >= m.nv) abort();
    }
    mesh_charts_free(&c);
    mesh_free(&m);
    return 0;
}
