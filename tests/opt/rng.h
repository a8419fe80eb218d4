/* tests/opt/rng: a tiny deterministic generator and random simplices. */
#ifndef SCAF_TESTS_OPT_RNG_H
#define SCAF_TESTS_OPT_RNG_H

#include <math.h>
#include <stdint.h>

typedef struct rng {
    uint64_t s;
} rng;

/* Uniform in [lo, hi). */
static inline double rng_uniform(rng *r, double lo, double hi)
{
    r->s = r->s * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}

static inline double det_d(int d, const double *J)
{
    if (d == 2) return J[0] * J[3] - J[1] * J[2];
    return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
        J[2] * (J[3] * J[7] - J[4] * J[6]);
}

/* d+1 random points (row-major, (d+1) by d) forming a simplex of positive
 * volume not too flat. */
static inline void rng_simplex(rng *r, int d, double *P)
{
    for (;;) {
        for (int k = 0; k < (d + 1) * d; k++) P[k] = rng_uniform(r, -1, 1);
        double E[9];
        for (int k = 0; k < d; k++)
            for (int a = 0; a < d; a++) E[a * d + k] = P[(k + 1) * d + a] - P[a];
        double det = det_d(d, E);
        if (det > 0.05) return;
        if (det < -0.05) {
            /* Swap two corners to flip the orientation. */
            for (int a = 0; a < d; a++) {
                double t = P[d + a];
                P[d + a] = P[2 * d + a];
                P[2 * d + a] = t;
            }
            return;
        }
    }
}

/* A random rotation (d by d, det +1). */
static inline void rng_rotation(rng *r, int d, double *R)
{
    if (d == 2) {
        double a = rng_uniform(r, 0, 6.283185307179586);
        R[0] = cos(a);
        R[1] = -sin(a);
        R[2] = sin(a);
        R[3] = cos(a);
        return;
    }
    /* Unit quaternion to matrix. */
    double q[4], n = 0;
    for (int k = 0; k < 4; k++) {
        q[k] = rng_uniform(r, -1, 1);
        n += q[k] * q[k];
    }
    n = sqrt(n);
    for (int k = 0; k < 4; k++) q[k] /= n;
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z);
    R[1] = 2 * (x * y - z * w);
    R[2] = 2 * (x * z + y * w);
    R[3] = 2 * (x * y + z * w);
    R[4] = 1 - 2 * (x * x + z * z);
    R[5] = 2 * (y * z - x * w);
    R[6] = 2 * (x * z - y * w);
    R[7] = 2 * (y * z + x * w);
    R[8] = 1 - 2 * (x * x + y * y);
}

#endif /* SCAF_TESTS_OPT_RNG_H */
