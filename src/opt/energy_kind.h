/* opt/energy_kind: what one distortion energy provides, and the table of
 * all of them.
 *
 * An energy is a density Psi(J) of the d by d Jacobian J (row-major, d = 2
 * or 3) that depends only on J's signed singular values s_1..s_d (it is
 * isotropic) and is +INFINITY where det J <= 0 (a barrier). One file per
 * energy (opt/energy_<name>.c) defines an opt_energy_kind with:
 *   - the value Psi(J) and its derivative dPsi/dJ, in closed form in J;
 *   - its SLIM proxy along the singular values (Rabinovich et al. 2017):
 *     squared weights w_i^2 > 0 and targets t_i with
 *     2 w_i^2 (s_i - t_i) = dPsi/ds_i where the energy allows it;
 *   - the second derivatives in the singular values that give the
 *     eigensystem of d2Psi/dJ2 (opt/isotropic_hessian): the d by d scaling
 *     block d2Psi/ds_i ds_j, and per pair i < j the flip and twist
 *     eigenvalues (Psi_i -+ Psi_j) / (s_i -+ s_j);
 *   - the offset its scaffold weight and convergence test add to the mean
 *     energy (opt_energy_scale_offset), its name and a line of help.
 * opt/energy_table.c lists the rows; the index of a row is its opt_energy
 * (and the public scaf_energy) value, so rows are only ever appended.
 * Everything else (opt/energy's sums, the proxies, the Newton fill, the
 * public scaf_energy_info, the CLI's --energy, Python's energy names)
 * reads this table. Nothing here fails or allocates; non-finite input
 * gives non-finite output.
 */
#ifndef SCAF_OPT_ENERGY_KIND_H
#define SCAF_OPT_ENERGY_KIND_H

typedef struct opt_energy_kind {
    const char *name;    /* identifier: [a-z_]+, also accepted with '-' for '_' */
    const char *aliases; /* further accepted names, space-separated ("" none) */
    const char *help;    /* one line: the formula and what it is for */
    double scale_offset; /* see opt_energy_scale_offset (opt/energy.h) */
    /* Psi(J). */
    double (*density)(int d, const double *J);
    /* Psi(J); G (d by d) = dPsi/dJ (NaN where det J <= 0). */
    double (*density_grad)(int d, const double *J, double *G);
    /* SLIM squared weights w2 and targets t (d each) at the signed
     * singular values s (the general path: any d, any J). */
    void (*slim_weights)(int d, const double *s, double *w2, double *t);
    /* Optional 2D shortcut (NULL: none): when it returns 1 the targets
     * are all 1 (the proxy aims at the closest rotation) and w0, w1 are the
     * squared weights at s0 >= s1 (J's signed singular values, computed
     * without trigonometry by opt/energy); 0: use slim_weights. */
    int (*slim_rotation2)(const double *J, double s0, double s1, double *w0, double *w1);
    /* d2Psi/ds_i ds_j (B, d by d), flip and twist eigenvalues per pair
     * (order (0,1), (0,2), (1,2)) at singular values s, all > 0. */
    void (*sv_hessian)(int d, const double *s, double *B, double *flip, double *twist);
} opt_energy_kind;

/* The rows, in opt_energy order, and their number. */
extern const opt_energy_kind *const opt_energy_table[];
extern const int opt_energy_table_size;

/* Small algebra the energies share (inline: they are in the hot loops). */

static inline double opt_ek_det(int d, const double *J)
{
    if (d == 2) return J[0] * J[3] - J[1] * J[2];
    return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
        J[2] * (J[3] * J[7] - J[4] * J[6]);
}

/* Inverse of J through the adjugate (Ji, d by d); returns det J. */
static inline double opt_ek_inverse(int d, const double *J, double *Ji)
{
    double det = opt_ek_det(d, J);
    if (d == 2) {
        Ji[0] = J[3] / det;
        Ji[1] = -J[1] / det;
        Ji[2] = -J[2] / det;
        Ji[3] = J[0] / det;
        return det;
    }
    Ji[0] = (J[4] * J[8] - J[5] * J[7]) / det;
    Ji[1] = (J[2] * J[7] - J[1] * J[8]) / det;
    Ji[2] = (J[1] * J[5] - J[2] * J[4]) / det;
    Ji[3] = (J[5] * J[6] - J[3] * J[8]) / det;
    Ji[4] = (J[0] * J[8] - J[2] * J[6]) / det;
    Ji[5] = (J[2] * J[3] - J[0] * J[5]) / det;
    Ji[6] = (J[3] * J[7] - J[4] * J[6]) / det;
    Ji[7] = (J[1] * J[6] - J[0] * J[7]) / det;
    Ji[8] = (J[0] * J[4] - J[1] * J[3]) / det;
    return det;
}

/* ||A||_F^2 of a d by d matrix. */
static inline double opt_ek_frob2(int d, const double *A)
{
    double s = 0;
    for (int k = 0; k < d * d; k++) s += A[k] * A[k];
    return s;
}

#endif /* SCAF_OPT_ENERGY_KIND_H */
