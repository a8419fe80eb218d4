/* bench/bench_predicates: calls per second of the exact predicates.
 *
 * Input sets per predicate: random points in [-1, 1] (decided by the
 * floating-point filter), near-degenerate points (exactly degenerate
 * configurations moved by an ulp or left exact, so the filter fails and
 * the adaptive stages decide), a mixed-magnitude set that exercises the
 * integer fallback, and for incircle/orient2d a "circle" set: points
 * computed as (cos t, sin t) like SCAF's Tutte boundary, quadruples
 * (triples) of neighbours or of arbitrary circle points. Prints a
 * Markdown table. Usage: bench_predicates [seconds], or, for instruction
 * counts under callgrind, bench_predicates --fixed PRED SET PASSES (PRED
 * 0..3 = orient2d, incircle, orient3d, insphere; SET 0..3 = random, near,
 * mixed, circle): fills the set and evaluates it PASSES times; run with
 * PASSES = 0 to measure the setup to subtract.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geom/predicates.h"

#define N 4096

static uint64_t state = 0x9E3779B97F4A7C15ULL;
static uint64_t next_u64(void)
{
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 0x2545F4914F6CDD1DULL;
}
static double sym(void) { return (double)(next_u64() >> 11) * 0x1p-52 - 1.0; }
static int irange(int lo, int hi) { return lo + (int)(next_u64() % (uint64_t)(hi - lo + 1)); }

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double pts[N][5][3];
static volatile double sink;

enum { RANDOM, NEAR, MIXED, CIRCLE };

static void fill(int kind, int pred)
{
    for (int i = 0; i < N; i++) {
        if (kind == RANDOM) {
            for (int q = 0; q < 5; q++)
                for (int j = 0; j < 3; j++) pts[i][q][j] = sym();
        } else if (kind == NEAR) {
            /* exactly degenerate, half of them nudged by one ulp:
             * orient2d on y = x, orient3d on z = x, incircle on rectangle
             * corners, insphere on box corners */
            double lo[3], hi[3];
            for (int j = 0; j < 3; j++) lo[j] = sym(), hi[j] = sym();
            for (int q = 0; q < 5; q++) {
                int corner = (q * 3 + 1) & 7;
                for (int j = 0; j < 3; j++) pts[i][q][j] = (corner >> j) & 1 ? hi[j] : lo[j];
                if (pred == 0) pts[i][q][1] = pts[i][q][0] = sym();
                if (pred == 2) pts[i][q][2] = pts[i][q][0] = sym(), pts[i][q][1] = sym();
            }
            int last = pred == 0 ? 2 : pred == 3 ? 4 : 3;
            if (irange(0, 1)) pts[i][last][1] = nextafter(pts[i][last][1], 2.0);
        } else if (kind == CIRCLE) {
            /* 10000 points on the unit circle; neighbours (the CDT's usual
             * query) or arbitrary circle points, one of them the 4th point */
            const int n = 10000;
            int base = irange(0, n - 1), stride = irange(0, 3) ? 1 : irange(1, n - 1);
            for (int q = 0; q < 5; q++) {
                double t = 2 * 3.14159265358979323846 * ((base + q * stride) % n) / n;
                pts[i][q][0] = cos(t);
                pts[i][q][1] = sin(t);
                pts[i][q][2] = 0.0;
            }
            if (pred == 0) { /* orient2d: a, c, b of three neighbours */
                for (int j = 0; j < 2; j++) {
                    double t = pts[i][1][j];
                    pts[i][1][j] = pts[i][2][j];
                    pts[i][2][j] = t;
                }
            }
        } else {
            for (int q = 0; q < 5; q++)
                for (int j = 0; j < 3; j++)
                    pts[i][q][j] = ldexp(sym(), irange(-600, 600)) * (irange(0, 3) ? 1.0 : 0.0);
            pts[i][1][1] = pts[i][1][0];
            pts[i][0][1] = pts[i][0][0];
            pts[i][2][1] = pts[i][2][0];
        }
    }
}

typedef double (*runner)(int i);
static double run_o2(int i) { return orient2d(pts[i][0], pts[i][1], pts[i][2]); }
static double run_ic(int i) { return incircle(pts[i][0], pts[i][1], pts[i][2], pts[i][3]); }
static double run_o3(int i) { return orient3d(pts[i][0], pts[i][1], pts[i][2], pts[i][3]); }
static double run_is(int i)
{
    return insphere(pts[i][0], pts[i][1], pts[i][2], pts[i][3], pts[i][4]);
}

static double rate(runner f, double seconds)
{
    long calls = 0;
    double t0 = now(), t;
    do {
        double s = 0;
        for (int i = 0; i < N; i++) s += f(i) > 0;
        sink = s;
        calls += N;
        t = now();
    } while (t - t0 < seconds);
    return (double)calls / (t - t0);
}

int main(int argc, char **argv)
{
    runner fs[4] = {run_o2, run_ic, run_o3, run_is};
    if (argc == 5 && !strcmp(argv[1], "--fixed")) {
        int p = atoi(argv[2]), k = atoi(argv[3]);
        long passes = atol(argv[4]);
        if (p < 0 || p > 3 || k < 0 || k > 3 || passes < 0) {
            fprintf(stderr, "usage: bench_predicates --fixed PRED(0-3) SET(0-3) PASSES\n");
            return 2;
        }
        fill(k, p);
        double s = 0;
        for (long r = 0; r < passes; r++)
            for (int i = 0; i < N; i++) s += fs[p](i) > 0;
        sink = s;
        printf("%s set %d: %ld calls, %.0f positive\n", argv[2], k, passes * N, s);
        return 0;
    }
    double seconds = argc > 1 ? atof(argv[1]) : 0.5;
    const char *names[4] = {"orient2d", "incircle", "orient3d", "insphere"};
    printf("| predicate | random (filter) calls/s | near-degenerate (exact) calls/s | "
           "mixed magnitudes calls/s | circle points calls/s |\n|---|---|---|---|---|\n");
    for (int p = 0; p < 4; p++) {
        double r[4] = {0, 0, 0, 0};
        for (int k = 0; k < 4; k++) {
            if (k == CIRCLE && p > 1) continue;
            fill(k, p);
            r[k] = rate(fs[p], seconds);
        }
        if (p > 1) printf("| %s | %.3g | %.3g | %.3g | - |\n", names[p], r[0], r[1], r[2]);
        else printf("| %s | %.3g | %.3g | %.3g | %.3g |\n", names[p], r[0], r[1], r[2], r[3]);
    }
    return 0;
}
