/* geom/tet_quality: how well shaped a tetrahedron is, one number.
 *
 * The volume-length ratio (Parthasarathy et al. 1994; the measure Klingner
 * and Shewchuk 2009 found best for mesh improvement)
 *     q = 6 sqrt(2) V / l_rms^3,   l_rms = sqrt(mean of the 6 squared edges)
 * is 1 for the regular tetrahedron, tends to 0 for every kind of
 * degenerate one (slivers included, which angle-free edge ratios miss),
 * is negative when the tet is inverted, and is invariant under scaling,
 * rotation and translation. It is smooth away from l_rms = 0, so its
 * gradient drives vertex smoothing.
 * Floating point: the sign of q is NOT an orientation test; decide
 * orientation with geom/tet_orient.
 */
#ifndef SCAF_GEOM_TET_QUALITY_H
#define SCAF_GEOM_TET_QUALITY_H

/* Quality of tet (a, b, c, d), positive when det[b - a, c - a, d - a] > 0. */
double tet_quality(const double a[3], const double b[3], const double c[3], const double d[3]);

/* Quality and its gradient with respect to the position of a (the other
 * three held still). */
double tet_quality_grad(const double a[3], const double b[3], const double c[3], const double d[3],
                        double grad_a[3]);

/* The k-th smallest (0-based, 0 <= k < n) of x[0..n-1], reordering x.
 * Deterministic quickselect, O(n) expected. */
double tet_quality_kth(double *x, int n, int k);

/* Summary of a set of qualities: the minimum and the 5th percentile (the
 * value below which 5% of the tets lie: element floor(0.05 n) in increasing
 * order). n may be 0 (both 0). Writes no input; O(n) (selection in a
 * scratch copy). Returns 0, or -1 when the scratch cannot be allocated. */
int tet_quality_summary(int n, const double *q, double *min, double *p5);

#endif /* SCAF_GEOM_TET_QUALITY_H */
