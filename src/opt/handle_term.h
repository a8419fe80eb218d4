/* opt/handle_term: soft positional constraints, an objective term
 * (opt/objective) w * sum_i ||x_{v_i} - t_i||^2 over handle vertices v_i
 * with targets t_i.
 *
 * The term is quadratic, so its proxy is itself: the block is w I on each
 * handle's diagonal and w t_i on the right-hand side (the system's
 * convention: half the Hessian, half the negative gradient at 0; its
 * Hessian is 2 w I). It has no barrier, no max step and no validity test:
 * the flip-free line search and the exact confirmation of the other terms
 * keep the map bijective whatever the targets, and handles approach their
 * targets as far as bijectivity (and the distortion energy) allows.
 *
 * Weight and units. The mesh term's energy is sum_f A_f SD(J_f): an area
 * (SD is dimensionless, 4 at a rigid motion). The handle weight is
 *   w = weight_ratio * A / (n * l^2),  l^2 = A,  i.e. w = weight_ratio / n
 * (A total rest area, n handles): a mean squared handle error of l^2 (the
 * squared characteristic length sqrt(A)) costs weight_ratio * A, the same
 * units as the distortion energy, so weight_ratio is dimensionless and the
 * result does not change when the mesh is scaled (nor with the number of
 * handles). opt_handle_weight computes it; OPT_HANDLE_WEIGHT_RATIO_DEFAULT
 * (1e4) makes the handles dominate: a rigid pull of l costs 2500 times the
 * rest energy 4A (measured on the spiral of mesh/spiral_strip: handle
 * error 5e-4 of a 1.9 wide spiral at E = 4.05; 1e3 leaves 3e-3).
 *
 * Handles and targets may change between iterations (opt_handle_term_set):
 * the block's pattern is rebuilt only when a handle's dof differs from the
 * one it was built for (other vertices, or a new numbering); moving
 * targets or changing the weight only changes values.
 * Fails with SCAF_ERR_USAGE (a handle index out of range, a target that is
 * not finite, a weight not finite or negative) or SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_HANDLE_TERM_H
#define SCAF_OPT_HANDLE_TERM_H

#include "opt/objective.h"

#define OPT_HANDLE_WEIGHT_RATIO_DEFAULT 1e4

typedef struct opt_handle_term {
    int d;          /* dimension of the positions */
    int nverts;     /* vertices of X a handle may name (0..nverts-1) */
    int n;          /* handles */
    int *vertex;    /* n vertex indices (repeats allowed) */
    double *target; /* n by d */
    double w;       /* the weight (not the ratio) */
    double *scale;  /* n: handle i weighs w * scale[i] (1 unless set with
                       opt_handle_term_set_scaled) */
    int *built_dof; /* n: the dofs the block's pattern was built for */
    int built;      /* the pattern exists */
    int cap;        /* allocated handles */
} opt_handle_term;

/* w = weight_ratio / nhandles (see above; total_area cancels out and is
 * taken only to state the units: it must be positive). 0 when there is no
 * handle. */
double opt_handle_weight(double weight_ratio, double total_area, int nhandles);

/* An empty term over positions of dimension d with nverts vertices. */
void opt_handle_term_init(opt_handle_term *h, int d, int nverts);

/* Replace the handles: n of them, vertex[i] in [0, nverts), target n by d,
 * weight w >= 0 (copied). On failure h is unchanged. */
scaf_status opt_handle_term_set(opt_handle_term *h, int n, const int *vertex, const double *target,
                                double w, scaf_error *err);

/* The same with a weight per handle: handle i weighs w * scale[i]
 * (scale: n finite values >= 0; NULL: all 1). A handle group (a chart
 * held rigidly by all its vertices) spreads one handle's weight over its
 * vertices this way. */
scaf_status opt_handle_term_set_scaled(opt_handle_term *h, int n, const int *vertex,
                                       const double *target, const double *scale, double w,
                                       scaf_error *err);

/* Largest distance of a handle to its target at X. 0 without handles. */
double opt_handle_term_max_error(const opt_handle_term *h, const double *X);

void opt_handle_term_free(opt_handle_term *h);

/* The term's ops over h (which must outlive it). */
opt_obj_term opt_handle_term_make(opt_handle_term *h);

#endif /* SCAF_OPT_HANDLE_TERM_H */
