/* geom/bigint: sign-magnitude integers of at most BIGINT_LIMBS 32-bit limbs.
 *
 * Magnitudes are little-endian limb arrays without leading zero limbs.
 * Callers keep values within the capacity (geom/predicates bounds the
 * degree and the bit length of its inputs); an operation that would exceed
 * it is a bug and is caught by an assert-like clamp that keeps memory safe.
 */
#include "geom/bigint.h"

#include <math.h>
#include <string.h>

int bigint_low_exponent(double x)
{
    int e;
    double m = frexp(fabs(x), &e); /* x = m * 2^e, m in [0.5, 1) */
    /* m * 2^53 is an integer of at most 53 bits; strip trailing zeros. */
    uint64_t mi = (uint64_t)ldexp(m, 53);
    int low = e - 53;
    while ((mi & 1u) == 0) {
        mi >>= 1;
        low++;
    }
    return low;
}

static void normalize(bigint *r)
{
    while (r->n > 0 && r->d[r->n - 1] == 0) r->n--;
    if (r->n == 0) r->sign = 0;
}

void bigint_from_double(bigint *r, double x, int emin)
{
    r->n = 0;
    r->sign = 0;
    if (x == 0.0) return;
    int e;
    double m = frexp(fabs(x), &e);
    uint64_t mi = (uint64_t)ldexp(m, 53);
    int shift = e - 53 - emin; /* x = mi * 2^(e-53), a multiple of 2^emin */
    while (shift < 0) {        /* trailing zero bits of mi absorb it */
        mi >>= 1;
        shift++;
    }
    int limb = shift / 32, bit = shift % 32;
    if (limb + 3 > BIGINT_LIMBS) return; /* out of capacity: caller's bug */
    memset(r->d, 0, (size_t)(limb + 3) * sizeof r->d[0]);
    /* mi < 2^53: spread over at most three limbs after a shift < 32. */
    uint64_t lo = (mi << bit) & 0xffffffffu;
    uint64_t mid = bit ? (mi >> (32 - bit)) : (mi >> 32);
    r->d[limb] = (uint32_t)lo;
    r->d[limb + 1] = (uint32_t)(mid & 0xffffffffu);
    r->d[limb + 2] = (uint32_t)(mid >> 32);
    r->n = limb + 3;
    r->sign = x < 0 ? -1 : 1;
    normalize(r);
}

static int mag_cmp(const bigint *a, const bigint *b)
{
    if (a->n != b->n) return a->n < b->n ? -1 : 1;
    for (int i = a->n - 1; i >= 0; i--)
        if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

/* r = |a| + |b|. */
static void mag_add(bigint *r, const bigint *a, const bigint *b)
{
    int n = a->n > b->n ? a->n : b->n;
    uint64_t carry = 0;
    for (int i = 0; i < n; i++) {
        uint64_t s = carry;
        if (i < a->n) s += a->d[i];
        if (i < b->n) s += b->d[i];
        r->d[i] = (uint32_t)s;
        carry = s >> 32;
    }
    if (carry && n < BIGINT_LIMBS) r->d[n++] = (uint32_t)carry;
    r->n = n;
}

/* r = |a| - |b|, requires |a| >= |b|. */
static void mag_sub(bigint *r, const bigint *a, const bigint *b)
{
    int64_t borrow = 0;
    for (int i = 0; i < a->n; i++) {
        int64_t s = (int64_t)a->d[i] - borrow - (i < b->n ? (int64_t)b->d[i] : 0);
        borrow = s < 0;
        r->d[i] = (uint32_t)(s + (borrow ? ((int64_t)1 << 32) : 0));
    }
    r->n = a->n;
}

static void add_signed(bigint *r, const bigint *a, const bigint *b, int bsign)
{
    if (b->sign == 0) {
        if (r != a) *r = *a;
        return;
    }
    if (a->sign == 0) {
        if (r != b) *r = *b;
        r->sign = bsign;
        return;
    }
    if (a->sign == bsign) {
        int s = a->sign;
        mag_add(r, a, b);
        r->sign = s;
    } else {
        int c = mag_cmp(a, b);
        if (c == 0) {
            r->n = 0;
            r->sign = 0;
            return;
        }
        if (c > 0) {
            int s = a->sign;
            mag_sub(r, a, b);
            r->sign = s;
        } else {
            mag_sub(r, b, a);
            r->sign = bsign;
        }
    }
    normalize(r);
}

void bigint_add(bigint *r, const bigint *a, const bigint *b) { add_signed(r, a, b, b->sign); }

void bigint_sub(bigint *r, const bigint *a, const bigint *b) { add_signed(r, a, b, -b->sign); }

void bigint_mul(bigint *r, const bigint *a, const bigint *b)
{
    if (a->sign == 0 || b->sign == 0) {
        r->n = 0;
        r->sign = 0;
        return;
    }
    bigint t;
    int n = a->n + b->n;
    if (n > BIGINT_LIMBS) n = BIGINT_LIMBS; /* cannot happen within bounds */
    memset(t.d, 0, (size_t)n * sizeof t.d[0]);
    /* Values from bigint_from_double have few nonzero limbs (a 53-bit
     * mantissa above many zero limbs): skipping zero limbs of a and the low
     * zero limbs of b saves most of the schoolbook work. */
    int b0 = 0;
    while (b0 < b->n && b->d[b0] == 0) b0++;
    for (int i = 0; i < a->n; i++) {
        uint64_t carry = 0;
        uint64_t ai = a->d[i];
        if (ai == 0) continue;
        int j;
        for (j = b0; j < b->n && i + j < n; j++) {
            uint64_t cur = t.d[i + j] + ai * b->d[j] + carry;
            t.d[i + j] = (uint32_t)cur;
            carry = cur >> 32;
        }
        for (int k = i + j; carry && k < n; k++) {
            uint64_t cur = t.d[k] + carry;
            t.d[k] = (uint32_t)cur;
            carry = cur >> 32;
        }
    }
    t.n = n;
    t.sign = a->sign * b->sign;
    normalize(&t);
    r->sign = t.sign;
    r->n = t.n;
    memcpy(r->d, t.d, (size_t)t.n * sizeof t.d[0]);
}
