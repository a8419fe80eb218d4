/* scaffold/scaffold_build: the scaffold triangulation around the charts.
 *
 * SCAF embeds the UV charts in a box and fills the space between the box
 * and the charts (including chart holes and the gaps between charts) with
 * triangles: the scaffold. Built with the constrained Delaunay mesher
 * (geom/cdt) from the chart boundary edges (kept whole: no Steiner point
 * on a chart edge) and the box edges (which may be split), refined to a
 * minimum angle (wherever the fixed edges allow). Scaffold triangles reference mesh vertex ids for chart
 * boundary vertices and new ids (>= nmesh) for box and Steiner points, so
 * the scaffold and the mesh share the boundary vertices.
 *
 * Fails with SCAF_ERR_MESH when the boundary edges cross or touch (the map
 * is then not bijective: cannot happen inside the SCAF loop) and with
 * SCAF_ERR_NOMEM.
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_BUILD_H
#define SCAF_SCAFFOLD_SCAFFOLD_BUILD_H

#include <stddef.h>

#include "base/error.h"

typedef struct scaffold_options {
    double box_scale;        /* box = scale * UV bounding box (3) */
    int box_square;          /* 1: square box around the bbox center (0) */
    int box_points_per_side; /* points per side including one corner (5) */
    double min_angle_deg;    /* CDT quality bound (20) */
    int box_splittable;      /* 1: Steiner points may go on the box edges;
                                0: the box keeps its points, like Triangle's
                                -YY in the reference implementation (0) */
} scaffold_options;

scaffold_options scaffold_default_options(void);

typedef struct scaffold {
    int nmesh;                  /* ids < nmesh are mesh vertices */
    int nextra;                 /* scaffold-only vertices: ids nmesh .. nmesh+nextra-1 */
    double *extra_uv;           /* nextra by 2 positions of the scaffold-only vertices */
    unsigned char *extra_fixed; /* nextra flags: 1 = on the box boundary */
    int ntri;                   /* |S| */
    int *T;                     /* ntri by 3 vertex ids, counter-clockwise in UV */
    double box[4];              /* xmin, ymin, xmax, ymax of the box */
    double min_edge;            /* l: shortest chart boundary edge length in UV */
    double eps;                 /* l^2 / 4: degeneracy guard area */
} scaffold;

/* The box around the UV positions of the listed vertices (all nmesh when
 * ids is NULL): `scale` times their bounding box around its center; with
 * `square`, a square of side scale * the longest bbox side. A zero-size
 * bbox side is widened so the box never degenerates.
 *   uv   nmesh by 2 positions
 *   box  out: xmin, ymin, xmax, ymax */
void scaffold_box(const double *uv, int nmesh, double scale, int square, double box[4]);

/* Build the scaffold around the charts.
 *   uv      nmesh by 2 current UV positions of the mesh vertices
 *   edges   nedges by 2 chart boundary edges a->b oriented with their
 *           chart on the left (as in the counter-clockwise face)
 *   box     xmin, ymin, xmax, ymax; must strictly contain every boundary
 *           vertex
 *   out     filled on success (free with scaffold_free); empty on failure */
scaf_status scaffold_build(const double *uv, int nmesh, const int *edges, int nedges,
                           const double box[4], const scaffold_options *opt, scaffold *out,
                           scaf_error *err);

void scaffold_free(scaffold *s);

/* Position of vertex id (mesh or scaffold-only). */
static inline const double *scaffold_pos(const scaffold *s, const double *uv, int id)
{
    return id < s->nmesh ? uv + 2 * (size_t)id : s->extra_uv + 2 * (size_t)(id - s->nmesh);
}

#endif /* SCAF_SCAFFOLD_SCAFFOLD_BUILD_H */
