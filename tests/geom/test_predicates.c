/* Tests for geom/predicates: signs equal those of GMP integer arithmetic.
 *
 * Every case is evaluated twice: by the predicate and by an independent
 * evaluation of the same determinant with GMP integers (all coordinates of
 * one call scaled by a common power of two so they become integers, which
 * keeps the sign). Generators are adversarial: points a few ulps off exact
 * lines, circles, planes and spheres; exact degeneracies (must give 0)
 * including ones with wildly mixed magnitudes (rectangle and box corners
 * are always cocircular/cospherical, points on y = x always collinear);
 * coordinates at the edges of the expansion stage's exact range; random
 * doubles over the whole exponent range. Zero disagreements allowed.
 * Case counts shrink under sanitizers, or set SCAF_PRED_CASES_SCALE
 * (a percentage, default 100).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom/predicates.h"

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

static long scaled(long n)
{
    long pct = SANITIZED ? 4 : 100;
    const char *s = getenv("SCAF_PRED_CASES_SCALE");
    if (s && *s) pct = atol(s);
    long r = n * pct / 100;
    return r < 100 ? 100 : r;
}

/* ---- deterministic random numbers ---- */

typedef struct rng {
    uint64_t s;
} rng;

static uint64_t next_u64(rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545F4914F6CDD1DULL;
}

static double unit(rng *r) /* [0, 1) with 53 random bits */
{
    return (double)(next_u64(r) >> 11) * 0x1p-53;
}

static double sym(rng *r) { return 2.0 * unit(r) - 1.0; }

static int irange(rng *r, int lo, int hi) { return lo + (int)(next_u64(r) % (uint64_t)(hi - lo + 1)); }

/* A double with random sign, mantissa and exponent over the whole range
 * (subnormals included), zero now and then. */
static double wild(rng *r)
{
    uint64_t u = next_u64(r);
    if ((u & 15) == 0) return 0.0;
    double m = 1.0 + unit(r);
    int e = irange(r, -1080, 1023);
    double x = ldexp(m, e);
    return (u & 16) ? -x : x;
}

/* x moved by k ulps (k may be negative). */
static double ulps(double x, int k)
{
    for (; k > 0; k--) x = nextafter(x, INFINITY);
    for (; k < 0; k++) x = nextafter(x, -INFINITY);
    return x;
}

/* ---- exact reference with GMP ---- */

static int low_exp(double x)
{
    int e;
    double m = frexp(fabs(x), &e);
    int64_t mi = (int64_t)ldexp(m, 53);
    int low = e - 53;
    while (!(mi & 1)) {
        mi >>= 1;
        low++;
    }
    return low;
}

/* z[i] = p[i] / 2^emin for the common emin: integers of the same ratios. */
static void to_ints(const double *p, int n, mpz_t *z)
{
    int emin = 0, any = 0;
    for (int i = 0; i < n; i++)
        if (p[i] != 0.0) {
            int e = low_exp(p[i]);
            if (!any || e < emin) emin = e;
            any = 1;
        }
    for (int i = 0; i < n; i++) {
        if (p[i] == 0.0) {
            mpz_set_ui(z[i], 0);
            continue;
        }
        int e;
        double m = frexp(p[i], &e);
        mpz_set_d(z[i], ldexp(m, 53)); /* exact: a 53-bit integer */
        int sh = e - 53 - emin;
        if (sh >= 0)
            mpz_mul_2exp(z[i], z[i], (mp_bitcnt_t)sh);
        else
            mpz_tdiv_q_2exp(z[i], z[i], (mp_bitcnt_t)(-sh)); /* exact */
    }
}

typedef struct ref {
    mpz_t v[15], d[12], t, u, m, acc, lift[4], m3;
} ref;

static void ref_init(ref *R)
{
    for (int i = 0; i < 15; i++) mpz_init(R->v[i]);
    for (int i = 0; i < 12; i++) mpz_init(R->d[i]);
    for (int i = 0; i < 4; i++) mpz_init(R->lift[i]);
    mpz_inits(R->t, R->u, R->m, R->acc, R->m3, NULL);
}

static void ref_clear(ref *R)
{
    for (int i = 0; i < 15; i++) mpz_clear(R->v[i]);
    for (int i = 0; i < 12; i++) mpz_clear(R->d[i]);
    for (int i = 0; i < 4; i++) mpz_clear(R->lift[i]);
    mpz_clears(R->t, R->u, R->m, R->acc, R->m3, NULL);
}

/* d[k*dim + j] = point k minus the last point, for nk points. */
static void diffs(ref *R, const double *p, int npts, int dim)
{
    to_ints(p, npts * dim, R->v);
    for (int k = 0; k < npts - 1; k++)
        for (int j = 0; j < dim; j++)
            mpz_sub(R->d[k * dim + j], R->v[k * dim + j], R->v[(npts - 1) * dim + j]);
}

/* 2x2 determinant |x1 y1; x2 y2| into out. */
static void det2(ref *R, mpz_t out, mpz_t x1, mpz_t y1, mpz_t x2, mpz_t y2)
{
    mpz_mul(R->t, x1, y2);
    mpz_mul(R->u, y1, x2);
    mpz_sub(out, R->t, R->u);
}

/* 3x3 determinant of rows r0, r1, r2 (3 entries each) into out. */
static void det3(ref *R, mpz_t out, mpz_t *r0, mpz_t *r1, mpz_t *r2)
{
    mpz_set_ui(out, 0);
    det2(R, R->m, r1[1], r1[2], r2[1], r2[2]);
    mpz_addmul(out, r0[0], R->m);
    det2(R, R->m, r1[0], r1[2], r2[0], r2[2]);
    mpz_submul(out, r0[1], R->m);
    det2(R, R->m, r1[0], r1[1], r2[0], r2[1]);
    mpz_addmul(out, r0[2], R->m);
}

static int ref_orient2d(ref *R, const double *a, const double *b, const double *c)
{
    double p[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    diffs(R, p, 3, 2);
    det2(R, R->acc, R->d[0], R->d[1], R->d[2], R->d[3]);
    return mpz_sgn(R->acc);
}

static int ref_orient3d(ref *R, const double *a, const double *b, const double *c, const double *d)
{
    double p[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
    diffs(R, p, 4, 3);
    det3(R, R->acc, R->d, R->d + 3, R->d + 6);
    return mpz_sgn(R->acc);
}

static int ref_incircle(ref *R, const double *a, const double *b, const double *c, const double *d)
{
    double p[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    diffs(R, p, 4, 2);
    /* rows (dx, dy, dx^2 + dy^2): expand along the lift column */
    mpz_t *D = R->d;
    for (int k = 0; k < 3; k++) {
        mpz_mul(R->lift[k], D[2 * k], D[2 * k]);
        mpz_addmul(R->lift[k], D[2 * k + 1], D[2 * k + 1]);
    }
    mpz_set_ui(R->acc, 0);
    det2(R, R->m3, D[2], D[3], D[4], D[5]);
    mpz_addmul(R->acc, R->lift[0], R->m3);
    det2(R, R->m3, D[0], D[1], D[4], D[5]);
    mpz_submul(R->acc, R->lift[1], R->m3);
    det2(R, R->m3, D[0], D[1], D[2], D[3]);
    mpz_addmul(R->acc, R->lift[2], R->m3);
    return mpz_sgn(R->acc);
}

static int ref_insphere(ref *R, const double *a, const double *b, const double *c, const double *d,
                        const double *e)
{
    double p[15] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2],
                    d[0], d[1], d[2], e[0], e[1], e[2]};
    diffs(R, p, 5, 3);
    mpz_t *D = R->d;
    for (int k = 0; k < 4; k++) {
        mpz_mul(R->lift[k], D[3 * k], D[3 * k]);
        mpz_addmul(R->lift[k], D[3 * k + 1], D[3 * k + 1]);
        mpz_addmul(R->lift[k], D[3 * k + 2], D[3 * k + 2]);
    }
    /* 4x4 with rows (dx, dy, dz, lift), expanded along the lift column:
     * signs -, +, -, + for rows a, b, c, d. */
    mpz_set_ui(R->acc, 0);
    det3(R, R->m3, D + 3, D + 6, D + 9);
    mpz_submul(R->acc, R->lift[0], R->m3);
    det3(R, R->m3, D, D + 6, D + 9);
    mpz_addmul(R->acc, R->lift[1], R->m3);
    det3(R, R->m3, D, D + 3, D + 9);
    mpz_submul(R->acc, R->lift[2], R->m3);
    det3(R, R->m3, D, D + 3, D + 6);
    mpz_addmul(R->acc, R->lift[3], R->m3);
    return mpz_sgn(R->acc);
}

static int sgn(double x) { return (x > 0) - (x < 0); }

/* ---- comparison drivers ---- */

typedef struct tally {
    long cases, zeros, disagreements;
} tally;

static void report(const char *what, const double *p, int n, double got, int want)
{
    fprintf(stderr, "%s disagrees: got %g, exact sign %d, points:", what, got, want);
    for (int i = 0; i < n; i++) fprintf(stderr, " %a", p[i]);
    fprintf(stderr, "\n");
}

static void check2(ref *R, tally *t, const double *a, const double *b, const double *c)
{
    double got = orient2d(a, b, c);
    int want = ref_orient2d(R, a, b, c);
    t->cases++;
    t->zeros += want == 0;
    if (sgn(got) != want || isnan(got)) {
        double p[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
        if (t->disagreements++ < 5) report("orient2d", p, 6, got, want);
    }
}

static void check3(ref *R, tally *t, const double *a, const double *b, const double *c,
                   const double *d)
{
    double got = orient3d(a, b, c, d);
    int want = ref_orient3d(R, a, b, c, d);
    t->cases++;
    t->zeros += want == 0;
    if (sgn(got) != want || isnan(got)) {
        double p[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
        if (t->disagreements++ < 5) report("orient3d", p, 12, got, want);
    }
}

static void check_ic(ref *R, tally *t, const double *a, const double *b, const double *c,
                     const double *d)
{
    double got = incircle(a, b, c, d);
    int want = ref_incircle(R, a, b, c, d);
    t->cases++;
    t->zeros += want == 0;
    if (sgn(got) != want || isnan(got)) {
        double p[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
        if (t->disagreements++ < 5) report("incircle", p, 8, got, want);
    }
}

static void check_is(ref *R, tally *t, const double *a, const double *b, const double *c,
                     const double *d, const double *e)
{
    double got = insphere(a, b, c, d, e);
    int want = ref_insphere(R, a, b, c, d, e);
    t->cases++;
    t->zeros += want == 0;
    if (sgn(got) != want || isnan(got)) {
        double p[15] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2],
                        d[0], d[1], d[2], e[0], e[1], e[2]};
        if (t->disagreements++ < 5) report("insphere", p, 15, got, want);
    }
}

/* Values at the edges of the expansion stages' ranges. */
static double edge_value(rng *r)
{
    static const int ex[] = {-450, 450, -280, 300, -200, 200, 0, -1022, -1074, 1023};
    double x = ldexp(1.0, ex[irange(r, 0, 9)]);
    switch (irange(r, 0, 3)) {
    case 0: x = nextafter(x, 0.0); break;
    case 1: x = nextafter(x, INFINITY); break;
    case 2: x *= 1.5; break;
    default: break;
    }
    if (!isfinite(x)) x = 0x1.fffffffffffffp1023;
    if (next_u64(r) & 1) x = -x;
    return (next_u64(r) % 8) == 0 ? 0.0 : x;
}

/* ---- orient2d ---- */

static void orient2d_matches_gmp(void **state)
{
    (void)state;
    rng r = {0x9E3779B97F4A7C15ULL};
    ref R;
    ref_init(&R);
    tally t = {0, 0, 0};
    long n = scaled(120000);
    for (long i = 0; i < n; i++) {
        double a[2], b[2], c[2];
        /* random */
        a[0] = sym(&r), a[1] = sym(&r), b[0] = sym(&r), b[1] = sym(&r), c[0] = sym(&r), c[1] = sym(&r);
        check2(&R, &t, a, b, c);
        /* a few ulps off a line through a and b */
        double s = unit(&r) * 3.0 - 1.0;
        c[0] = ulps(a[0] + s * (b[0] - a[0]), irange(&r, -3, 3));
        c[1] = ulps(a[1] + s * (b[1] - a[1]), irange(&r, -3, 3));
        check2(&R, &t, a, b, c);
        /* exact: integer multiples of a direction, scaled by 2^k */
        int k = irange(&r, -1070, 980);
        double u = irange(&r, -1000, 1000), v = irange(&r, -1000, 1000);
        double px = irange(&r, -100000, 100000), py = irange(&r, -100000, 100000);
        int l1 = irange(&r, -50, 50), l2 = irange(&r, -50, 50);
        a[0] = ldexp(px, k), a[1] = ldexp(py, k);
        b[0] = ldexp(px + l1 * u, k), b[1] = ldexp(py + l1 * v, k);
        c[0] = ldexp(px + l2 * u, k), c[1] = ldexp(py + l2 * v, k);
        check2(&R, &t, a, b, c);
        c[irange(&r, 0, 1)] = ulps(c[0], irange(&r, -2, 2));
        check2(&R, &t, a, b, c);
        /* exact with mixed magnitudes: on y = x, and on a line through 0 */
        a[0] = a[1] = wild(&r), b[0] = b[1] = wild(&r), c[0] = c[1] = wild(&r);
        check2(&R, &t, a, b, c);
        c[1] = ulps(c[1], irange(&r, -2, 2));
        check2(&R, &t, a, b, c);
        /* power-of-two multiples of one point: collinear through 0 (when
         * the scaling neither overflows nor drops bits) */
        double w0 = ldexp(1.0 + unit(&r), irange(&r, -400, 400)), w1 = wild(&r);
        int e1 = irange(&r, -500, 500), e2 = irange(&r, -500, 500);
        a[0] = w0, a[1] = w1;
        b[0] = ldexp(w0, e1), b[1] = ldexp(w1, e1);
        c[0] = ldexp(w0, e2), c[1] = ldexp(w1, e2);
        if (isfinite(b[1]) && isfinite(c[1])) check2(&R, &t, a, b, c);
        /* wild and range-edge coordinates */
        a[0] = wild(&r), a[1] = wild(&r), b[0] = wild(&r), b[1] = wild(&r), c[0] = wild(&r), c[1] = wild(&r);
        check2(&R, &t, a, b, c);
        a[0] = edge_value(&r), a[1] = edge_value(&r), b[0] = edge_value(&r);
        b[1] = edge_value(&r), c[0] = edge_value(&r), c[1] = edge_value(&r);
        check2(&R, &t, a, b, c);
    }
    ref_clear(&R);
    fprintf(stderr, "orient2d: %ld cases, %ld exactly degenerate, %ld disagreements\n", t.cases,
            t.zeros, t.disagreements);
    assert_int_equal(t.disagreements, 0);
    assert_true(t.zeros > t.cases / 10); /* the degenerate generators work */
}

/* ---- orient3d ---- */

static void orient3d_matches_gmp(void **state)
{
    (void)state;
    rng r = {0xD1B54A32D192ED03ULL};
    ref R;
    ref_init(&R);
    tally t = {0, 0, 0};
    long n = scaled(40000);
    for (long i = 0; i < n; i++) {
        double a[3], b[3], c[3], d[3];
        for (int j = 0; j < 3; j++) a[j] = sym(&r), b[j] = sym(&r), c[j] = sym(&r), d[j] = sym(&r);
        check3(&R, &t, a, b, c, d);
        /* a few ulps off the plane through a, b, c */
        double s = sym(&r) * 2, u = sym(&r) * 2;
        for (int j = 0; j < 3; j++)
            d[j] = ulps(a[j] + s * (b[j] - a[j]) + u * (c[j] - a[j]), irange(&r, -3, 3));
        check3(&R, &t, a, b, c, d);
        /* exact: integer combinations, scaled */
        int k = irange(&r, -1060, 970);
        double o[3], e1[3], e2[3];
        for (int j = 0; j < 3; j++)
            o[j] = irange(&r, -10000, 10000), e1[j] = irange(&r, -100, 100), e2[j] = irange(&r, -100, 100);
        double *pts[4] = {a, b, c, d};
        for (int q = 0; q < 4; q++) {
            int s1 = irange(&r, -30, 30), s2 = irange(&r, -30, 30);
            for (int j = 0; j < 3; j++) pts[q][j] = ldexp(o[j] + s1 * e1[j] + s2 * e2[j], k);
        }
        check3(&R, &t, a, b, c, d);
        d[irange(&r, 0, 2)] = ulps(d[0], irange(&r, -2, 2));
        check3(&R, &t, a, b, c, d);
        /* exact, mixed magnitudes: on the plane z = x */
        for (int q = 0; q < 4; q++) pts[q][0] = pts[q][2] = wild(&r), pts[q][1] = wild(&r);
        check3(&R, &t, a, b, c, d);
        d[2] = ulps(d[2], irange(&r, -2, 2));
        check3(&R, &t, a, b, c, d);
        /* box corners: faces are planes */
        double x1 = wild(&r), x2 = wild(&r), y1 = wild(&r), y2 = wild(&r), z1 = wild(&r);
        a[0] = x1, a[1] = y1, a[2] = z1;
        b[0] = x2, b[1] = y1, b[2] = z1;
        c[0] = x1, c[1] = y2, c[2] = z1;
        d[0] = x2, d[1] = y2, d[2] = ulps(z1, irange(&r, -1, 1));
        check3(&R, &t, a, b, c, d);
        for (int q = 0; q < 4; q++)
            for (int j = 0; j < 3; j++) pts[q][j] = (q + j) % 2 ? wild(&r) : edge_value(&r);
        check3(&R, &t, a, b, c, d);
        for (int q = 0; q < 4; q++)
            for (int j = 0; j < 3; j++) pts[q][j] = edge_value(&r);
        check3(&R, &t, a, b, c, d);
    }
    ref_clear(&R);
    fprintf(stderr, "orient3d: %ld cases, %ld exactly degenerate, %ld disagreements\n", t.cases,
            t.zeros, t.disagreements);
    assert_int_equal(t.disagreements, 0);
    assert_true(t.zeros > t.cases / 10);
}

/* ---- incircle ---- */

/* Integer points on the circle x^2 + y^2 = 65^2. */
static const int circ65[][2] = {{65, 0}, {63, 16}, {60, 25}, {56, 33}, {52, 39}, {39, 52},
                                {33, 56}, {25, 60}, {16, 63}, {0, 65}};

static void circle_point(rng *r, double *p, double ox, double oy, int k)
{
    int i = irange(r, 0, 9);
    double x = circ65[i][0], y = circ65[i][1];
    if (next_u64(r) & 1) x = -x;
    if (next_u64(r) & 1) y = -y;
    if (next_u64(r) & 1) {
        double t = x;
        x = y;
        y = t;
    }
    p[0] = ldexp(ox + x, k);
    p[1] = ldexp(oy + y, k);
}

static void incircle_matches_gmp(void **state)
{
    (void)state;
    rng r = {0x8CB92BA72F3D8DD7ULL};
    ref R;
    ref_init(&R);
    tally t = {0, 0, 0};
    long n = scaled(40000);
    for (long i = 0; i < n; i++) {
        double a[2], b[2], c[2], d[2];
        a[0] = sym(&r), a[1] = sym(&r), b[0] = sym(&r), b[1] = sym(&r);
        c[0] = sym(&r), c[1] = sym(&r), d[0] = sym(&r), d[1] = sym(&r);
        check_ic(&R, &t, a, b, c, d);
        /* nearly cocircular: points computed on a circle, d moved by ulps */
        double cx = sym(&r), cy = sym(&r), rad = unit(&r) + 0.01;
        double *pts[4] = {a, b, c, d};
        for (int q = 0; q < 4; q++) {
            double th = unit(&r) * 6.283185307179586;
            pts[q][0] = cx + rad * cos(th);
            pts[q][1] = cy + rad * sin(th);
        }
        d[0] = ulps(d[0], irange(&r, -3, 3));
        check_ic(&R, &t, a, b, c, d);
        /* exactly cocircular integer points, translated and scaled */
        int k = irange(&r, -1060, 970);
        double ox = irange(&r, -100000, 100000), oy = irange(&r, -100000, 100000);
        for (int q = 0; q < 4; q++) circle_point(&r, pts[q], ox, oy, k);
        check_ic(&R, &t, a, b, c, d);
        d[irange(&r, 0, 1)] = ulps(d[1], irange(&r, -2, 2));
        check_ic(&R, &t, a, b, c, d);
        /* rectangle corners are cocircular, whatever the magnitudes */
        double x1 = wild(&r), x2 = wild(&r), y1 = wild(&r), y2 = wild(&r);
        a[0] = x1, a[1] = y1, b[0] = x2, b[1] = y1, c[0] = x2, c[1] = y2, d[0] = x1, d[1] = y2;
        check_ic(&R, &t, a, b, c, d);
        d[0] = ulps(d[0], irange(&r, -2, 2));
        check_ic(&R, &t, a, b, c, d);
        x1 = sym(&r), x2 = sym(&r), y1 = sym(&r), y2 = sym(&r);
        a[0] = x1, a[1] = y1, b[0] = x2, b[1] = y1, c[0] = x2, c[1] = y2, d[0] = x1, d[1] = y2;
        d[1] = ulps(d[1], irange(&r, -1, 1));
        check_ic(&R, &t, a, b, c, d);
        for (int q = 0; q < 4; q++) pts[q][0] = wild(&r), pts[q][1] = wild(&r);
        check_ic(&R, &t, a, b, c, d);
        for (int q = 0; q < 4; q++) pts[q][0] = edge_value(&r), pts[q][1] = edge_value(&r);
        check_ic(&R, &t, a, b, c, d);
    }
    ref_clear(&R);
    fprintf(stderr, "incircle: %ld cases, %ld exactly degenerate, %ld disagreements\n", t.cases,
            t.zeros, t.disagreements);
    assert_int_equal(t.disagreements, 0);
    assert_true(t.zeros > t.cases / 10);
}

/* ---- insphere ---- */

static void insphere_matches_gmp(void **state)
{
    (void)state;
    rng r = {0x94D049BB133111EBULL};
    ref R;
    ref_init(&R);
    tally t = {0, 0, 0};
    long n = scaled(15000);
    for (long i = 0; i < n; i++) {
        double a[3], b[3], c[3], d[3], e[3];
        double *pts[5] = {a, b, c, d, e};
        for (int q = 0; q < 5; q++)
            for (int j = 0; j < 3; j++) pts[q][j] = sym(&r);
        check_is(&R, &t, a, b, c, d, e);
        /* nearly cospherical: on a sphere in floating point, e by ulps */
        double cen[3] = {sym(&r), sym(&r), sym(&r)}, rad = unit(&r) + 0.01;
        for (int q = 0; q < 5; q++) {
            double th = unit(&r) * 6.283185307179586, z = sym(&r), s = sqrt(1 - z * z);
            pts[q][0] = cen[0] + rad * s * cos(th);
            pts[q][1] = cen[1] + rad * s * sin(th);
            pts[q][2] = cen[2] + rad * z;
        }
        e[irange(&r, 0, 2)] = ulps(e[0], irange(&r, -3, 3));
        check_is(&R, &t, a, b, c, d, e);
        /* box corners are cospherical, whatever the magnitudes */
        double x[2] = {wild(&r), wild(&r)}, y[2] = {wild(&r), wild(&r)}, z[2] = {wild(&r), wild(&r)};
        for (int q = 0; q < 5; q++) {
            int corner = irange(&r, 0, 7);
            pts[q][0] = x[corner & 1], pts[q][1] = y[(corner >> 1) & 1], pts[q][2] = z[corner >> 2];
        }
        check_is(&R, &t, a, b, c, d, e);
        int k = irange(&r, -1060, 960);
        double x2[2] = {irange(&r, -99, 99), irange(&r, -99, 99)};
        double y2[2] = {irange(&r, -99, 99), irange(&r, -99, 99)};
        double z2[2] = {irange(&r, -99, 99), irange(&r, -99, 99)};
        for (int q = 0; q < 5; q++) {
            int corner = (q * 3 + irange(&r, 0, 1)) & 7;
            pts[q][0] = ldexp(x2[corner & 1], k), pts[q][1] = ldexp(y2[(corner >> 1) & 1], k);
            pts[q][2] = ldexp(z2[corner >> 2], k);
        }
        check_is(&R, &t, a, b, c, d, e);
        e[1] = ulps(e[1], irange(&r, -1, 1));
        check_is(&R, &t, a, b, c, d, e);
        for (int q = 0; q < 5; q++)
            for (int j = 0; j < 3; j++) pts[q][j] = wild(&r);
        check_is(&R, &t, a, b, c, d, e);
        for (int q = 0; q < 5; q++)
            for (int j = 0; j < 3; j++) pts[q][j] = edge_value(&r);
        check_is(&R, &t, a, b, c, d, e);
    }
    ref_clear(&R);
    fprintf(stderr, "insphere: %ld cases, %ld exactly degenerate, %ld disagreements\n", t.cases,
            t.zeros, t.disagreements);
    assert_int_equal(t.disagreements, 0);
    assert_true(t.zeros > t.cases / 20);
}

/* ---- sign conventions, documented in predicates.h ---- */

static void sign_conventions(void **state)
{
    (void)state;
    double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1}, in[2] = {0.25, 0.25}, out[2] = {2, 2};
    assert_true(orient2d(a, b, c) > 0);
    assert_true(orient2d(a, c, b) < 0);
    assert_true(orient2d(a, b, (double[2]){2, 0}) == 0);
    assert_true(incircle(a, b, c, in) > 0);
    assert_true(incircle(a, b, c, out) < 0);
    assert_true(incircle(a, b, c, (double[2]){1, 1}) == 0);
    double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0};
    double below[3] = {0, 0, -1}, above[3] = {0, 0, 1};
    assert_true(orient3d(A, B, C, below) > 0);
    assert_true(orient3d(A, B, C, above) < 0);
    assert_true(orient3d(A, B, C, (double[3]){5, 7, 0}) == 0);
    /* orient3d(A, B, C, below) > 0: positively oriented tetrahedron */
    assert_true(insphere(A, B, C, below, (double[3]){0.1, 0.1, -0.1}) > 0);
    assert_true(insphere(A, B, C, below, (double[3]){3, 3, 3}) < 0);
    assert_true(insphere(A, B, C, below, (double[3]){1, 1, -1}) == 0);
    /* swapping two points flips the sign */
    assert_true(insphere(B, A, C, below, (double[3]){0.1, 0.1, -0.1}) < 0);
}

static void non_finite_gives_nan(void **state)
{
    (void)state;
    double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {INFINITY, 1}, n[2] = {NAN, 0};
    assert_true(isnan(orient2d(a, b, c)));
    assert_true(isnan(orient2d(a, b, n)));
    assert_true(isnan(incircle(a, b, n, c)));
    double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0}, N[3] = {0, NAN, 0};
    assert_true(isnan(orient3d(A, B, C, N)));
    assert_true(isnan(insphere(A, B, C, N, A)));
}

/* Extreme magnitudes where the plain formula overflows or underflows. */
static void extremes(void **state)
{
    (void)state;
    double big = 0x1.fffffffffffffp1023, tiny = 0x1p-1074;
    double a[2] = {-big, -big}, b[2] = {big, big}, c[2] = {0, 0};
    assert_true(orient2d(a, b, c) == 0);
    c[1] = tiny;
    assert_true(orient2d(a, b, c) > 0);
    c[1] = -tiny;
    assert_true(orient2d(a, b, c) < 0);
    double p[2] = {tiny, 0}, q[2] = {0, tiny}, s[2] = {0, 0};
    assert_true(orient2d(s, p, q) > 0);
    assert_true(incircle(s, p, q, (double[2]){tiny, tiny}) == 0);
    assert_true(incircle((double[2]){-big, 0}, (double[2]){0, -big}, (double[2]){big, 0},
                         (double[2]){0, 0}) > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sign_conventions),
        cmocka_unit_test(non_finite_gives_nan),
        cmocka_unit_test(extremes),
        cmocka_unit_test(orient2d_matches_gmp),
        cmocka_unit_test(orient3d_matches_gmp),
        cmocka_unit_test(incircle_matches_gmp),
        cmocka_unit_test(insphere_matches_gmp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
