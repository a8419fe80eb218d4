/* geom/bigint: small fixed-capacity signed integers for the predicates'
 * last-resort exact path.
 *
 * Doubles with arbitrary exponents (from 2^-1074 to 2^1023) do not fit the
 * range where expansion arithmetic is exact (tiny products underflow, huge
 * ones overflow). Here every coordinate of one predicate call is written as
 * an integer times 2^emin, emin the smallest exponent among them, and the
 * determinant is evaluated with integers: exact for every finite double.
 * Capacity covers a degree-5 polynomial (insphere) of 2100-bit integers;
 * values are on the stack, nothing allocates or fails. Slow-ish (schoolbook
 * multiplication on 32-bit limbs), used only for out-of-range inputs.
 */
#ifndef SCAF_GEOM_BIGINT_H
#define SCAF_GEOM_BIGINT_H

#include <stdint.h>

/* 5 * 2100 bits plus carries, in 32-bit limbs. */
#define BIGINT_LIMBS 340

typedef struct bigint {
    int sign; /* -1, 0, +1 */
    int n;    /* used limbs of the magnitude, 0 when sign == 0 */
    uint32_t d[BIGINT_LIMBS];
} bigint;

/* The lowest exponent e such that x is an integer multiple of 2^e (x finite
 * and nonzero). */
int bigint_low_exponent(double x);

/* r = x / 2^emin exactly; x must be finite and a multiple of 2^emin. */
void bigint_from_double(bigint *r, double x, int emin);

/* r = a + b, r = a - b, r = a * b (r may alias a or b). */
void bigint_add(bigint *r, const bigint *a, const bigint *b);
void bigint_sub(bigint *r, const bigint *a, const bigint *b);
void bigint_mul(bigint *r, const bigint *a, const bigint *b);

#endif /* SCAF_GEOM_BIGINT_H */
