/* app/distortion_scale: the colour of a triangle's distortion, one scale
 * for every picture (--svg, --png of param, the legends' colour bars).
 *
 * The energy is the symmetric Dirichlet energy of one triangle, 4 at an
 * isometry. The scale position t in [0, 1] is
 *     t = sqrt(min(1, log2(E / 4) / 2))      (t = 0 for E <= 4),
 * so t = 1 at E = 16 (a triangle stretched about 3.7 times) and above,
 * and the sqrt opens up the range typical optimized maps live in: E = 4.4
 * (10% over an isometry) is t = 0.26, E = 5 t = 0.40, E = 8 t = 0.71. The
 * previous scale (log2(E / 4) / 4) put E = 4.4 at t = 0.03, so most of a
 * map read as the same pale blue. The colours run through five stops,
 * dark blue, teal, green, yellow, red, with red rising and blue falling
 * monotonically along the bar (so the colour order can be checked and
 * read without the labels); non-finite energies are the top colour.
 * Pure functions; nothing fails.
 */
#ifndef SCAF_APP_DISTORTION_SCALE_H
#define SCAF_APP_DISTORTION_SCALE_H

/* The energy at which the scale saturates (t = 1). */
#define DISTORTION_SCALE_TOP 16.0

/* The energies the colour bars label. */
#define DISTORTION_SCALE_TICKS 6
extern const double distortion_scale_ticks[DISTORTION_SCALE_TICKS];

/* t in [0, 1] of an energy (monotone nondecreasing in E). */
double distortion_scale_t(double energy);

/* The energy at scale position t (the inverse on (0, 1]). */
double distortion_scale_energy(double t);

/* The colour 0xRRGGBB at position t (clamped to [0, 1]). */
unsigned distortion_scale_colour_at(double t);

/* The colour of an energy: distortion_scale_colour_at(distortion_scale_t(E)). */
unsigned distortion_scale_colour(double energy);

#endif /* SCAF_APP_DISTORTION_SCALE_H */
