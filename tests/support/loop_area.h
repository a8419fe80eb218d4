/* tests/support/loop_area: the signed area of a boundary loop, for tests
 * that check a loop's orientation (mesh on the left: outer loops CCW,
 * holes CW).
 *
 * Plain floating point (the tests use it on meshes whose loops enclose
 * areas far from zero); it cannot fail. */
#ifndef SCAF_TESTS_LOOP_AREA_H
#define SCAF_TESTS_LOOP_AREA_H

#include "mesh/complex.h"
#include "mesh/mesh.h"

/* Signed area, in the xy plane of m's positions, of ordered loop l of cx
 * (a complex over m's vertex indices: loop corner i is the start vertex
 * m->F[cx->loop_he[i]]): > 0 when counter-clockwise. */
double test_loop_area_xy(const mesh *m, const tri_complex *cx, int l);

#endif
