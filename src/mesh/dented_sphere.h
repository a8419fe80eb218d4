/* mesh/dented_sphere: a closed genus-0 surface that intersects itself by
 * a known displacement, the test case of `scaf untangle` (sample
 * "dented" of mesh/samples).
 *
 * The unit icosphere (mesh/samples), turned about the z axis by
 * DENTED_SPHERE_TURN radians (clockwise seen from +z) so that one of its
 * twelve corners, (1, g, 0) / |(1, g, 0)|, is the top pole (0, 1, 0). Its
 * top cap -- the points whose angle from +y is below
 * DENTED_SPHERE_CAP degrees -- is pushed down: a point at angle t moves
 * by DENTED_SPHERE_DEPTH cos^2(90 t / DENTED_SPHERE_CAP) along -y, so the
 * cap stays a smooth graph over the xz-plane and its pole ends at y =
 * 1 - DENTED_SPHERE_DEPTH, below the bottom of the sphere: the cap
 * passes through the lower half along one closed curve. The rest of the
 * sphere does not move.
 */
#ifndef SCAF_MESH_DENTED_SPHERE_H
#define SCAF_MESH_DENTED_SPHERE_H

#include "mesh/mesh.h"

#define DENTED_SPHERE_CAP 60.0
#define DENTED_SPHERE_DEPTH 2.3

/* How far (>= 0, along -y) the point p of the unit sphere is pushed. */
double dented_sphere_push_of(const double p[3]);

/* atan(1 / g), g the golden ratio: the angle of the corner (1, g, 0) from +y */
#define DENTED_SPHERE_TURN 0.55357435889704525151

/* Turn every vertex of m (the unit icosphere) by DENTED_SPHERE_TURN and
 * push it down by dented_sphere_push_of. */
void dented_sphere_push(mesh *m);

#endif
