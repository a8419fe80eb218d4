/* opt/small_svd: signed SVD of 2x2 and 3x3 matrices (Jacobians).
 *
 * J = U diag(s) V^T with U and V proper rotations (det +1), s sorted by
 * decreasing magnitude, s[0] >= ... >= |s[d-1]|, and the last singular value
 * carrying the sign of det J (negative for an inverted simplex). This is the
 * form SLIM and ARAP need: the closest rotation to J is U V^T.
 * The 2x2 case is closed form; the 3x3 case diagonalizes J^T J with cyclic
 * Jacobi rotations and recovers U from J V, completing it with a cross
 * product so degenerate (rank-deficient) J still yields rotations. Never
 * fails; non-finite input gives non-finite output.
 * All matrices are row-major: M[r*d + c].
 */
#ifndef SCAF_OPT_SMALL_SVD_H
#define SCAF_OPT_SMALL_SVD_H

#include <float.h>
#include <math.h>

/* sqrt(a^2 + b^2): the plain formula when its square is a normal number
 * (within 2 ulp of hypot), libm's hypot otherwise (no overflow or
 * underflow); hypot's exact scaling cost 1.6% of a SLIM iteration. */
static inline double svd_hypot(double a, double b)
{
    double q = a * a + b * b;
    return q >= DBL_MIN && q <= DBL_MAX ? sqrt(q) : hypot(a, b);
}

/* J: 2 by 2 input. U, V: 2 by 2 rotations out. s: 2 signed singular values out. */
void svd2_signed(const double J[4], double U[4], double s[2], double V[4]);

/* J: 3 by 3 input. U, V: 3 by 3 rotations out. s: 3 signed singular values out. */
void svd3_signed(const double J[9], double U[9], double s[3], double V[9]);

/* Dispatch on d (2 or 3). */
void svd_signed(int d, const double *J, double *U, double *s, double *V);

#endif /* SCAF_OPT_SMALL_SVD_H */
