/* opt/sd_weight: the squared SLIM weight of symmetric Dirichlet along one
 * signed singular value, shared by the energy's row
 * (opt/energy_symmetric_dirichlet.c) and its vector lanes (opt/sd2_lanes),
 * so both compute the same bits. g / (2 (s - 1)) with g = 2s - 2/s^3,
 * simplified so that s = 1 is no 0/0; 1 where s <= 0 (an inverted simplex
 * has infinite energy; any positive weight keeps the proxy definite).
 * Nothing here fails.
 */
#ifndef SCAF_OPT_SD_WEIGHT_H
#define SCAF_OPT_SD_WEIGHT_H

static inline double opt_sd_w2(double s)
{
    return s > 0 ? (s + 1) * (s * s + 1) / (s * s * s) : 1.0;
}

#endif /* SCAF_OPT_SD_WEIGHT_H */
