/* mesh/spiral_strip: the stress test of the SCAF paper's Figure 4.
 *
 * A thin planar strip along a circle (radius 1, width SPIRAL_STRIP_WIDTH,
 * cut open by one segment's gap so it is a disk): n segments, 2(n + 1)
 * vertices (inner, outer per station), 2n triangles, counter-clockwise,
 * z = 0. The paper's Table 1 has 54 vertices and 52 triangles: n = 26.
 * The targets wind it into a spiral of SPIRAL_STRIP_TURNS turns inside
 * the circle: the centre line keeps its start and its length, its
 * curvature grows linearly along it (see spiral_strip.c), the inner /
 * outer vertex of each station half a width to its left / right. Every
 * vertex is a handle (vertex i has target i). Deterministic.
 */
#ifndef SCAF_MESH_SPIRAL_STRIP_H
#define SCAF_MESH_SPIRAL_STRIP_H

#include "base/error.h"
#include "mesh/mesh.h"

#define SPIRAL_STRIP_WIDTH 0.06
#define SPIRAL_STRIP_TURNS 2

/* The strip with n >= 3 segments into *m (free with mesh_free). */
scaf_status spiral_strip_make(int n, mesh *m, scaf_error *err);

/* Positions of the 2(n + 1) vertices (2(n + 1) by 2) curled by t in
 * [0, 1]: 0 the circle, 1 the spiral (the targets). The frames in between
 * are the path the handles follow (SPIRAL_STRIP_FRAMES of them, t = k /
 * SPIRAL_STRIP_FRAMES, k = 1 .. SPIRAL_STRIP_FRAMES - 1, before the
 * targets): pulled straight to the spiral at once, the strip folds onto
 * itself and stalls, re-meshed or not (measured: handle error ~0.45). */
void spiral_strip_curl(int n, double t, double *T);

#define SPIRAL_STRIP_FRAMES 24

#endif /* SCAF_MESH_SPIRAL_STRIP_H */
