/* fuzz/fuzz_uv_numbers: libFuzzer target for extreme but finite UV
 * coordinates in the measures `scaf check` prints (geom/bijectivity,
 * geom/chart_gap, base/json_write).
 *
 * Input: byte 0 the number of triangles (1..8), byte 1 a power-of-two
 * exponent k (-64..63), then 3 index bytes per triangle (mod the point
 * count, so triangles share points or not), then the points as raw
 * doubles (missing bytes are 0; NaN and infinities become 0: the readers
 * refuse them). Beyond the sanitizers' checks it aborts when a finite
 * layout gets a non-finite or negative efficiency, a non-finite gap with
 * two or more charts (unless SCAF_ERR_NUMERIC: a gap beyond the largest
 * double), JSON text with a nan/inf token, or results that change when
 * the layout is scaled exactly by 2^k (gaps compared when not subnormal,
 * where the answer itself rounds).
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/json_write.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { MAX_TRI = 8, MAX_PTS = 3 * MAX_TRI };

/* Gap (status in *st) and efficiency of the layout. */
static void measure(const double *UV, int npts, int nf, const int *F, double *gap, scaf_status *st,
                    double *eff)
{
    scaf_error err;
    *st = chart_gap_min(npts, UV, nf, F, NULL, 0.0, gap, NULL, &err);
    *eff = chart_packing_efficiency(npts, UV, nf, F);
}

/* JSON of a number must hold no nan/inf token. */
static void check_json(double x)
{
    char buf[64];
    FILE *f = fmemopen(buf, sizeof buf, "w");
    if (!f) return;
    json_write_number(f, x);
    fclose(f);
    buf[sizeof buf - 1] = '\0';
    if (strstr(buf, "nan") || strstr(buf, "inf")) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    int nf = 1 + data[0] % MAX_TRI, k = (int)(data[1] % 128) - 64;
    int npts = 3 * nf;
    size_t at = 2;
    int F[3 * MAX_TRI];
    for (int i = 0; i < 3 * nf; i++) F[i] = at < size ? data[at++] % npts : i;
    double UV[2 * MAX_PTS] = {0}, S[2 * MAX_PTS];
    for (int i = 0; i < 2 * npts && at < size; i++) {
        size_t n = size - at < sizeof(double) ? size - at : sizeof(double);
        memcpy(&UV[i], data + at, n);
        at += n;
        if (!isfinite(UV[i])) UV[i] = 0.0;
    }

    bij_report r;
    scaf_error err;
    if (bij_check(npts, UV, nf, F, NULL, NULL, &r, &err) != SCAF_OK) abort();
    int chart[MAX_TRI], nc;
    if (chart_gap_labels(npts, nf, F, chart, &nc, &err) != SCAF_OK) abort();

    double gap, eff;
    scaf_status st;
    measure(UV, npts, nf, F, &gap, &st, &eff);
    if (st != SCAF_OK && st != SCAF_ERR_NUMERIC) abort();
    if (!isfinite(eff) || eff < 0.0) abort();
    if (st == SCAF_OK && (nc >= 2 ? !(gap >= 0.0 && isfinite(gap)) : !isinf(gap))) abort();
    check_json(gap);
    check_json(eff);

    /* scaled by 2^k exactly (every coordinate round-trips): same results */
    for (int i = 0; i < 2 * npts; i++) {
        S[i] = ldexp(UV[i], k);
        if (ldexp(S[i], -k) != UV[i]) return 0;
    }
    double gap2, eff2;
    scaf_status st2;
    measure(S, npts, npts > 0 ? nf : 0, F, &gap2, &st2, &eff2);
    if (eff2 != eff) abort();
    /* (a subnormal gap is rounded to its coarser grid: compare normal ones) */
    if (st == SCAF_OK && st2 == SCAF_OK && (gap == 0.0 || (gap >= DBL_MIN && gap2 >= DBL_MIN)) &&
        gap2 != ldexp(gap, k))
        abort();
    bij_report r2;
    if (bij_check(npts, S, nf, F, NULL, NULL, &r2, &err) != SCAF_OK) abort();
    if (r2.bijective != r.bijective || r2.flipped != r.flipped ||
        r2.boundary_touchings != r.boundary_touchings || r2.nested_loops != r.nested_loops)
        abort();
    return 0;
}
