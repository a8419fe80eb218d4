/* geom/self_intersect: does a triangle surface intersect itself? Exact.
 *
 * Which pairs count (decided by vertex INDICES shared by the two faces and
 * exact orient3d/orient2d tests of geom/tri_intersect, never a tolerance;
 * the closed triangles are compared, so touching counts):
 *   crossing   faces sharing no vertex index whose closed triangles share
 *              any point (crossing, touching, coplanar overlap, distinct
 *              vertices at one position);
 *   vertex     faces sharing exactly one vertex v that meet at a point other
 *              than v (the edge opposite v in one face meets the other face:
 *              a face passing through its neighbour, or two faces overlapping
 *              around v in one plane);
 *   edge       faces sharing an edge that are coplanar with their third
 *              vertices on the same side of the edge (folded onto each
 *              other); two faces on an edge meet only along it otherwise;
 *   duplicate  faces with the same three vertex indices.
 * This is the classification of the exact Möller / Guigue-Devillers style
 * checkers (e.g. libigl's / CGAL's self-intersection tests): adjacent faces
 * only count when they meet in more than what they share. Degenerate faces
 * (three collinear or coinciding points) have no plane: they are counted
 * apart in `degenerate_faces` and not paired.
 *
 * Other tools on ../shared/data/closed/leg-intersect.off: scaf counts 239
 * pairs, 237 sharing no vertex and 2 sharing one. The MANIFEST's 237 counts
 * only pairs sharing no vertex position (scaf's crossing_pairs); Debian's
 * `tetgen -d` prints 690 "facet #i intersects facet #j" lines, but they
 * repeat pairs (one pair up to 18 times): the
 * distinct pairs are exactly scaf's 239 (checked pair by pair). The
 * MANIFEST's numbers agree with crossing_pairs on bad/cow.obj (71) and
 * disk/camelhead.off (3) and differ where vertices share a position or
 * faces only touch: disk/camel_b.obj, cut open with duplicated seam
 * vertices, has 1946 crossing (touching) pairs along its seams, 14 by
 * position; aphrodite 38 (32), human_neutral 322 (320).
 *
 * Speed: a uniform grid over the bounding box (about one cell per face, the
 * cell edge the mean face extent; coarsened when faces would cover too
 * many cells) with each pair tested once, in the cell holding the low
 * corner of the overlap of their bounding boxes. Cell indices are computed
 * from half-coordinates, so extreme coordinates (up to the largest double)
 * neither overflow nor produce out-of-range cells.
 */
#ifndef SCAF_GEOM_SELF_INTERSECT_H
#define SCAF_GEOM_SELF_INTERSECT_H

#include "base/error.h"

#define SI_FIRST_MAX 16

typedef enum si_pair_kind {
    SI_PAIR_NONE = 0, /* meet in at most what they share */
    SI_PAIR_CROSSING, /* share no vertex index and meet */
    SI_PAIR_VERTEX,   /* share one vertex and meet elsewhere */
    SI_PAIR_EDGE,     /* share an edge and fold onto each other */
    SI_PAIR_DUPLICATE /* the same three vertex indices */
} si_pair_kind;

typedef struct si_report {
    int faces;            /* faces checked */
    int degenerate_faces; /* zero-area faces (not paired) */
    long long pairs;      /* intersecting pairs: the sum of the four below */
    long long crossing_pairs;
    long long vertex_pairs;
    long long edge_pairs;
    long long duplicate_pairs;
    int nfirst;                 /* entries of first[] used (<= SI_FIRST_MAX) */
    int first[SI_FIRST_MAX][2]; /* the intersecting pairs (i < j) smallest in
                                  (i, j) order: deterministic */
    int first_degenerate;       /* lowest degenerate face, -1 when none */
    int intersection_free;      /* 1 when pairs == 0 and no degenerate face */
} si_report;

/* Classify faces fa and fb (3 vertex indices each) of the surface with
 * positions V (#V by 3). Both faces must be non-degenerate. */
si_pair_kind si_classify_pair(const double *V, const int fa[3], const int fb[3]);

/* Check the surface.
 *   nv, V   #V by 3 vertex positions (finite)
 *   nf, F   #F by 3 vertex indices, 0-based (orientation does not matter)
 *   r       output: the counts
 * Errors: SCAF_ERR_MESH for an index out of range or a non-finite
 * coordinate (naming it), SCAF_ERR_NOMEM. Works on any surface: open,
 * non-manifold, several components. */
scaf_status si_check(int nv, const double *V, int nf, const int *F, si_report *r, scaf_error *err);

#endif /* SCAF_GEOM_SELF_INTERSECT_H */
