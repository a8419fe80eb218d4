/* geom/predicates: exact orient2d, incircle, orient3d, insphere on doubles.
 *
 * Stages per call; each later stage runs only when the earlier ones could
 * not decide the sign. u = 2^-53 is the unit roundoff.
 *  A. Filter: the determinant in plain doubles with a forward error bound
 *     (Shewchuk's permanent-based bound, constants from his analysis) plus
 *     an absolute term for products that underflow into the subnormal
 *     range (each such product is off by at most 2^-1075, scaled by the
 *     factors it is later multiplied with). Overflow turns the bound into
 *     inf or NaN, which never passes. Most calls end here.
 *  Range guard: a NaN or infinite coordinate gives NaN; if some nonzero
 *     coordinate magnitude lies outside [2^-LO, 2^HI] the call goes to the
 *     integer stage E:
 *        orient2d: [2^-450, 2^450]   orient3d: [2^-280, 2^300]
 *        incircle: [2^-200, 2^200]   insphere: always E
 *     Inside the range every coordinate is a multiple of g = 2^-(LO+52),
 *     so every coordinate difference, its rounded value ("head" x =
 *     fl(a - d)) and its rounding error ("tail" xt = (a - d) - x, exact by
 *     two_diff, |xt| <= u |x|) is a multiple of g of magnitude at most
 *     2^(HI+1). Rounding a multiple of a power of two >= 2^-1074 gives a
 *     multiple of it, so any value computed with + - x from such numbers
 *     at polynomial degree k (exactly or in floating point) is 0 or a
 *     multiple of g^k >= 2^-1008: a normal number. Degrees here are <= 4
 *     (orient2d 2, orient3d 3), magnitudes stay below 2^995. Hence in
 *     stages B-D no bits are lost to underflow (the filter's absolute
 *     term is not needed: each rounding has relative error <= u), nothing
 *     overflows, and the Veltkamp split of geom/expansion is exact.
 *  Notation: D = the determinant of the exact differences, D(h) = the same
 *     polynomial of the heads, P = its permanent (sum of the magnitudes of
 *     its monomials) in the heads. The filter's computed permanent P' has
 *     at most 2 (orient2d), 5 (orient3d), 7 (incircle) roundings per
 *     monomial, so P <= P' (1 + 8u). An n-degree monomial of the exact
 *     differences is the heads' monomial times prod(1 + d_i), |d_i| <= u.
 *     A value held as an expansion (nonoverlapping, sorted) exceeds E in
 *     magnitude when |largest| > E + 3 |second largest| (everything below
 *     the largest sums to less than 2 |second|; see exceeds()).
 *  B. D(h) as an exact expansion. If every tail is 0, D(h) = D: done
 *     (e.g. all coordinates within a factor 2 of each other: Sterbenz).
 *     Otherwise |D - D(h)| <= ((1+u)^n - 1) P: decided when D(h) exceeds
 *     (2 + 16u)u P' (orient2d), (3 + 32u)u P' (orient3d).
 *  B1 (incircle only, before B because it is ~8x cheaper): each lift and
 *     minor of the heads as an unevaluated sum of two doubles (errors <=
 *     4u^2 of their permanents), the leading products exact, leading sums
 *     exact (two_sum), the rest and the first-order tail correction L'
 *     (stage C) in floating point. Error <= u |det| + 114 u^2 P + O(u^3)P
 *     (27 from the products, 44 from summing the small parts, 43 from the
 *     tails as in C); decided when |det| > (1 + 8u)u |det| + 256 u^2 P'.
 *     When it fails, |D| is below ~300 u^2 P, where B's 4u P test would
 *     practically never pass: incircle skips that test (skipping a test
 *     never costs exactness) and uses B only for the all-tails-zero exit
 *     and as the base of C.
 *  C. D(h) + L' exactly (one more expansion component), where L' is the
 *     first-order tail correction (sum over each monomial's factors of the
 *     monomial with that factor replaced by its tail) in floating point:
 *     |D - D(h) - L'| <= ((1+u)^n - 1 - nu) P + gamma_k n u P, k the
 *     roundings per term of L' (3, 7, 9), i.e. 7, 24, 42 u^2 P; decided
 *     when the sum exceeds 16, 48, 64 u^2 P' (orient2d, orient3d,
 *     incircle; the slack covers P <= P'(1 + 8u) and the rounding of the
 *     bound itself).
 *  D. Expansion arithmetic (geom/expansion) on the exact differences (two
 *     components each): the exact determinant, valid by the range guard.
 *  E. Fixed-point integers (geom/bigint): exact for every finite double,
 *     slower. insphere's exact stage always uses it.
 * So the sign is exact for ALL finite inputs. No state, no allocation.
 */
#include "geom/predicates.h"

#include <math.h>

#include "geom/bigint.h"
#include "geom/expansion.h"

#define EPS 0x1p-53 /* half an ulp of 1: the unit roundoff */
static const double ccw_bound = (3.0 + 16.0 * EPS) * EPS;
static const double o3d_bound = (7.0 + 56.0 * EPS) * EPS;
static const double icc_bound = (10.0 + 96.0 * EPS) * EPS;
static const double isp_bound = (16.0 + 224.0 * EPS) * EPS;
/* Stage B/B1/C bounds (derivation in the banner): B = the difference
 * rounding errors; C = second-order terms plus the rounding of the
 * first-order correction; B1 = C plus the double-double evaluation. */
static const double ccw_boundB = (2.0 + 16.0 * EPS) * EPS;
static const double ccw_boundC = 16.0 * EPS * EPS;
static const double o3d_boundB = (3.0 + 32.0 * EPS) * EPS;
static const double o3d_boundC = 48.0 * EPS * EPS;
static const double icc_boundC = 64.0 * EPS * EPS;
static const double icc_boundB1 = 256.0 * EPS * EPS;
static const double icc_resultB1 = (1.0 + 8.0 * EPS) * EPS;
/* Generous multiple of the largest underflow error of one product. */
#define UFL 0x1p-1060

/* The slow paths stay out of line so the filter's fast path keeps a small
 * stack frame. */
#if defined(__GNUC__) || defined(__clang__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/* ---- range test for the expansion stage ---- */

static int in_range(const double *x, int n, double lo, double hi)
{
    for (int i = 0; i < n; i++) {
        double a = fabs(x[i]);
        if (a != 0.0 && !(a >= lo && a <= hi)) return 0; /* also NaN */
    }
    return 1;
}

static int all_finite(const double *x, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* Smallest exponent over the nonzero values (0 when all are zero). */
static int low_exponent(const double *x, int n)
{
    int emin = 0, any = 0;
    for (int i = 0; i < n; i++) {
        if (x[i] == 0.0) continue;
        int e = bigint_low_exponent(x[i]);
        if (!any || e < emin) emin = e;
        any = 1;
    }
    return emin;
}

static double sign_of(const bigint *b) { return (double)b->sign; }

/* ---- helpers of the adaptive stages B and C ---- */

/* h = a * b exactly, 0..2 components (zeros dropped). */
static int prod_exp(double a, double b, double *h)
{
    double x, y;
    two_product(a, b, &x, &y);
    int n = 0;
    if (y != 0.0) h[n++] = y;
    if (x != 0.0) h[n++] = x;
    return n;
}

/* m = a * b - c * d exactly, 0..4 components. */
static int det2_exp(double a, double b, double c, double d, double *m)
{
    double l[2], r[2];
    int nl = prod_exp(a, b, l);
    int nr = prod_exp(-c, d, r); /* negating a factor is exact */
    return exp_sum(nl, l, nr, r, m);
}

/* 1 when the value of the expansion e surely exceeds err in magnitude.
 * e is nonoverlapping and sorted, so everything below its largest
 * component T sums to less than 2 |e[n-2]| in magnitude (e[n-2] plus the
 * rest, which is below e[n-2]'s lowest bit): |value| > |T| - 2 |e[n-2]|.
 * The computed right side rounds down by at most (1 - EPS)^2 on err and
 * 3 (1 - EPS)^2 > 2 on e[n-2]; the B/C constants absorb the former. */
static int exceeds(int n, const double *e, double err)
{
    if (n == 0) return 0;
    double below = n > 1 ? fabs(e[n - 2]) : 0.0;
    return fabs(e[n - 1]) > err + 3.0 * below;
}

/* ---- orient2d ---- */

static double orient2d_bigint(const double *p)
{
    /* p = {ax, ay, bx, by, cx, cy} */
    int emin = low_exponent(p, 6);
    bigint v[6], acx, acy, bcx, bcy, l, r;
    for (int i = 0; i < 6; i++) bigint_from_double(&v[i], p[i], emin);
    bigint_sub(&acx, &v[0], &v[4]);
    bigint_sub(&acy, &v[1], &v[5]);
    bigint_sub(&bcx, &v[2], &v[4]);
    bigint_sub(&bcy, &v[3], &v[5]);
    bigint_mul(&l, &acx, &bcy);
    bigint_mul(&r, &acy, &bcx);
    bigint_sub(&l, &l, &r);
    return sign_of(&l);
}

/* Stages B and C (coordinates in range). perm is the filter's permanent.
 * Sets *done when the sign is decided. */
static double orient2d_adapt(const double a[2], const double b[2], const double c[2], double perm,
                             int *done)
{
    double acx, acy, bcx, bcy, acxt, acyt, bcxt, bcyt;
    two_diff(a[0], c[0], &acx, &acxt);
    two_diff(a[1], c[1], &acy, &acyt);
    two_diff(b[0], c[0], &bcx, &bcxt);
    two_diff(b[1], c[1], &bcy, &bcyt);
    double v[4], w[5];
    int nv = det2_exp(acx, bcy, acy, bcx, v);
    *done = 1;
    if (acxt == 0.0 && acyt == 0.0 && bcxt == 0.0 && bcyt == 0.0) return exp_sign_estimate(nv, v);
    if (exceeds(nv, v, ccw_boundB * perm)) return v[nv - 1];
    double lt = (acxt * bcy + acx * bcyt) - (acyt * bcx + acy * bcxt);
    int nw = exp_sum(nv, v, lt != 0.0, &lt, w);
    if (exceeds(nw, w, ccw_boundC * perm)) return w[nw - 1];
    *done = 0;
    return 0.0;
}

/* Stage D: the exact determinant from the exact differences. */
static double orient2d_exact(const double a[2], const double b[2], const double c[2])
{
    double acx[2], acy[2], bcx[2], bcy[2], l[8], r[8], h[16], w[16];
    int nacx = exp_from_diff(a[0], c[0], acx);
    int nacy = exp_from_diff(a[1], c[1], acy);
    int nbcx = exp_from_diff(b[0], c[0], bcx);
    int nbcy = exp_from_diff(b[1], c[1], bcy);
    int nl = exp_mul(nacx, acx, nbcy, bcy, l, w);
    int nr = exp_mul(nacy, acy, nbcx, bcx, r, w);
    exp_negate(nr, r, r);
    int nh = exp_sum(nl, l, nr, r, h);
    return exp_sign_estimate(nh, h);
}

/* Filter failed: the range guard, then stages B, C, D (see the banner). */
static NOINLINE double orient2d_slow(const double a[2], const double b[2], const double c[2],
                                     double perm)
{
    const double p[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    if (!all_finite(p, 6)) return NAN;
    if (!in_range(p, 6, 0x1p-450, 0x1p450)) return orient2d_bigint(p);
    int done;
    double det = orient2d_adapt(a, b, c, perm, &done);
    if (done) return det;
    return orient2d_exact(a, b, c);
}

double orient2d(const double a[2], const double b[2], const double c[2])
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double l = acx * bcy, r = acy * bcx;
    double det = l - r;
    double perm = fabs(l) + fabs(r);
    double bound = ccw_bound * perm + UFL;
    if (det > bound || -det > bound) return det;
    return orient2d_slow(a, b, c, perm);
}

/* ---- orient3d ---- */

static double orient3d_bigint(const double *p)
{
    int emin = low_exponent(p, 12);
    bigint v[12], d[9], m, t, s, acc;
    for (int i = 0; i < 12; i++) bigint_from_double(&v[i], p[i], emin);
    for (int k = 0; k < 3; k++) /* rows a-d, b-d, c-d */
        for (int j = 0; j < 3; j++) bigint_sub(&d[3 * k + j], &v[3 * k + j], &v[9 + j]);
    /* det = adz (bdx cdy - bdy cdx) - bdz (adx cdy - ady cdx) + cdz (adx bdy - ady bdx) */
    bigint_mul(&m, &d[3], &d[7]);
    bigint_mul(&t, &d[4], &d[6]);
    bigint_sub(&m, &m, &t);
    bigint_mul(&acc, &d[2], &m);
    bigint_mul(&m, &d[0], &d[7]);
    bigint_mul(&t, &d[1], &d[6]);
    bigint_sub(&m, &m, &t);
    bigint_mul(&s, &d[5], &m);
    bigint_sub(&acc, &acc, &s);
    bigint_mul(&m, &d[0], &d[4]);
    bigint_mul(&t, &d[1], &d[3]);
    bigint_sub(&m, &m, &t);
    bigint_mul(&s, &d[8], &m);
    bigint_add(&acc, &acc, &s);
    return sign_of(&acc);
}

/* m = x1 * y2 - y1 * x2 for 2-component expansions; m has room for 16. */
static int exp_minor(int nx1, const double *x1, int ny2, const double *y2, int ny1,
                     const double *y1, int nx2, const double *x2, double *m)
{
    double l[8], r[8], w[16];
    int nl = exp_mul(nx1, x1, ny2, y2, l, w);
    int nr = exp_mul(ny1, y1, nx2, x2, r, w);
    exp_negate(nr, r, r);
    return exp_sum(nl, l, nr, r, m);
}

/* Stages B and C (coordinates in range), as for orient2d. */
static double orient3d_adapt(const double a[3], const double b[3], const double c[3],
                             const double d[3], double perm, int *done)
{
    const double *pt[3] = {a, b, c};
    double x[3], y[3], z[3], xt[3], yt[3], zt[3];
    int inexact = 0;
    for (int k = 0; k < 3; k++) {
        two_diff(pt[k][0], d[0], &x[k], &xt[k]);
        two_diff(pt[k][1], d[1], &y[k], &yt[k]);
        two_diff(pt[k][2], d[2], &z[k], &zt[k]);
        inexact |= (xt[k] != 0.0) | (yt[k] != 0.0) | (zt[k] != 0.0);
    }
    /* det = sum over k of z_k (x_i y_j - x_j y_i), (k, i, j) cyclic */
    double m[4], t[3][8], v01[16], v[24], w[25];
    int nt[3];
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        int nm = det2_exp(x[i], y[j], x[j], y[i], m);
        nt[k] = exp_scale(nm, m, z[k], t[k]);
    }
    int n01 = exp_sum(nt[0], t[0], nt[1], t[1], v01);
    int nv = exp_sum(n01, v01, nt[2], t[2], v);
    *done = 1;
    if (!inexact) return exp_sign_estimate(nv, v);
    if (exceeds(nv, v, o3d_boundB * perm)) return v[nv - 1];
    double tc[3];
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        double mh = x[i] * y[j] - x[j] * y[i];
        double mt = (xt[i] * y[j] + x[i] * yt[j]) - (xt[j] * y[i] + x[j] * yt[i]);
        tc[k] = zt[k] * mh + z[k] * mt;
    }
    double lt = (tc[0] + tc[1]) + tc[2];
    int nw = exp_sum(nv, v, lt != 0.0, &lt, w);
    if (exceeds(nw, w, o3d_boundC * perm)) return w[nw - 1];
    *done = 0;
    return 0.0;
}

/* Stage D: the exact determinant from the exact differences. */
static double orient3d_exact(const double a[3], const double b[3], const double c[3],
                             const double d[3])
{
    double ad[3][2], bd[3][2], cd[3][2];
    int na[3], nb[3], nc[3];
    for (int j = 0; j < 3; j++) {
        na[j] = exp_from_diff(a[j], d[j], ad[j]);
        nb[j] = exp_from_diff(b[j], d[j], bd[j]);
        nc[j] = exp_from_diff(c[j], d[j], cd[j]);
    }
    double m[16], t1[64], t2[64], t3[64], s12[128], h[192], w[128];
    int nm, n1, n2, n3;
    nm = exp_minor(nb[0], bd[0], nc[1], cd[1], nb[1], bd[1], nc[0], cd[0], m);
    n1 = exp_mul(na[2], ad[2], nm, m, t1, w);
    nm = exp_minor(nc[0], cd[0], na[1], ad[1], nc[1], cd[1], na[0], ad[0], m);
    n2 = exp_mul(nb[2], bd[2], nm, m, t2, w);
    nm = exp_minor(na[0], ad[0], nb[1], bd[1], na[1], ad[1], nb[0], bd[0], m);
    n3 = exp_mul(nc[2], cd[2], nm, m, t3, w);
    int n12 = exp_sum(n1, t1, n2, t2, s12);
    int nh = exp_sum(n12, s12, n3, t3, h);
    return exp_sign_estimate(nh, h);
}

/* Filter failed: the range guard, then stages B, C, D (see the banner). */
static NOINLINE double orient3d_slow(const double a[3], const double b[3], const double c[3],
                                     const double d[3], double perm)
{
    const double p[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
    if (!all_finite(p, 12)) return NAN;
    if (!in_range(p, 12, 0x1p-280, 0x1p300)) return orient3d_bigint(p);
    int done;
    double det = orient3d_adapt(a, b, c, d, perm, &done);
    if (done) return det;
    return orient3d_exact(a, b, c, d);
}

double orient3d(const double a[3], const double b[3], const double c[3], const double d[3])
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    double az = fabs(adz), bz = fabs(bdz), cz = fabs(cdz);
    double perm = (fabs(bdxcdy) + fabs(cdxbdy)) * az + (fabs(cdxady) + fabs(adxcdy)) * bz +
        (fabs(adxbdy) + fabs(bdxady)) * cz;
    double bound = o3d_bound * perm + UFL * (az + bz + cz + 1.0);
    if (det > bound || -det > bound) return det;
    return orient3d_slow(a, b, c, d, perm);
}

/* ---- incircle ---- */

static double incircle_bigint(const double *p)
{
    int emin = low_exponent(p, 8);
    bigint v[8], dx[3], dy[3], lift[3], t, u, m, acc, s;
    for (int i = 0; i < 8; i++) bigint_from_double(&v[i], p[i], emin);
    for (int k = 0; k < 3; k++) {
        bigint_sub(&dx[k], &v[2 * k], &v[6]);
        bigint_sub(&dy[k], &v[2 * k + 1], &v[7]);
        bigint_mul(&t, &dx[k], &dx[k]);
        bigint_mul(&u, &dy[k], &dy[k]);
        bigint_add(&lift[k], &t, &u);
    }
    acc.sign = 0;
    acc.n = 0;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3; /* cyclic minors */
        bigint_mul(&t, &dx[i], &dy[j]);
        bigint_mul(&u, &dx[j], &dy[i]);
        bigint_sub(&m, &t, &u);
        bigint_mul(&s, &lift[k], &m);
        bigint_add(&acc, &acc, &s);
    }
    return sign_of(&acc);
}

/* Stages B and C (coordinates in range), as for orient2d. */
static double incircle_adapt(const double a[2], const double b[2], const double c[2],
                             const double d[2], double perm, int *done)
{
    const double *pt[3] = {a, b, c};
    double x[3], y[3], xt[3], yt[3];
    int inexact = 0;
    for (int k = 0; k < 3; k++) {
        two_diff(pt[k][0], d[0], &x[k], &xt[k]);
        two_diff(pt[k][1], d[1], &y[k], &yt[k]);
        inexact |= (xt[k] != 0.0) | (yt[k] != 0.0);
    }
    /* first-order tail correction: d(lift) = 2 (x xt + y yt), d(minor) = mt */
    double lc = 0.0;
    if (inexact) {
        double tc[3];
        for (int k = 0; k < 3; k++) {
            int i = (k + 1) % 3, j = (k + 2) % 3;
            double mh = x[i] * y[j] - x[j] * y[i];
            double mt = (xt[i] * y[j] + x[i] * yt[j]) - (xt[j] * y[i] + x[j] * yt[i]);
            double lift = x[k] * x[k] + y[k] * y[k];
            double lt = x[k] * xt[k] + y[k] * yt[k];
            tc[k] = lift * mt + (2.0 * lt) * mh;
        }
        lc = (tc[0] + tc[1]) + tc[2];
    }
    /* stage B1: lifts and minors of the heads as unevaluated double sums
     * (l + lo, s + r), their products' leading parts l s exact, summed
     * exactly; the rest plus the tail correction in plain floating point */
    double ps[3], small = 0.0;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        double p, e, q, f, sh, st, a1, ea, b1, eb, l, lt, pe;
        two_product(x[i], y[j], &p, &e);
        two_product(x[j], y[i], &q, &f);
        two_diff(p, q, &sh, &st);
        double r = (st + e) - f;
        two_product(x[k], x[k], &a1, &ea);
        two_product(y[k], y[k], &b1, &eb);
        two_sum(a1, b1, &l, &lt);
        double lo = (lt + ea) + eb;
        two_product(l, sh, &ps[k], &pe);
        small += (l * r + lo * sh) + pe;
    }
    {
        double g, gt, G, Gt;
        two_sum(ps[0], ps[1], &g, &gt);
        two_sum(g, ps[2], &G, &Gt);
        double rest = (((gt + Gt) + small) + lc);
        double det = G + rest;
        double err = icc_boundB1 * perm + icc_resultB1 * fabs(det);
        if (det > err || -det > err) {
            *done = 1;
            return det;
        }
    }
    /* det = sum over k of (x_k^2 + y_k^2) (x_i y_j - x_j y_i), (k, i, j)
     * cyclic; each lift times minor as ((m x) x) + ((m y) y) */
    double m[4], s1[8], s2[16], s3[8], s4[16], t[3][32], v01[64], v[96], w[97];
    int nt[3];
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        int nm = det2_exp(x[i], y[j], x[j], y[i], m);
        int n1 = exp_scale(nm, m, x[k], s1);
        int n2 = exp_scale(n1, s1, x[k], s2);
        int n3 = exp_scale(nm, m, y[k], s3);
        int n4 = exp_scale(n3, s3, y[k], s4);
        nt[k] = exp_sum(n2, s2, n4, s4, t[k]);
    }
    int n01 = exp_sum(nt[0], t[0], nt[1], t[1], v01);
    int nv = exp_sum(n01, v01, nt[2], t[2], v);
    *done = 1;
    if (!inexact) return exp_sign_estimate(nv, v);
    int nw = exp_sum(nv, v, lc != 0.0, &lc, w);
    if (exceeds(nw, w, icc_boundC * perm)) return w[nw - 1];
    *done = 0;
    return 0.0;
}

/* Stage D: the exact determinant from the exact differences. */
static double incircle_exact(const double a[2], const double b[2], const double c[2],
                             const double d[2])
{
    const double *pt[3] = {a, b, c};
    double dx[3][2], dy[3][2], lift[3][16];
    int nx[3], ny[3], nlift[3];
    double sq1[8], sq2[8], w[1024];
    for (int k = 0; k < 3; k++) {
        nx[k] = exp_from_diff(pt[k][0], d[0], dx[k]);
        ny[k] = exp_from_diff(pt[k][1], d[1], dy[k]);
        int n1 = exp_mul(nx[k], dx[k], nx[k], dx[k], sq1, w);
        int n2 = exp_mul(ny[k], dy[k], ny[k], dy[k], sq2, w);
        nlift[k] = exp_sum(n1, sq1, n2, sq2, lift[k]);
    }
    double m[16], term[512], acc[1536], tmp[1536];
    int nacc = 0;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        int nm = exp_minor(nx[i], dx[i], ny[j], dy[j], ny[i], dy[i], nx[j], dx[j], m);
        int nt = exp_mul(nlift[k], lift[k], nm, m, term, w);
        for (int q = 0; q < nacc; q++) tmp[q] = acc[q];
        nacc = exp_sum(nacc, tmp, nt, term, acc);
    }
    return exp_sign_estimate(nacc, acc);
}

/* Filter failed: the range guard, then stages B, C, D (see the banner). */
static NOINLINE double incircle_slow(const double a[2], const double b[2], const double c[2],
                                     const double d[2], double perm)
{
    const double p[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    if (!all_finite(p, 8)) return NAN;
    if (!in_range(p, 8, 0x1p-200, 0x1p200)) return incircle_bigint(p);
    int done;
    double det = incircle_adapt(a, b, c, d, perm, &done);
    if (done) return det;
    return incircle_exact(a, b, c, d);
}

double incircle(const double a[2], const double b[2], const double c[2], const double d[2])
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double alift = adx * adx + ady * ady;
    double blift = bdx * bdx + bdy * bdy;
    double clift = cdx * cdx + cdy * cdy;
    double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    double pa = fabs(bdxcdy) + fabs(cdxbdy);
    double pb = fabs(cdxady) + fabs(adxcdy);
    double pc = fabs(adxbdy) + fabs(bdxady);
    double perm = pa * alift + pb * blift + pc * clift;
    double bound = icc_bound * perm + UFL * (alift + blift + clift + pa + pb + pc + 1.0);
    if (det > bound || -det > bound) return det;
    return incircle_slow(a, b, c, d, perm);
}

/* ---- insphere ---- */

static double insphere_bigint(const double *p)
{
    /* p = {a, b, c, d, e} as 15 doubles. det = -alift bcd + blift cda
     * - clift dab + dlift abc, the 4x4 determinant with rows (x-e, |x-e|^2). */
    int emin = low_exponent(p, 15);
    bigint v[15], dd[4][3], lift[4], t, u, m2, m3, acc, s;
    for (int i = 0; i < 15; i++) bigint_from_double(&v[i], p[i], emin);
    for (int k = 0; k < 4; k++) {
        lift[k].sign = 0;
        lift[k].n = 0;
        for (int j = 0; j < 3; j++) {
            bigint_sub(&dd[k][j], &v[3 * k + j], &v[12 + j]);
            bigint_mul(&t, &dd[k][j], &dd[k][j]);
            bigint_add(&lift[k], &lift[k], &t);
        }
    }
    /* 3x3 determinant of rows r0, r1, r2 (xyz). */
    static const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    acc.sign = 0;
    acc.n = 0;
    for (int k = 0; k < 4; k++) {
        const bigint *r0 = dd[rows[k][0]], *r1 = dd[rows[k][1]], *r2 = dd[rows[k][2]];
        m3.sign = 0;
        m3.n = 0;
        for (int z = 0; z < 3; z++) {
            int x = (z + 1) % 3, y = (z + 2) % 3; /* cofactor along column z */
            bigint_mul(&t, &r1[x], &r2[y]);
            bigint_mul(&u, &r1[y], &r2[x]);
            bigint_sub(&m2, &t, &u);
            bigint_mul(&s, &r0[z], &m2);
            bigint_add(&m3, &m3, &s);
        }
        bigint_mul(&s, &lift[k], &m3);
        if (k % 2 == 0) bigint_sub(&acc, &acc, &s); /* cofactor signs -, +, -, + */
        else bigint_add(&acc, &acc, &s);
    }
    return sign_of(&acc);
}

double insphere(const double a[3], const double b[3], const double c[3], const double d[3],
                const double e[3])
{
    double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    double aexbey = aex * bey, bexaey = bex * aey;
    double bexcey = bex * cey, cexbey = cex * bey;
    double cexdey = cex * dey, dexcey = dex * cey;
    double dexaey = dex * aey, aexdey = aex * dey;
    double aexcey = aex * cey, cexaey = cex * aey;
    double bexdey = bex * dey, dexbey = dex * bey;
    double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
    double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
    double abc = aez * bc - bez * ac + cez * ab;
    double bcd = bez * cd - cez * bd + dez * bc;
    double cda = cez * da + dez * ac + aez * cd;
    double dab = dez * ab + aez * bd + bez * da;
    double alift = aex * aex + aey * aey + aez * aez;
    double blift = bex * bex + bey * bey + bez * bez;
    double clift = cex * cex + cey * cey + cez * cez;
    double dlift = dex * dex + dey * dey + dez * dez;
    double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    double az = fabs(aez), bz = fabs(bez), cz = fabs(cez), dz = fabs(dez);
    double pab = fabs(aexbey) + fabs(bexaey), pbc = fabs(bexcey) + fabs(cexbey);
    double pcd = fabs(cexdey) + fabs(dexcey), pda = fabs(dexaey) + fabs(aexdey);
    double pac = fabs(aexcey) + fabs(cexaey), pbd = fabs(bexdey) + fabs(dexbey);
    double pabc = az * pbc + bz * pac + cz * pab;
    double pbcd = bz * pcd + cz * pbd + dz * pbc;
    double pcda = cz * pda + dz * pac + az * pcd;
    double pdab = dz * pab + az * pbd + bz * pda;
    double perm = dlift * pabc + clift * pdab + blift * pcda + alift * pbcd;
    double lsum = alift + blift + clift + dlift;
    double bound = isp_bound * perm +
        UFL * ((az + bz + cz + dz + 2.0) * (lsum + 1.0) + pabc + pbcd + pcda + pdab + 1.0);
    if (det > bound || -det > bound) return det;
    const double p[15] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1],
                          c[2], d[0], d[1], d[2], e[0], e[1], e[2]};
    if (!all_finite(p, 15)) return NAN;
    return insphere_bigint(p);
}
