/* tests/support/loop_area: see loop_area.h. */
#include "support/loop_area.h"

double test_loop_area_xy(const mesh *m, const tri_complex *cx, int l)
{
    double a = 0;
    int s = cx->loop_start[l], t = cx->loop_start[l + 1];
    for (int i = s; i < t; i++) {
        const double *p = m->V + 3 * m->F[cx->loop_he[i]];
        const double *q = m->V + 3 * m->F[cx->loop_he[i + 1 < t ? i + 1 : s]];
        a += p[0] * q[1] - p[1] * q[0];
    }
    return a / 2;
}
