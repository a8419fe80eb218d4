/* mesh/uv_charts: the charts a parametrization works on, and whether each
 * one can be embedded (a disk, or a disk with holes).
 *
 * With UVs (mesh_has_uv), a chart is a set of faces connected through
 * shared vt-index edges: the mesh cut along its UV seams. The chart's
 * surface lives in vt-index space (FT): its boundary loops, Euler
 * characteristic and manifoldness are those of the triangles FT. Without
 * UVs, the charts are the connected components and the index space is the
 * 3D vertices (F). Either way, every loop vertex is given both as a 3D
 * vertex index and (with UVs) as a vt index.
 *
 * Loops of a chart are listed longest first (3D length): for a disk with
 * holes the first one is the likely outer boundary, which the caller may
 * decide otherwise. Ordered loops run with the chart on their left when
 * its faces are counter-clockwise. Faces whose vt indices are missing or
 * repeated ("invalid" in mesh/edges.h) make their chart fail the check.
 */
#ifndef SCAF_MESH_UV_CHARTS_H
#define SCAF_MESH_UV_CHARTS_H

#include "base/error.h"
#include "mesh/complex.h"
#include "mesh/mesh.h"

typedef struct mesh_charts {
    int uses_uv; /* 1: index space = vt (FT); 0: vertices (F) */
    int ncharts;
    tri_complex cx;          /* over FT or F, groups = charts: cx.face_group[f] is the
                              chart of face f, cx.group_faces its faces, cx.group_* stats */
    int *loop_v;             /* per loop vertex, CSR by cx.loop_start: 3D vertex index */
    int *loop_vt;            /* same positions: vt index, or -1 when !uses_uv */
    double *loop_length;     /* #loops 3D length of each loop */
    int *chart_loop_start;   /* ncharts+1: loops of chart c are                    */
    int *chart_loops;        /*   chart_loops[chart_loop_start[c] .. [c+1]-1], longest first */
    int *chart_vertex_start; /* ncharts+1: the distinct indices (vt, or vertices   */
    int *chart_vertices;     /*   without UVs) used by chart c's valid faces, ascending:
                                chart_vertices[chart_vertex_start[c] .. [c+1]-1] */
} mesh_charts;

/* What a chart is, topologically (in its own index space). */
typedef enum mesh_chart_kind {
    MESH_CHART_DISK = 0,        /* manifold, oriented, genus 0, one loop */
    MESH_CHART_DISK_WITH_HOLES, /* manifold, oriented, genus 0, >1 loops */
    MESH_CHART_CLOSED,          /* no boundary */
    MESH_CHART_HIGHER_GENUS,    /* handles (genus > 0) */
    MESH_CHART_NON_MANIFOLD,    /* a non-manifold edge or vertex, or invalid faces */
    MESH_CHART_MISORIENTED,     /* faces disagree in orientation */
    MESH_CHART_NON_ORIENTABLE   /* no consistent orientation exists */
} mesh_chart_kind;

/* Label faces by UV chart. face_chart: #F output (charts numbered in order
 * of their first face); *ncharts receives the count. */
scaf_status mesh_uv_chart_labels(const mesh *m, int *face_chart, int *ncharts, scaf_error *err);

/* Compute charts, their face lists and ordered boundary loops. On failure
 * *c is left empty. */
scaf_status mesh_charts_compute(const mesh *m, mesh_charts *c, scaf_error *err);

/* Free and reset to empty. Safe on an empty (zeroed) struct. */
void mesh_charts_free(mesh_charts *c);

/* Classify chart `chart` (0 <= chart < c->ncharts). */
mesh_chart_kind mesh_chart_classify(const mesh_charts *c, int chart);

/* SCAF_OK if the chart can be embedded: a disk, or with allow_holes also a
 * disk with holes. Otherwise SCAF_ERR_MESH with a message naming the chart
 * and the reason (the offending edge / vertex, the genus, ...). */
scaf_status mesh_chart_check(const mesh_charts *c, int chart, int allow_holes, scaf_error *err);

/* Boundary loop i (0 <= i < number of loops of the chart, longest first)
 * of chart `chart`: returns its length in vertices and points *v at its
 * 3D vertex indices and *vt at its vt indices (all -1 without UVs), in
 * loop order. Ordered loops (c->cx.loop_ordered[id]) run with the chart on
 * their left; *id (may be NULL) receives the loop's global id. Returns 0
 * when i is out of range. */
int mesh_chart_loop(const mesh_charts *c, int chart, int i, const int **v, const int **vt, int *id);

/* A short static English name of a kind ("disk", "closed", ...). */
const char *mesh_chart_kind_name(mesh_chart_kind kind);

#endif /* SCAF_MESH_UV_CHARTS_H */
