/* tests/opt/tet_grid: a cube of m^3 cells, each split into 6 positively
 * oriented tetrahedra (Kuhn subdivision). Header-only. */
#ifndef SCAF_TESTS_OPT_TET_GRID_H
#define SCAF_TESTS_OPT_TET_GRID_H

#include <stdlib.h>

typedef struct tet_grid {
    int nv, nt;
    double *X;               /* nv by 3, in [0,1]^3 */
    int *T;                  /* nt by 4 */
    unsigned char *boundary; /* nv flags: on the cube's surface */
} tet_grid;

static inline void tet_grid_free(tet_grid *g)
{
    free(g->X);
    free(g->T);
    free(g->boundary);
}

static inline int tet_grid_make(tet_grid *g, int m)
{
    int s = m + 1;
    g->nv = s * s * s;
    g->nt = 6 * m * m * m;
    g->X = malloc(3 * (size_t)g->nv * sizeof *g->X);
    g->T = malloc(4 * (size_t)g->nt * sizeof *g->T);
    g->boundary = malloc((size_t)g->nv);
    if (!g->X || !g->T || !g->boundary) return -1;
    for (int z = 0; z < s; z++)
        for (int y = 0; y < s; y++)
            for (int x = 0; x < s; x++) {
                int v = (z * s + y) * s + x;
                g->X[3 * v] = (double)x / m;
                g->X[3 * v + 1] = (double)y / m;
                g->X[3 * v + 2] = (double)z / m;
                g->boundary[v] = x == 0 || y == 0 || z == 0 || x == m || y == m || z == m;
            }
    static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int t = 0;
    for (int z = 0; z < m; z++)
        for (int y = 0; y < m; y++)
            for (int x = 0; x < m; x++)
                for (int p = 0; p < 6; p++) {
                    int c[3] = {x, y, z}, *tt = g->T + 4 * t++;
                    tt[0] = (c[2] * s + c[1]) * s + c[0];
                    for (int k = 0; k < 3; k++) {
                        c[perms[p][k]]++;
                        tt[k + 1] = (c[2] * s + c[1]) * s + c[0];
                    }
                    /* Orient positively. */
                    double e[3][3];
                    for (int k = 0; k < 3; k++)
                        for (int a = 0; a < 3; a++)
                            e[k][a] = g->X[3 * tt[k + 1] + a] - g->X[3 * tt[0] + a];
                    double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                        e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                        e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
                    if (det < 0) {
                        int k = tt[1];
                        tt[1] = tt[2];
                        tt[2] = k;
                    }
                }
    return 0;
}

#endif /* SCAF_TESTS_OPT_TET_GRID_H */
