/* mesh/degenerate: exact zero-area test for 3D triangles (see degenerate.h).
 *
 * Collinear in 3D <=> the cross product (b-a)x(c-a) vanishes <=> each of its
 * components, which are the orient2d determinants of the projections onto
 * the yz, zx and xy planes, is zero. orient2d's sign is exact for any
 * finite doubles, so no tolerance is involved. Cannot fail.
 */
#include "mesh/degenerate.h"

#include "geom/predicates.h"

int tri3_is_degenerate(const double a[3], const double b[3], const double c[3])
{
    for (int axis = 0; axis < 3; axis++) {
        int i = (axis + 1) % 3, j = (axis + 2) % 3;
        double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
        if (orient2d(pa, pb, pc) != 0.0) return 0;
    }
    return 1;
}
