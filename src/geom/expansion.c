/* geom/expansion: exact floating-point expansion arithmetic.
 *
 * Implements the merge-based expansion sum and the expansion-by-double
 * product of Shewchuk's paper, with zero elimination, and a full product
 * of two expansions built from them. Nothing here allocates or fails; the
 * caller sizes the output arrays (see expansion.h).
 */
#include "geom/expansion.h"

#include <math.h>
#include <string.h>

int exp_sum(int elen, const double *e, int flen, const double *f, double *h)
{
    if (elen == 0) {
        memmove(h, f, (size_t)flen * sizeof *h);
        return flen;
    }
    if (flen == 0) {
        memmove(h, e, (size_t)elen * sizeof *h);
        return elen;
    }
    /* Merge by increasing magnitude, carrying a running sum q: each step is
     * an error-free two_sum whose low part is final (it is smaller than
     * everything still to come). */
    int i = 0, j = 0, n = 0;
    double q, g, hi, lo;
    if (fabs(e[0]) < fabs(f[0])) q = e[i++];
    else q = f[j++];
    while (i < elen || j < flen) {
        if (j >= flen || (i < elen && fabs(e[i]) < fabs(f[j]))) g = e[i++];
        else g = f[j++];
        two_sum(q, g, &hi, &lo);
        if (lo != 0.0) h[n++] = lo;
        q = hi;
    }
    if (q != 0.0 || n == 0) h[n++] = q;
    if (n == 1 && h[0] == 0.0) return 0;
    return n;
}

int exp_scale(int elen, const double *e, double b, double *h)
{
    if (elen == 0 || b == 0.0) return 0;
    int n = 0;
    double q, lo, thi, tlo, s, bhi, blo;
    split(b, &bhi, &blo);
    two_product_presplit(e[0], b, bhi, blo, &q, &lo);
    if (lo != 0.0) h[n++] = lo;
    for (int i = 1; i < elen; i++) {
        two_product_presplit(e[i], b, bhi, blo, &thi, &tlo);
        two_sum(q, tlo, &s, &lo);
        if (lo != 0.0) h[n++] = lo;
        fast_two_sum(thi, s, &q, &lo);
        if (lo != 0.0) h[n++] = lo;
    }
    if (q != 0.0 || n == 0) h[n++] = q;
    if (n == 1 && h[0] == 0.0) return 0;
    return n;
}

int exp_mul(int elen, const double *e, int flen, const double *f, double *h, double *work)
{
    /* Multiply the longer expansion by each component of the shorter one
     * and accumulate; work holds one scaled term and the previous sum. */
    if (elen < flen) {
        const double *t = e;
        e = f;
        f = t;
        int tl = elen;
        elen = flen;
        flen = tl;
    }
    int hlen = 0;
    double *term = work;
    double *acc = work + 2 * elen;
    for (int k = 0; k < flen; k++) {
        int tlen = exp_scale(elen, e, f[k], term);
        memcpy(acc, h, (size_t)hlen * sizeof *h);
        hlen = exp_sum(hlen, acc, tlen, term, h);
    }
    return hlen;
}

void exp_negate(int elen, const double *e, double *h)
{
    for (int i = 0; i < elen; i++) h[i] = -e[i];
}

int exp_from_diff(double a, double b, double *h)
{
    double x, y;
    two_diff(a, b, &x, &y);
    int n = 0;
    if (y != 0.0) h[n++] = y;
    if (x != 0.0) h[n++] = x;
    return n;
}
