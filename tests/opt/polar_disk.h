/* tests/opt/polar_disk: a generated disk (or annulus) mesh for opt tests.
 *
 * Polar grid: `rings` rings of `seg` vertices at radii k/rings (k = 1..rings),
 * plus a center vertex joined by a fan (disk) or no center (annulus: ring 1
 * is the hole's boundary). Faces are counter-clockwise seen from +z. The
 * surface is lifted to z = height * (1 - r^2) so it is not flat.
 * Header-only so the benchmark can share it. Returns 0 on success, -1 on
 * allocation failure.
 */
#ifndef SCAF_TESTS_OPT_POLAR_DISK_H
#define SCAF_TESTS_OPT_POLAR_DISK_H

#include <math.h>
#include <stdlib.h>

typedef struct polar_disk {
    int nv, nf;
    double *V; /* nv by 3 */
    int *F;    /* nf by 3 */
    int nloops;
    int start[3];
    int *loops; /* outer ring first, then the inner ring for an annulus */
} polar_disk;

static inline void polar_disk_free(polar_disk *m)
{
    free(m->V);
    free(m->F);
    free(m->loops);
    m->V = NULL;
    m->F = NULL;
    m->loops = NULL;
}

static inline int polar_disk_make(polar_disk *m, int rings, int seg, double height, int annulus)
{
    int center = annulus ? 0 : 1;
    m->nv = center + rings * seg;
    m->nf = (annulus ? 0 : seg) + 2 * seg * (rings - 1);
    m->V = malloc(3 * (size_t)m->nv * sizeof *m->V);
    m->F = malloc(3 * (size_t)m->nf * sizeof *m->F);
    m->nloops = annulus ? 2 : 1;
    m->loops = malloc((size_t)2 * seg * sizeof *m->loops);
    if (!m->V || !m->F || !m->loops) {
        polar_disk_free(m);
        return -1;
    }
    const double pi = 3.14159265358979323846;
    if (center) {
        m->V[0] = 0;
        m->V[1] = 0;
        m->V[2] = height;
    }
    for (int k = 1; k <= rings; k++)
        for (int j = 0; j < seg; j++) {
            double r = (double)k / rings, a = 2 * pi * j / seg + 0.3 * k / rings;
            double *p = m->V + 3 * (size_t)(center + (k - 1) * seg + j);
            p[0] = r * cos(a);
            p[1] = r * sin(a);
            p[2] = height * (1 - r * r);
        }
#define PD_V(k, j) (center + ((k)-1) * seg + ((j) % seg))
    int f = 0;
    if (center)
        for (int j = 0; j < seg; j++) {
            m->F[3 * f] = 0;
            m->F[3 * f + 1] = PD_V(1, j);
            m->F[3 * f + 2] = PD_V(1, j + 1);
            f++;
        }
    for (int k = 1; k < rings; k++)
        for (int j = 0; j < seg; j++) {
            int a = PD_V(k, j), b = PD_V(k, j + 1), c = PD_V(k + 1, j), d = PD_V(k + 1, j + 1);
            m->F[3 * f] = a;
            m->F[3 * f + 1] = c;
            m->F[3 * f + 2] = d;
            f++;
            m->F[3 * f] = a;
            m->F[3 * f + 1] = d;
            m->F[3 * f + 2] = b;
            f++;
        }
    m->start[0] = 0;
    for (int j = 0; j < seg; j++) m->loops[j] = PD_V(rings, j);
    m->start[1] = seg;
    if (annulus) {
        for (int j = 0; j < seg; j++) m->loops[seg + j] = PD_V(1, j);
        m->start[2] = 2 * seg;
    }
#undef PD_V
    return 0;
}

#endif /* SCAF_TESTS_OPT_POLAR_DISK_H */
