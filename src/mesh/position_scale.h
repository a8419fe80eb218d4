/* mesh/position_scale: bringing vertex positions to unit scale by a power
 * of two.
 *
 * Results must not depend on the units of the input: a mesh in
 * kilometres, in nanometres or scaled by 1e80 is the same surface. The
 * optimizer works with squared lengths and areas (products of four
 * coordinates), which overflow above about 1e77 and underflow below about
 * 1e-77. Dividing every position used by a face by 2^e, with e the
 * exponent of the largest coordinate magnitude, puts the largest one in
 * [1, 2): exact in floating point (only the exponents change, barring a
 * coordinate that falls below 2^-1022 relative to the largest), so
 * exact predicates give the same verdicts on the scaled positions, and a
 * result in the scaled units times 2^e is the result in the input's
 * units (bit for bit when the input was itself scaled by a power of two).
 * Translation is not applied: it would round.
 */
#ifndef SCAF_MESH_POSITION_SCALE_H
#define SCAF_MESH_POSITION_SCALE_H

/* The exponent e such that the largest |coordinate| of the vertices used
 * by the faces, divided by 2^e, is in [1, 2); 0 when there is none or all
 * are 0 (or one is not finite: the caller's own checks report that).
 *   V   #V by 3 positions
 *   F   nf by 3 vertex indices, each in range (checked by the caller) */
int position_scale_exponent(const double *V, int nf, const int *F);

/* Vs = V with every vertex used by a face divided by 2^e (ldexp; the
 * others copied as they are). Vs (#V by 3, nv rows) may not alias V. */
void position_scale_apply(double *Vs, const double *V, int nv, int nf, const int *F, int e);

#endif /* SCAF_MESH_POSITION_SCALE_H */
