/* geom/expansion: exact floating-point expansion arithmetic.
 *
 * An expansion is an array of doubles, ordered by increasing magnitude and
 * nonoverlapping, whose exact (real) sum is the number it represents
 * (Priest; Shewchuk, "Adaptive Precision Floating-Point Arithmetic", 1997).
 * The error-free transformations below are exact under IEEE-754
 * round-to-nearest-even as long as no intermediate result overflows and no
 * product loses bits to underflow; callers (geom/predicates) guarantee that
 * by checking the input range first. The build uses -ffp-contract=off: a
 * fused multiply-add would silently break two_product's split arithmetic.
 * Zero components are eliminated, so lengths adapt to the data.
 */
#ifndef SCAF_GEOM_EXPANSION_H
#define SCAF_GEOM_EXPANSION_H

/* x + y = a + b exactly, with x = fl(a + b). Any a, b. */
static inline void two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    double bv = s - a;
    double av = s - bv;
    *x = s;
    *y = (a - av) + (b - bv);
}

/* Same as two_sum, valid when |a| >= |b| (or a == 0). */
static inline void fast_two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    *x = s;
    *y = b - (s - a);
}

/* x + y = a - b exactly. */
static inline void two_diff(double a, double b, double *x, double *y)
{
    double s = a - b;
    double bv = a - s;
    double av = s + bv;
    *x = s;
    *y = (a - av) + (bv - b);
}

/* Veltkamp split: a = hi + lo, each with at most 26 significant bits.
 * Needs |a| < 2^995 (the multiplication by 2^27+1 must not overflow). */
static inline void split(double a, double *hi, double *lo)
{
    double c = 134217729.0 * a; /* 2^27 + 1 */
    double big = c - a;
    double h = c - big;
    *hi = h;
    *lo = a - h;
}

/* x + y = a * b exactly (Dekker), with x = fl(a * b). */
static inline void two_product(double a, double b, double *x, double *y)
{
    double p = a * b;
    double ahi, alo, bhi, blo;
    split(a, &ahi, &alo);
    split(b, &bhi, &blo);
    double e1 = p - ahi * bhi;
    double e2 = e1 - alo * bhi;
    double e3 = e2 - ahi * blo;
    *x = p;
    *y = alo * blo - e3;
}

/* two_product with b already split into bhi + blo (saves a split when one
 * factor multiplies many). */
static inline void two_product_presplit(double a, double b, double bhi, double blo, double *x,
                                        double *y)
{
    double p = a * b;
    double ahi, alo;
    split(a, &ahi, &alo);
    double e1 = p - ahi * bhi;
    double e2 = e1 - alo * bhi;
    double e3 = e2 - ahi * blo;
    *x = p;
    *y = alo * blo - e3;
}

/* h = e + f. h must have room for elen + flen components. Returns the
 * length of h (zero components dropped; 0 means the value 0). */
int exp_sum(int elen, const double *e, int flen, const double *f, double *h);

/* h = e * b. h must have room for 2 * elen components. Returns length. */
int exp_scale(int elen, const double *e, double b, double *h);

/* h = e * f. h must have room for 2 * elen * flen components; work must
 * have room for 4 * elen * flen components. Returns the length of h. */
int exp_mul(int elen, const double *e, int flen, const double *f, double *h, double *work);

/* h = -e (in place allowed). */
void exp_negate(int elen, const double *e, double *h);

/* The expansion of a - b for two doubles: h has room for 2. Returns length. */
int exp_from_diff(double a, double b, double *h);

/* Sign of the value: the sign of the largest (last) nonzero component. */
static inline double exp_sign_estimate(int elen, const double *e)
{
    return elen > 0 ? e[elen - 1] : 0.0;
}

#endif /* SCAF_GEOM_EXPANSION_H */
