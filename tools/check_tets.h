/* tools/check_tets: `scaf check FILE.mesh`, the orientation of every
 * tetrahedron of a Medit tet mesh (scaf_check_tets, exact orient3d).
 * Exit status: 0 every tet positively oriented, 1 some inverted or flat,
 * 3 unreadable or malformed file, 7 out of memory. */
#ifndef SCAF_TOOLS_CHECK_TETS_H
#define SCAF_TOOLS_CHECK_TETS_H

/* 1 when path names a Medit mesh (ends in ".mesh"). */
int check_tets_applies(const char *path);

/* Read, check and print the report; returns the exit status. */
int check_tets_run(const char *path, int json);

#endif
