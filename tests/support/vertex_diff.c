/* tests/support/vertex_diff: see the header. */
#include "support/vertex_diff.h"

#include <math.h>

double test_max_vertex_diff_rel(int nv, const double *a, const double *b)
{
    double lo[3], hi[3], mx = 0;
    for (int d = 0; d < 3; d++) lo[d] = hi[d] = b[d];
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++) {
            lo[d] = fmin(lo[d], b[3 * v + d]);
            hi[d] = fmax(hi[d], b[3 * v + d]);
            mx = fmax(mx, fabs(a[3 * v + d] - b[3 * v + d]));
        }
    return mx /
        sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
             (hi[2] - lo[2]) * (hi[2] - lo[2]));
}
