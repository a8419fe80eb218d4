/* geom/min_box: convex hull and the rotations that fit a point set best
 * into a rectangle or a square.
 *
 * The hull is Andrew's monotone chain with the exact orient2d
 * (geom/predicates), so it is the exact convex hull of the doubles given.
 * The angles are floating point (they only choose a rotation; whoever
 * rotates checks the rotated triangles exactly).
 *
 * A rotation by theta maps p to (cos t p.x - sin t p.y, sin t p.x +
 * cos t p.y). Width and height of the rotated set are periodic in theta
 * with period pi/2 (up to a swap); the angles returned are in [0, pi/2).
 *   - min_box_area_angle: the rotation whose axis-aligned bounding box has
 *     the least area. That box has a side along a hull edge (Freeman and
 *     Shapira 1975), so only the hull edges' directions are candidates.
 *   - min_box_square_angle: the rotation whose bounding SQUARE is the
 *     smallest, i.e. that minimises max(width, height). Between two
 *     consecutive "breakpoints" (angles where a hull edge becomes axis
 *     parallel) the extreme vertices are fixed, width and height are
 *     concave in theta, so the minimum of their maximum is at a breakpoint
 *     or where width = height (solved in closed form per interval).
 */
#ifndef SCAF_GEOM_MIN_BOX_H
#define SCAF_GEOM_MIN_BOX_H

/* The convex hull of the n points P (n by 2): writes the indices of its
 * vertices, counter-clockwise, without collinear points, into hull (room
 * for n + 1) and returns their number (0 for n == 0; 1 or 2 for
 * degenerate sets). Fails (returns -1) only when out of memory. */
int min_box_hull(const double *P, int n, int *hull);

/* Width and height of the bounding box of the hull points after rotation
 * by theta. */
void min_box_extent(const double *P, const int *hull, int nh, double theta, double *w, double *h);

/* The angle in [0, pi/2) of the least-area bounding rectangle (0 for
 * fewer than 3 hull points). */
double min_box_area_angle(const double *P, const int *hull, int nh);

/* The angle in [0, pi/2) of the smallest bounding square; *side (may be
 * NULL) gets its side. */
double min_box_square_angle(const double *P, const int *hull, int nh, double *side);

#endif /* SCAF_GEOM_MIN_BOX_H */
