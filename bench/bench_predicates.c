/* bench/bench_predicates: calls per second of the exact predicates.
 *
 * Two input sets per predicate: random points in [-1, 1] (decided by the
 * floating-point filter) and near-degenerate points (exactly degenerate
 * integer configurations moved by an ulp or left exact, so the filter
 * fails and expansion arithmetic decides), plus a mixed-magnitude set that
 * exercises the integer fallback. Prints a Markdown table.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
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

enum { RANDOM, NEAR, MIXED };

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
    double seconds = argc > 1 ? atof(argv[1]) : 0.5;
    const char *names[4] = {"orient2d", "incircle", "orient3d", "insphere"};
    runner fs[4] = {run_o2, run_ic, run_o3, run_is};
    printf("| predicate | random (filter) calls/s | near-degenerate (exact) calls/s | "
           "mixed magnitudes calls/s |\n|---|---|---|---|\n");
    for (int p = 0; p < 4; p++) {
        double r[3];
        for (int k = 0; k < 3; k++) {
            fill(k, p);
            r[k] = rate(fs[p], seconds);
        }
        printf("| %s | %.3g | %.3g | %.3g |\n", names[p], r[0], r[1], r[2]);
    }
    return 0;
}
