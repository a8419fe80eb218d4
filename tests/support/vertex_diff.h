/* tests/support/vertex_diff: how far two vertex arrays of one mesh are. */
#ifndef SCAF_TESTS_VERTEX_DIFF_H
#define SCAF_TESTS_VERTEX_DIFF_H

/* The largest coordinate difference between a and b (nv vertices, 3
 * coordinates each), relative to the bounding-box diagonal of b. */
double test_max_vertex_diff_rel(int nv, const double *a, const double *b);

#endif
