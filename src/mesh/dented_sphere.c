/* mesh/dented_sphere: the cap pushed through the sphere (see dented_sphere.h). */
#include "mesh/dented_sphere.h"

#include <math.h>

static const double PI = 3.14159265358979323846;

double dented_sphere_push_of(const double p[3])
{
    double r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (!(r > 0.0)) return 0.0;
    double c = p[1] / r;
    double t = acos(c < -1.0 ? -1.0 : (c > 1.0 ? 1.0 : c)) * 180.0 / PI;
    if (t >= DENTED_SPHERE_CAP) return 0.0;
    double w = cos(0.5 * PI * t / DENTED_SPHERE_CAP);
    return DENTED_SPHERE_DEPTH * w * w;
}

void dented_sphere_push(mesh *m)
{
    double c = cos(DENTED_SPHERE_TURN), s = sin(DENTED_SPHERE_TURN);
    for (int v = 0; v < m->nv; v++) {
        double *p = m->V + 3 * (size_t)v, x = p[0], y = p[1];
        p[0] = c * x - s * y;
        p[1] = s * x + c * y;
        p[1] -= dented_sphere_push_of(p);
    }
}
