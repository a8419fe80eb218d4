/* opt/energy: distortion energies of one simplex's Jacobian and their sums.
 *
 * The energies are the rows of opt/energy_table (opt/energy_kind.h: one
 * file each, with the formulas); an opt_energy is a row's index. Each is
 * a density of the d by d Jacobian J (row-major), d = 2 or 3, +INFINITY
 * where det J <= 0, with its derivative dE/dJ and its SLIM proxy
 * (Rabinovich et al. 2017): a symmetric weight matrix W and target T with
 * the property that the gradient of ||W (J - T)||^2 at the current J
 * equals dE/dJ. An opt_term pairs a simplex set with an energy; sums are
 * weight-weighted: E = sum_s weight_s * density(J_s).
 * Nothing here fails; non-finite input gives non-finite output. The
 * functions taking an opt_energy need a valid one (opt_energy_valid).
 */
#ifndef SCAF_OPT_ENERGY_H
#define SCAF_OPT_ENERGY_H

#include "opt/simplices.h"

/* The first rows of opt/energy_table, named because code picks them by
 * value (the scaffold's energy, the 2D symmetric Dirichlet lanes); any
 * index below opt_energy_count() is an energy. */
typedef enum opt_energy {
    OPT_ENERGY_SYMMETRIC_DIRICHLET = 0, /* default */
    OPT_ENERGY_ARAP,
    OPT_ENERGY_CONFORMAL
} opt_energy;

/* One part of an objective: the simplices and the energy measured on them.
 * The scaffold is a term with OPT_ENERGY_SYMMETRIC_DIRICHLET and weight
 * lambda per simplex; the chart a term with the user's energy. */
typedef struct opt_term {
    const opt_simplices *s;
    opt_energy energy;
} opt_term;

/* The number of energies (rows of opt/energy_table). */
int opt_energy_count(void);

/* Whether e is an energy: 0 <= e < opt_energy_count(). */
int opt_energy_valid(int e);

/* The row's identifier ("symmetric_dirichlet", "arap", ...); "unknown"
 * for an invalid e. */
const char *opt_energy_name(opt_energy e);

/* Parse a name: a row's identifier (with '-' accepted for '_') or one of
 * its aliases; returns 0 and sets *e, or -1 if unknown. */
int opt_energy_parse(const char *name, opt_energy *e);

/* What is added to the mean energy (per unit of rest area) where a scale
 * is needed that does not vanish at the minimum (the row's scale_offset:
 * 1 for ARAP, 0 at a rotation; E + 1 then weighs like symmetric
 * Dirichlet's E >= 4 and conformal's E >= 1, which need nothing: 0). Used
 * by the scaffold weight (scaffold/scaf_loop) and the convergence test
 * (app/param). */
double opt_energy_scale_offset(opt_energy e);

/* Density of J (d by d). */
double opt_density(opt_energy e, int d, const double *J);

/* Density of J; dEdJ (d by d) gets its derivative. */
double opt_density_grad(opt_energy e, int d, const double *J, double *dEdJ);

/* SLIM proxy of J: W (d by d, symmetric positive definite) and T (d by d)
 * so that grad_J ||W (J - T)||_F^2 = dE/dJ where the energy is convex along
 * singular values (always for symmetric Dirichlet and ARAP with det J > 0;
 * where a row's exact weights would be negative, as conformal's can, it
 * falls back to a positive value and the property holds only
 * approximately). */
void opt_slim_proxy(opt_energy e, int d, const double *J, double *W, double *T);

/* The same with each squared weight w_i^2 limited to w2_cap (INFINITY: no
 * limit). Squared SLIM weights of symmetric Dirichlet grow like s^-3: a
 * Tutte start with singular values of 1e-6 gives 1e18, and a system mixing
 * such stiffness with O(1) entries is numerically indefinite for Cholesky
 * (the soft part is lost to rounding). Capping keeps the proxy SPD and well
 * enough conditioned, at the price of under-weighting the most compressed
 * simplices. Returns the largest UNcapped squared weight. */
double opt_slim_proxy_capped(opt_energy e, int d, const double *J, double w2_cap, double *W,
                             double *T);

/* sum_s weight_s * density(J_s) over a term at positions X (#X by d). */
double opt_term_energy(const opt_term *t, const double *X);

/* Weighted mean density: opt_term_energy / sum_s weight_s. For a chart
 * built by opt_simplices_from_surface this is the reported energy E
 * (4 at an isometry for symmetric Dirichlet). 0 for an empty term. */
double opt_term_mean_energy(const opt_term *t, const double *X);

/* g (#X by d) += gradient of opt_term_energy w.r.t. X. */
void opt_term_gradient(const opt_term *t, const double *X, double *g);

/* Determinant of a d by d matrix. */
double opt_det(int d, const double *J);

#endif /* SCAF_OPT_ENERGY_H */
