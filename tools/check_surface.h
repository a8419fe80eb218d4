/* tools/check_surface: the 3D half of `scaf check`, self-intersections of
 * a triangle surface (scaf_check_surface), printed as text or JSON.
 *
 * Used for a closed surface without UVs, or for any surface with --3d.
 * Exit status as the UV check: 0 intersection-free, 1 self-intersecting
 * (or with zero-area faces), 4 invalid mesh, 7 out of memory. */
#ifndef SCAF_TOOLS_CHECK_SURFACE_H
#define SCAF_TOOLS_CHECK_SURFACE_H

#include "mesh/mesh.h"

/* 1 when m has faces and no boundary edge (every edge has two or more
 * faces); 0 otherwise or when its topology cannot be computed. */
int check_surface_is_closed(const mesh *m);

/* Check m (read from path) and print the report; returns the exit status. */
int check_surface_run(const char *path, const mesh *m, int json);

#endif
