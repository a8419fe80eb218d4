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
#include "support/sanitized.h"

static long scaled(long n)
{
    long pct = test_is_sanitized() ? 4 : 100;
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

static int irange(rng *r, int lo, int hi)
{
    return lo + (int)(next_u64(r) % (uint64_t)(hi - lo + 1));
}

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
        if (sh >= 0) mpz_mul_2exp(z[i], z[i], (mp_bitcnt_t)sh);
        else mpz_tdiv_q_2exp(z[i], z[i], (mp_bitcnt_t)(-sh)); /* exact */
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

/* The ref_* functions take the points packed: p = a, b, c, ... (dim each). */

static int ref_orient2d(ref *R, const double *p)
{
    diffs(R, p, 3, 2);
    det2(R, R->acc, R->d[0], R->d[1], R->d[2], R->d[3]);
    return mpz_sgn(R->acc);
}

static int ref_orient3d(ref *R, const double *p)
{
    diffs(R, p, 4, 3);
    det3(R, R->acc, R->d, R->d + 3, R->d + 6);
    return mpz_sgn(R->acc);
}

static int ref_incircle(ref *R, const double *p)
{
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

static int ref_insphere(ref *R, const double *p)
{
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

/* One case: the predicate's value `got` against the exact sign `want` of
 * the n packed coordinates p; the first disagreements are reported. */
static void record(tally *t, const char *what, double got, int want, const double *p, int n)
{
    t->cases++;
    t->zeros += want == 0;
    if (sgn(got) != want || isnan(got)) {
        if (t->disagreements++ < 5) report(what, p, n, got, want);
    }
}

static void check2(ref *R, tally *t, const double *a, const double *b, const double *c)
{
    double p[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
    record(t, "orient2d", orient2d(a, b, c), ref_orient2d(R, p), p, 6);
}

static void check3(ref *R, tally *t, const double *a, const double *b, const double *c,
                   const double *d)
{
    double p[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
    record(t, "orient3d", orient3d(a, b, c, d), ref_orient3d(R, p), p, 12);
}

static void check_ic(ref *R, tally *t, const double *a, const double *b, const double *c,
                     const double *d)
{
    double p[8] = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    record(t, "incircle", incircle(a, b, c, d), ref_incircle(R, p), p, 8);
}

static void check_is(ref *R, tally *t, const double *a, const double *b, const double *c,
                     const double *d, const double *e)
{
    double p[15] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1],
                    c[2], d[0], d[1], d[2], e[0], e[1], e[2]};
    record(t, "insphere", insphere(a, b, c, d, e), ref_insphere(R, p), p, 15);
}

/* One round of a generator: a few related cases drawn from r, each
 * checked against GMP into t. ctx: the generator's fixed data, or NULL. */
typedef void (*round_fn)(rng *r, ref *R, tally *t, const void *ctx);

/* Runs scaled(rounds) rounds from the given seed and asserts zero
 * disagreements and that more than 1/zero_share of the cases were exactly
 * degenerate (the degenerate generators work). `what` names the run. */
static void run_rounds(const char *what, uint64_t seed, long rounds, round_fn round,
                       const void *ctx, long zero_share)
{
    rng r = {seed};
    ref R;
    ref_init(&R);
    tally t = {0, 0, 0};
    long n = scaled(rounds);
    for (long i = 0; i < n; i++) round(&r, &R, &t, ctx);
    ref_clear(&R);
    fprintf(stderr, "%s: %ld cases, %ld exactly degenerate, %ld disagreements\n", what, t.cases,
            t.zeros, t.disagreements);
    if (t.disagreements != 0) fail_msg("%s: %ld disagreements with GMP", what, t.disagreements);
    if (!(t.zeros > t.cases / zero_share))
        fail_msg("%s: only %ld of %ld cases exactly degenerate (need more than 1/%ld)", what,
                 t.zeros, t.cases, zero_share);
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

static void orient2d_round(rng *r, ref *R, tally *t, const void *ctx)
{
    (void)ctx;
    double a[2], b[2], c[2];
    /* random */
    a[0] = sym(r), a[1] = sym(r), b[0] = sym(r), b[1] = sym(r), c[0] = sym(r), c[1] = sym(r);
    check2(R, t, a, b, c);
    /* a few ulps off a line through a and b */
    double s = unit(r) * 3.0 - 1.0;
    c[0] = ulps(a[0] + s * (b[0] - a[0]), irange(r, -3, 3));
    c[1] = ulps(a[1] + s * (b[1] - a[1]), irange(r, -3, 3));
    check2(R, t, a, b, c);
    /* exact: integer multiples of a direction, scaled by 2^k */
    int k = irange(r, -1070, 980);
    double u = irange(r, -1000, 1000), v = irange(r, -1000, 1000);
    double px = irange(r, -100000, 100000), py = irange(r, -100000, 100000);
    int l1 = irange(r, -50, 50), l2 = irange(r, -50, 50);
    a[0] = ldexp(px, k), a[1] = ldexp(py, k);
    b[0] = ldexp(px + l1 * u, k), b[1] = ldexp(py + l1 * v, k);
    c[0] = ldexp(px + l2 * u, k), c[1] = ldexp(py + l2 * v, k);
    check2(R, t, a, b, c);
    c[irange(r, 0, 1)] = ulps(c[0], irange(r, -2, 2));
    check2(R, t, a, b, c);
    /* exact with mixed magnitudes: on y = x, and on a line through 0 */
    a[0] = a[1] = wild(r), b[0] = b[1] = wild(r), c[0] = c[1] = wild(r);
    check2(R, t, a, b, c);
    c[1] = ulps(c[1], irange(r, -2, 2));
    check2(R, t, a, b, c);
    /* power-of-two multiples of one point: collinear through 0 (when
     * the scaling neither overflows nor drops bits) */
    double w0 = ldexp(1.0 + unit(r), irange(r, -400, 400)), w1 = wild(r);
    int e1 = irange(r, -500, 500), e2 = irange(r, -500, 500);
    a[0] = w0, a[1] = w1;
    b[0] = ldexp(w0, e1), b[1] = ldexp(w1, e1);
    c[0] = ldexp(w0, e2), c[1] = ldexp(w1, e2);
    if (isfinite(b[1]) && isfinite(c[1])) check2(R, t, a, b, c);
    /* wild and range-edge coordinates */
    a[0] = wild(r), a[1] = wild(r), b[0] = wild(r), b[1] = wild(r), c[0] = wild(r), c[1] = wild(r);
    check2(R, t, a, b, c);
    a[0] = edge_value(r), a[1] = edge_value(r), b[0] = edge_value(r);
    b[1] = edge_value(r), c[0] = edge_value(r), c[1] = edge_value(r);
    check2(R, t, a, b, c);
}

static void orient2d_matches_gmp(void **state)
{
    (void)state;
    run_rounds("orient2d", 0x9E3779B97F4A7C15ULL, 120000, orient2d_round, NULL, 10);
}

/* ---- orient3d ---- */

static void orient3d_round(rng *r, ref *R, tally *t, const void *ctx)
{
    (void)ctx;
    double a[3], b[3], c[3], d[3];
    for (int j = 0; j < 3; j++) a[j] = sym(r), b[j] = sym(r), c[j] = sym(r), d[j] = sym(r);
    check3(R, t, a, b, c, d);
    /* a few ulps off the plane through a, b, c */
    double s = sym(r) * 2, u = sym(r) * 2;
    for (int j = 0; j < 3; j++)
        d[j] = ulps(a[j] + s * (b[j] - a[j]) + u * (c[j] - a[j]), irange(r, -3, 3));
    check3(R, t, a, b, c, d);
    /* exact: integer combinations, scaled */
    int k = irange(r, -1060, 970);
    double o[3], e1[3], e2[3];
    for (int j = 0; j < 3; j++)
        o[j] = irange(r, -10000, 10000), e1[j] = irange(r, -100, 100), e2[j] = irange(r, -100, 100);
    double *pts[4] = {a, b, c, d};
    for (int q = 0; q < 4; q++) {
        int s1 = irange(r, -30, 30), s2 = irange(r, -30, 30);
        for (int j = 0; j < 3; j++) pts[q][j] = ldexp(o[j] + s1 * e1[j] + s2 * e2[j], k);
    }
    check3(R, t, a, b, c, d);
    d[irange(r, 0, 2)] = ulps(d[0], irange(r, -2, 2));
    check3(R, t, a, b, c, d);
    /* exact, mixed magnitudes: on the plane z = x */
    for (int q = 0; q < 4; q++) pts[q][0] = pts[q][2] = wild(r), pts[q][1] = wild(r);
    check3(R, t, a, b, c, d);
    d[2] = ulps(d[2], irange(r, -2, 2));
    check3(R, t, a, b, c, d);
    /* box corners: faces are planes */
    double x1 = wild(r), x2 = wild(r), y1 = wild(r), y2 = wild(r), z1 = wild(r);
    a[0] = x1, a[1] = y1, a[2] = z1;
    b[0] = x2, b[1] = y1, b[2] = z1;
    c[0] = x1, c[1] = y2, c[2] = z1;
    d[0] = x2, d[1] = y2, d[2] = ulps(z1, irange(r, -1, 1));
    check3(R, t, a, b, c, d);
    for (int q = 0; q < 4; q++)
        for (int j = 0; j < 3; j++) pts[q][j] = (q + j) % 2 ? wild(r) : edge_value(r);
    check3(R, t, a, b, c, d);
    for (int q = 0; q < 4; q++)
        for (int j = 0; j < 3; j++) pts[q][j] = edge_value(r);
    check3(R, t, a, b, c, d);
}

static void orient3d_matches_gmp(void **state)
{
    (void)state;
    run_rounds("orient3d", 0xD1B54A32D192ED03ULL, 40000, orient3d_round, NULL, 10);
}

/* ---- incircle ---- */

/* Integer points on the circle x^2 + y^2 = 65^2. */
static const int circ65[][2] = {{65, 0},  {63, 16}, {60, 25}, {56, 33}, {52, 39},
                                {39, 52}, {33, 56}, {25, 60}, {16, 63}, {0, 65}};

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

static void incircle_round(rng *r, ref *R, tally *t, const void *ctx)
{
    (void)ctx;
    double a[2], b[2], c[2], d[2];
    a[0] = sym(r), a[1] = sym(r), b[0] = sym(r), b[1] = sym(r);
    c[0] = sym(r), c[1] = sym(r), d[0] = sym(r), d[1] = sym(r);
    check_ic(R, t, a, b, c, d);
    /* nearly cocircular: points computed on a circle, d moved by ulps */
    double cx = sym(r), cy = sym(r), rad = unit(r) + 0.01;
    double *pts[4] = {a, b, c, d};
    for (int q = 0; q < 4; q++) {
        double th = unit(r) * 6.283185307179586;
        pts[q][0] = cx + rad * cos(th);
        pts[q][1] = cy + rad * sin(th);
    }
    d[0] = ulps(d[0], irange(r, -3, 3));
    check_ic(R, t, a, b, c, d);
    /* exactly cocircular integer points, translated and scaled */
    int k = irange(r, -1060, 970);
    double ox = irange(r, -100000, 100000), oy = irange(r, -100000, 100000);
    for (int q = 0; q < 4; q++) circle_point(r, pts[q], ox, oy, k);
    check_ic(R, t, a, b, c, d);
    d[irange(r, 0, 1)] = ulps(d[1], irange(r, -2, 2));
    check_ic(R, t, a, b, c, d);
    /* rectangle corners are cocircular, whatever the magnitudes */
    double x1 = wild(r), x2 = wild(r), y1 = wild(r), y2 = wild(r);
    a[0] = x1, a[1] = y1, b[0] = x2, b[1] = y1, c[0] = x2, c[1] = y2, d[0] = x1, d[1] = y2;
    check_ic(R, t, a, b, c, d);
    d[0] = ulps(d[0], irange(r, -2, 2));
    check_ic(R, t, a, b, c, d);
    x1 = sym(r), x2 = sym(r), y1 = sym(r), y2 = sym(r);
    a[0] = x1, a[1] = y1, b[0] = x2, b[1] = y1, c[0] = x2, c[1] = y2, d[0] = x1, d[1] = y2;
    d[1] = ulps(d[1], irange(r, -1, 1));
    check_ic(R, t, a, b, c, d);
    for (int q = 0; q < 4; q++) pts[q][0] = wild(r), pts[q][1] = wild(r);
    check_ic(R, t, a, b, c, d);
    for (int q = 0; q < 4; q++) pts[q][0] = edge_value(r), pts[q][1] = edge_value(r);
    check_ic(R, t, a, b, c, d);
}

static void incircle_matches_gmp(void **state)
{
    (void)state;
    run_rounds("incircle", 0x8CB92BA72F3D8DD7ULL, 40000, incircle_round, NULL, 10);
}

/* ---- insphere ---- */

static void insphere_round(rng *r, ref *R, tally *t, const void *ctx)
{
    (void)ctx;
    double a[3], b[3], c[3], d[3], e[3];
    double *pts[5] = {a, b, c, d, e};
    for (int q = 0; q < 5; q++)
        for (int j = 0; j < 3; j++) pts[q][j] = sym(r);
    check_is(R, t, a, b, c, d, e);
    /* nearly cospherical: on a sphere in floating point, e by ulps */
    double cen[3] = {sym(r), sym(r), sym(r)}, rad = unit(r) + 0.01;
    for (int q = 0; q < 5; q++) {
        double th = unit(r) * 6.283185307179586, z = sym(r), s = sqrt(1 - z * z);
        pts[q][0] = cen[0] + rad * s * cos(th);
        pts[q][1] = cen[1] + rad * s * sin(th);
        pts[q][2] = cen[2] + rad * z;
    }
    e[irange(r, 0, 2)] = ulps(e[0], irange(r, -3, 3));
    check_is(R, t, a, b, c, d, e);
    /* box corners are cospherical, whatever the magnitudes */
    double x[2] = {wild(r), wild(r)}, y[2] = {wild(r), wild(r)}, z[2] = {wild(r), wild(r)};
    for (int q = 0; q < 5; q++) {
        int corner = irange(r, 0, 7);
        pts[q][0] = x[corner & 1], pts[q][1] = y[(corner >> 1) & 1], pts[q][2] = z[corner >> 2];
    }
    check_is(R, t, a, b, c, d, e);
    int k = irange(r, -1060, 960);
    double x2[2] = {irange(r, -99, 99), irange(r, -99, 99)};
    double y2[2] = {irange(r, -99, 99), irange(r, -99, 99)};
    double z2[2] = {irange(r, -99, 99), irange(r, -99, 99)};
    for (int q = 0; q < 5; q++) {
        int corner = (q * 3 + irange(r, 0, 1)) & 7;
        pts[q][0] = ldexp(x2[corner & 1], k), pts[q][1] = ldexp(y2[(corner >> 1) & 1], k);
        pts[q][2] = ldexp(z2[corner >> 2], k);
    }
    check_is(R, t, a, b, c, d, e);
    e[1] = ulps(e[1], irange(r, -1, 1));
    check_is(R, t, a, b, c, d, e);
    for (int q = 0; q < 5; q++)
        for (int j = 0; j < 3; j++) pts[q][j] = wild(r);
    check_is(R, t, a, b, c, d, e);
    for (int q = 0; q < 5; q++)
        for (int j = 0; j < 3; j++) pts[q][j] = edge_value(r);
    check_is(R, t, a, b, c, d, e);
}

static void insphere_matches_gmp(void **state)
{
    (void)state;
    run_rounds("insphere", 0x94D049BB133111EBULL, 15000, insphere_round, NULL, 20);
}

/* ---- cases aimed at the adaptive stages ----
 * Stage B computes the determinant exactly from the ROUNDED coordinate
 * differences: it alone decides when every difference is exact (Sterbenz:
 * coordinates within a factor 2 of each other, or integers), and otherwise
 * when the determinant is larger than the difference roundings can move
 * it. Stage C adds a first-order tail correction: it decides determinants
 * down to about EPS^2 times the permanent. Exactly degenerate inputs with
 * inexact differences, and nudges of a tiny-magnitude coordinate, reach the
 * full exact stage. Each group below targets one of these situations, with
 * scales near the edges of the expansion range (where the integer fallback
 * takes over). */

/* 2^k for k near the adaptive-range edges of a predicate, or moderate. */
static int stage_scale(rng *r, int lo, int hi)
{
    switch (irange(r, 0, 3)) {
    case 0: return irange(r, lo - 8, lo + 60);
    case 1: return irange(r, hi - 60, hi + 4);
    default: return irange(r, -40, 40);
    }
}

static void orient2d_stages_round(rng *r, ref *R, tally *t, const void *ctx)
{
    (void)ctx;
    double a[2], b[2], c[2];
    int k = stage_scale(r, -450, 440);
    /* exact differences: collinear points within a factor 2 (offset
     * 2^20, integer steps), then c nudged by ulps: stage B decides */
    double ux = irange(r, -1000, 1000), uy = irange(r, -1000, 1000);
    double px = 0x1p20 + irange(r, 0, 1000), py = 0x1p20 + irange(r, 0, 1000);
    int l1 = irange(r, -200, 200), l2 = irange(r, -200, 200);
    a[0] = ldexp(px, k), a[1] = ldexp(py, k);
    b[0] = ldexp(px + l1 * ux, k), b[1] = ldexp(py + l1 * uy, k);
    c[0] = ldexp(px + l2 * ux, k), c[1] = ldexp(py + l2 * uy, k);
    check2(R, t, a, b, c);
    int co = irange(r, 0, 1);
    c[co] = ulps(c[co], irange(r, -3, 3));
    check2(R, t, a, b, c);
    /* inexact differences, exactly collinear: on y = 2^j x with mixed
     * magnitudes (stage D), then a tiny coordinate nudged (C or D) */
    int j = irange(r, -3, 3);
    for (int q = 0; q < 3; q++) {
        double *p = q == 0 ? a : q == 1 ? b : c;
        p[0] = ldexp(sym(r), k - irange(r, 0, 60));
        p[1] = ldexp(p[0], j);
    }
    check2(R, t, a, b, c);
    double *sm = fabs(a[0]) < fabs(b[0]) ? a : b;
    co = irange(r, 0, 1);
    sm[co] = ulps(sm[co], irange(r, -1, 1) | 1);
    check2(R, t, a, b, c);
    /* nearly collinear in floating point, differences inexact */
    double s = sym(r) * 2.0;
    a[0] = ldexp(sym(r), k), a[1] = ldexp(sym(r), k);
    b[0] = ldexp(sym(r), k - irange(r, 0, 30)), b[1] = ldexp(sym(r), k);
    c[0] = a[0] + s * (b[0] - a[0]), c[1] = a[1] + s * (b[1] - a[1]);
    co = irange(r, 0, 1);
    c[co] = ulps(c[co], irange(r, -1, 1));
    check2(R, t, a, b, c);
}

static void orient2d_stages_match_gmp(void **state)
{
    (void)state;
    run_rounds("orient2d stages", 0x2545F4914F6CDD1DULL, 40000, orient2d_stages_round, NULL, 10);
}

static void orient3d_stages_round(rng *r, ref *R, tally *t, const void *ctx)
{
    (void)ctx;
    double a[3], b[3], c[3], d[3];
    double *pts[4] = {a, b, c, d};
    int k = stage_scale(r, -280, 290);
    /* exact differences: coplanar integer points offset by 2^20 */
    double o[3], e1[3], e2[3];
    for (int j = 0; j < 3; j++)
        o[j] = 0x1p20 + irange(r, 0, 1000), e1[j] = irange(r, -50, 50), e2[j] = irange(r, -50, 50);
    for (int q = 0; q < 4; q++) {
        int s1 = irange(r, -100, 100), s2 = irange(r, -100, 100);
        for (int j = 0; j < 3; j++) pts[q][j] = ldexp(o[j] + s1 * e1[j] + s2 * e2[j], k);
    }
    check3(R, t, a, b, c, d);
    int co = irange(r, 0, 2);
    d[co] = ulps(d[co], irange(r, -3, 3));
    check3(R, t, a, b, c, d);
    /* inexact differences, exactly coplanar: z = 2^j x, mixed scales */
    int jj = irange(r, -3, 3);
    for (int q = 0; q < 4; q++) {
        pts[q][0] = ldexp(sym(r), k - irange(r, 0, 60));
        pts[q][1] = ldexp(sym(r), k - irange(r, 0, 60));
        pts[q][2] = ldexp(pts[q][0], jj);
    }
    check3(R, t, a, b, c, d);
    int q = irange(r, 0, 3), q1 = (q + 1) % 4;
    int qq = fabs(pts[q][0]) < fabs(pts[q1][0]) ? q : q1;
    pts[qq][2] = ulps(pts[qq][2], irange(r, -1, 1) | 1);
    check3(R, t, a, b, c, d);
    /* nearly coplanar in floating point */
    double s = sym(r) * 2, u = sym(r) * 2;
    for (int j = 0; j < 3; j++) {
        a[j] = ldexp(sym(r), k), b[j] = ldexp(sym(r), k - irange(r, 0, 20));
        c[j] = ldexp(sym(r), k);
    }
    for (int j = 0; j < 3; j++) d[j] = a[j] + s * (b[j] - a[j]) + u * (c[j] - a[j]);
    co = irange(r, 0, 2);
    d[co] = ulps(d[co], irange(r, -1, 1));
    check3(R, t, a, b, c, d);
}

static void orient3d_stages_match_gmp(void **state)
{
    (void)state;
    run_rounds("orient3d stages", 0x9FB21C651E98DF25ULL, 20000, orient3d_stages_round, NULL, 10);
}

/* Integer points on x^2 + y^2 = 5525^2 (5525 = 5^2 13 17: many of them). */
static int circle5525(int (*out)[2], int max)
{
    int n = 0;
    for (int x = 0; x <= 5525 && n < max; x++) {
        long y2 = 5525L * 5525L - (long)x * x;
        long y = (long)sqrt((double)y2);
        while (y * y > y2) y--;
        while ((y + 1) * (y + 1) <= y2) y++;
        if (y * y == y2) out[n][0] = x, out[n][1] = (int)y, n++;
    }
    return n;
}

/* Integer points on that circle: incircle_stages_round's ctx. */
typedef struct circle_points {
    int p[200][2];
    int n;
} circle_points;

static void incircle_stages_round(rng *r, ref *R, tally *t, const void *ctx)
{
    const circle_points *circle = ctx;
    /* unit-circle points as SCAF's Tutte boundary: (cos t, sin t) */
    enum { NU = 10000 };
    double a[2], b[2], c[2], d[2];
    double *pts[4] = {a, b, c, d};
    int k = stage_scale(r, -200, 186);
    /* exact differences: integer circle of radius 5525 around
     * (2^16, 2^16) (coordinates within a factor 2), d nudged by ulps:
     * stage B decides */
    for (int q = 0; q < 4; q++) {
        const int *p = circle->p[irange(r, 0, circle->n - 1)];
        double x = p[0], y = p[1];
        if (next_u64(r) & 1) x = -x;
        if (next_u64(r) & 1) y = -y;
        pts[q][0] = ldexp(0x1p16 + x, k), pts[q][1] = ldexp(0x1p16 + y, k);
    }
    check_ic(R, t, a, b, c, d);
    int co = irange(r, 0, 1);
    d[co] = ulps(d[co], irange(r, -3, 3));
    check_ic(R, t, a, b, c, d);
    /* the same circle around a center with inexact differences
     * (offset not a multiple of the spacing): rounded, so only
     * nearly cocircular; B, C or D */
    double ox = ldexp(sym(r), irange(r, 10, 16)), oy = ldexp(sym(r), irange(r, 10, 16));
    int sh = irange(r, 0, 12);
    for (int q = 0; q < 4; q++) {
        const int *p = circle->p[irange(r, 0, circle->n - 1)];
        pts[q][0] = ldexp(ox + ldexp((next_u64(r) & 1) ? p[0] : -p[0], -sh), k);
        pts[q][1] = ldexp(oy + ldexp((next_u64(r) & 1) ? p[1] : -p[1], -sh), k);
    }
    check_ic(R, t, a, b, c, d);
    /* rectangles with mixed magnitudes (exactly cocircular, inexact
     * differences: stage D), then a tiny coordinate nudged by one ulp
     * (determinant far below EPS times the permanent: C or D) */
    double x1 = ldexp(sym(r), k), x2 = ldexp(sym(r), k - irange(r, 0, 70));
    double y1 = ldexp(sym(r), k), y2 = ldexp(sym(r), k - irange(r, 0, 70));
    a[0] = x1, a[1] = y1, b[0] = x2, b[1] = y1, c[0] = x2, c[1] = y2, d[0] = x1, d[1] = y2;
    check_ic(R, t, a, b, c, d);
    double *sm = fabs(x2) < fabs(y2) ? &c[0] : &c[1];
    *sm = ulps(*sm, irange(r, -1, 1) | 1);
    check_ic(R, t, a, b, c, d);
    /* unit-circle points (neighbours, or arbitrary) scaled by 2^k */
    int base = irange(r, 0, NU - 1), stride = irange(r, 0, 1) ? 1 : irange(r, 1, NU - 1);
    for (int q = 0; q < 4; q++) {
        double th = 2 * 3.14159265358979323846 * ((base + q * stride) % NU) / NU;
        pts[q][0] = ldexp(cos(th), k), pts[q][1] = ldexp(sin(th), k);
    }
    check_ic(R, t, a, b, c, d);
}

static void incircle_stages_match_gmp(void **state)
{
    (void)state;
    circle_points circle;
    circle.n = circle5525(circle.p, 200);
    assert_true(circle.n > 20);
    run_rounds("incircle stages", 0x3C6EF372FE94F82BULL, 30000, incircle_stages_round, &circle, 10);
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
        cmocka_unit_test(orient2d_stages_match_gmp),
        cmocka_unit_test(orient3d_stages_match_gmp),
        cmocka_unit_test(incircle_stages_match_gmp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
