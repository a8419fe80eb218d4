/* mesh/degenerate: zero-area test for 3D triangles (see degenerate.h).
 *
 * Collinear in 3D <=> the cross product (b-a)x(c-a) vanishes <=> each of its
 * components, which are the orient2d determinants of the projections onto
 * the yz, zx and xy planes, is zero.
 *
 * TEMPORARY: geom/predicates.c (branch pred) has not landed yet, so the
 * determinants are evaluated in floating point here. Once it lands, the
 * body of proj_orient() becomes `return orient2d(pa, pb, pc);` (exact).
 */
#include "mesh/degenerate.h"

static double proj_orient(const double pa[2], const double pb[2], const double pc[2])
{
    return (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
}

int tri3_is_degenerate(const double a[3], const double b[3], const double c[3])
{
    for (int axis = 0; axis < 3; axis++) {
        int i = (axis + 1) % 3, j = (axis + 2) % 3;
        double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
        if (proj_orient(pa, pb, pc) != 0.0) return 0;
    }
    return 1;
}
