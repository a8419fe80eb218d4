/* opt/cmcf: conformalized mean curvature flow (Kazhdan, Solomon,
 * Ben-Chen 2012), the flow that makes a self-intersecting closed surface
 * round (and, after a few steps, free of intersections).
 *
 * Implicit steps of the heat equation whose metric is frozen at the INPUT:
 * the cotangent stiffness L of the input (opt/cotan_laplacian) is built
 * once, the mass M of the current shape U is rebuilt each step and
 *     (M - delta L) U' = M U
 * is solved with CHOLMOD (one analysis, a numerical factorization per
 * step: the pattern of M - delta L is that of L). After the solve the
 * shape is moved so that its area-weighted centroid is the origin and
 * scaled to unit area, which keeps delta's meaning the same at every step.
 * Conventions checked against the authors' data
 * (../shared/data/closed/leg-flow6.off = six steps with delta = 1e-3 of
 * leg-intersect.off, tests/opt/test_cmcf.c): barycentric mass (it
 * reproduces their output to round-off; no Voronoi mass is needed), the
 * result left in the normalized
 * frame (not moved back to the input's centre and size). Their input file
 * was already normalized and written with 7 digits (area 1 + 5e-9): six
 * steps from it as read match their output to 2.5e-15 of the bounding-box
 * diagonal, six steps after normalizing it again (what a caller should do
 * with an arbitrary surface: cmcf_normalize before the first step, so
 * that delta means the same for every input) to 1.5e-10.
 */
#ifndef SCAF_OPT_CMCF_H
#define SCAF_OPT_CMCF_H

#include "base/error.h"
#include "opt/cholmod_solver.h"
#include "opt/csc.h"

typedef struct cmcf {
    int nv, nf;
    const int *F; /* the caller's faces (kept, not copied) */
    double delta;
    opt_csc L;    /* input's cotangent stiffness */
    opt_csc A;    /* M - delta L: L's pattern */
    int *diag;    /* index of each diagonal entry in A.val */
    double *mass; /* current lumped mass */
    double *rhs;  /* M U, column-major (x, y, z columns), then U' */
    double *next; /* U' row-major, normalized before it replaces U */
    opt_chol *chol;
    int steps; /* steps done */
} cmcf;

/* The frame cmcf_normalize takes away: the area-weighted centroid of the
 * surface U (#V by 3) and its area (SCAF_ERR_NUMERIC when zero or not
 * finite). A normalized shape N is back in U's frame as centre +
 * sqrt(area) N. */
scaf_status cmcf_frame(int nv, const double *U, int nf, const int *F, double centre[3],
                       double *area, scaf_error *err);

/* Normalize U in place: area-weighted centroid at the origin, total area
 * 1. Fails with SCAF_ERR_NUMERIC when the area is zero or not finite. */
scaf_status cmcf_normalize(int nv, double *U, int nf, const int *F, scaf_error *err);

/* Prepare the flow of the surface (nv, V, nf, F) with time step delta > 0:
 * builds L from V (scale-independent, so V need not be normalized). F must
 * stay valid while f is used. Errors: SCAF_ERR_USAGE (delta not positive
 * and finite, no face), SCAF_ERR_MESH (a zero-area face),
 * SCAF_ERR_NOMEM. On failure f is left freed. */
scaf_status cmcf_init(cmcf *f, int nv, const double *V, int nf, const int *F, double delta,
                      scaf_error *err);

/* One step: U (#V by 3, row-major, the current normalized shape) is
 * replaced by the next one, normalized. SCAF_ERR_NUMERIC when the system
 * is not positive definite or the result is not finite (U unchanged
 * then); SCAF_ERR_NOMEM. */
scaf_status cmcf_step(cmcf *f, double *U, scaf_error *err);

/* Free; safe on a zeroed or freed struct. */
void cmcf_free(cmcf *f);

#endif /* SCAF_OPT_CMCF_H */
