/* tools/cli_unit_scale: 3D commands work on the input at unit scale.
 *
 * Squared lengths and areas overflow above about 1e77 and underflow below
 * about 1e-77: `scaf tet` on a tetrahedron at 1e300 made TetGen assert
 * (exit 70), at 1e-300 it saw "facets intersect", and `scaf flow` called
 * a face at 1e300 "zero area". As the 2D commands already do
 * (geom/coord_scale), the positions are divided by a power of two so the
 * largest coordinate is in [1, 2) -- exact, so every exact predicate says
 * the same -- and the results are multiplied back before writing. Inputs
 * whose largest coordinate is within 2^+-CLI_UNIT_SCALE_SAFE are used as
 * they are (their products of four coordinates stay in range), so their
 * results keep the same bits as before.
 *
 * Fails (exit 4, with the range) when the input spans more binary orders
 * of magnitude than a double holds at once (a nonzero coordinate would
 * become subnormal at unit scale), or when a result in the input's units
 * is beyond the largest double (the box around a surface near 1e308).
 */
#ifndef SCAF_TOOLS_CLI_UNIT_SCALE_H
#define SCAF_TOOLS_CLI_UNIT_SCALE_H

#include "mesh/mesh.h"

/* Binary exponents of the largest coordinate left as they are. */
#define CLI_UNIT_SCALE_SAFE 60

/* Divide m->V by 2^*e (*e from geom/coord_scale over the faces' corners).
 * Exit status (0, or 4 with a message "scaf CMD: IN: ..."). */
int cli_unit_scale(const char *cmd, const char *in, mesh *m, int *e);

/* Multiply the n values X by 2^e. Exit status (0, or 4 with a message
 * when one is not finite). */
int cli_unit_unscale(const char *cmd, const char *in, double *X, size_t n, int e);

#endif /* SCAF_TOOLS_CLI_UNIT_SCALE_H */
