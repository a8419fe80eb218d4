/* mesh/cut_graph: cut a labelled triangle surface so that every chart is
 * a topological disk (possibly with holes): the UV topology of a
 * parametrization or an atlas.
 *
 * Input: a manifold, consistently oriented triangle surface (F over
 * 0..nv-1, positions V) and a chart label per face. Edges between faces
 * of different labels become seams; within each edge-connected piece of a
 * label the surface is then cut until it is a disk or a disk with holes:
 *   - handles (genus g > 0) by the greedy shortest system of 2g loops of
 *     Erickson & Whittlesey (2005): a shortest-path tree T from a root
 *     in which each boundary loop counts as one point (its vertices join
 *     T together, along the loop: loops may follow a hole for free, and
 *     each hole leaves one border edge out of T, whose loop is the hole's
 *     own and is not cut), a maximum spanning tree of the dual over the
 *     faces and the inside edges not in T, weighted by the length of the
 *     loop each edge closes in T; the inside edges in neither close the
 *     2g loops, whose union is pruned of its dangling branches. The dual
 *     tree's edges are never cut, so the chart stays one piece;
 *   - a closed piece (no boundary) also gets a tree of shortest paths
 *     joining cone vertices (Gu, Gortler & Hoppe 2002 cut toward the
 *     points of concentrated curvature; here picked at once, not
 *     iteratively): the piece is split into geodesic regions by farthest
 *     point sampling, and the regions whose total angle defect is largest
 *     in magnitude give the cones (at least two on a sphere, so the cut is
 *     not empty); the tree grows from the handle loops (or the first cone)
 *     by the nearest cone's shortest path (a Steiner tree heuristic);
 *     with cut_disks, pieces with a boundary get such a tree too, grown
 *     from the boundary, toward their regions of concentrated curvature
 *     only (a body in one piece with a small hole at the neck would
 *     otherwise flatten through that hole);
 * Paths are shortest for an edge weight of length times a crease factor:
 * concave creases (valleys) are cheaper, so seams hide in them where that
 * costs little extra length (Sheffer & Hart 2002, "Seamster").
 * Vertices are split where the cut and the chart borders pass (and where
 * a chart touches itself at a vertex: one vertex per fan). Deterministic:
 * ties are broken by index. The result is checked: each chart's Euler
 * characteristic and boundary loops after the cut must make it a disk
 * (SCAF_ERR_INTERNAL otherwise, a bug).
 *
 * Fails with SCAF_ERR_MESH naming the edge when an edge has more than two
 * faces or two faces use it in the same direction, SCAF_ERR_USAGE on bad
 * arguments, SCAF_ERR_NOMEM.
 */
#ifndef SCAF_MESH_CUT_GRAPH_H
#define SCAF_MESH_CUT_GRAPH_H

#include "base/error.h"

typedef struct cut_graph_options {
    int cones;            /* 1: closed pieces are cut along a tree through
                             cone vertices (0: the fewest cuts: the handle
                             loops, or one edge on a sphere) (1) */
    double crease_factor; /* an edge's weight is its length divided by
                             1 + crease_factor * (1 - cos of the dihedral
                             angle) on a concave edge (2: a right-angle
                             valley costs a third of its length) */
    int max_cones;        /* cap of the cone count of one piece (16) */
    int cut_disks;        /* 1: also cut pieces with a boundary toward their
                             cones (regions of concentrated curvature),
                             from the boundary (0: leave disks as they are) */
    int min_cones;        /* cones at least on a closed piece of genus 0 (4: on a
                             round sphere E 4.19 after param, 4.56 with 2) */
} cut_graph_options;

void cut_graph_defaults(cut_graph_options *o);

typedef struct cut_graph {
    int nsplit;        /* vertices of the cut surface */
    int *FT;           /* #F by 3: cut-surface vertex of each corner */
    int *split_vertex; /* nsplit: the input vertex of each */
    int ncharts;       /* edge-connected pieces of the labels (the charts) */
    int *face_chart;   /* #F: chart of each face, numbered by first face */
    int cut_edges;     /* interior edges cut (chart borders not counted) */
    int handle_loops;  /* loops cut for handles (2 g summed) */
    int cones;         /* cone vertices joined by cut trees */
    int closed_charts; /* pieces that had no boundary */
    int genus_charts;  /* pieces that had handles */
} cut_graph;

/* input:  nv, V   #V by 3 positions
 *         nf, F   #F by 3 indices in [0, nv)
 *         face_chart  #F label of each face (any ints; NULL: all one label)
 *         o       options (NULL: defaults)
 * output: *g (free with cut_graph_free); on failure *g is empty. */
scaf_status cut_graph_compute(int nv, const double *V, int nf, const int *F, const int *face_chart,
                              const cut_graph_options *o, cut_graph *g, scaf_error *err);

void cut_graph_free(cut_graph *g);

/* Topology of each chart of a cut: per edge-connected piece of faces
 * linked where two faces share an edge with the same FT indices on it,
 * its Euler characteristic and boundary loop count (over the FT indices).
 * face_chart out #F, chi and loops out (room for nf each); *ncharts out.
 * SCAF_ERR_MESH when FT is not a manifold surface (an FT index with two
 * boundary fans), SCAF_ERR_NOMEM. For tests and the final check. */
scaf_status cut_graph_chart_topology(int nf, const int *FT, int *face_chart, int *ncharts, int *chi,
                                     int *loops, scaf_error *err);

#endif /* SCAF_MESH_CUT_GRAPH_H */
